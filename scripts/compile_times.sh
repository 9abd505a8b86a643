#!/usr/bin/env bash
# Measures the compile time of every translation unit of the project, cold (ccache off), and
# prints a table, slowest first: wall seconds of each compilation (ninja's log), and with
# --phases, from g++'s -ftime-report, its three phases: parsing (preprocessing, parsing, and
# the template instantiations the parser does on the way), "deferred" (the templates
# instantiated at the end of the unit) and "codegen" (optimisation and code generation), with
# the memory the compiler allocated. Link steps of a second or more are listed too.
#   scripts/compile_times.sh [--asan] [--phases] [--jobs N] [--dir DIR] [target ...]
#   scripts/compile_times.sh --from BUILD_DIR   (the table of a build already made with Ninja,
#                                                e.g. build/ after a cold scripts/test.sh)
# --asan measures the sanitizer stage's build (Debug, -DHOT_SANITIZE=ON, clang++ as in
# scripts/test.sh) instead of Release.
# --phases: -ftime-report reads the clock at every phase change, which on a virtual machine
# costs system time: the wall times are then 1.5-3 times those of a plain build (compare
# the phases' shares, not their seconds, with a run without it).
# With targets, only those are built (and what they need); default: everything.
# The build goes into DIR (default: a new temporary folder, removed at the end); the table
# and the raw build log are kept in DIR as compile_times.txt and compile_times.log
# when --dir is given, else printed only. The manual's developer page (\ref HOT_Building)
# keeps the table of one run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs="${HOT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
dir=""
from=""
asan=0
phases=0
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --asan) asan=1 ;;
    --phases) phases=1 ;;
    --jobs) jobs="$2"; shift ;;
    --dir) dir="$2"; shift ;;
    --from) from="$2"; shift ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    -*) echo "compile_times.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1") ;;
  esac
  shift
done
# the table from a build folder's .ninja_log (and, with -ftime-report, the build's output)
print_table() {
  local build_dir="$1" output="$2"
  awk -v ninja_log="$build_dir/.ninja_log" '
  BEGIN {
    while((getline line < ninja_log) > 0) {
      n = split(line, f, "\t")
      if(n >= 4) secs[f[4]] = (f[2] - f[1]) / 1000
    }
  }
  / Building CXX object / { obj = $NF; next }
  / Linking CXX / { obj = ""; next }
  obj != "" && /^ phase parsing/ { split($0, a, ":"); split(a[2], b, " "); parse[obj] = b[5] }
  obj != "" && /^ phase lang. deferred/ { split($0, a, ":"); split(a[2], b, " "); deferred[obj] = b[5] }
  obj != "" && /^ phase opt and generate/ { split($0, a, ":"); split(a[2], b, " "); codegen[obj] = b[5] }
  obj != "" && /^ TOTAL/ { split($0, a, ":"); split(a[2], b, " "); mem[obj] = b[4] }
  END {
    for(o in secs) {
      name = o; sub(/^.*CMakeFiles\//, "", name); sub(/\.dir\//, ": ", name)
      if(o ~ /\.o$/)
        printf "%8.1f %8s %8s %8s %8s  %s\n", secs[o], parse[o], deferred[o], codegen[o], mem[o], name
      else if(secs[o] >= 1)
        printf "%8.1f %8s %8s %8s %8s  %s (link)\n", secs[o], "", "", "", "", name
    }
  }' "$output" | sort -rn
}
summary() {
  echo "$1"
  printf "%8s %8s %8s %8s %8s  %s\n" "wall s" "parse" "deferred" "codegen" "GC mem" "unit"
  echo "$2"
  awk '{ if($NF != "(link)") { s += $1; n++ } } END { printf "%8.1f  seconds of compilation in all, %d units\n", s, n }' <<< "$2"
}
if [ -n "$from" ]; then
  [ -f "$from/.ninja_log" ] || { echo "compile_times.sh: no .ninja_log in $from (a Ninja build folder)" >&2; exit 2; }
  summary "compile times of $from (its last build of each unit)" "$(print_table "$from" /dev/null)"
  exit 0
fi
command -v ninja >/dev/null || { echo "compile_times.sh: needs ninja (Debian: ninja-build; scripts/install-deps.sh)" >&2; exit 2; }
keep=1
if [ -z "$dir" ]; then dir="$(mktemp -d)"; keep=0; trap 'rm -rf "$dir"' EXIT; fi
log="$dir/compile_times.log"
config=(-DCMAKE_BUILD_TYPE=Release)
if [ "$asan" = 1 ]; then
  . "$root/scripts/sanitizer_config.sh" # the sanitizer stage's settings and compiler (scripts/test.sh)
  config=("${sanitizer_config[@]}")
fi
export CCACHE_DISABLE=1
flags=""
[ "$phases" = 1 ] && flags=-ftime-report
cmake -G Ninja -S "$root" -B "$dir/build" "${config[@]}" "-DCMAKE_CXX_FLAGS=$flags" >/dev/null
t0=$SECONDS
ninja -C "$dir/build" -j "$jobs" ${targets[@]+"${targets[@]}"} > "$log" 2>&1 || { tail -30 "$log" >&2; exit 1; }
wall=$(( SECONDS - t0 ))
# ninja prints an edge's description when the edge ends, followed by its output (the report)
table="$(print_table "$dir/build" "$log")"
summary "compile times ($([ "$asan" = 1 ] && echo "Debug + sanitizers" || echo Release), $jobs jobs, ccache off): wall $wall s" "$table" \
  | tee "$dir/compile_times.txt"
