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
# each step's time is printed ("== <step>: N s"): install, build, tests, sanitizer build, sanitizer tests
step() { echo "== $1: $(( SECONDS - t_step )) s"; t_step=$SECONDS; }
t_step=$SECONDS
"$root/scripts/install-deps.sh"
step install
"$root/scripts/build.sh" all   # (everything the tests run; not the benchmarks, which no test runs)
step build
build="${HOT_BUILD_DIR:-$root/build}"
jobs="${HOT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
(cd "$build" && ctest --output-on-failure -j "$jobs" ${ctest_args[@]+"${ctest_args[@]}"} | tee "$build/ctest-summary.log")
step tests
if grep -q "Not Run\|Skipped" "$build/ctest-summary.log"; then
  echo "== skipped in this build (not passed):"
  grep "\*\*\*Skipped\|Not Run" "$build/ctest-summary.log" || true
fi

[ "${HOT_SANITIZE_STAGE:-1}" != 0 ] || exit 0
# The subset: labels unit, input, cut, maps, cli, embedding (not heavy, example, doc), the
# replay of the fuzz corpus included (label input); only the programs these tests run are
# built (add new test programs to `targets`), in Debug (CGAL's and Eigen's assertions on),
# with Ninja where it is installed (make would build the named targets one after the other).
labels='^(unit|input|cut|maps|cli|embedding)$'
# Left to the first stage (measured under the sanitizers: about 200 of 1,050 processor
# seconds): larger runs of code paths that smaller tests run here. The collection with
# --refine (cli.map_refine and test_refine run the refinement), the sharded collection
# (cli.collection runs the same stage jobs in one process), the order ranking (the other
# cli_order cases choose orders), the CLI's charts (cli_certify.charts and
# test_maps.charts_capsules_with_tip_landmark build and check charts), and the agreement of
# the preconditioned and direct solvers (test_parameterizer.multigrid_and_factorisations_
# reach_the_same_embedding runs both solvers' code), and the scan defects mapped with --repair
# (cli_repair.scan_defects: 82 of the stage's 909 test seconds on 2026-12-05; the repair
# of debris, holes under landmarks and openings runs here in cli_repair.holes_map, .handles and
# .collection, and in test_prepare_mesh), and the refinement's longest unit case
# (test_refine.refinement_moves_a_map_towards_the_isometry, 67 s there on 2026-12-06; the
# refinement runs here in cli.map_refine and test_refine's collection and refusal cases).
first_stage_only='^(test_refine\.refinement_is_not_stalled_by_a_squeezed_protrusion|test_refine\.refinement_moves_a_map_towards_the_isometry|cli\.collection_refine|cli\.collection_shards|cli_order\.map_ranking|cli\.charts|test_parameterizer\.preconditioned_and_direct_solvers_agree|cli_repair\.scan_defects)$'
targets=(test_hyperbolic_kernel test_orbifold_tiles test_multigrid test_traits_archetype test_input_checks test_prepare_mesh test_cut_graph
         test_parameterizer test_maps test_refine test_cgal_drop_in test_certify fuzz_mesh_reader hyperbolic_orbifold_tutte)
asan="${HOT_ASAN_BUILD_DIR:-$build-asan}"
t0=$SECONDS
echo "== sanitizer stage (address, undefined) in $asan"
# The settings and the compiler (clang++ where installed, $HOT_ASAN_CXX): sanitizer_config.sh.
. "$root/scripts/sanitizer_config.sh"
configure=()
if [ ! -f "$asan/CMakeCache.txt" ]; then
  if command -v ninja >/dev/null 2>&1; then configure+=(-G Ninja); fi
  configure+=("${sanitizer_config[@]}")
else
  configure+=("${sanitizer_config[@]:0:3}") # (the compiler of a configured folder stays)
fi
cmake "${configure[@]}" -S "$root" -B "$asan" >/dev/null
cmake --build "$asan" -j "$jobs" --target "${targets[@]}"
step "sanitizer build"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$asan" && ctest --output-on-failure -j "$jobs" -L "$labels" -E "$first_stage_only")
step "sanitizer tests"
echo "== sanitizer stage: passed in $(( SECONDS - t0 ))s"
