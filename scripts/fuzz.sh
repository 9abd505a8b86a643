#!/usr/bin/env bash
# Fuzzes the mesh and landmark readers and the input checks (fuzz/fuzz_mesh_reader.cpp)
# with libFuzzer, AddressSanitizer (leaks included) and UndefinedBehaviorSanitizer.
#
#   scripts/fuzz.sh [SECONDS]    build into build-fuzz/ (or $HOT_FUZZ_DIR) and fuzz for
#                                SECONDS (default 60), one process, niced
#   scripts/fuzz.sh --repro FILE...  run the target once on saved inputs (e.g. a crash file)
#   scripts/fuzz.sh --pack       merge (by coverage) the committed corpus, the seeds and the
#                                corpus found so far into fuzz/corpus.tar.gz, the corpus that
#                                ctest replays (fuzz.replay_corpus; fuzz/CMakeLists.txt)
#
# The corpus (build-fuzz/corpus) grows from run to run; it is seeded with small valid files
# written by this script (build-fuzz/seeds). Exits with status 1 if the run found a crash,
# a leak, undefined behaviour, a broken reader contract or an input slower than 10 s; the
# input is left in build-fuzz/crashes/ (crash-*, leak-*, timeout-*, oom-*). Turn it into a
# regression TEST_CASE in test/test_input_checks.cpp.
#
# Needs clang++ and libFuzzer's runtime (libclang_rt.fuzzer-x86_64.a; Debian 12 package
# libclang-rt-14-dev): installed with apt-get when missing (as root, or with sudo).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOT_FUZZ_DIR:-$root/build-fuzz}"
mkdir -p "$build"

# --- compiler and libFuzzer runtime -----------------------------------------------------
apt_install() {
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "fuzz.sh: need $* but not root and no sudo" >&2; exit 1; }
    sudo="sudo"
  fi
  echo "fuzz.sh: installing $*"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}
find_clang() {
  local c
  for c in "${CXX_FUZZ:-}" clang++ clang++-19 clang++-18 clang++-17 clang++-16 clang++-15 clang++-14; do
    if [ -n "$c" ] && command -v "$c" >/dev/null 2>&1; then echo "$c"; return 0; fi
  done
  return 1
}
cxx="$(find_clang || true)"
if [ -z "$cxx" ]; then
  apt_install clang
  cxx="$(find_clang)"
fi
clang_major="$("$cxx" -dumpversion | cut -d. -f1)"
fuzzer_lib() { echo "$("$cxx" --print-runtime-dir 2>/dev/null)/libclang_rt.fuzzer-x86_64.a"; }
if [ ! -f "$(fuzzer_lib)" ]; then
  apt_install "libclang-rt-${clang_major}-dev"
  [ -f "$(fuzzer_lib)" ] || { echo "fuzz.sh: libFuzzer runtime still missing: $(fuzzer_lib)" >&2; exit 1; }
fi

# --- build (again when the target or a header is newer than the binary) ---------------
bin="$build/fuzz_mesh_reader"
src="$root/fuzz/fuzz_mesh_reader.cpp"
if [ ! -x "$bin" ] || [ -n "$(find "$src" "$root/include" "$root/application" -newer "$bin" -print -quit)" ]; then
  echo "fuzz.sh: building $bin with $cxx"
  nice "$cxx" -std=c++17 -O1 -g -fno-omit-frame-pointer \
    -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I "$root/include" -I "$root/tools" -I /usr/include/eigen3 \
    "$src" -o "$bin.tmp" -lgmp -lmpfr
  mv "$bin.tmp" "$bin"
fi

if [ "${1:-}" = "--repro" ]; then
  shift
  exec "$bin" -runs=1 "$@"
fi
pack=0
[ "${1:-}" = "--pack" ] && { pack=1; shift; }
seconds="${1:-60}"
case "$seconds" in ''|*[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS] | --repro FILE... | --pack" >&2; exit 2 ;; esac
# the committed corpus (what ctest replays): read as seeds too
committed="$build/committed"
rm -rf "$committed"
mkdir -p "$committed"
tar xzf "$root/fuzz/corpus.tar.gz" -C "$committed"

# --- seeds: small valid files in every format ---------------------------------------------
# input = selector byte, landmark length (2 bytes, little endian), mesh file, landmark file
seeds="$build/seeds"
rm -rf "$seeds"
mkdir -p "$seeds" "$build/corpus" "$build/crashes"
byte() { printf "\\$(printf %03o "$(( $1 & 255 ))")"; }
seed() { # seed NAME SELECTOR MESH_FILE LANDMARK_TEXT
  local n=${#4}
  { byte "$2"; byte "$n"; byte "$(( n >> 8 ))"; cat "$3"; printf '%s' "$4"; } > "$seeds/$1"
}
t="$build/seed-tmp"
mkdir -p "$t"
octa_v='1 0 0
-1 0 0
0 1 0
0 -1 0
0 0 1
0 0 -1'
octa_f='0 2 4
2 1 4
1 3 4
3 0 4
2 0 5
1 2 5
3 1 5
0 3 5'
{ echo OFF; echo "6 8 0"; echo "$octa_v"; echo "$octa_f" | sed 's/^/3 /'; } > "$t/octa.off"
{ echo "$octa_v" | sed 's/^/v /'; echo "$octa_f" | awk '{ print "f", $1 + 1, $2 + 1, $3 + 1 }'; } > "$t/octa.obj"
{ printf 'ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n'
  printf 'element face 8\nproperty list uchar int vertex_indices\nend_header\n'
  echo "$octa_v"; echo "$octa_f" | sed 's/^/3 /'; } > "$t/octa.ply"
f32() { case "$1" in 0) printf '\0\0\0\0' ;; 1) printf '\0\0\200\77' ;; -1) printf '\0\0\200\277' ;; esac; }  # little endian
f32be() { case "$1" in 0) printf '\0\0\0\0' ;; 1) printf '\77\200\0\0' ;; -1) printf '\277\200\0\0' ;; esac; }
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n'
  printf 'element face 8\nproperty list uchar int vertex_indices\nend_header\n'
  echo "$octa_v" | while read -r x y z; do f32 "$x"; f32 "$y"; f32 "$z"; done
  echo "$octa_f" | while read -r a b c; do byte 3; for i in $a $b $c; do byte "$i"; printf '\0\0\0'; done; done
} > "$t/octa_bin.ply"
{ echo "solid octa"
  echo "$octa_f" | while read -r a b c; do
    echo " facet normal 0 0 0"; echo "  outer loop"
    for i in $a $b $c; do echo "   vertex $(echo "$octa_v" | sed -n "$((i + 1))p")"; done
    echo "  endloop"; echo " endfacet"
  done
  echo "endsolid octa"; } > "$t/octa.stl"
{ head -c 80 /dev/zero; byte 8; printf '\0\0\0'
  echo "$octa_f" | while read -r a b c; do
    f32 0; f32 0; f32 0
    for i in $a $b $c; do for x in $(echo "$octa_v" | sed -n "$((i + 1))p"); do f32 "$x"; done; done
    printf '\0\0'
  done; } > "$t/octa_bin.stl"
{ printf 'GOCAD TSurf 1\nHEADER {\nname:octa\n}\nTFACE\n'
  echo "$octa_v" | awk '{ print "VRTX", NR - 1, $0 }'; echo "$octa_f" | sed 's/^/TRGL /'; echo END; } > "$t/octa.ts"
{ printf 'OFF BINARY\n'; byte 0; byte 0; byte 0; byte 6; byte 0; byte 0; byte 0; byte 8; printf '\0\0\0\0'
  echo "$octa_v" | while read -r x y z; do for c in $x $y $z; do f32be "$c"; done; done
  echo "$octa_f" | while read -r a b c; do printf '\0\0\0\3'; for i in $a $b $c; do printf '\0\0\0'; byte "$i"; done; printf '\0\0\0\0'; done
} > "$t/octa_bin.off"
# a disk: a fan of 6 triangles around vertex 0
{ echo OFF; echo "7 6 0"; echo "0 0 0"
  awk 'BEGIN { for (k = 0; k < 6; k++) printf "%.6f %.6f 0\n", cos(k * 1.0471975512), sin(k * 1.0471975512)
               for (k = 1; k <= 6; k++) print 3, 0, k, k % 6 + 1 }'; } > "$t/fan.off"
seed off_octa 0 "$t/octa.off" "0 1 2 3 4"
seed off_octa_lines 0 "$t/octa.off" $'5\n3\n1\n0\n2\n'
seed off_octa_sphere_sample 35 "$t/octa.off" "0 1 2 3 5"
seed off_octa_selection 15 "$t/octa.off" $'0 1 2 3 4\n\n1 2\n'
seed off_octa_binary 0 "$t/octa_bin.off" "0 1 2 3 4"
seed off_fan_disk 10 "$t/fan.off" "1 2 3 4 5"
seed off_fan_sample 30 "$t/fan.off" "1 2 3 5 6"
seed obj_octa 1 "$t/octa.obj" "0 1 2 3 4"
seed ply_octa 2 "$t/octa.ply" "0 1 2 3 4"
seed ply_octa_binary 2 "$t/octa_bin.ply" "0 1 2 3 4"
seed stl_octa 3 "$t/octa.stl" "0 1 2 3 4"
seed stl_octa_binary 3 "$t/octa_bin.stl" "0 1 2 3 4"
seed ts_octa 4 "$t/octa.ts" "0 1 2 3 4"
rm -rf "$t"

if [ $pack = 1 ]; then
  merged="$build/merged"
  rm -rf "$merged"
  mkdir -p "$merged/corpus"
  nice "$bin" -merge=1 -timeout=10 -rss_limit_mb=2048 "$merged/corpus" "$committed/corpus" "$seeds" "$build/corpus" > "$build/merge.log" 2>&1
  (cd "$merged" && tar --sort=name --owner=0 --group=0 --numeric-owner --mtime=@0 -cf - corpus | gzip -n -9 > "$root/fuzz/corpus.tar.gz")
  echo "fuzz.sh: fuzz/corpus.tar.gz: $(ls "$merged/corpus" | wc -l) inputs (update --min-inputs in fuzz/CMakeLists.txt if it shrank)"
  exit 0
fi

# --- run ------------------------------------------------------------------------------------
log="$build/fuzz.log"
before="$(ls "$build/crashes" | wc -l)"
echo "fuzz.sh: fuzzing for $seconds s (log: $log)"
set +e
nice "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 \
  -artifact_prefix="$build/crashes/" "$build/corpus" "$seeds" "$committed/corpus" > "$log" 2>&1
status=$?
set -e
runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
after="$(ls "$build/crashes" | wc -l)"
echo "fuzz.sh: ${runs:-?} executions in $seconds s, corpus of $(ls "$build/corpus" | wc -l) inputs, exit status $status"
if [ "$status" -ne 0 ] || [ "$after" -gt "$before" ]; then
  grep -E "ERROR|SUMMARY|runtime error|contract broken|Test unit written" "$log" | head -20 >&2 || true
  echo "fuzz.sh: FOUND A PROBLEM: see $log and $build/crashes/ (reproduce: scripts/fuzz.sh --repro FILE)" >&2
  exit 1
fi
echo "fuzz.sh: no crash, leak, undefined behaviour or timeout found"
