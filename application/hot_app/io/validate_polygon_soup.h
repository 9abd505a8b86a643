// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_VALIDATE_POLYGON_SOUP_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_VALIDATE_POLYGON_SOUP_H

// Validation of a polygon soup before it becomes a mesh (the tool's readers), and the
// edge table the soup-to-mesh builder links.
//
// Soup validation (`validate_polygon_soup()`), first failure wins:
//   ERROR_READ_FAILED            a vertex index is out of range
//   ERROR_DEGENERATE_FACE        a face has fewer than 3 vertices or uses a vertex twice
//   ERROR_NON_MANIFOLD           a face is repeated (same vertices, same cyclic order;
//                                reported instead of the edge errors below it causes)
//   ERROR_NON_MANIFOLD           an edge is shared by more than two faces
//   ERROR_NON_MANIFOLD           two faces traverse an edge in the same direction
//                                ("inconsistent face orientation"; also duplicated faces)
//   ERROR_NON_MANIFOLD           the faces around a vertex form several fans
//   ERROR_NON_FINITE_COORDINATES a coordinate is NaN or infinite (also a text coordinate
//                                that overflows a double, e.g. 1e999)
// A soup without face is not an error here (`check_mesh()` reports ERROR_EMPTY_MESH);
// an empty file is (ERROR_READ_FAILED).

#include "common.h"
#include "polygon_soup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file validate_polygon_soup.h

namespace hot_tools {

/// The edge table of a valid soup, used to build the halfedge structure.
struct Soup_topology
{
  typedef std::uint32_t Id;
  static constexpr Id none = static_cast<Id>(-1);

  std::vector<Id> corner_face;              ///< face of each corner (position in face_vertices)
  std::vector<Id> corner_edge;              ///< edge of the halfedge that leaves each corner
  std::vector<unsigned char> corner_side;   ///< 0: first halfedge of that edge, 1: its opposite
  std::vector<std::array<Id, 2> > edge_corners; ///< corners of the two sides (`none`: border side)
};

namespace io_impl {

typedef Soup_topology::Id Soup_id;

/// the corner after corner `c` in its face (`corner_face`: the face of each corner)
inline std::size_t next_corner(const Polygon_soup& soup, const std::vector<Soup_id>& corner_face, std::size_t c)
{
  const std::size_t f = corner_face[c];
  return c + 1 < soup.face_begin[f + 1] ? c + 1 : soup.face_begin[f];
}

/// step 1, faces: indices in range, at least 3 distinct vertices; fills `corner_face`
inline HOT::Status check_soup_faces(const Polygon_soup& soup, std::vector<Soup_id>& corner_face)
{
  const Soup_id none = Soup_topology::none;
  const std::size_t np = soup.number_of_points();
  const std::size_t nf = soup.number_of_faces();
  const std::vector<std::size_t>& fv = soup.face_vertices;
  std::vector<Soup_id> seen(np, none);
  for(std::size_t f = 0; f < nf; ++f) {
    const std::size_t b = soup.face_begin[f], e = soup.face_begin[f + 1];
    for(std::size_t c = b; c < e; ++c) {
      if(fv[c] >= np) {
        std::ostringstream os;
        os << soup.face_name(f) << ": vertex index " << fv[c] << " is out of range (the file has "
           << np << " vertices)";
        return read_fail(os.str());
      }
    }
    if(e - b < 3) {
      std::ostringstream os;
      os << soup.face_name(f) << " is degenerate: it has only " << (e - b) << " vertices";
      return fail(HOT::ERROR_DEGENERATE_FACE, os.str());
    }
    for(std::size_t c = b; c < e; ++c) {
      corner_face[c] = static_cast<Soup_id>(f);
      if(seen[fv[c]] == static_cast<Soup_id>(f)) {
        std::ostringstream os;
        os << soup.face_name(f) << " is degenerate: it uses vertex " << fv[c] << " more than once";
        return fail(HOT::ERROR_DEGENERATE_FACE, os.str());
      }
      seen[fv[c]] = static_cast<Soup_id>(f);
    }
  }
  return HOT::Status();
}

/// step 1b, a face repeated (the same vertices in the same cyclic order): hash of each face
/// read from its smallest vertex, faces with equal hashes compared. A repeated face
/// makes two faces traverse an edge in the same direction, so this runs only when
/// step 2 finds such an edge (no cost for valid soups), to give the specific reason.
inline HOT::Status find_duplicated_face(const Polygon_soup& soup, const std::vector<Soup_id>& corner_face)
{
  const Soup_id none = Soup_topology::none;
  const std::size_t nf = soup.number_of_faces();
  const std::vector<std::size_t>& fv = soup.face_vertices;
  auto smallest_corner = [&](std::size_t f) {
    std::size_t best = soup.face_begin[f];
    for(std::size_t c = best + 1; c < soup.face_begin[f + 1]; ++c)
      if(fv[c] < fv[best])
        best = c;
    return best;
  };
  std::vector<std::size_t> first_corner(nf);
  std::unordered_map<std::uint64_t, Soup_id> first_with_hash;
  std::vector<Soup_id> next_with_hash(nf, none);
  first_with_hash.reserve(nf);
  for(std::size_t f = 0; f < nf; ++f) {
    const std::size_t c0 = first_corner[f] = smallest_corner(f);
    std::uint64_t h = soup.face_size(f);
    std::size_t c = c0;
    do {
      h = (h ^ fv[c]) * 0x100000001b3ull + 0x9e3779b97f4a7c15ull;
      h ^= h >> 29;
      c = next_corner(soup, corner_face, c);
    } while(c != c0);
    auto ins = first_with_hash.emplace(h, static_cast<Soup_id>(f));
    if(ins.second)
      continue;
    for(Soup_id g = ins.first->second; g != none; g = next_with_hash[g]) {
      if(soup.face_size(g) != soup.face_size(f))
        continue;
      std::size_t a = first_corner[g], b = c0;
      std::size_t k = 0;
      while(k < soup.face_size(f) && fv[a] == fv[b]) {
        a = next_corner(soup, corner_face, a);
        b = next_corner(soup, corner_face, b);
        ++k;
      }
      if(k == soup.face_size(f)) {
        std::ostringstream os;
        os << "duplicated face: " << soup.face_name(f) << " repeats " << soup.face_name(g)
           << " (the same vertices in the same order)";
        return fail(HOT::ERROR_NON_MANIFOLD, os.str());
      }
    }
    next_with_hash[f] = next_with_hash[ins.first->second]; // chain f after the first face with this hash
    next_with_hash[ins.first->second] = static_cast<Soup_id>(f);
  }
  return HOT::Status();
}

/// a halfedge of the soup, filed under its smaller vertex: the other vertex and its corner
struct Soup_halfedge_entry { Soup_id other; Soup_id corner; };

/// step 2a: the halfedges grouped by their smaller vertex (counting sort); those of vertex
/// `a` are `entries[start[a]]` ... `entries[start[a+1]-1]`
inline void group_soup_halfedges(const Polygon_soup& soup, const std::vector<Soup_id>& corner_face,
                                 std::vector<Soup_id>& start, std::vector<Soup_halfedge_entry>& entries)
{
  const std::size_t np = soup.number_of_points();
  const std::vector<std::size_t>& fv = soup.face_vertices;
  const std::size_t m = fv.size();
  start.assign(np + 1, 0);
  for(std::size_t c = 0; c < m; ++c)
    ++start[(std::min)(fv[c], fv[next_corner(soup, corner_face, c)]) + 1];
  for(std::size_t v = 0; v < np; ++v)
    start[v + 1] += start[v];
  entries.resize(m);
  std::vector<Soup_id> fill(start.begin(), start.end() - 1);
  for(std::size_t c = 0; c < m; ++c) {
    const std::size_t a = fv[c], b = fv[next_corner(soup, corner_face, c)];
    entries[fill[(std::min)(a, b)]++] = Soup_halfedge_entry{ static_cast<Soup_id>((std::max)(a, b)), static_cast<Soup_id>(c) };
  }
}

/// step 2b, edges: the halfedges of each vertex sorted by their other vertex, then paired
/// into the edges of `topology` (`corner_face` filled); the first edge shared by more than
/// two faces and the first edge traversed twice in the same direction are described in
/// `non_manifold_edge` and `bad_orientation`
inline void pair_soup_halfedges(const Polygon_soup& soup, const std::vector<Soup_id>& start,
                                std::vector<Soup_halfedge_entry>& entries, Soup_topology& topology,
                                std::string& non_manifold_edge, std::string& bad_orientation)
{
  const Soup_id none = Soup_topology::none;
  const std::size_t np = soup.number_of_points();
  const std::vector<std::size_t>& fv = soup.face_vertices;
  const std::vector<Soup_id>& corner_face = topology.corner_face;
  std::vector<Soup_id>& corner_edge = topology.corner_edge;
  std::vector<unsigned char>& corner_side = topology.corner_side;
  std::vector<std::array<Soup_id, 2> >& edge_corners = topology.edge_corners;
  for(std::size_t a = 0; a < np; ++a) {
    const auto first = entries.begin() + start[a], last = entries.begin() + start[a + 1];
    std::sort(first, last, [](const Soup_halfedge_entry& x, const Soup_halfedge_entry& y) {
      return x.other < y.other || (x.other == y.other && x.corner < y.corner);
    });
    for(auto g = first; g != last;) {
      auto h = g;
      while(h != last && h->other == g->other)
        ++h;
      const std::size_t s = static_cast<std::size_t>(h - g);
      if(s > 2) {
        if(non_manifold_edge.empty()) {
          std::ostringstream os;
          os << "non-manifold edge: the edge (" << a << ", " << g->other << ") is shared by " << s << " faces (";
          for(auto k = g; k != h && k - g < 4; ++k)
            os << (k == g ? "" : ", ") << soup.face_name(corner_face[k->corner]);
          os << (s > 4 ? ", ...)" : ")");
          non_manifold_edge = os.str();
        }
      } else if(s == 2 && (fv[g->corner] == a) == (fv[(g + 1)->corner] == a)) {
        if(bad_orientation.empty()) {
          const std::size_t from = fv[g->corner], to = fv[next_corner(soup, corner_face, g->corner)];
          std::ostringstream os;
          os << "inconsistent face orientation: " << soup.face_name(corner_face[g->corner]) << " and "
             << soup.face_name(corner_face[(g + 1)->corner]) << " both traverse the edge " << from << " -> " << to
             << " (faces must be oriented consistently; or a face is duplicated)";
          bad_orientation = os.str();
        }
      } else {
        const Soup_id e = static_cast<Soup_id>(edge_corners.size());
        edge_corners.push_back({ { g->corner, s == 2 ? (g + 1)->corner : none } });
        corner_edge[g->corner] = e;
        corner_side[g->corner] = 0;
        if(s == 2) {
          corner_edge[(g + 1)->corner] = e;
          corner_side[(g + 1)->corner] = 1;
        }
      }
      g = h;
    }
  }
}

/// step 3, vertices: the corners around a vertex must form a single fan (union-find of
/// the corners at a vertex that share an edge)
inline HOT::Status check_soup_vertex_fans(const Polygon_soup& soup, const Soup_topology& topology)
{
  const Soup_id none = Soup_topology::none;
  const std::size_t np = soup.number_of_points();
  const std::vector<std::size_t>& fv = soup.face_vertices;
  const std::size_t m = fv.size();
  const std::vector<Soup_id>& corner_face = topology.corner_face;
  std::vector<Soup_id> parent(m);
  for(std::size_t c = 0; c < m; ++c)
    parent[c] = static_cast<Soup_id>(c);
  auto find = [&](Soup_id x) {
    while(parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  auto unite = [&](Soup_id x, Soup_id y) {
    x = find(x);
    y = find(y);
    if(x != y)
      parent[(std::max)(x, y)] = (std::min)(x, y);
  };
  for(const auto& ec : topology.edge_corners) {
    if(ec[1] == none)
      continue;
    // ec[0]: u -> w in one face; ec[1]: w -> u in the other
    unite(ec[0], static_cast<Soup_id>(next_corner(soup, corner_face, ec[1]))); // corners at u
    unite(static_cast<Soup_id>(next_corner(soup, corner_face, ec[0])), ec[1]); // corners at w
  }
  std::vector<Soup_id> fan(np, none);
  for(std::size_t c = 0; c < m; ++c) {
    const Soup_id r = find(static_cast<Soup_id>(c));
    Soup_id& f = fan[fv[c]];
    if(f == none) {
      f = r;
    } else if(f != r) {
      std::ostringstream os;
      os << "non-manifold vertex: the faces around " << soup.point_name(fv[c]) << " form more than one fan ("
         << soup.face_name(corner_face[f]) << " and " << soup.face_name(corner_face[c])
         << " are in different fans)";
      return fail(HOT::ERROR_NON_MANIFOLD, os.str());
    }
  }
  return HOT::Status();
}

/// step 4: finite coordinates
inline HOT::Status check_soup_coordinates(const Polygon_soup& soup)
{
  for(std::size_t i = 0; i < soup.number_of_points(); ++i) {
    const auto& p = soup.points[i];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      std::ostringstream os;
      os << soup.point_name(i) << " has a non-finite coordinate (" << p[0] << " " << p[1] << " " << p[2] << ")";
      return fail(HOT::ERROR_NON_FINITE_COORDINATES, os.str());
    }
  }
  return HOT::Status();
}

} // namespace io_impl

/*!
Validates `soup` (see the list at the top of this file) in linear expected time and,
if `topology` is not null and the soup is valid, fills the edge table used by
`polygon_soup_to_mesh()`.
*/
inline HOT::Status validate_polygon_soup(const Polygon_soup& soup, Soup_topology* topology = nullptr)
{
  typedef Soup_topology::Id Id;
  const Id none = Soup_topology::none;
  const std::size_t np = soup.number_of_points();
  const std::size_t nf = soup.number_of_faces();
  const std::size_t m = soup.face_vertices.size();

  if(np >= none || m >= none || nf >= none)
    return io_impl::read_fail("the mesh is too large (more than 4 billion vertices or face corners)");

  Soup_topology t;
  t.corner_face.resize(m);
  HOT::Status r = io_impl::check_soup_faces(soup, t.corner_face);
  if(!r)
    return r;

  t.corner_edge.assign(m, none);
  t.corner_side.assign(m, 0);
  t.edge_corners.reserve(m / 2 + 1);
  std::string non_manifold_edge, bad_orientation;
  {
    std::vector<Id> start;
    std::vector<io_impl::Soup_halfedge_entry> entries;
    io_impl::group_soup_halfedges(soup, t.corner_face, start, entries);
    io_impl::pair_soup_halfedges(soup, start, entries, t, non_manifold_edge, bad_orientation);
  }
  if(!non_manifold_edge.empty() || !bad_orientation.empty()) {
    HOT::Status dup = io_impl::find_duplicated_face(soup, t.corner_face);
    if(!dup)
      return dup;
    return io_impl::fail(HOT::ERROR_NON_MANIFOLD, !non_manifold_edge.empty() ? non_manifold_edge : bad_orientation);
  }

  if(!(r = io_impl::check_soup_vertex_fans(soup, t)))
    return r;
  if(!(r = io_impl::check_soup_coordinates(soup)))
    return r;

  if(topology) {
    topology->corner_face.swap(t.corner_face);
    topology->corner_edge.swap(t.corner_edge);
    topology->corner_side.swap(t.corner_side);
    topology->edge_corners.swap(t.edge_corners);
  }
  return HOT::Status();
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_VALIDATE_POLYGON_SOUP_H
