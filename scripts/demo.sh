#!/usr/bin/env bash
# Quick start, part 1: installs what is missing, builds (Release) into build/, and runs
# the main job on a default input: the hyperbolic orbifold Tutte embedding of Debian's
# libcgal-demo bear.off with 7 landmarks chosen by farthest-point sampling, written as
# OBJ + SVG (+ PNG) + JSON report; plus pictures of the orbifold tiles (Figure 4), of the
# (2,3,7) tiling and of a genus-2 mesh in its fundamental polygon.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" hyperbolic_orbifold_tutte
build="${HOT_BUILD_DIR:-$root/build}"
bin="$build/bin/hyperbolic_orbifold_tutte"
mesh="${1:-$build/data/meshes/bear.off}"
out="$build/demo"
mkdir -p "$out"
name="$(basename "${mesh%.*}")"
"$bin" landmarks --mesh "$mesh" --count 7 --out "$out/$name.cones.txt"
"$bin" embed --mesh "$mesh" --cones "$out/$name.cones.txt" --out "$out/$name.obj" --svg "$out/$name.svg" \
  --report "$out/$name.report.json"
"$bin" tile --orbifold sphere --cones 7 --svg "$out/sphere_tile_7.svg"
"$bin" tile --orbifold disk --cones 5 --svg "$out/disk_tile_5.svg"
"$bin" tile --orbifold sphere --cone-orders 2,3,7 --depth 5 --svg "$out/sphere_tile_237.svg"
# a closed surface of genus 2 without landmark: libcgal-demo's eight in its cut graph's polygon
: > "$out/none.cones.txt"
"$bin" embed --mesh "$build/data/meshes/eight.off" --cones "$out/none.cones.txt" --out "$out/eight.obj" \
  --svg "$out/genus2_eight.svg" --cut-graph-out "$out/eight.cut.txt"
if command -v rsvg-convert >/dev/null 2>&1; then
  for f in "$out"/*.svg; do rsvg-convert "$f" -o "${f%.svg}.png"; done
fi
echo
echo "Results are in $out:"
ls -1 "$out"
