// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_CUT_GRAPH_FILE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_CUT_GRAPH_FILE_H

// The cut graph of a closed mesh of genus g >= 1 as a text file (--cut-graph, --cut-graph-out):
//
//   # hot cut graph
//   12 40 41 7
//   7 300 12
//
// one vertex path per non-empty line, 0-based vertex indices of the mesh file separated by
// blanks, '#' starting a comment; consecutive vertices of a path are joined by an edge of the
// mesh; the paths together are the cut graph (each edge once), which must cut the mesh into a
// disk and hold every landmark; the first path's first edge sets the tile's corner 0, so two
// meshes cut along corresponding graphs (the same paths, vertex for vertex) get the same tile.

#include "common.h"
#include "files.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace hot_tools {

inline HOT::Status read_cut_graph(const std::string& path, std::vector<std::vector<std::size_t> >& paths)
{
  using namespace io_impl;
  paths.clear();
  std::string data;
  HOT::Status r = read_file_contents(path, data);
  if(!r)
    return r;
  Cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string_view> fields;
  while(!cur.at_end()) {
    const std::size_t line = cur.line();
    split(cur.rest_of_line(true), fields);
    if(fields.empty())
      continue;
    std::vector<std::size_t> p;
    for(std::string_view f : fields) {
      std::uint64_t v = 0;
      if(parse_unsigned(f, v) != NUMBER_OK) {
        paths.clear();
        return read_fail(path + ": " + at_line(line) + quote(f) + " is not a vertex index (a non-negative integer)");
      }
      p.push_back(static_cast<std::size_t>(v));
    }
    if(p.size() < 2) {
      paths.clear();
      return read_fail(path + ": " + at_line(line) + "a path of the cut graph needs at least 2 vertices");
    }
    paths.push_back(p);
  }
  if(paths.empty())
    return read_fail(path + ": the file holds no path of a cut graph");
  return HOT::Status();
}

inline void write_cut_graph(std::ostream& os, const std::vector<std::vector<std::size_t> >& paths)
{
  os << "# hot cut graph: one vertex path per line (0-based vertex indices)\n";
  for(const auto& p : paths) {
    for(std::size_t j = 0; j < p.size(); ++j)
      os << (j ? " " : "") << p[j];
    os << "\n";
  }
}

} // namespace hot_tools

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_CUT_GRAPH_FILE_H
