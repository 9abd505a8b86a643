#!/usr/bin/env bash
# Stress test of the embedding with random landmark sets (not part of ctest / CI): builds
# stress_landmarks (Release, build/ or $HOT_BUILD_DIR) and runs it on every closed genus-0
# and every disk-type mesh among Debian's libcgal-demo meshes (<build>/data/meshes), the
# smallest first, one process per mesh; other meshes are skipped with the reason.
#
#   scripts/stress.sh [--meshes LIST] [--ks LIST] [--seeds LIST] [--max-vertices N] [--time-budget S]
#     --meshes a.off,b.off   file names in <build>/data/meshes, or paths (default: all)
#     --ks 5,7,10,16,23,35,50  --seeds 1-8 (a list 1,4,9 or a range)
#     --max-vertices 60000   bigger meshes are skipped (0: no limit)
#     --time-budget 1200     seconds for all the runs, shared between the meshes in
#                            proportion to their sizes (what a mesh leaves goes to the next,
#                            bigger ones); runs that do not fit are counted as "not run"
#
# Prints one line per run (see benchmark/stress_landmarks.cpp), a table per mesh, then a
# table of all meshes, the overall success rate (success = certified bijective), the runs
# refused with a reason and the failures with their reproduction data. Everything is also
# written to <build>/stress/stress.log. Exit status 1 when a run failed or crashed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOT_BUILD_DIR:-$root/build}"
meshes_opt="" ks="5,7,10,16,23,35,50" seeds="1-8" max_vertices=60000 budget=1200
usage() { sed -n '7,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  [ $# -ge 2 ] || usage
  case "$1" in
    --meshes) meshes_opt="$2" ;;
    --ks) ks="$2" ;;
    --seeds) seeds="$2" ;;
    --max-vertices) max_vertices="$2" ;;
    --time-budget) budget="$2" ;;
    *) usage ;;
  esac
  shift 2
done
[[ "$budget" =~ ^[0-9]+$ && "$max_vertices" =~ ^[0-9]+$ ]] || usage

"$root/scripts/install-deps.sh" >/dev/null
"$root/scripts/build.sh" stress_landmarks >/dev/null
prog="$build/bin/stress_landmarks"
meshdir="$build/data/meshes"
out="$build/stress"
mkdir -p "$out"
rm -f "$out"/*.out "$out"/*.err
log="$out/stress.log"
exec > >(tee "$log") 2>&1

files=()
if [ -n "$meshes_opt" ]; then
  IFS=',' read -r -a items <<<"$meshes_opt"
  for m in "${items[@]}"; do
    if [ -f "$m" ]; then files+=("$m"); elif [ -f "$meshdir/$m" ]; then files+=("$meshdir/$m");
    else echo "stress: no mesh '$m' (neither a file nor in $meshdir)" >&2; exit 2; fi
  done
else
  for f in "$meshdir"/*; do
    case "${f,,}" in *.off|*.obj|*.ply|*.stl) files+=("$f") ;; esac
  done
fi
[ ${#files[@]} -gt 0 ] || { echo "stress: no meshes in $meshdir" >&2; exit 2; }

start=$SECONDS
echo "== stress: ${#files[@]} meshes, k in {$ks}, seeds $seeds, at most $max_vertices vertices, budget ${budget}s"
declare -A path_of
for f in "${files[@]}"; do path_of["$(basename "$f")"]="$f"; done
classes="$out/classes.txt"
"$prog" --classify --max-vertices "$max_vertices" "${files[@]}" >"$classes"
grep '^SKIP ' "$classes" || true
mapfile -t eligible < <(grep '^CLASS ' "$classes" | sort -k4,4n | awk '{print $2}')
declare -A weight_of # budget weight: the number of vertices, at least 1000
total_weight=0
while read -r _ name _ nv; do
  weight_of["$name"]=$(( nv > 1000 ? nv : 1000 )); total_weight=$(( total_weight + weight_of["$name"] ))
done < <(grep '^CLASS ' "$classes")
echo "== ${#eligible[@]} meshes to run: $(grep -c '^CLASS .* sphere ' "$classes" || true) sphere type, $(grep -c '^CLASS .* disk ' "$classes" || true) disk type"

crashes=()
for name in "${eligible[@]}"; do
  # this mesh's share of the time left, in proportion to its size among the meshes left
  remaining=$(( budget - (SECONDS - start) ))
  share=$(( remaining > 0 ? remaining * weight_of["$name"] / total_weight : 0 ))
  [ "$share" -gt 0 ] || share=1
  total_weight=$(( total_weight - weight_of["$name"] ))
  set +e
  timeout --signal=KILL $(( 2 * share + 300 )) \
    "$prog" --ks "$ks" --seeds "$seeds" --max-vertices "$max_vertices" --time-budget "$share" "${path_of[$name]}" \
    2>"$out/$name.err" | tee "$out/$name.out"
  rc=${PIPESTATUS[0]}
  set -e
  if [ "$rc" -ne 0 ]; then
    last="$(grep '^START ' "$out/$name.err" | tail -n 1 || true)"
    msg="CRASH $name exit status $rc$([ "$rc" -eq 137 ] && echo ' (killed by the time limit)') during: ${last#START } -- $(grep -v '^START ' "$out/$name.err" | head -n 3 | tr '\n' ' ')"
    echo "$msg"
    crashes+=("$msg")
  fi
done

echo
echo "== all meshes (success = certified bijective; rate over the runs made, and over the runs not refused)"
for name in "${eligible[@]}"; do cat "$out/$name.out" 2>/dev/null || true; done | { grep '^SUMMARY ' || true; } | awk '
  { for(i = 3; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
    rate = v["runs"] > 0 ? sprintf("%.1f%%", 100 * v["certified"] / v["runs"]) : "-"
    printf "%-28s %-6s %8s %5s %9s %7s %6s %7s %8s %9s\n", $2, v["type"], v["vertices"], v["runs"], v["certified"],
           v["refused"], v["failed"], v["not_run"], rate, v["seconds"]
    R += v["runs"]; C += v["certified"]; F += v["refused"]; X += v["failed"]; N += v["not_run"]; M += 1 }
  BEGIN { printf "%-28s %-6s %8s %5s %9s %7s %6s %7s %8s %9s\n", "mesh", "type", "vertices", "runs", "certified",
                 "refused", "failed", "not_run", "success", "seconds" }
  END { printf "TOTAL %d meshes: %d runs, %d certified, %d refused with a reason, %d failed, %d not run\n", M, R, C, F, X, N
        if(R > 0) printf "SUCCESS RATE: %.2f%% of the runs certified (%d/%d); %.2f%% of the runs not refused (%d/%d)\n",
                         100 * C / R, C, R, (R > F ? 100 * C / (R - F) : 0), C, R - F }'
echo "crashes / killed processes: ${#crashes[@]}"
refused_runs="$(cat "$out"/*.out 2>/dev/null | grep '^RUN .* REFUSED ' || true)"
failed_runs="$(cat "$out"/*.out 2>/dev/null | grep '^RUN .* FAILED ' || true)"
echo
echo "== refused with a reason"
echo "${refused_runs:-(none)}"
echo
echo "== failures (reproduce one with: $prog --ks K --seeds SEED MESH, or the command-line"
echo "   program's embed --mesh MESH --cones FILE --order tsp|given with the landmarks printed)"
[ -z "$failed_runs" ] || echo "$failed_runs"
for c in "${crashes[@]+"${crashes[@]}"}"; do echo "$c"; done
[ -n "$failed_runs" ] || [ ${#crashes[@]} -gt 0 ] || echo "(none)"
echo "== stress: $(( SECONDS - start ))s; log: $log"
[ -z "$failed_runs" ] && [ ${#crashes[@]} -eq 0 ]
