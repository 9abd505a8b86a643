#!/bin/bash
# The installed package, used by another CMake project (ctest: package_install.consumer,
# label package). In WORK = BUILD/package-test, emptied first:
#   1. cmake --install BUILD --component Hyperbolic_orbifold_Tutte_Development into WORK/prefix
#      (headers and the CMake package only: nothing that a partial build may not have built);
#   2. no path of the source or build tree in the installed CMake files;
#   3. test/consumer configured in WORK/consumer-build with CMAKE_PREFIX_PATH=WORK/prefix only
#      (find_package(Hyperbolic_orbifold_Tutte CONFIG REQUIRED): a failure fails the test), and
#      the package it found must be the one in WORK/prefix;
#   4. the consumer built (one example, EXAMPLE) and run on MESH: it must exit 0 and print a
#      bijective certificate.
#   test_package.sh CMAKE BUILD SOURCE EXAMPLE MESH BUILD_TYPE CXX_COMPILER [CCACHE]
set -euo pipefail

if [ $# -lt 7 ]; then
  echo "usage: $0 CMAKE BUILD SOURCE EXAMPLE MESH BUILD_TYPE CXX_COMPILER [CCACHE]" >&2
  exit 2
fi
cmake=$1 build=$2 source=$3 example=$4 mesh=$5 build_type=$6 cxx=$7 ccache=${8:-}
work=$build/package-test
prefix=$work/prefix
consumer=$work/consumer-build

fail() { echo "test_package: FAILED: $*" >&2; exit 1; }

[ -f "$mesh" ] || fail "no mesh $mesh (libcgal-demo's meshes are extracted into the build's data/meshes)"
rm -rf "$work"
mkdir -p "$work"

echo "== cmake --install $build --prefix $prefix"
"$cmake" --install "$build" --prefix "$prefix" --component Hyperbolic_orbifold_Tutte_Development \
  || fail "cmake --install"
[ -f "$prefix/include/CGAL/hyperbolic_orbifold_Tutte.h" ] || fail "headers not installed"
config=$(find "$prefix" -name Hyperbolic_orbifold_TutteConfig.cmake)
[ -n "$config" ] || fail "no Hyperbolic_orbifold_TutteConfig.cmake under $prefix"
config_dir=$(dirname "$config")
for f in Hyperbolic_orbifold_TutteConfigVersion.cmake Hyperbolic_orbifold_TutteTargets.cmake; do
  [ -f "$config_dir/$f" ] || fail "no $f in $config_dir"
done
# the exported target must not point into the source or build tree (the prefix itself lies in
# the build tree, and the installed files name it only relative to themselves)
if grep -nF -e "$source" -e "$build" "$config_dir"/*.cmake; then
  fail "installed CMake files name the source or build tree (above)"
fi

echo "== configure test/consumer against $prefix"
# nothing but CMAKE_PREFIX_PATH may lead find_package to a package: no package registry, no
# <Package>_DIR/_ROOT from the environment
unset Hyperbolic_orbifold_Tutte_DIR Hyperbolic_orbifold_Tutte_ROOT CMAKE_PREFIX_PATH
options=(-DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_CXX_COMPILER="$cxx"
         -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DHOT_EXAMPLE_SOURCE="$example")
if [ -n "$ccache" ] && [ -x "$ccache" ]; then
  # as the package's own build: paths under the source tree rewritten relative, build folder
  # out of the hash
  options+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$ccache")
  export CCACHE_BASEDIR=$source CCACHE_NOHASHDIR=1
fi
"$cmake" -S "$source/test/consumer" -B "$consumer" "${options[@]}" || fail "configuring the consumer"
found=$(sed -n 's/^Hyperbolic_orbifold_Tutte_DIR:[A-Z]*=//p' "$consumer/CMakeCache.txt")
[ -n "$found" ] && [ "$(realpath "$found")" = "$(realpath "$config_dir")" ] || fail "the consumer found the package in '$found', not in $config_dir"

echo "== build the consumer"
"$cmake" --build "$consumer" --parallel 1 || fail "building the consumer"

echo "== run it on $mesh"
output=$("$consumer/consumer_example" "$mesh") || { echo "$output"; fail "the consumer's program failed"; }
echo "$output"
grep -qF "iterations; bijective" <<<"$output" || fail "no bijective certificate in the program's output"
echo "test_package: OK"
