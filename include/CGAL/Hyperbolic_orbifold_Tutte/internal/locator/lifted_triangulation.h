// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LIFTED_TRIANGULATION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LIFTED_TRIANGULATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/interpolation_model.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/corner_table.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/locator/start_grid.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

// The data of the point locator (Embedding_locator.h), independent of the mesh type: the
// faces of the embedding with their corner points, their neighbours and the group element
// across each edge (the lifted triangulation: B's triangles and their images under the
// orbifold group), the start points and the corner table.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

struct Lifted_face
{
  std::complex<double> z[3]; // corner points (Poincare)
  int v[3];             // corner vertex indices
  int nf[3];            // neighbour face across edge j (corner j -> corner j+1)
  int ne[3];            // the edge's index in the neighbour face
  int tr[3];            // index of the transition element in transitions (0: identity, -1: none)
  bool mirror[3];       // border edge glued to itself by a reflection: the neighbour is this face, reflected
};

// Traits: a model of HyperbolicOrbifoldTraits_2, the traits of the tile
template <class Traits_>
struct Lifted_triangulation
{
  typedef Traits_ Traits;
  typedef typename Traits::Point_2 Point_2;
  typedef Orbifold_tile<Traits> Tile;
  typedef Hyperbolic_isometry_2<double> Isometry;
  typedef std::complex<double> C;

  static constexpr std::size_t no_face = static_cast<std::size_t>(-1);

  Interpolation_model model = Klein_linear;
  bool valid = false;
  std::string message;
  Tile tile;
  std::vector<Isometry> transitions; // 0: identity, 1 + s: the pairing of side s, then products of two
  std::vector<Lifted_face> faces;
  std::vector<C> centroids;          // Klein centroids (Poincare coordinates)
  Corner_table corner_table;
  Start_grid grid;
  std::size_t n_cut_edges = 0, n_border_edges = 0, n_inverted = 0;

  // the orientation of the geodesic triangle (a, b, c), exact (the tile's traits)
  int orient(const C& a, const C& b, const C& c) const
  {
    const typename Traits::Hyperbolic_orientation_2 o = tile.traits().hyperbolic_orientation_2_object();
    return static_cast<int>(o(Point_2(a.real(), a.imag()), Point_2(b.real(), b.imag()), Point_2(c.real(), c.imag())));
  }

  // the face edge joining corners a and b (edge j joins corners j and j+1)
  static int edge_index(int a, int b) { return ((a + 1) % 3 == b) ? a : b; }

  template <class PointT>
  static C to_c(const PointT& p) { return C(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

  // a failed build: returns false
  bool fail(const std::string& m)
  {
    valid = false;
    message = m;
    return false;
  }

  // the start of a build over the tile `t`, for a mesh with n vertices
  void reset(const Tile& t, std::size_t n)
  {
    tile = t;
    valid = true;
    message.clear();
    transitions.assign(1, Isometry());
    corner_table.reset(n + n / 8); // cut vertices have several points
    for(int s = 0; s < tile.number_of_sides(); ++s)
      transitions.push_back(tile.side_pairing(s)); // index 1 + s
  }

  // g with g(a_from) = a_to and g(b_from) = b_to up to rounding, among the side pairings
  // and their products of two; -1 if none
  int find_transition(const C& a_from, const C& a_to, const C& b_from, const C& b_to)
  {
    const double tol = 1e-12; // sinh^2(d/2): hyperbolic distances below 2e-6
    auto error = [&](const Isometry& g) {
      return (std::max)(hyperbolic_proximity(g.apply(a_from), a_to), hyperbolic_proximity(g.apply(b_from), b_to));
    };
    int best = -1;
    double best_err = tol;
    for(std::size_t i = 1; i < transitions.size(); ++i) {
      const double e = error(transitions[i]);
      if(e < best_err) {
        best_err = e;
        best = static_cast<int>(i);
      }
    }
    if(best >= 0)
      return best;
    const int ns = tile.number_of_sides();
    for(int i = 0; i < ns; ++i)
      for(int j = 0; j < ns; ++j) {
        const Isometry g = tile.side_pairing(i) * tile.side_pairing(j);
        if(g.is_identity(1e-9))
          continue;
        if(error(g) < tol) {
          transitions.push_back(g);
          return static_cast<int>(transitions.size()) - 1;
        }
      }
    return -1;
  }

  // the mirror side (a side paired with itself by an orientation-reversing pairing) that
  // holds both points, as a transition index; -1 if none
  int find_mirror(const C& a, const C& b) const
  {
    const C ka = poincare_to_klein(a), kb = poincare_to_klein(b);
    int best = -1;
    double best_err = 1e-7; // Klein distance to the side's line
    for(int s = 0; s < tile.number_of_sides(); ++s) {
      if(tile.paired_side(s) != s || tile.side_pairing(s).is_orientation_preserving())
        continue;
      const C k0 = poincare_to_klein(to_c(tile.corner(tile.side_source(s))));
      const C k1 = poincare_to_klein(to_c(tile.corner(tile.side_target(s))));
      const C d = k1 - k0;
      const double len = std::abs(d);
      auto dist = [&](const C& p) { return std::abs(d.real() * (p.imag() - k0.imag()) - d.imag() * (p.real() - k0.real())) / len; };
      const double e = (std::max)(dist(ka), dist(kb));
      if(e < best_err) {
        best_err = e;
        best = 1 + s;
      }
    }
    return best;
  }

  // start points: Klein centroids strictly inside positively oriented faces (exact tests),
  // the corner table and the grid; false if no face can start a walk
  bool place_start_points()
  {
    centroids.resize(faces.size());
    std::vector<char> good(faces.size(), 0);
    double xmin = 1, xmax = -1, ymin = 1, ymax = -1;
    std::size_t n_good = 0;
    for(std::size_t fi = 0; fi < faces.size(); ++fi) {
      const Lifted_face& F = faces[fi];
      const C c = klein_to_poincare((poincare_to_klein(F.z[0]) + poincare_to_klein(F.z[1]) + poincare_to_klein(F.z[2])) / 3.0);
      centroids[fi] = c;
      if(orient(F.z[0], F.z[1], F.z[2]) <= 0) {
        ++n_inverted;
        continue;
      }
      if(orient(F.z[0], F.z[1], c) > 0 && orient(F.z[1], F.z[2], c) > 0 && orient(F.z[2], F.z[0], c) > 0) {
        good[fi] = 1;
        ++n_good;
        xmin = (std::min)(xmin, c.real());
        xmax = (std::max)(xmax, c.real());
        ymin = (std::min)(ymin, c.imag());
        ymax = (std::max)(ymax, c.imag());
      }
      for(int j = 0; j < 3; ++j)
        corner_table.insert(point_key(F.z[j]), static_cast<int>(fi), j);
    }
    if(n_good == 0)
      return fail("no face of the embedding is positively oriented with an inner centroid");
    if(n_inverted > 0)
      message = std::to_string(n_inverted) + " faces are not positively oriented: the embedding is not bijective";
    grid.build(centroids, good, n_good, xmin, xmax, ymin, ymax);
    return true;
  }

  // a query exactly at a corner's point: that corner, with the element `element`
  template <class Location>
  bool corner_hit(const C& q, const Isometry& element, Location& loc) const
  {
    std::pair<int, int> c;
    if(!corner_table.find(point_key(q), c))
      return false;
    loc.face_index = static_cast<std::size_t>(c.first);
    loc.barycentric = {{0.0, 0.0, 0.0}};
    loc.barycentric[c.second] = 1.0;
    loc.min_raw_barycentric = 0.0;
    loc.element = element;
    loc.success = true;
    loc.steps = 0;
    return true;
  }
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_LIFTED_TRIANGULATION_H
