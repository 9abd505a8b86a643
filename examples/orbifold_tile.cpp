// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Builds the basic tile of a 7-cone sphere-type hyperbolic orbifold, prints its
// corners and area, and maps a point near the disk's boundary into the tile.

#include <CGAL/hyperbolic_orbifold_Tutte.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

int main()
{
  typedef HOT::Poincare_disk_traits_2<> Traits;
  HOT::Orbifold_tile<Traits> tile;
  if(HOT::make_orbifold_tile(HOT::Sphere_type, 7, tile) != HOT::OK)
    return EXIT_FAILURE;

  std::cout << "tile with " << tile.number_of_corners() << " corners, area " << tile.area() << "\n";
  for(int c = 0; c < tile.number_of_cones(); ++c)
    std::cout << "  cone " << c << " at " << tile.cone_point(c) << "\n";

  const Traits::Point_2 far(0.99999, 0.001);
  const auto r = tile.reduce_to_tile(far);
  std::cout << "point " << far << " -> " << r.point << " after " << r.steps << " side pairings ("
            << (tile.bounded_side(r.point) == CGAL::ON_UNBOUNDED_SIDE ? "outside" : "inside") << " the tile)\n";
  // Gauss-Bonnet: a sphere with k cones of angle pi has hyperbolic area 2 pi (k/2 - 2) = (k - 4) pi
  const double expected = (7 - 4) * CGAL_PI;
  if(std::abs(tile.area() - expected) > 1e-12 * expected) {
    std::cerr << "tile area " << tile.area() << ", not (k - 4) pi = " << expected << "\n";
    return EXIT_FAILURE;
  }
  return tile.bounded_side(r.point) == CGAL::ON_UNBOUNDED_SIDE ? EXIT_FAILURE : EXIT_SUCCESS;
}
