#!/usr/bin/env bash
# doc/ARCHITECTURE.md against the tree: every header of include/CGAL/Hyperbolic_orbifold_Tutte/
# (and include/CGAL/hyperbolic_orbifold_Tutte.h) is named on the page, in backquotes, by its
# path below that folder (internal/ ones below internal/); every header the page's "Headers"
# section names exists. The same for the programs' headers (application/, tools/, generators/):
# each is named in the "Programs" section by its path below its folder, and each header that
# section names exists in one of them.
#   test_architecture.sh SOURCE_DIR
set -u
root="${1:?usage: test_architecture.sh SOURCE_DIR}"
page="$root/doc/ARCHITECTURE.md"
inc="$root/include/CGAL/Hyperbolic_orbifold_Tutte"
[ -f "$page" ] || { echo "FAIL: $page missing"; exit 1; }
[ -d "$inc" ] || { echo "FAIL: $inc missing"; exit 1; }
bad=0 checked=0
while IFS= read -r h; do
  rel="${h#$inc/}"; rel="${rel#internal/}"
  [ "$h" = "$root/include/CGAL/hyperbolic_orbifold_Tutte.h" ] && rel="hyperbolic_orbifold_Tutte.h"
  checked=$((checked + 1))
  grep -qF "\`$rel\`" "$page" || { echo "FAIL: ${h#$root/} is not on doc/ARCHITECTURE.md"; bad=1; }
done < <(find "$inc" "$root/include/CGAL/hyperbolic_orbifold_Tutte.h" -name '*.h' | sort)
named=0
while IFS= read -r n; do
  named=$((named + 1))
  [ -f "$inc/$n" ] || [ -f "$inc/internal/$n" ] || [ -f "$root/include/CGAL/$n" ] ||
    { echo "FAIL: doc/ARCHITECTURE.md names \`$n\`, which is not a header of the package"; bad=1; }
done < <(sed -n '/^## Headers/,$p' "$page" | grep -o '`[A-Za-z0-9_/]*\.h`' | tr -d '`' | sort -u)
# the programs' headers
programs=0
while IFS= read -r h; do
  rel="${h#$root/}"; rel="${rel#*/}"
  programs=$((programs + 1))
  sed -n '/^## Programs/,/^## Headers/p' "$page" | grep -qF "\`$rel\`" ||
    { echo "FAIL: ${h#$root/} is not on doc/ARCHITECTURE.md (section Programs, as \`$rel\`)"; bad=1; }
done < <(find "$root/application" "$root/tools" "$root/generators" -name '*.h' 2>/dev/null | sort)
while IFS= read -r n; do
  [ -f "$root/application/$n" ] || [ -f "$root/tools/$n" ] || [ -f "$root/generators/$n" ] ||
    { echo "FAIL: doc/ARCHITECTURE.md names \`$n\` (section Programs), which is not a header of application/, tools/ or generators/"; bad=1; }
done < <(sed -n '/^## Programs/,/^## Headers/p' "$page" | grep -o '`[A-Za-z0-9_/]*\.h`' | tr -d '`' | sort -u)
[ "$checked" -ge 90 ] && [ "$named" -ge 90 ] || { echo "FAIL: only $checked headers in the tree and $named on the page"; bad=1; }
[ "$bad" = 0 ] && echo "ok: $checked headers in the tree, $named named on the page; $programs headers of the programs"
exit "$bad"
