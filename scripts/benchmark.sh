#!/usr/bin/env bash
# Builds (Release) and runs the benchmarks (never run by ctest):
#  1. bench_parameterizer: CGAL's Euclidean orbifold Tutte vs our hyperbolic embedding vs the
#     Cholesky floor, on Debian's libcgal-demo meshes, on generated blobs of about 100K and
#     400K vertices (and 1M with --large), with 7 and 50 landmarks; on ../shared/data meshes
#     (the paper's cases) when that folder exists (read in place, never copied);
#  2. bench_collection: 20 poses of bull.off (6.2K vertices) with 23 landmarks, all 380 maps;
#  3. bench_tiles: the kernel;
#  4. bench_input_checks: soup validation, mesh build and input checks on generated meshes of
#     growing size (a cube's surface, 15K to 960K vertices, 4x per step; a fan of 50K to 400K
#     triangles around one vertex, 2x per step), with the ratio of times per step (linear
#     time: 4 and 2; Euler::add_face would make the fan quadratic: 4);
#  5. the whole `embed` process with and without --repair on meshes that need no repair (the
#     preparation's overhead, target <= 10%), and on meshes that need it.
# Prints the machine first. Usage: scripts/benchmark.sh [--large] [--quick]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
large=0; quick=0
for a in "$@"; do
  case "$a" in --large) large=1 ;; --quick) quick=1 ;; *) echo "usage: $0 [--large] [--quick]" >&2; exit 2 ;; esac
done
"$root/scripts/install-deps.sh" >/dev/null
"$root/scripts/build.sh" bench_parameterizer bench_collection bench_tiles bench_input_checks hyperbolic_orbifold_tutte >/dev/null
build="${HOT_BUILD_DIR:-$root/build}"
echo "== machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GB", $2/1048576}' /proc/meminfo), $(. /etc/os-release; echo "$PRETTY_NAME"), $(g++ --version | head -1)"
meshes=()
for m in hand homer triceratops camel bear diplodocus armadillo bunny00; do meshes+=("$build/data/meshes/$m.off"); done
shared="$root/../shared/data/sphere"
paper=()
if [ -d "$shared" ]; then
  for m in bunny_3k spot; do [ -f "$shared/$m.off" ] && paper+=("$shared/$m.off"); done
  [ -f "$shared/david_head.paper_cones5.txt" ] && paper+=("$shared/david_head.off@$shared/david_head.paper_cones5.txt")
  [ -f "$shared/david_head.off" ] && paper+=("$shared/david_head.off")
  [ -f "$shared/igea_134k.off" ] && paper+=("$shared/igea_134k.off")
fi
generated=(generated:100000)
[ $quick = 1 ] || generated+=(generated:400000)
[ $large = 1 ] && generated+=(generated:1000000)
cd "$build"
echo "== 7 landmarks (libcgal-demo meshes, then generated blobs, then the paper's meshes)"
# (ours and the floor: the fastest of 3 runs; CGAL's Euclidean: one run)
"$build/bin/bench_parameterizer" --landmarks 7 --repeat 3 "${meshes[@]}"
"$build/bin/bench_parameterizer" --landmarks 7 --repeat 3 --no-map "${generated[@]}" | tail -n +2
[ ${#paper[@]} -eq 0 ] || "$build/bin/bench_parameterizer" --landmarks 7 --repeat 3 "${paper[@]}" | tail -n +2
echo "== 50 landmarks"
"$build/bin/bench_parameterizer" --landmarks 50 "${meshes[@]:0:7}"
echo "== collection (the paper's FAUST setting)"
"$build/bin/bench_collection"
echo "== kernel"
"$build/bin/bench_tiles"
echo "== input path: soup validation, mesh build, checks (linear time: the ratio is the size ratio)"
"$build/bin/bench_input_checks"
echo "== --repair: whole embed process, fastest of 3 runs (7 landmarks from 'landmarks')"
cli="$build/bin/hyperbolic_orbifold_tutte"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fastest() { # fastest of 3 runs of the command, in seconds
  local best=""
  for _ in 1 2 3; do
    local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1 || { echo fail; return; }; t1=$(date +%s.%N)
    best=$(awk -v a="$best" -v d="$(awk -v x="$t0" -v y="$t1" 'BEGIN{print y-x}')" 'BEGIN{ if(a == "" || d < a) print d; else print a }')
  done
  echo "$best"
}
printf '%-24s %10s %10s %8s  %s\n' mesh plain_s repair_s ratio "what --repair did"
clean=("$build/data/meshes/bear.off" "$build/data/meshes/armadillo.off" "$build/data/meshes/bunny00.off" "$build/data/meshes/diplodocus.off")
[ -f "$shared/igea_134k.off" ] && clean+=("$shared/igea_134k.off")
for m in "${clean[@]}" "$build/data/meshes/pig.off" "$build/data/meshes/mannequin-devil.off" "$build/data/meshes/blobby-shuffled.off"; do
  "$cli" landmarks --mesh "$m" --count 7 --repair --out "$work/c.txt" >/dev/null 2>&1 || continue
  plain=$(fastest "$cli" embed --mesh "$m" --cones "$work/c.txt" --out "$work/e.obj")
  repair=$(fastest "$cli" embed --mesh "$m" --cones "$work/c.txt" --repair --out "$work/e.obj")
  what=$("$cli" embed --mesh "$m" --cones "$work/c.txt" --repair --out "$work/e.obj" 2>/dev/null | sed -n 's/^repaired [^:]*: //p')
  ratio=$(awk -v a="$plain" -v b="$repair" 'BEGIN { if(a + 0 > 0) printf "%.2f", b / a; else print "-" }')
  printf '%-24s %10s %10s %8s  %s\n' "$(basename "$m")" "$plain" "$repair" "$ratio" "$what"
done
