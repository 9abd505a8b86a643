#!/usr/bin/env bash
# Quick start, part 1: installs what is missing, builds (Release) into build/, and runs
# the main job on a default input. Until the embedding lands, the main job draws the
# basic tiles of the two orbifold families (the paper's Figure 4).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build="${HOT_BUILD_DIR:-$root/build}"
out="$build/demo"
mkdir -p "$out"
"$build/bin/hyperbolic_orbifold_tutte" tile --orbifold sphere --cones 7 --svg "$out/sphere_tile_7.svg"
"$build/bin/hyperbolic_orbifold_tutte" tile --orbifold disk --cones 5 --svg "$out/disk_tile_5.svg"
if command -v rsvg-convert >/dev/null 2>&1; then
  for f in "$out"/*.svg; do rsvg-convert "$f" -o "${f%.svg}.png"; done
fi
echo
echo "Results are in $out:"
ls -1 "$out"
