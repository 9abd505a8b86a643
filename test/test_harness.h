// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A minimal test harness: TEST_CASE(name) registers a function, CHECK(...) counts
// failures (unlike assert, it is not compiled out by NDEBUG). The program runs the
// case named on its command line (ctest registers one test per case, found by
// scanning the source for TEST_CASE), all of them without argument, and lists
// them with --list.
//
// A case that performs no CHECK fails ("performed no check"): a test that cannot fail
// is not a test. A case that cannot run in this build (e.g. it needs CHOLMOD) says so
// with SKIP("reason"), which returns from the case; run alone, the program then exits
// with hot_test::skip_exit_code (77), which ctest reports as "Skipped" (SKIP_RETURN_CODE,
// test/CMakeLists.txt), never as passed.

#ifndef HOT_TEST_HARNESS_H
#define HOT_TEST_HARNESS_H

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <string>

namespace hot_test {

struct Registry
{
  std::map<std::string, std::function<void()> > cases;
  static Registry& get() { static Registry r; return r; }
};

inline int& failures() { static int n = 0; return n; }
inline int& checks() { static int n = 0; return n; }
// the reason the running case gave for skipping itself (empty: not skipped)
inline std::string& skip_reason() { static std::string r; return r; }
constexpr int skip_exit_code = 77;
inline std::string& data_dir() { static std::string d; return d; }

struct Registrar
{
  Registrar(const char* name, std::function<void()> f) { Registry::get().cases[name] = f; }
};

inline void report(bool ok, const char* expr, const char* file, int line, const std::string& extra = std::string())
{
  ++checks();
  if(!ok) {
    ++failures();
    std::cerr << file << ":" << line << ": CHECK failed: " << expr;
    if(!extra.empty())
      std::cerr << "  [" << extra << "]";
    std::cerr << std::endl;
  }
}

inline int run_main(int argc, char** argv)
{
  Registry& r = Registry::get();
  std::string only;
  for(int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if(a == "--list") {
      for(auto& c : r.cases)
        std::cout << c.first << "\n";
      return EXIT_SUCCESS;
    } else if(a == "--data" && i + 1 < argc) {
      data_dir() = argv[++i];
    } else {
      only = a;
    }
  }
  if(data_dir().empty()) {
    if(const char* d = std::getenv("HOT_DATA_DIR"))
      data_dir() = d;
  }
  int ran = 0, skipped = 0;
  for(auto& c : r.cases) {
    if(!only.empty() && c.first != only)
      continue;
    const int before = failures(), checks_before = checks();
    skip_reason().clear();
    std::cout << "[ RUN  ] " << c.first << std::endl;
    c.second();
    ++ran;
    if(!skip_reason().empty() && failures() == before) {
      std::cout << "[ SKIP ] " << c.first << ": " << skip_reason() << std::endl;
      ++skipped;
      continue;
    }
    if(checks() == checks_before) {
      ++failures();
      std::cerr << "test case " << c.first << " performed no check (a test that cannot fail)" << std::endl;
    }
    std::cout << (failures() == before ? "[  OK  ] " : "[ FAIL ] ") << c.first << std::endl;
  }
  if(ran == 0) {
    std::cerr << "no test case named '" << only << "'" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << checks() << " checks, " << failures() << " failed";
  if(skipped > 0)
    std::cout << ", " << skipped << " case" << (skipped > 1 ? "s" : "") << " skipped";
  std::cout << std::endl;
  if(failures() != 0)
    return EXIT_FAILURE;
  return skipped == ran ? skip_exit_code : EXIT_SUCCESS;
}

} // namespace hot_test

#define HOT_CONCAT2(a, b) a##b
#define HOT_CONCAT(a, b) HOT_CONCAT2(a, b)
#define TEST_CASE(name)                                                                  \
  static void HOT_CONCAT(test_fn_, name)();                                             \
  static hot_test::Registrar HOT_CONCAT(test_reg_, name)(#name, &HOT_CONCAT(test_fn_, name)); \
  static void HOT_CONCAT(test_fn_, name)()

#define CHECK(expr) hot_test::report(static_cast<bool>(expr), #expr, __FILE__, __LINE__)
#define CHECK_MSG(expr, msg)                                                             \
  do {                                                                                   \
    std::ostringstream hot_os_;                                                          \
    hot_os_ << msg;                                                                      \
    hot_test::report(static_cast<bool>(expr), #expr, __FILE__, __LINE__, hot_os_.str()); \
  } while(0)
#define CHECK_NEAR(a, b, tol)                                                            \
  do {                                                                                   \
    const double hot_a_ = (a), hot_b_ = (b);                                             \
    std::ostringstream hot_os_;                                                          \
    hot_os_.precision(17);                                                               \
    hot_os_ << hot_a_ << " vs " << hot_b_ << " (tol " << (tol) << ")";                   \
    hot_test::report(std::abs(hot_a_ - hot_b_) <= (tol), #a " ~ " #b, __FILE__, __LINE__, hot_os_.str()); \
  } while(0)

// skips the running case, with the reason printed (e.g. "built without CHOLMOD")
#define SKIP(reason)                                                                     \
  do {                                                                                   \
    hot_test::skip_reason() = (reason);                                                  \
    return;                                                                              \
  } while(0)

#define HOT_TEST_MAIN \
  int main(int argc, char** argv) { return hot_test::run_main(argc, argv); }

#include <sstream>

#endif // HOT_TEST_HARNESS_H
