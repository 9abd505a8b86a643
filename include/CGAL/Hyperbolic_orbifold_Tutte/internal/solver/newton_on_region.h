// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_NEWTON_ON_REGION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_NEWTON_ON_REGION_H

#include <CGAL/disable_warnings.h>

/// \file newton_on_region.h
// Newton on a region of the flat problem only, the rest held fixed.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/solver_doors.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// Newton on a region only: the vertices whose variables' owner is marked in `region`
// move, their neighbours stay where they are. The region's energy, gradient and linear
// solves are then at the region's own scale, which the whole problem's cannot see: a
// squeezed part of the embedding (a long protrusion without landmarks, 1e-20 across and
// shrinking along it) has forces 1e-20 times the largest ones, below the rounding of any
// global quantity. Returns the region's solver status.
inline Error_code minimize_energy_on_region(const Flat_problem& P, std::vector<double>& x, const std::vector<char>& region,
                                            const Solver_options& opt, Solver_statistics& st)
{
  auto moving = [&](int v) { return P.kind[v] != Fixed && region[owner_vertex(P, v)]; };
  // the region's vertices and their neighbours, in a problem of their own
  std::vector<int> local(P.n, -1), global;
  auto add = [&](int v) {
    if(local[v] < 0) {
      local[v] = static_cast<int>(global.size());
      global.push_back(v);
    }
  };
  Flat_problem Q;
  for(std::size_t e = 0; e < P.edges.size(); ++e) {
    const int a = P.edges[e][0], b = P.edges[e][1];
    if(!moving(a) && !moving(b))
      continue;
    add(a);
    add(b);
    if(P.kind[a] == Transformed) add(P.twin[a]);
    if(P.kind[b] == Transformed) add(P.twin[b]);
    Q.edges.push_back({a, b});
    Q.edge_weight.push_back(P.edge_weight[e]);
  }
  if(global.empty())
    return OK;
  for(auto& e : Q.edges)
    e = {local[e[0]], local[e[1]]};
  Q.type = P.type;
  Q.k = P.k;
  Q.n = static_cast<int>(global.size());
  Q.kind.assign(Q.n, Fixed);
  Q.var.assign(Q.n, -1);
  Q.twin.assign(Q.n, -1);
  Q.transform.assign(Q.n, Flat_problem::Isometry());
  Q.fixed.assign(Q.n, Flat_problem::C());
  Q.line_k0.assign(Q.n, Flat_problem::C());
  Q.line_D.assign(Q.n, Flat_problem::C());
  std::vector<double> xq;
  for(int i = 0; i < Q.n; ++i) { // variables of the owners first (a twin's index is needed below)
    const int v = global[i];
    if(!moving(v) || P.kind[v] == Transformed) {
      if(!moving(v))
        Q.fixed[i] = position(P, x, v);
      continue;
    }
    Q.kind[i] = P.kind[v];
    Q.var[i] = static_cast<int>(xq.size());
    xq.push_back(x[P.var[v]]);
    if(P.kind[v] == Free)
      xq.push_back(x[P.var[v] + 1]);
    else {
      Q.line_k0[i] = P.line_k0[v];
      Q.line_D[i] = P.line_D[v];
    }
  }
  for(int i = 0; i < Q.n; ++i) {
    const int v = global[i];
    if(moving(v) && P.kind[v] == Transformed) {
      Q.kind[i] = Transformed;
      Q.twin[i] = local[P.twin[v]];
      Q.transform[i] = P.transform[v];
    }
  }
  Q.n_vars = static_cast<int>(xq.size());
  Solver_options region_options = opt;
  region_options.single_precision_small_preconditioner = false; // (see Solver_options)
  const Error_code ec = minimize_energy(Q, xq, region_options, st);
  for(int i = 0; i < Q.n; ++i) {
    const int v = global[i];
    if(Q.kind[i] == Free) {
      x[P.var[v]] = xq[Q.var[i]];
      x[P.var[v] + 1] = xq[Q.var[i] + 1];
    } else if(Q.kind[i] == On_line) {
      x[P.var[v]] = xq[Q.var[i]];
    }
  }
  return ec;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_SOLVER_NEWTON_ON_REGION_H
