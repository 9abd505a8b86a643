// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// hyperbolic_orbifold_tutte: the package's main jobs from the command line.
//
//   hyperbolic_orbifold_tutte tile --orbifold sphere|disk --cones K --svg FILE [--depth D]
//
// Every error ends the program with a non-zero status and one line on stderr;
// output files are written to a temporary name and renamed only when complete.

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/svg_writer.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

namespace {

struct Usage_error
{
  std::string message;
};

const char* const usage_text =
  "usage:\n"
  "  hyperbolic_orbifold_tutte tile --orbifold sphere|disk --cones K --svg FILE [--depth D]\n"
  "      draws the basic tile of the orbifold with K cones and its images under the group\n"
  "      (products of at most D side pairings, default 3) in the Poincare disk\n";

// --name value options; every option takes a value.
class Options
{
public:
  Options(int argc, char** argv, int first, const std::set<std::string>& known)
  {
    for(int i = first; i < argc; ++i) {
      const std::string a = argv[i];
      if(a.size() < 3 || a.compare(0, 2, "--") != 0)
        throw Usage_error{"unexpected argument '" + a + "'"};
      const std::string name = a.substr(2);
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

// Writes a file atomically: the content goes to FILE.tmp, renamed to FILE on success.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer)
{
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    if(!out)
      throw std::runtime_error("cannot write '" + path + "'");
    writer(out);
    out.flush();
    if(!out) {
      out.close();
      std::remove(tmp.c_str());
      throw std::runtime_error("error while writing '" + path + "'");
    }
  }
  if(std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write '" + path + "'");
  }
}

HOT::Orbifold_type parse_orbifold(const std::string& s)
{
  if(s == "sphere")
    return HOT::Sphere_type;
  if(s == "disk")
    return HOT::Disk_type;
  throw Usage_error{"--orbifold must be 'sphere' or 'disk', got '" + s + "'"};
}

int run_tile(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"orbifold", "cones", "svg", "depth"});
  const HOT::Orbifold_type type = parse_orbifold(opt.get("orbifold"));
  const long k = opt.get_int("cones", -1000000, 1000000);
  const int depth = opt.has("depth") ? static_cast<int>(opt.get_int("depth", 0, 6)) : 3;
  const std::string svg = opt.get("svg");
  if(k > 200)
    throw Usage_error{"--cones must be at most 200 for a picture, got " + std::to_string(k)};

  HOT::Orbifold_tile<> tile;
  const HOT::Error_code ec = HOT::make_orbifold_tile(type, static_cast<int>(k), tile);
  if(ec != HOT::OK)
    throw std::runtime_error(std::string(HOT::error_message(ec)) + ": got " + std::to_string(k) + " cones");

  const std::string pi = "&#960;";
  const std::string multiple = (k == 5) ? std::string() : std::to_string(k - 4);
  std::ostringstream title;
  if(type == HOT::Sphere_type)
    title << "sphere-type orbifold, " << k << " cones of angle " << pi << ", tile with " << tile.number_of_corners()
          << " corners, area " << multiple << pi;
  else
    title << "disk-type orbifold, " << k << " corners of angle " << pi << "/2, area " << multiple << pi << "/2";
  write_file_atomically(svg, [&](std::ostream& os) { HOT::internal::write_tile_svg(os, tile, depth, title.str()); });
  std::cout << "wrote " << svg << " (" << (type == HOT::Sphere_type ? "sphere" : "disk") << ", " << k
            << " cones, depth " << depth << ")" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    if(argc < 2)
      throw Usage_error{"missing command"};
    const std::string command = argv[1];
    if(command == "--help" || command == "-h" || command == "help") {
      std::cout << usage_text;
      return EXIT_SUCCESS;
    }
    if(command == "tile")
      return run_tile(argc, argv);
    throw Usage_error{"unknown command '" + command + "'"};
  } catch(const Usage_error& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << e.message << " (see --help)" << std::endl;
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "hyperbolic_orbifold_tutte: " << e.what() << std::endl;
    return 1;
  }
}
