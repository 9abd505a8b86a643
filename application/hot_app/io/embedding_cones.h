// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_CONES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_CONES_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>

#include <cstddef>
#include <ostream>
#include <vector>

/// \file embedding_cones.h

namespace hot_tools {

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

// The orbifold and the cones of an embedding, written as comments at the head of its OBJ file
// (any OBJ reader skips them) so that the file alone is enough to map from it (`map
// --source-embedding`, collections run as separate jobs):
//   # hot orbifold TYPE genus G cones K reversed R   TYPE sphere or disk; R 1 if a disk's
//                                                    landmarks were given clockwise
//   # hot cone C LANDMARK VERTEX ORDER               cone C (0-based, in the order of the cut,
//                                                    the tile's) is landmark LANDMARK (0-based
//                                                    line of the landmark file), vertex VERTEX
//                                                    (0-based, as the v lines), of order ORDER
struct Embedding_cones
{
  HOT::Orbifold_type type = HOT::Sphere_type;
  long long genus = 0;
  bool reversed = false;
  std::vector<std::size_t> landmark; // per cone, in the order of the cut
  std::vector<std::size_t> vertex;
  std::vector<int> order;
};

inline void write_embedding_cones(std::ostream& os, const Embedding_cones& c)
{
  os << "# hot orbifold " << (c.type == HOT::Sphere_type ? "sphere" : "disk") << " genus " << c.genus << " cones "
     << c.landmark.size() << " reversed " << (c.reversed ? 1 : 0) << "\n";
  for(std::size_t i = 0; i < c.landmark.size(); ++i)
    os << "# hot cone " << i << " " << c.landmark[i] << " " << c.vertex[i] << " " << (i < c.order.size() ? c.order[i] : 2) << "\n";
}

} // namespace hot_tools

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_EMBEDDING_CONES_H
