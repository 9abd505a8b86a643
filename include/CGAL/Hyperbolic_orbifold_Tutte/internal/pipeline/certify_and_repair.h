// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CERTIFY_AND_REPAIR_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CERTIFY_AND_REPAIR_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/solver/orbifold_solver.h>

#include <vector>

// The pipeline's last stage on the solver's coordinates: the certificate, and the mends
// tried when it fails on flipped or flat faces only (the paper's one-ring repair, then a
// valid position a few ulps away).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the certificate of the coordinates xq (written to uvq)
template <class Tile>
void certify(const Flat_problem& Q, const Tile& T, const std::vector<double>& xq, std::vector<std::complex<double> >& uvq,
             Embedding_statistics& st)
{
  for(int v = 0; v < Q.n; ++v)
    uvq[v] = position(Q, xq, v);
  st.certificate = certify_flat(Q, T, uvq);
}

// the certificate fails on flipped or flat faces only
inline bool flipped_only(const Embedding_statistics& st)
{
  return !st.certificate.is_bijective() && st.certificate.points_outside_disk == 0 &&
         (st.certificate.flipped_faces > 0 || st.certificate.degenerate_faces > 0);
}

// the paper's one-ring repair for vertices left outside the hull of their neighbours,
// then (at the resolution of double) a valid position a few ulps away
template <class Tile>
void repair(const Flat_problem& Q, const Tile& T, std::vector<double>& xq, std::vector<std::complex<double> >& uvq,
            Embedding_statistics& st)
{
  if(!flipped_only(st))
    return;
  st.repaired_vertices += repair_one_rings(Q, xq, T.traits());
  certify(Q, T, xq, uvq, st);
  if(flipped_only(st)) {
    st.repaired_vertices += snap_one_rings(Q, xq, T.traits());
    certify(Q, T, xq, uvq, st);
  }
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_CERTIFY_AND_REPAIR_H
