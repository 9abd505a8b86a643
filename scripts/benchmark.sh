#!/usr/bin/env bash
# Builds (Release) and runs the benchmarks: CGAL's Euclidean orbifold Tutte vs our hyperbolic
# embedding vs the Cholesky floor on Debian's libcgal-demo meshes, and on ../shared/data
# meshes when that folder exists (they are read in place, never copied into the project).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" bench_parameterizer bench_tiles >/dev/null
build="${HOT_BUILD_DIR:-$root/build}"
meshes=()
for m in hand homer triceratops camel bear diplodocus armadillo bunny00; do meshes+=("$build/data/meshes/$m.off"); done
shared="$root/../shared/data/sphere"
if [ -d "$shared" ]; then
  for m in bunny_3k spot david_head igea_134k; do [ -f "$shared/$m.off" ] && meshes+=("$shared/$m.off"); done
fi
echo "== 7 landmarks"
"$build/bin/bench_parameterizer" --landmarks 7 "${meshes[@]}"
echo "== 50 landmarks"
"$build/bin/bench_parameterizer" --landmarks 50 "${meshes[@]:0:6}"
echo "== kernel"
"$build/bin/bench_tiles"
