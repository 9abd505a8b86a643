#!/usr/bin/env bash
# Collections that survive faults: test_cli_faults.sh PROGRAM CASE DATA_DIR
#   kill_resume      the single-process collection killed (SIGKILL) once some embeddings are
#                    in DIR/.parts; run again it resumes (the finished embeddings untouched) and
#                    gives the files of an uninterrupted run
#   staged_resume    a maps job killed mid-stage; run again it maps only the pairs left; the
#                    merge gives the files of the single-process run
#   disk_full        a full disk (a file size limit, ulimit -f: writes fail with EFBIG): one line,
#                    exit non-zero, no truncated file under a final name
#   unwritable_dir   DIR not writable (chmod 0555; as root, where that does not stop writes, the
#                    program runs as nobody with runuser, or else a file size limit of 0 blocks):
#                    one line, exit non-zero, nothing left
#   concurrent_lock  a second collection into a DIR in use refuses with one line; shards of a
#                    stage run at once; a killed run's lock does not block
set -u
prog="$1"; case_name="$2"; data="${3:-}"
tmp="$(mktemp -d)"; trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

. "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"   # make_hands, same_files

# no_truncated DIR [MESH]: every OBJ under its final name is complete (all its face lines are
# there), every map as long as the mesh (hand.off, or MESH: every mesh of the collection has its
# triangulation) has vertices
no_truncated() {
  local f nv nf mesh="${2:-$data/meshes/hand.off}"
  nv=$(awk 'NR==2 {print $1}' "$mesh")
  nf=$(awk 'NR==2 {print $2}' "$mesh")
  for f in "$1"/*.obj; do
    [ -e "$f" ] || continue
    [ "$(grep -c '^f ' "$f")" -eq "$nf" ] || fail "$(basename "$f") is truncated"
  done
  for f in "$1"/*.map.txt; do
    [ -e "$f" ] || continue
    [ "$(wc -l < "$f")" -eq "$nv" ] || fail "$(basename "$f") is truncated"
  done
}

hands_collection() { # N letters: hands_collection a b c ... -> $tmp/list.txt
  make_hands "$@"
  "$prog" landmarks --mesh "$tmp/hand_$1.off" --count 9 --out "$tmp/cones.txt" >/dev/null || fail "landmarks"
  : > "$tmp/list.txt"
  for d in "$@"; do echo "hand_$d.off cones.txt" >> "$tmp/list.txt"; done
}

# wait_for COUNT GLOB TIMEOUT_S: until COUNT files match GLOB
wait_for() {
  local n="$1" glob="$2" t=0
  while [ "$t" -lt $(( $3 * 20 )) ]; do
    # shellcheck disable=SC2086
    [ "$(ls $glob 2>/dev/null | wc -l)" -ge "$n" ] && return 0
    sleep 0.05; t=$((t + 1))
  done
  return 1
}

inode() { stat -c %i "$1"; }

bears_collection() { # bear.off (libcgal-demo) and three bent copies (test/bend.awk): a few seconds
  local r
  echo "10138 5326 2877 3940 7260 13588 121" > "$tmp/bear.cones"
  echo "$(cd "$data" && pwd)/meshes/bear.off bear.cones" > "$tmp/list.txt"
  for r in 3 4 6; do
    awk -v R=$r -f "$(dirname "$0")/bend.awk" "$data/meshes/bear.off" > "$tmp/bent$r.off"
    echo "bent$r.off bear.cones" >> "$tmp/list.txt"
  done
}

case "$case_name" in
  kill_resume)
    bears_collection
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ref" --all-pairs >/dev/null 2>&1 || fail "uninterrupted collection"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs > /dev/null 2> "$tmp/err1" &
    pid=$!
    wait_for 1 "$tmp/out/.parts/mesh_*.json" 60 || { kill -9 $pid; fail "no embedding checkpointed: $(cat "$tmp/err1")"; }
    kill -9 $pid; wait $pid 2>/dev/null
    [ -d "$tmp/out/.parts" ] || fail "the collection ended before it was killed (a larger one is needed)"
    [ ! -e "$tmp/out/report.json" ] || fail "report.json before the end"
    no_truncated "$tmp/out" "$data/meshes/bear.off"
    # the embeddings finished before the kill: their OBJ files must not be written again
    declare -A ino
    for p in "$tmp"/out/.parts/mesh_*.json; do
      i=$(basename "$p" .json); i=${i#mesh_}
      f=$(ls "$tmp"/out/${i}_*.obj); ino[$f]=$(inode "$f")
    done
    done_before=${#ino[@]}
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs > "$tmp/out2" 2> "$tmp/err2" || fail "the resumed run: $(cat "$tmp/err2")"
    grep -q "resuming" "$tmp/err2" || fail "the rerun does not say it resumes"
    [ "$(grep -c 'embedded before' "$tmp/err2")" -eq "$done_before" ] || fail "the rerun skipped $(grep -c 'embedded before' "$tmp/err2") embeddings, $done_before were done"
    [ "$(grep -c '^  embedded ' "$tmp/err2")" -eq $((4 - done_before)) ] || fail "the rerun embedded $(grep -c '^  embedded ' "$tmp/err2"), $((4 - done_before)) were left"
    for f in "${!ino[@]}"; do [ "$(inode "$f")" = "${ino[$f]}" ] || fail "$(basename "$f") was written again"; done
    same_files "$tmp/ref" "$tmp/out"
    [ ! -e "$tmp/out/.parts" ] || fail ".parts left behind"
    # a finished collection run again is computed again, and says so
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs > /dev/null 2> "$tmp/err3" || fail "the finished collection run again"
    grep -q "finished collection" "$tmp/err3" || fail "no note on the finished collection"
    same_files "$tmp/ref" "$tmp/out"
    echo "ok ($done_before of 4 embeddings kept)" ;;
  staged_resume)
    bears_collection
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ref" --all-pairs >/dev/null 2>&1 || fail "single-process collection"
    for i in 0 1; do "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage embed --shard $i/2 >/dev/null 2>&1 || fail "embed shard $i"; done
    # an embed job run again skips its meshes
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage embed --shard 0/2 > "$tmp/o" 2> "$tmp/e" || fail "embed again"
    [ "$(grep -c 'embedded before' "$tmp/e")" -eq 2 ] && ! grep -q '^  embedded ' "$tmp/e" || fail "the embed job run again embedded again: $(cat "$tmp/e")"
    # other options refuse the parts
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --order tsp --stage embed --shard 0/2 > /dev/null 2> "$tmp/e" && fail "other options mixed"
    [ "$(wc -l < "$tmp/e")" -eq 1 ] && grep -q "other options" "$tmp/e" || fail "other options: $(cat "$tmp/e")"
    # the maps job killed once some maps are in .parts
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage maps > /dev/null 2>&1 &
    pid=$!
    wait_for 3 "$tmp/jobs/.parts/map_*.bin" 60 || { kill -9 $pid; fail "no map part"; }
    kill -9 $pid; wait $pid 2>/dev/null
    no_truncated "$tmp/jobs" "$data/meshes/bear.off"
    n=$(ls "$tmp"/jobs/.parts/map_*.bin | wc -l)
    [ "$n" -lt 12 ] || fail "the maps stage ended before it was killed"
    first=$(ls "$tmp"/jobs/.parts/map_*.bin | head -1); ino1=$(inode "$first")
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage maps > "$tmp/o" 2> "$tmp/e" || fail "maps again: $(cat "$tmp/e")"
    grep -q "mapped $((12 - n)) of 12 pairs.*($n mapped before)" "$tmp/o" || fail "the maps job run again: $(cat "$tmp/o")"
    [ "$(inode "$first")" = "$ino1" ] || fail "a finished map was written again"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage merge > /dev/null || fail "merge"
    same_files "$tmp/ref" "$tmp/jobs"
    echo "ok ($n of 12 maps kept)" ;;
  disk_full)
    hands_collection a b c
    # a file size limit of 100 KB: the embeddings (about 1 MB) cannot be written; SIGXFSZ is
    # ignored, the write fails with EFBIG
    ( ulimit -f 100; exec "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs ) > /dev/null 2> "$tmp/e"
    rc=$?
    [ $rc -ne 0 ] && [ $rc -lt 128 ] || fail "exit status $rc (killed by a signal?)"
    [ "$(wc -l < "$tmp/e")" -eq 1 ] || fail "stderr is not one line: $(cat "$tmp/e")"
    grep -q "File too large" "$tmp/e" || fail "no reason: $(cat "$tmp/e")"
    [ -z "$(find "$tmp/out" -name '*.tmp')" ] || fail "temporary files left: $(find "$tmp/out" -name '*.tmp')"
    [ ! -e "$tmp/out/report.json" ] || fail "report.json written"
    no_truncated "$tmp/out"
    # the disk freed, the run again completes with the files of an uninterrupted run
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs > /dev/null 2>&1 || fail "the run once the disk is freed"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ref" --all-pairs > /dev/null 2>&1 || fail "reference"
    same_files "$tmp/ref" "$tmp/out"
    # a stage job alike
    ( ulimit -f 100; exec "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --stage embed ) > /dev/null 2> "$tmp/e"
    rc=$?
    [ $rc -ne 0 ] && [ $rc -lt 128 ] && [ "$(wc -l < "$tmp/e")" -eq 1 ] || fail "embed stage on a full disk: $rc $(cat "$tmp/e")"
    no_truncated "$tmp/jobs"
    echo "ok: $(cat "$tmp/e")" ;;
  unwritable_dir)
    hands_collection a b c
    mkdir "$tmp/ro"
    if [ "$(id -u)" -ne 0 ]; then
      chmod 0555 "$tmp/ro"
      "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ro" > /dev/null 2> "$tmp/e"; rc=$?
      what="chmod 0555"
    elif command -v runuser >/dev/null 2>&1 && runuser -u nobody -- true 2>/dev/null; then
      # (root writes through chmod 0555: the program runs as nobody, the inputs readable)
      chmod 0755 "$tmp"; chmod a+r "$tmp"/*.off "$tmp"/*.txt; chmod 0555 "$tmp/ro"
      runuser -u nobody -- "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ro" > /dev/null 2> "$tmp/e"; rc=$?
      what="as root: run as nobody, chmod 0555"
    else # (root writes through chmod 0555: no file may grow at all)
      # (stderr through a pipe: a file would be under the limit too)
      ( ulimit -f 0; exec "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ro" 2>&1 > /dev/null ) | cat > "$tmp/e"; rc=${PIPESTATUS[0]}
      what="as root: ulimit -f 0"
    fi
    [ $rc -ne 0 ] && [ $rc -lt 128 ] || fail "exit status $rc"
    [ "$(wc -l < "$tmp/e")" -eq 1 ] || fail "stderr is not one line: $(cat "$tmp/e")"
    grep -q "^hyperbolic_orbifold_tutte: .*'$tmp/ro" "$tmp/e" || fail "the line does not name the folder or file: $(cat "$tmp/e")"
    [ -z "$(find "$tmp/ro" -type f -size +0)" ] || fail "files left: $(find "$tmp/ro" -type f)"
    # a folder that cannot be created
    chmod 0555 "$tmp/ro" 2>/dev/null
    if [ "$(id -u)" -ne 0 ]; then
      "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ro/sub" > /dev/null 2> "$tmp/e" && fail "a folder in an unwritable one"
      [ "$(wc -l < "$tmp/e")" -eq 1 ] && grep -q "cannot create the folder" "$tmp/e" || fail "$(cat "$tmp/e")"
    fi
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/list.txt/x" > /dev/null 2> "$tmp/e" && fail "a folder under a file"
    [ "$(wc -l < "$tmp/e")" -eq 1 ] || fail "$(cat "$tmp/e")"
    echo "ok ($what): $(head -1 "$tmp/e")" ;;
  concurrent_lock)
    bears_collection
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs > /dev/null 2>&1 &
    pid=$!
    wait_for 1 "$tmp/out" 30 || fail "no folder"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs > /dev/null 2> "$tmp/e"; rc=$?
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs --stage embed --shard 1/2 > /dev/null 2> "$tmp/e2"; rc2=$?
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/out" --all-pairs --stage merge > /dev/null 2> "$tmp/e3"; rc3=$?
    kill -0 $pid 2>/dev/null || fail "the first run ended before the second started (a larger collection is needed)"
    [ $rc -ne 0 ] && [ "$(wc -l < "$tmp/e")" -eq 1 ] && grep -q "in use by another collection run" "$tmp/e" || fail "the second run: $rc $(cat "$tmp/e")"
    [ $rc2 -ne 0 ] && grep -q "in use" "$tmp/e2" || fail "a shard during the run: $rc2 $(cat "$tmp/e2")"
    [ $rc3 -ne 0 ] && grep -q "in use" "$tmp/e3" || fail "a merge during the run: $rc3 $(cat "$tmp/e3")"
    wait $pid || fail "the first run failed"
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/ref" --all-pairs > /dev/null 2>&1 || fail "reference"
    same_files "$tmp/ref" "$tmp/out"
    # a killed run's lock is gone with it (flock: released by the kernel)
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/k" --all-pairs > /dev/null 2>&1 &
    pid=$!
    wait_for 1 "$tmp/k/.parts/mesh_*.json" 60 || { kill -9 $pid; fail "no part"; }
    kill -9 $pid; wait $pid 2>/dev/null
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/k" --all-pairs > /dev/null 2> "$tmp/e" || fail "after a killed run: $(cat "$tmp/e")"
    same_files "$tmp/ref" "$tmp/k"
    # the shards of a stage run at once (a shared lock), the merge after them
    for i in 0 1; do "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage embed --shard $i/2 > /dev/null 2> "$tmp/s$i" & pids[$i]=$!; done
    for i in 0 1; do wait ${pids[$i]} || fail "embed shard $i at once: $(cat "$tmp/s$i")"; done
    for i in 0 1; do "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage maps --shard $i/2 > /dev/null 2> "$tmp/s$i" & pids[$i]=$!; done
    for i in 0 1; do wait ${pids[$i]} || fail "maps shard $i at once: $(cat "$tmp/s$i")"; done
    "$prog" collection --manifest "$tmp/list.txt" --out "$tmp/jobs" --all-pairs --stage merge > /dev/null || fail "merge"
    same_files "$tmp/ref" "$tmp/jobs"
    echo "ok: $(cat "$tmp/e" | head -0)$(head -1 "$tmp/e2")" ;;
  *)
    fail "unknown case $case_name" ;;
esac
