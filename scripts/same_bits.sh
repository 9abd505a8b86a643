#!/usr/bin/env bash
# Same bits before and after a change that should not change results (a refactoring):
#   scripts/same_bits.sh BASE_REF [PROGRAM]
# builds the command-line program at BASE_REF (a git worktree in $HOT_SAME_BITS_DIR, default
# /tmp/hot-same-bits/<commit>, built once and kept), runs a fixed set of jobs with it and with
# PROGRAM (default: this tree's build/bin/hyperbolic_orbifold_tutte, built first), and compares
# every output byte for byte: embeddings (OBJ, Poincare coordinates printed to 17 digits),
# landmarks, maps, collections, and the verdict lines of the reports (timings left out).
# The jobs: bear (7 and 50 landmarks, cotangent, mean-value and uniform weights, given and
# tour orders), armadillo (7, 23), mushroom (disk, the CLI test's 6 corners with mean-value
# weights, 9 landmarks), hand, homer, camel, a capsule that needs --recentre, a map and a
# collection. Exit 0 when everything is identical, 1 otherwise (the differing files listed).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
base_ref="${1:?usage: scripts/same_bits.sh BASE_REF [PROGRAM]}"
base_commit="$(git -C "$root" rev-parse "$base_ref^{commit}")"
work="${HOT_SAME_BITS_DIR:-/tmp/hot-same-bits}"
jobs="${HOT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
base_tree="$work/$base_commit"
if [ ! -x "$base_tree/build/bin/hyperbolic_orbifold_tutte" ]; then
  mkdir -p "$work"
  [ -d "$base_tree" ] || git -C "$root" worktree add --detach "$base_tree" "$base_commit" >/dev/null
  cmake -S "$base_tree" -B "$base_tree/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
  cmake --build "$base_tree/build" -j "$jobs" --target hyperbolic_orbifold_tutte >/dev/null
fi
base_prog="$base_tree/build/bin/hyperbolic_orbifold_tutte"
if [ $# -ge 2 ]; then new_prog="$2"; else
  "$root/scripts/build.sh" hyperbolic_orbifold_tutte >/dev/null
  new_prog="${HOT_BUILD_DIR:-$root/build}/bin/hyperbolic_orbifold_tutte"
fi
data="$base_tree/build/data/meshes"
[ -f "$data/bear.off" ] || { echo "same_bits: no libcgal-demo meshes in $data" >&2; exit 2; }

tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
# a capsule of radius 1 and length 50 (landmarks at the bottom): needs --recentre
awk -v L=50 -v S=24 -f "$root/test/capsule.awk" > "$tmp/tube.off" 2> "$tmp/tube.cones"
echo "1166 1785 147 932 2251 139" > "$tmp/mushroom6.cones"
src="$data/hand.off"; nv=$(awk 'NR==2 {print $1}' "$src")
for d in a b; do
  awk -v n="$nv" -v d="$d" 'NR<=2 || NF==0 {print; next}
    NF==3 && c<n { x=$1; y=$2; z=$3; c++; if(d=="b") { x=x+0.1*sin(3*y); z=1.2*z }
      printf "%.9g %.9g %.9g\n", x, y, z; next } {print}' "$src" > "$tmp/hand_$d.off"
done

run_jobs() { # run_jobs PROGRAM OUTDIR
  local p="$1" o="$2"; mkdir -p "$o"
  # everything after the verdict-free fields of a report: sizes, counts, verdict, frame
  strip() { grep -v '"time\|seconds' "$1" > "$1.kept" 2>/dev/null || true; rm -f "$1"; }
  local m k
  for m in bear armadillo hand homer camel; do
    for k in 7 23; do "$p" landmarks --mesh "$data/$m.off" --count $k --out "$o/$m.$k.cones" >/dev/null; done
    "$p" embed --mesh "$data/$m.off" --cones "$o/$m.7.cones" --out "$o/$m.7.obj" --report "$o/$m.7.json" >/dev/null 2>&1 \
      || echo "exit $?" > "$o/$m.7.status"; strip "$o/$m.7.json"
  done
  "$p" landmarks --mesh "$data/bear.off" --count 50 --out "$o/bear.50.cones" >/dev/null
  "$p" embed --mesh "$data/bear.off" --cones "$o/bear.50.cones" --out "$o/bear.50.obj" >/dev/null 2>&1 || echo "exit $?" > "$o/bear.50.status"
  "$p" embed --mesh "$data/armadillo.off" --cones "$o/armadillo.23.cones" --out "$o/armadillo.23.obj" >/dev/null 2>&1 || echo "exit $?" > "$o/armadillo.23.status"
  for w in mvc uniform; do
    "$p" embed --mesh "$data/bear.off" --cones "$o/bear.7.cones" --weights $w --out "$o/bear.7.$w.obj" >/dev/null 2>&1 || echo "exit $?" > "$o/bear.7.$w.status"
  done
  "$p" embed --mesh "$data/bear.off" --cones "$o/bear.7.cones" --order given --out "$o/bear.7.given.obj" >/dev/null 2>&1 || echo "exit $?" > "$o/bear.7.given.status"
  "$p" embed --mesh "$data/mushroom.off" --cones "$tmp/mushroom6.cones" --weights mvc --out "$o/mushroom.6.obj" >/dev/null 2>&1 || echo "exit $?" > "$o/mushroom.6.status"
  "$p" landmarks --mesh "$data/mushroom.off" --count 9 --out "$o/mushroom.9.cones" >/dev/null
  "$p" embed --mesh "$data/mushroom.off" --cones "$o/mushroom.9.cones" --out "$o/mushroom.9.obj" --report "$o/mushroom.9.json" >/dev/null 2>&1 \
    || echo "exit $?" > "$o/mushroom.9.status"; strip "$o/mushroom.9.json"
  "$p" embed --mesh "$tmp/tube.off" --cones "$tmp/tube.cones" --out "$o/tube.obj" --report "$o/tube.json" --recentre >/dev/null 2>&1 \
    || echo "exit $?" > "$o/tube.status"; strip "$o/tube.json"
  "$p" map --source "$tmp/hand_a.off" --source-cones "$o/hand.7.cones" --target "$tmp/hand_b.off" --target-cones "$o/hand.7.cones" \
    --out "$o/hand_a_to_b.map.txt" >/dev/null 2>&1 || echo "exit $?" > "$o/map.status"
  cp "$o/hand.7.cones" "$tmp/hand.cones"
  printf 'hand_a.off hand.cones\nhand_b.off hand.cones\n' > "$tmp/list.txt"
  "$p" collection --manifest "$tmp/list.txt" --out "$o/collection" --all-pairs >/dev/null 2>&1 || echo "exit $?" > "$o/collection.status"
  [ -f "$o/collection/report.json" ] && strip "$o/collection/report.json"
  return 0
}
echo "same_bits: base $base_commit"
run_jobs "$base_prog" "$tmp/base"
run_jobs "$new_prog" "$tmp/new"
n=$(find "$tmp/base" -type f | wc -l)
if diff -rq "$tmp/base" "$tmp/new"; then
  echo "same_bits: $n output files identical"
else
  echo "same_bits: outputs differ (above)"; exit 1
fi
