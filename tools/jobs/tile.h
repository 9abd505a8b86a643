// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_TILE_H
#define HOT_TOOLS_JOBS_TILE_H

// The `tile` command: the picture of an orbifold's tile and its images (SVG).

#include "command_line.h"
#include "hot_app/io/svg.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace hot_cli {

inline int run_tile(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"orbifold", "cones", "svg", "depth", "cone-orders"});
  const HOT::Orbifold_type type = parse_orbifold(opt.get("orbifold"));
  const std::vector<int> orders = parse_cone_orders(opt);
  const long k = orders.empty() || opt.has("cones") ? opt.get_int("cones", -1000000, 1000000) : static_cast<long>(orders.size());
  const int depth = opt.has("depth") ? static_cast<int>(opt.get_int("depth", 0, 6)) : 3;
  const std::string svg = opt.get("svg");
  if(k > 200)
    throw Usage_error{"--cones must be at most 200 for a picture, got " + std::to_string(k)};

  HOT::Orbifold_tile<> tile;
  if(!orders.empty()) {
    require(HOT::internal::tile_of_cone_orders(type, orders, static_cast<int>(k), tile, HOT::Poincare_disk_traits_2<>()));
  } else {
    const HOT::Error_code ec = HOT::make_orbifold_tile(type, static_cast<int>(k), tile);
    if(ec != HOT::OK)
      throw std::runtime_error(std::string(HOT::error_message(ec)) + ": got " + std::to_string(k) + " cones");
  }

  const std::string pi = "&#960;";
  const std::string multiple = (k == 5) ? std::string() : std::to_string(k - 4);
  std::ostringstream title;
  if(!orders.empty()) {
    std::string list;
    for(int p : orders)
      list += (list.empty() ? "" : ",") + std::to_string(p);
    title.precision(4);
    title << "sphere-type orbifold with cones of orders (" << list << "), tile with " << tile.number_of_corners() << " corners, area "
          << tile.area() / CGAL_PI << pi;
  } else if(type == HOT::Sphere_type)
    title << "sphere-type orbifold, " << k << " cones of angle " << pi << ", tile with " << tile.number_of_corners()
          << " corners, area " << multiple << pi;
  else
    title << "disk-type orbifold, " << k << " corners of angle " << pi << "/2, area " << multiple << pi << "/2";
  write_file_atomically(svg, [&](std::ostream& os) { hot_tools::write_tile_svg(os, tile, depth, title.str()); });
  std::cout << "wrote " << svg << " (" << (type == HOT::Sphere_type ? "sphere" : "disk") << ", " << k << " cones"
            << (orders.empty() ? std::string() : " of the given orders") << ", depth " << depth << ")" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_TILE_H
