// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_RECENTRING_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_RECENTRING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/certify_and_repair.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/orbifold_solver.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

// Triangles below what double resolves, and the recentring that solves such a region
// again in a frame that moves it to the origin (Hyperbolic_orbifold_Tutte_parameterizer_3's
// set_recentring()).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the most rounds of recentring
constexpr int max_recentring_rounds = 24;

struct Unresolved_faces
{
  typedef std::complex<double> C;
  std::size_t count = 0;                                      // the faces flagged
  double smallest = std::numeric_limits<double>::infinity(); // the shortest edge of all
  C where;                    // the deepest vertex of the flagged faces (most face steps from the others)
  std::vector<char> flag;     // per face
};

// Faces that double cannot resolve (an edge within 256 units in the last place of its
// ends), and with `not_positive` also the faces that are not positive (exact test with the
// traits `tr`, the tile's).
template <class Traits>
Unresolved_faces unresolved_faces(const Flat_problem& Q, const std::vector<std::complex<double> >& uv, const Traits& tr,
                                  bool not_positive)
{
  typedef std::complex<double> C;
  Unresolved_faces u;
  u.flag.assign(Q.faces.size(), 0);
  for(std::size_t fi = 0; fi < Q.faces.size(); ++fi) {
    const auto& f = Q.faces[fi];
    for(int i = 0; i < 3; ++i) {
      const C a = uv[f[i]], b = uv[f[(i + 1) % 3]];
      const double len = std::abs(a - b), ulp = std::numeric_limits<double>::epsilon() * (std::max)(std::abs(a), std::abs(b));
      u.smallest = (std::min)(u.smallest, len);
      u.flag[fi] = u.flag[fi] || len < 256 * ulp;
    }
    if(not_positive && !u.flag[fi])
      u.flag[fi] = !positive_triangle(tr, uv[f[0]], uv[f[1]], uv[f[2]]);
    u.count += u.flag[fi] ? 1 : 0;
  }
  if(u.count == 0)
    return u;
  // the deepest point of the flagged region (a protrusion's tip): breadth first from
  // the vertices of the other faces
  std::vector<std::vector<int> > faces_of(Q.n);
  for(std::size_t fi = 0; fi < Q.faces.size(); ++fi)
    for(int v : Q.faces[fi])
      faces_of[v].push_back(static_cast<int>(fi));
  std::vector<int> depth(Q.n, -1), queue;
  for(std::size_t fi = 0; fi < Q.faces.size(); ++fi)
    if(!u.flag[fi])
      for(int v : Q.faces[fi])
        if(depth[v] < 0) {
          depth[v] = 0;
          queue.push_back(v);
        }
  if(queue.empty()) { // every face flagged: from anywhere
    depth[Q.faces[0][0]] = 0;
    queue.push_back(Q.faces[0][0]);
  }
  for(std::size_t i = 0; i < queue.size(); ++i)
    for(int fi : faces_of[queue[i]])
      for(int w : Q.faces[fi])
        if(depth[w] < 0) {
          depth[w] = depth[queue[i]] + 1;
          queue.push_back(w);
        }
  u.where = uv[queue.back()];
  return u;
}

// Double resolves 1e-16 of a coordinate's size: far finer near the origin. A squeezed
// region (a protrusion without landmarks shrinks by e per radius of its length) is solved
// again in a frame that moves its deepest point to the origin (the tile moved by the same
// isometry), from the current coordinates, by Newton on it and two rings around it alone:
// the whole problem's linear solves cannot resolve forces 1e-16 times its largest ones,
// and their rounding would move the region by more than its size. Each round resolves
// the region up to 16 digits deeper (a tube: about 30 radii further); rounds go on while they
// reduce the faces left (at most `max_recentring_rounds`). Then the one-ring repairs.
// On success, `uv` and the certificate are those of the moved frame, `st.frame` records
// it; else `uv` and the certificate are left as they were.
template <class SeamMesh, class Landmarks, class Cut_vertices, class Tile>
void recentre(const SeamMesh& mesh, typename boost::graph_traits<SeamMesh>::halfedge_descriptor bhd,
              const Landmarks& landmarks, const Cut_vertices& cut_vertices, const Tile& tile, const Flat_problem& P,
              const Solver_options& options, std::vector<std::complex<double> >& uv, Embedding_statistics& st)
{
  typedef std::complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;
  typedef typename boost::graph_traits<typename SeamMesh::TriangleMesh>::vertex_descriptor TM_vertex_descriptor;
  const Embedding_certificate canonical = st.certificate;
  Isometry frame;
  Tile moved = tile;
  Flat_problem Q;
  std::vector<C> uvq = uv;
  std::vector<double> xq;
  Unresolved_faces left = unresolved_faces(P, uvq, tile.traits(), true);
  std::size_t best = left.count;
  for(int round = 0, idle = 0; round < max_recentring_rounds && left.count > 0 && idle < 4; ++round) {
    const Isometry step = Isometry::translation_to_origin(left.where);
    frame = step * frame;
    moved = tile.transformed(frame);
    Flat_problem R;
    std::vector<TM_vertex_descriptor> base_vertex;
    Cut_vertices cut_vertices_r;
    std::string msg;
    if(build_flat_topology(mesh, bhd, landmarks, moved, R, base_vertex, cut_vertices_r, msg) != OK ||
       cut_vertices_r != cut_vertices)
      return; // (the same mesh and landmarks as the first time: not expected)
    R.edge_weight = P.edge_weight;
    xq.assign(R.n_vars, 0.0);
    for(int v = 0; v < R.n; ++v) {
      const C z = step.apply(uvq[v]);
      if(R.kind[v] == Free) {
        xq[R.var[v]] = z.real();
        xq[R.var[v] + 1] = z.imag();
      } else if(R.kind[v] == On_line) { // its Klein segment's parameter
        const C k = poincare_to_klein(z), d = k - R.line_k0[v];
        xq[R.var[v]] = (d.real() * R.line_D[v].real() + d.imag() * R.line_D[v].imag()) / squared_modulus(R.line_D[v]);
      }
    }
    Q = std::move(R);
    // the faces left, and two rings around them (marked at the owners of the variables)
    auto owner = [&](int v) { return owner_vertex(Q, v); };
    std::vector<char> region(Q.n, 0);
    for(std::size_t f = 0; f < Q.faces.size(); ++f)
      if(left.flag[f])
        for(int v : Q.faces[f])
          region[owner(v)] = 1;
    for(int ring = 0; ring < 2; ++ring) {
      std::vector<char> grown = region;
      for(const auto& f : Q.faces)
        if(region[owner(f[0])] || region[owner(f[1])] || region[owner(f[2])])
          for(int v : f)
            grown[owner(v)] = 1;
      region.swap(grown);
    }
    Solver_options opt = options;
    opt.max_iterations = (std::min)(opt.max_iterations, 50);
    Solver_statistics rs;
    minimize_energy_on_region(Q, xq, region, opt, rs);
    st.polishing_iterations += rs.iterations;
    st.cg_iterations += rs.cg_iterations;
    for(int v = 0; v < Q.n; ++v)
      uvq[v] = position(Q, xq, v);
    left = unresolved_faces(Q, uvq, tile.traits(), true);
    if(options.verbose)
      std::cerr << "  recentred " << round + 1 << " times: " << left.count
                << " faces not positive or below what double resolves (smallest edge " << left.smallest << ")"
                << std::endl;
    idle = left.count < best ? 0 : idle + 1;
    best = (std::min)(best, left.count);
  }
  if(xq.empty())
    return;
  certify(Q, moved, xq, uvq, st);
  repair(Q, moved, xq, uvq, st);
  if(st.certificate.is_bijective()) {
    uv.swap(uvq);
    st.recentred = true;
    st.frame = frame;
  } else {
    st.certificate = canonical;
  }
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_RECENTRING_H
