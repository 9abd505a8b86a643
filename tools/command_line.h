// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_COMMAND_LINE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_COMMAND_LINE_H

// The command-line program's conventions: its options (Options, the parsers of shared
// options), its usage errors and its progress line. main() ends the program with status 2 on
// a Usage_error, 3 on a Failure (the data: an Error_code and a one-line reason, the
// application layer's hot_app/job_support.h, as are the output files written atomically), 1 on
// any other exception (files), each with one line on stderr.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h> // Orbifold_type

#include "hot_app/io/prepared_input.h" // Repair_options
#include "hot_app/job_support.h" // Failure, require(), Output_files, minimum_landmarks()

#include <unistd.h> // isatty (Progress_line)

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace hot_cli {

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

struct Usage_error
{
  std::string message;
};

// `JOB --help` (or -h): the job's usage on stdout, exit 0 (thrown by Options, caught by main())
struct Help_request
{
};

// whether --help or -h is among the arguments from `first` on, wherever it stands: it wins over
// every other argument, missing, unknown or wrong ones included (main() asks before a job runs)
inline bool help_requested(int argc, char** argv, int first)
{
  for(int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--help" || a == "-h")
      return true;
  }
  return false;
}

// --name value options, and --flag options without value (listed in `flags`); --help or -h,
// for every job, throws Help_request before any other check.
class Options
{
public:
  // `flags` take no value; `optional` take one when the next argument is not an option
  // (get() then answers "" without it)
  Options(int argc, char** argv, int first, const std::set<std::string>& known,
          const std::set<std::string>& flags = std::set<std::string>(), const std::set<std::string>& optional = std::set<std::string>())
  {
    if(help_requested(argc, argv, first))
      throw Help_request{};
    for(int i = first; i < argc; ++i) {
      const std::string a = argv[i];
      if(a.size() < 3 || a.compare(0, 2, "--") != 0)
        throw Usage_error{"unexpected argument '" + a + "'"};
      const std::string name = a.substr(2);
      if(flags.count(name) || optional.count(name)) {
        if(values_.count(name))
          throw Usage_error{"option '" + a + "' given twice"};
        const bool value = optional.count(name) && i + 1 < argc && std::string(argv[i + 1]).compare(0, 2, "--") != 0;
        values_[name] = value ? std::string(argv[++i]) : flags.count(name) ? "1" : "";
        continue;
      }
      if(!known.count(name))
        throw Usage_error{"unknown option '" + a + "'"};
      if(i + 1 >= argc)
        throw Usage_error{"option '" + a + "' needs a value"};
      if(values_.count(name))
        throw Usage_error{"option '" + a + "' given twice"};
      values_[name] = argv[++i];
    }
  }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::string get(const std::string& name) const
  {
    auto it = values_.find(name);
    if(it == values_.end())
      throw Usage_error{"missing option --" + name};
    return it->second;
  }
  long get_int(const std::string& name, long lo, long hi) const
  {
    const std::string s = get(name);
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if(s.empty() || *end != '\0' || errno != 0)
      throw Usage_error{"--" + name + " must be an integer, got '" + s + "'"};
    if(v < lo || v > hi)
      throw Usage_error{"--" + name + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                        ", got " + s};
    return v;
  }

private:
  std::map<std::string, std::string> values_;
};


inline HOT::Orbifold_type parse_orbifold(const std::string& s)
{
  if(s == "sphere")
    return HOT::Sphere_type;
  if(s == "disk")
    return HOT::Disk_type;
  throw Usage_error{"--orbifold must be 'sphere' or 'disk', got '" + s + "'"};
}

// --order given|tsp; `fallback` when the option is absent (empty: the default of the type)
// the repair options of embed, landmarks, map and collection: --repair, --largest-component,
// --max-hole F, --target-genus G, --max-handle F and --snap-landmarks (the last one also works
// without --repair)
inline const std::set<std::string>& repair_flags()
{
  static const std::set<std::string> f{"repair", "largest-component", "snap-landmarks"};
  return f;
}

inline hot_tools::Repair_options parse_repair_options(const Options& opt)
{
  hot_tools::Repair_options r;
  r.repair = opt.has("repair");
  r.largest_component = opt.has("largest-component");
  r.snap_landmarks = opt.has("snap-landmarks");
  if(opt.has("max-hole")) {
    r.max_hole_given = true;
    const std::string s = opt.get("max-hole");
    char* end = nullptr;
    r.max_hole = std::strtod(s.c_str(), &end);
    if(s.empty() || end == nullptr || *end != '\0' || !(r.max_hole >= 0) || !(r.max_hole <= 1e6))
      throw Usage_error{"--max-hole must be a number >= 0 (a length in bounding box diagonals), got '" + s + "'"};
  }
  if(opt.has("target-genus")) {
    const std::string s = opt.get("target-genus");
    char* end = nullptr;
    const long g = std::strtol(s.c_str(), &end, 10);
    if(s.empty() || end == nullptr || *end != '\0' || g < 0 || g > 1000000)
      throw Usage_error{"--target-genus must be an integer >= 0, got '" + s + "'"};
    r.target_genus = g;
  }
  if(opt.has("max-handle")) {
    const std::string s = opt.get("max-handle");
    char* end = nullptr;
    r.max_handle = std::strtod(s.c_str(), &end);
    if(s.empty() || end == nullptr || *end != '\0' || !(r.max_handle >= 0) || !(r.max_handle <= 1e6))
      throw Usage_error{"--max-handle must be a number >= 0 (a length in bounding box diagonals), got '" + s + "'"};
  }
  for(const char* o : {"largest-component", "max-hole", "target-genus", "max-handle"})
    if(opt.has(o) && !r.repair)
      throw Usage_error{std::string("--") + o + " needs --repair"};
  return r;
}

inline std::string parse_order(const Options& opt, const std::string& fallback)
{
  const std::string s = opt.has("order") ? opt.get("order") : fallback;
  if(!s.empty() && s != "given" && s != "tsp")
    throw Usage_error{"--order must be given or tsp, got '" + s + "'"};
  return s;
}

// --order given|tsp|auto of map and collection: one order for all the meshes, as given, the
// first mesh's tour, or (auto, the default) the best of the meshes' tours with the others tried
// in turn when an embedding is refused
inline std::string parse_common_order(const Options& opt)
{
  const std::string s = opt.has("order") ? opt.get("order") : "auto";
  if(s != "given" && s != "tsp" && s != "auto")
    throw Usage_error{"--order must be given, tsp or auto, got '" + s + "'"};
  return s;
}

// --cone-orders p1,p2,...: one integer >= 2 per landmark (cone angle 2 pi / p); absent: empty
// (2 for every cone). Whether the count matches the landmarks and the orbifold is hyperbolic
// is the library's to say.
inline std::vector<int> parse_cone_orders(const Options& opt)
{
  std::vector<int> orders;
  if(!opt.has("cone-orders"))
    return orders;
  const std::string s = opt.get("cone-orders");
  std::size_t pos = 0;
  while(pos <= s.size()) {
    const std::size_t comma = s.find(',', pos);
    const std::string f = s.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    char* end = nullptr;
    const long p = f.empty() ? 0 : std::strtol(f.c_str(), &end, 10);
    if(f.empty() || end == nullptr || *end != '\0' || !hot_tools::is_cone_order(p))
      throw Usage_error{"--cone-orders must be integers of at least 2 separated by commas (one per landmark, e.g. 2,3,7), got '" + s + "'"};
    orders.push_back(static_cast<int>(p));
    if(comma == std::string::npos)
      break;
    pos = comma + 1;
  }
  return orders;
}

// A long job's progress on stderr, 'JOB: PHASE NN%' (the library's phases through its
// `progress` parameter, the program's own such as "read" and "write" at 0 and 100%): on a
// terminal one line updated in place ('\r', at most every 0.1 s, cleared when the job ends);
// otherwise, with --progress, one line per update (at most one per 0.5 s, and one at every
// change of phase and at every 100%); otherwise nothing (stderr stays as without it). The
// percentage is the fraction rounded down: 100% only at a phase's end.
class Progress_line
{
public:
  Progress_line(const std::string& job, bool flag)
    : job_(job), terminal_(isatty(2) != 0), on_(terminal_ || flag)
  {}
  Progress_line(const Progress_line&) = delete;
  Progress_line& operator=(const Progress_line&) = delete;
  ~Progress_line() { clear(); }

  bool on() const { return on_; }

  void operator()(const std::string& phase, double fraction)
  {
    if(!on_)
      return;
    const int percent = static_cast<int>(std::floor(std::min(1.0, std::max(0.0, fraction)) * 100));
    if(phase == phase_ && percent == percent_)
      return;
    const auto now = std::chrono::steady_clock::now();
    const bool forced = phase != phase_ || percent == 100;
    if(!forced && printed_ && now - last_ < std::chrono::milliseconds(terminal_ ? 100 : 500))
      return;
    phase_ = phase;
    percent_ = percent;
    last_ = now;
    printed_ = true;
    const std::string text = job_ + ": " + phase + " " + std::to_string(percent) + "%";
    if(terminal_) {
      std::fprintf(stderr, "\r%s%s", text.c_str(), std::string(text.size() < width_ ? width_ - text.size() : 0, ' ').c_str());
      width_ = std::max(width_, text.size());
    } else
      std::fprintf(stderr, "%s\n", text.c_str());
    std::fflush(stderr);
  }
  // a phase of the program's own, done in one step: 0% and 100%
  void step(const std::string& phase) { (*this)(phase, 0.0); }
  void done(const std::string& phase) { (*this)(phase, 1.0); }

  // the library's `progress` parameter, the phases named "PREFIX PHASE" (none: empty function)
  std::function<void(const char*, double)> callback(const std::string& prefix = std::string())
  {
    if(!on_)
      return std::function<void(const char*, double)>();
    return [this, prefix](const char* phase, double f) { (*this)(prefix.empty() ? std::string(phase) : prefix + " " + phase, f); };
  }

  // on a terminal, clears the line (before the job's own output on stdout or stderr)
  void clear()
  {
    if(terminal_ && printed_ && width_ > 0) {
      std::fprintf(stderr, "\r%s\r", std::string(width_, ' ').c_str());
      std::fflush(stderr);
      width_ = 0;
    }
    printed_ = false;
    phase_.clear();
    percent_ = -1;
  }

private:
  std::string job_;
  bool terminal_, on_;
  bool printed_ = false;
  std::string phase_;
  int percent_ = -1;
  std::size_t width_ = 0;
  std::chrono::steady_clock::time_point last_;
};

} // namespace hot_cli

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_COMMAND_LINE_H
