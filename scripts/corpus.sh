#!/usr/bin/env bash
# Tries every mesh of a corpus as a new user would: 7 automatic landmarks, then embed
# (certified with exact predicates by the embed job itself), then the independent checker
# `certify` on the OBJ (which holds the prepared mesh with --repair). Prints one line per mesh
# (mesh, vertices, verdict, reason) and the totals: a mesh counts when embed and certify both
# accept it.
#   scripts/corpus.sh [--repair [--largest-component] [--max-hole F]] DIR_OR_FILE ...
# The meshes are read where they are (e.g. ../shared/data, libcgal-demo's data/meshes);
# nothing is copied. Meshes with fewer than 30 vertices are skipped.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${HOT_BIN:-$root/build/bin/hyperbolic_orbifold_tutte}"
repair=()  # the repair options, given to both landmarks and embed
while [ $# -gt 0 ]; do
  case "$1" in
    --repair|--largest-component) repair+=("$1"); shift ;;
    --max-hole) repair+=("$1" "$2"); shift 2 ;;
    *) break ;;
  esac
done
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
files=()
for a in "$@"; do
  if [ -d "$a" ]; then
    while IFS= read -r f; do files+=("$f"); done < <(find "$a" -type f \( -name '*.off' -o -name '*.obj' -o -name '*.ply' -o -name '*.stl' \) | sort)
  else files+=("$a"); fi
done
ok=0; total=0
count_vertices() { # the header's count: OFF line 2 / OBJ v lines / PLY element vertex / STL 3 per facet
  case "$1" in
    *.off) awk 'NF && $1 !~ /^#/ { n++; if(n==1 && $1 ~ /OFF$/ && NF==1) next; if(n<=2) { print $1; exit } }' "$1" ;;
    *.obj) grep -c '^v ' "$1" ;;
    *.ply) awk '/^element vertex/ { print $3; exit }' "$1" ;;
    *.stl) echo 999 ;;
  esac
}
# the specific reason of a refusal: the program's line without its name, the error code's
# description and the file name
reason() { head -n 1 "$work/err" | sed 's/^hyperbolic_orbifold_tutte: [^:]*: //; s/^[^ ]*\.[A-Za-z]*: //' | cut -c1-400; }
printf '%-48s %8s  %-8s %s\n' mesh vertices verdict reason
for f in "${files[@]}"; do
  n="$(count_vertices "$f" 2>/dev/null)"; n="${n:-0}"
  [[ "$n" =~ ^[0-9]+$ ]] || n=0
  [ "$n" -ge 30 ] || continue
  total=$((total + 1))
  name="${f#"$root"/}"
  if ! "$bin" landmarks --mesh "$f" --count 7 "${repair[@]}" --out "$work/c.txt" >/dev/null 2>"$work/err"; then
    printf '%-48s %8s  %-8s %s\n' "$name" "$n" refused "landmarks: $(reason)"
    continue
  fi
  if "$bin" embed --mesh "$f" --cones "$work/c.txt" "${repair[@]}" --out "$work/e.obj" --report "$work/r.json" >"$work/out" 2>"$work/err"; then
    genus=$(grep -o '"genus": [0-9]*' "$work/r.json" | grep -o '[0-9]*$' || echo 0)
    if "$bin" certify --mesh "$work/e.obj" --embedding "$work/e.obj" --cones "$work/c.txt" >"$work/cout" 2>"$work/err"; then
      ok=$((ok + 1)); printf '%-48s %8s  %-8s %s\n' "$name" "$n" certified \
        "genus ${genus:-0}$(sed -n 's/^repaired [^:]*: / (repair: /p' "$work/out" | head -1 | sed 's/$/)/')"
    else
      printf '%-48s %8s  %-8s %s\n' "$name" "$n" uncertified "genus ${genus:-0}, certify: $(reason)"
    fi
  else
    printf '%-48s %8s  %-8s %s\n' "$name" "$n" refused "$(reason)"
  fi
done
echo "embedded and certified $ok of $total meshes"
