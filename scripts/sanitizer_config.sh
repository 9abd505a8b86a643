# Sourced by scripts/test.sh and scripts/compile_times.sh --asan: the sanitizer stage's
# CMake settings, in the array `sanitizer_config`. Debug (CGAL's and Eigen's assertions on) with
# -DHOT_SANITIZE=ON (AddressSanitizer + UndefinedBehaviorSanitizer), compiled by clang++ where
# it is installed, or by $HOT_ASAN_CXX: clang++ compiles these programs with the sanitizers in
# about 0.77 of g++'s processor time (test_certify.cpp: 75 s against 97 s; compile_times.sh
# --asan). The first stage keeps the default compiler (g++: the outputs users get).
# A compiler is chosen when a build folder is configured the first time: $HOT_ASAN_CXX does
# not change the compiler of an existing folder (remove it, or $HOT_ASAN_BUILD_DIR elsewhere).
sanitizer_config=(-DCMAKE_BUILD_TYPE=Debug -DHOT_SANITIZE=ON -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE)
sanitizer_cxx="${HOT_ASAN_CXX:-$(command -v clang++ || true)}"
if [ -n "$sanitizer_cxx" ]; then sanitizer_config+=(-DCMAKE_CXX_COMPILER="$sanitizer_cxx"); fi
