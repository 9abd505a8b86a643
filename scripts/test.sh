#!/usr/bin/env bash
# Quick start, part 2: installs what is missing, builds, and runs the whole test suite,
# the tests labelled heavy included (what CI runs). Then the sanitizer stage: the test
# programs built with AddressSanitizer + UndefinedBehaviorSanitizer (-DHOT_SANITIZE=ON) in
# <build>-asan (or $HOT_ASAN_BUILD_DIR) and a subset of the tests run there; any sanitizer
# report fails. HOT_SANITIZE_STAGE=0 skips that stage.
#   scripts/test.sh [--quick] [ctest arguments]
# --quick leaves out the tests labelled heavy (the long ones: test cases named heavy_*,
# test/CMakeLists.txt) in the first stage; the other arguments go to that ctest.
# A test case that cannot run in this build (e.g. it needs CHOLMOD) is reported by ctest
# as "Skipped" (not passed), and listed after the run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ctest_args=()
for a in "$@"; do
  case "$a" in
    --quick) ctest_args+=(-LE heavy) ;;
    --heavy) echo "scripts/test.sh: the heavy tests run by default (--quick leaves them out)" >&2; exit 2 ;;
    *) ctest_args+=("$a") ;;
  esac
done
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build="${HOT_BUILD_DIR:-$root/build}"
jobs="${HOT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
(cd "$build" && ctest --output-on-failure -j "$jobs" ${ctest_args[@]+"${ctest_args[@]}"} | tee "$build/ctest-summary.log")
if grep -q "Not Run\|Skipped" "$build/ctest-summary.log"; then
  echo "== skipped in this build (not passed):"
  grep "\*\*\*Skipped\|Not Run" "$build/ctest-summary.log" || true
fi

[ "${HOT_SANITIZE_STAGE:-1}" != 0 ] || exit 0
# The subset: labels unit, input, cut, maps, cli, embedding (not heavy, example, doc), the
# replay of the fuzz corpus included (label input); only the programs these tests run are
# built (add new test programs to `targets`), in Debug (CGAL's and Eigen's assertions on).
# Measured with one job: build 11-12 min with an empty ccache (seconds with a warm one),
# tests under 3 min; the CI's two jobs about halve both.
labels='^(unit|input|cut|maps|cli|embedding)$'
targets=(test_hyperbolic_kernel test_orbifold_tiles test_multigrid test_traits_archetype test_input_checks test_prepare_mesh test_cut_graph
         test_parameterizer test_maps test_cgal_drop_in test_certify fuzz_mesh_reader hyperbolic_orbifold_tutte)
asan="${HOT_ASAN_BUILD_DIR:-$build-asan}"
t0=$SECONDS
echo "== sanitizer stage (address, undefined) in $asan"
cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=Debug -DHOT_SANITIZE=ON -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE >/dev/null
cmake --build "$asan" -j "$jobs" --target "${targets[@]}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$asan" && ctest --output-on-failure -j "$jobs" -L "$labels")
echo "== sanitizer stage: passed in $(( SECONDS - t0 ))s"
