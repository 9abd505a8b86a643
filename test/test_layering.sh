#!/usr/bin/env bash
# The subsystems of include/CGAL/Hyperbolic_orbifold_Tutte/internal/ against their READMEs:
#  - every header of internal/ is in a folder, and every folder has a README.md that names each
#    of its headers (in backquotes) and ends with "Includes from internal/: A, B, ..." (the
#    folders it may include, itself among them);
#  - every include of internal/X/ from folder D is of a folder D's README allows;
#  - the allowed includes have no cycle (the folders are layers);
#  - internal/ includes a public header only when internal/README.md lists it as vocabulary, and
#    a vocabulary header includes only vocabulary headers and internal/core/.
# First on a copy of the tree with one forbidden include of each kind, which must be refused,
# then on the tree itself.
#   test_layering.sh SOURCE_DIR
set -u
root="${1:?usage: test_layering.sh SOURCE_DIR}"

check_tree() { # check_tree INCLUDE_DIR: prints FAIL lines, returns 1 on any
  local inc="$1" int="$1/internal" bad=0 d f h deps allowed vocab
  [ -f "$int/README.md" ] || { echo "FAIL: internal/README.md missing"; return 1; }
  vocab=$(grep '^Vocabulary:' "$int/README.md" | grep -o '`[A-Za-z0-9_]*\.h`' | tr -d '`')
  [ -n "$vocab" ] || { echo "FAIL: internal/README.md lists no vocabulary"; bad=1; }
  for f in "$int"/*.h; do [ -e "$f" ] && { echo "FAIL: internal/${f##*/} is in no subsystem folder"; bad=1; }; done
  declare -A allow
  for d in "$int"/*/; do
    d="${d%/}"; d="${d##*/}"
    local readme="$int/$d/README.md"
    [ -f "$readme" ] || { echo "FAIL: internal/$d/ has no README.md"; bad=1; continue; }
    allowed=$(grep '^Includes from internal/:' "$readme" | sed 's/^Includes from internal\/://; s/([^)]*)//g; s/[,.]/ /g')
    [ -n "$allowed" ] || { echo "FAIL: internal/$d/README.md says nothing of what it may include"; bad=1; }
    allow[$d]="$allowed"
    for x in $allowed; do [ -d "$int/$x" ] || { echo "FAIL: internal/$d/README.md allows '$x', which is not a folder of internal/"; bad=1; }; done
    for f in "$int/$d"/*.h; do
      [ -e "$f" ] || continue
      grep -qF "\`${f##*/}\`" "$readme" || { echo "FAIL: internal/$d/README.md does not name ${f##*/}"; bad=1; }
    done
    for h in $(grep -o '`[A-Za-z0-9_]*\.h`' "$readme" | tr -d '`' | sort -u); do
      [ -f "$int/$d/$h" ] || [ -f "$inc/$h" ] || { echo "FAIL: internal/$d/README.md names $h, which does not exist"; bad=1; }
    done
  done
  for d in "${!allow[@]}"; do
    for f in "$int/$d"/*.h; do
      [ -e "$f" ] || continue
      while IFS= read -r x; do
        case " ${allow[$d]} " in *" $x "*) ;; *) echo "FAIL: internal/$d/${f##*/} includes internal/$x/, which internal/$d/README.md does not allow"; bad=1;; esac
      done < <(grep -o '#include <CGAL/Hyperbolic_orbifold_Tutte/internal/[a-z_]*/' "$f" | sed 's#.*/internal/##; s#/$##' | sort -u)
      while IFS= read -r x; do
        grep -qx "$x" <<< "$vocab" || { echo "FAIL: internal/$d/${f##*/} includes the public header $x, which is not vocabulary"; bad=1; }
      done < <(grep -o '#include <CGAL/Hyperbolic_orbifold_Tutte/[A-Za-z0-9_]*\.h>' "$f" | sed 's#.*Tutte/##; s#>$##' | sort -u)
    done
  done
  for x in $vocab; do
    [ -f "$inc/$x" ] || { echo "FAIL: vocabulary header $x does not exist"; bad=1; continue; }
    while IFS= read -r y; do
      case "$y" in internal/core/*) continue;; esac
      grep -qx "$y" <<< "$vocab" || { echo "FAIL: vocabulary header $x includes $y, which is not vocabulary"; bad=1; }
    done < <(grep -o '#include <CGAL/Hyperbolic_orbifold_Tutte/[A-Za-z0-9_/]*\.h>' "$inc/$x" | sed 's#.*Tutte/##; s#>$##' | sort -u)
  done
  # layers: remove, round after round, the folders that allow only removed ones (and themselves)
  local left="${!allow[*]}" removed="" progress=1
  while [ -n "$left" ] && [ "$progress" = 1 ]; do
    progress=0; local next=""
    for d in $left; do
      local ok=1
      for x in ${allow[$d]}; do [ "$x" = "$d" ] && continue; case " $removed " in *" $x "*) ;; *) ok=0;; esac; done
      if [ "$ok" = 1 ]; then removed="$removed $d"; progress=1; else next="$next $d"; fi
    done
    left="${next# }"
  done
  [ -z "$left" ] || { echo "FAIL: the allowed includes of internal/ have a cycle among: $left"; bad=1; }
  return "$bad"
}

inc="$root/include/CGAL/Hyperbolic_orbifold_Tutte"
[ -d "$inc/internal" ] || { echo "FAIL: $inc/internal missing"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# controls: each forbidden include, planted in a copy, must be refused with its reason
control() { # control NAME FILE LINE PATTERN
  rm -rf "$tmp/inc"; cp -r "$inc" "$tmp/inc"
  sed -i "0,/^#include/s||$3\n#include|" "$tmp/inc/$2"
  if out=$(check_tree "$tmp/inc"); then echo "FAIL: control '$1' was not refused"; return 1; fi
  grep -q "$4" <<< "$out" || { echo "FAIL: control '$1' refused for another reason: $out"; return 1; }
  return 0
}
bad=0
control "core includes solver" internal/core/mesh_graph.h '#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/newton.h>' 'does not allow' || bad=1
control "input climbs to check_input.h" internal/input/input_stage.h '#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>' 'not vocabulary' || bad=1
control "vocabulary includes an algorithm" genus.h '#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>' 'vocabulary header genus.h' || bad=1
rm -rf "$tmp/inc"; cp -r "$inc" "$tmp/inc"; sed -i 's/^Includes from internal\/: core, linear_algebra/Includes from internal\/: core, pipeline, linear_algebra/' "$tmp/inc/internal/solver/README.md"
if out=$(check_tree "$tmp/inc"); then echo "FAIL: control 'solver and pipeline include each other' was not refused"; bad=1
else grep -q "cycle" <<< "$out" || { echo "FAIL: the cycle control refused for another reason: $out"; bad=1; }; fi
out=$(check_tree "$inc") || { echo "$out"; bad=1; }
folders=$(ls -d "$inc/internal"/*/ | wc -l); headers=$(find "$inc/internal" -name '*.h' | wc -l)
[ "$folders" -ge 8 ] && [ "$headers" -ge 60 ] || { echo "FAIL: only $folders folders and $headers headers"; bad=1; }
[ "$bad" = 0 ] && echo "ok: $headers headers in $folders subsystem folders; 4 controls refused"
exit "$bad"
