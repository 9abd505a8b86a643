// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_TIMINGS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_TIMINGS_H

// Where a command-line process spends its time, for measuring only: with the environment
// variable HOT_TIMINGS set (to anything but "0"), the process prints to stderr, when it ends,
// one line per phase (the wall time since the previous phase ended) and the CPU time spent
// before the first phase (start-up: dynamic loading, static initialisation). Without it,
// nothing is printed and a phase costs one test of a flag. Never changes stdout or a file.
//
//   hot_tools::timings().phase("parse");   // ends the phase "parse" (started at the previous call)

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

/// \file timings.h

namespace hot_tools {

class Phase_timings
{
public:
  typedef std::chrono::steady_clock Clock;

  Phase_timings()
  {
    const char* e = std::getenv("HOT_TIMINGS");
    enabled_ = e != nullptr && *e != '\0' && std::string(e) != "0";
    first_ = last_ = Clock::now();
    timespec ts;
    if(clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) == 0)
      startup_cpu_ = double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  }
  Phase_timings(const Phase_timings&) = delete;
  Phase_timings& operator=(const Phase_timings&) = delete;

  /// at the end of the process: the phases, then "teardown" (what ran after the last phase:
  /// destructors, freeing the mesh)
  ~Phase_timings()
  {
    if(!enabled_)
      return;
    phase("teardown");
    std::fprintf(stderr, "timings: start-up (CPU before the first phase) %.4f s\n", startup_cpu_);
    double total = 0;
    for(const auto& p : phases_) {
      std::fprintf(stderr, "timings: %-28s %.4f s\n", p.first.c_str(), p.second);
      if(p.first.empty() || p.first[0] != ' ')
        total += p.second; // (an indented name is a part of the phase above it)
    }
    std::fprintf(stderr, "timings: %-28s %.4f s\n", "total (after start-up)", total);
  }

  bool enabled() const { return enabled_; }

  /// ends the phase `name` (its time: since the previous phase ended, or since the timer
  /// was made); a name given again adds to that phase
  void phase(const char* name)
  {
    if(!enabled_)
      return;
    const Clock::time_point now = Clock::now();
    add(name, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

  /// adds `seconds` to the phase `name` without ending a phase (a part measured elsewhere,
  /// e.g. the library's own phases inside a phase: give it a name starting with a space, it
  /// is then printed but not added to the total)
  void add(const char* name, double seconds)
  {
    if(!enabled_)
      return;
    for(auto& p : phases_)
      if(p.first == name) {
        p.second += seconds;
        return;
      }
    phases_.emplace_back(name, seconds);
  }

private:
  bool enabled_ = false;
  Clock::time_point first_, last_;
  double startup_cpu_ = 0;
  std::vector<std::pair<std::string, double> > phases_;
};

/// the process's timer (made at the first call: call it early, e.g. first thing in a command)
inline Phase_timings& timings()
{
  static Phase_timings t;
  return t;
}

} // namespace hot_tools

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_TIMINGS_H
