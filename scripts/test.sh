#!/usr/bin/env bash
# Quick start, part 2: installs what is missing, builds, and runs the whole test suite.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build="${HOT_BUILD_DIR:-$root/build}"
cd "$build"
ctest --output-on-failure -j "${HOT_JOBS:-$(nproc 2>/dev/null || echo 2)}" "$@"
