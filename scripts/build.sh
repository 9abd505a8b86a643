#!/usr/bin/env bash
# Configures and builds the project (Release) into build/ (or $HOT_BUILD_DIR).
#   scripts/build.sh [target ...]   (default: everything: `all` and `benchmarks`)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOT_BUILD_DIR:-$root/build}"
jobs="${HOT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
# Ninja for a new build folder (it builds the named targets in parallel, where make builds
# them one after the other); a folder configured before keeps its generator.
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
cmake ${generator[@]+"${generator[@]}"} -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
if [ $# -eq 0 ]; then
  cmake --build "$build" -j "$jobs" --target all benchmarks
else
  cmake --build "$build" -j "$jobs" --target "$@"
fi
