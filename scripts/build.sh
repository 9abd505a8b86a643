#!/usr/bin/env bash
# Configures and builds the project (Release) into build/ (or $HOT_BUILD_DIR).
#   scripts/build.sh [target ...]   (default: everything)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HOT_BUILD_DIR:-$root/build}"
jobs="${HOT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
if [ $# -eq 0 ]; then
  cmake --build "$build" -j "$jobs"
else
  for t in "$@"; do cmake --build "$build" -j "$jobs" --target "$t"; done
fi
