#!/usr/bin/env bash
# Scans as they come (issue 38): generated scan defects with ground truth, mapped with
# `map --repair` onto a clean shape. Each defective copy keeps the clean mesh's vertex
# numbers (test/scan_defects.awk, test/add_handle.awk), so the truth is the identity
# correspondence between the source and the target (the same mesh, or poses of one
# triangulation). Per defect class and size: the error of the map (mean and largest, in
# bounding box diagonals of the target; test/map_error.awk) against the clean pair's, the
# vertices the map reports in closed holes, and the whole process's time.
#   benchmark/scan_defects.sh CLI DATA_DIR [SHARED_DATA_DIR]
# DATA_DIR: libcgal-demo's data (bear.off); SHARED_DATA_DIR: ../shared/data (TOSCA wolves,
# 7 suggested landmarks; read in place, never copied), used when it exists.
set -euo pipefail
cli="$1"; data="$2"; shared="${3:-}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"; t="$here/../test"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }
error_of() { awk -v per_vertex="$work/errors" -f "$t/off_reader.awk" -f "$t/map_error.awk" "$1" "$2" "$3" | awk '{printf "%.3f%% %.2f%%", 100 * $8, 100 * $6}'; }
# the unreliable vertices of REPORT.json against the errors of the last error_of(): "% flagged,
# % of the worst 1% flagged"
flags_of() {
  grep -o '"unreliable_vertices": \[[^]]*\]' "$1" | grep -o '[0-9][0-9]*' > "$work/flagged" || true
  sort -k2,2 -g -r "$work/errors" | awk -v n="$(wc -l < "$work/errors")" 'NR <= (n + 99) / 100 { print $1 }' > "$work/worst"
  awk -v n="$(wc -l < "$work/errors")" 'FILENAME == ARGV[1] { f[$1] = 1; nf++; next } { w++; if($1 in f) hit++ }
    END { printf "%.1f%% %.0f%%", 100 * nf / n, (w ? 100 * hit / w : 0) }' "$work/flagged" "$work/worst"
}

# bench NAME SOURCE TARGET LANDMARKS: the defects on SOURCE, mapped onto TARGET
bench() {
  local name="$1" src="$2" tgt="$3" lm="$4"
  local first; first=$(head -1 "$lm")
  local all; all=$(tr '\n' ',' < "$lm" | sed 's/,$//')
  "$cli" map --source "$src" --source-cones "$lm" --target "$tgt" --target-cones "$lm" --out "$work/clean.txt" --report "$work/r.json" >/dev/null 2>&1
  local clean; clean=$(error_of "$work/clean.txt" "$tgt" "$tgt")
  echo "== $name: clean pair error (mean, largest): $clean; flagged, worst 1% flagged: $(flags_of "$work/r.json")"
  printf "%-34s %-26s %-20s %-18s %10s %8s\n" "defect" "size" "error mean, largest" "flagged, worst 1%" "in holes" "time"
  # four centres far from the landmarks and from each other (farthest-point sampling in rings)
  local centres=() from="$all" reach=0
  for k in 1 2 3 4; do
    local far; far=$(awk -v from="$from" -v farthest=1 -f "$t/ring_distance.awk" "$src")
    centres+=("${far% *}"); from="$from,${far% *}"
    [ "$k" -gt 1 ] || reach="${far#* }"
  done
  local specs=()
  specs+=("debris (3 stray triangles)|debris=3")
  for frac in 0.02 0.05; do # an opening whose rim passes near landmark 0, grown to the area fraction
    local r=2
    while :; do
      local c; c=$(awk -v from="$first" -v rings="$r" -f "$t/ring_distance.awk" "$src" | sort -n | head -1)
      awk -v openings="$c:$r" -v stats="$work/st" -f "$t/scan_defects.awk" "$src" > /dev/null
      local got; got=$(awk '{print $4}' "$work/st")
      if awk -v g="$got" -v f="$frac" 'BEGIN { exit !(g >= f) }' || [ "$r" -ge 60 ]; then specs+=("opening beside landmark 0|openings=$c:$r"); break; fi
      r=$((r + 1))
    done
  done
  for frac in 0.1 0.2; do # four openings between the landmarks, grown together to the area fraction
    local r=2 o
    while :; do
      o="${centres[0]}:$r,${centres[1]}:$r,${centres[2]}:$r,${centres[3]}:$r"
      awk -v openings="$o" -v stats="$work/st" -f "$t/scan_defects.awk" "$src" > /dev/null
      awk -v g="$(awk '{print $4}' "$work/st")" -v f="$frac" 'BEGIN { exit !(g >= f) }' && break
      [ "$r" -lt "$reach" ] || break
      r=$((r + 1))
    done
    specs+=("4 openings between the landmarks|openings=$o")
  done
  specs+=("handle (a tube, fused limbs)|handle")
  for s in "${specs[@]}"; do
    local label="${s%%|*}" args="${s#*|}" size
    if [ "$args" = handle ]; then
      local f=$(( $(awk 'NR == 2 { print $2 }' "$src") / 3 ))
      awk -v face="$f" -v min_rings=30 -v stats="$work/st" -f "$t/add_handle.awk" "$src" > "$work/d.off"
      size="$(awk '{printf "%.3f apart", $5}' "$work/st")"
    else
      awk -v "$args" -v stats="$work/st" -f "$t/scan_defects.awk" "$src" > "$work/d.off"
      size="$(awk '{ if($4 > 0) printf "%.1f%% of the area", 100 * $4; else printf "%d vertices", $6 }' "$work/st")"
    fi
    local t0; t0=$(now)
    if "$cli" map --repair --source "$work/d.off" --source-cones "$lm" --target "$tgt" --target-cones "$lm" --out "$work/m.txt" \
         --report "$work/r.json" >/dev/null 2>"$work/err"; then
      local t1; t1=$(now)
      "$cli" map --repair --source "$tgt" --source-cones "$lm" --target "$work/d.off" --target-cones "$lm" --out "$work/n.txt" --report "$work/q.json" >/dev/null 2>&1 || true
      local holes; holes=$(grep -o '"images_in_filled_holes_count": [0-9]*' "$work/q.json" 2>/dev/null | awk '{print $2}')
      local err; err=$(error_of "$work/m.txt" "$tgt" "$tgt")
      printf "%-34s %-26s %-20s %-18s %10s %7.2fs\n" "$label" "$size" "$err" "$(flags_of "$work/r.json")" "${holes:--}" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')"
    else
      printf "%-34s %-26s refused: %s\n" "$label" "$size" "$(cut -c1-160 "$work/err")"
    fi
  done
}

echo "7 landmarks, map --repair DEFECTIVE -> CLEAN (in holes: of the reverse map, vertices whose image is in a closed hole)"
printf '10138\n5326\n2877\n3940\n7260\n13588\n121\n' > "$work/bear.txt"
bench "bear.off (libcgal-demo) onto itself" "$data/meshes/bear.off" "$data/meshes/bear.off" "$work/bear.txt"
w="$shared/collections/tosca_wolf"
if [ -n "$shared" ] && [ -f "$w/tosca_wolf0.off" ]; then
  awk 'NR == FNR { row[$1 + 1] = 1; next } FNR in row' "$w/tosca_wolf.suggested_rows7.txt" "$w/tosca_wolf0.landmarks.txt" | awk '{print $1}' > "$work/wolf.txt"
  bench "TOSCA wolf0 onto wolf1 (suggested 7 landmarks)" "$w/tosca_wolf0.off" "$w/tosca_wolf1.off" "$work/wolf.txt"
fi
