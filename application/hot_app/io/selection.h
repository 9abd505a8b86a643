// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_SELECTION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_SELECTION_H

// CGAL's selection file (`.selection.txt`) of a cut through cones, the `cut` command's output.

#include <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h>

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <ostream>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file selection.h

namespace hot_tools {

// Writes a selection file as CGAL's Polyhedron demo does and as `Seam_mesh::add_seams(file)`
// and `Surface_mesh_parameterization::locate_cones(mesh, file, ...)` read it: line 1 the
// selected vertices (the cones, in the cut's order), line 2 the selected faces (none), line 3
// the selected edges as pairs of vertex indices "s0 t0 s1 t1 ..." (the seam edges, along the
// cut from the first cone to the last). Indices are 0-based positions in vertices(m).
template <class Point_3>
void write_selection_file(std::ostream& os, const CGAL::Surface_mesh<Point_3>& m,
                          const std::vector<typename CGAL::Surface_mesh<Point_3>::Vertex_index>& cones,
                          const CGAL::Hyperbolic_orbifold_Tutte::Cut_result<CGAL::Surface_mesh<Point_3> >& cut)
{
  for(std::size_t i = 0; i < cones.size(); ++i)
    os << (i ? " " : "") << cones[i].idx();
  os << "\n\n";
  const char* separator = "";
  for(const auto& path : cut.paths)
    for(const auto& h : path) {
      os << separator << source(h, m).idx() << " " << target(h, m).idx();
      separator = " ";
    }
  os << "\n";
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_SELECTION_H
