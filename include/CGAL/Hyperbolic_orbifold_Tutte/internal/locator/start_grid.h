// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_START_GRID_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_START_GRID_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// The point locator's start triangles: a uniform grid over the bounding box of the faces'
// Klein centroids, built in linear time. In each cell the good face (one whose centroid is
// strictly inside it) whose centroid is nearest to the cell's centre; empty cells take a
// neighbour's face (multi-source breadth-first fill).
class Start_grid
{
public:
  typedef std::complex<double> C;

  // the grid over the centroids of the faces marked good (n_good of them, in the box
  // [xmin, xmax] x [ymin, ymax])
  void build(const std::vector<C>& centroids, const std::vector<char>& good, std::size_t n_good,
             double xmin, double xmax, double ymin, double ymax)
  {
    n_ = (std::max)(1, static_cast<int>(std::sqrt(static_cast<double>(n_good) / 2.0)));
    x0_ = xmin;
    y0_ = ymin;
    cw_ = (std::max)((xmax - xmin), 1e-300) / n_;
    ch_ = (std::max)((ymax - ymin), 1e-300) / n_;
    const std::size_t nc = static_cast<std::size_t>(n_) * n_;
    cells_.assign(nc, -1);
    std::vector<double> best(nc, std::numeric_limits<double>::infinity());
    for(std::size_t fi = 0; fi < centroids.size(); ++fi) {
      if(!good[fi])
        continue;
      const C& c = centroids[fi];
      const int cx = cell_x(c.real()), cy = cell_y(c.imag());
      const std::size_t id = static_cast<std::size_t>(cy) * n_ + cx;
      const double dx = c.real() - (x0_ + (cx + 0.5) * cw_), dy = c.imag() - (y0_ + (cy + 0.5) * ch_);
      const double d = dx * dx + dy * dy;
      if(d < best[id]) {
        best[id] = d;
        cells_[id] = static_cast<int>(fi);
      }
    }
    fill_empty_cells();
  }

  // the start face for a query point q
  int start_face(const C& q) const { return cells_[static_cast<std::size_t>(cell_y(q.imag())) * n_ + cell_x(q.real())]; }

private:
  void fill_empty_cells()
  {
    const std::size_t nc = cells_.size();
    std::vector<std::size_t> queue;
    queue.reserve(nc);
    for(std::size_t id = 0; id < nc; ++id)
      if(cells_[id] >= 0)
        queue.push_back(id);
    for(std::size_t qi = 0; qi < queue.size(); ++qi) {
      const std::size_t id = queue[qi];
      const int cx = static_cast<int>(id % n_), cy = static_cast<int>(id / n_);
      const int nx[4] = {cx - 1, cx + 1, cx, cx};
      const int ny[4] = {cy, cy, cy - 1, cy + 1};
      for(int d = 0; d < 4; ++d) {
        if(nx[d] < 0 || ny[d] < 0 || nx[d] >= n_ || ny[d] >= n_)
          continue;
        const std::size_t nid = static_cast<std::size_t>(ny[d]) * n_ + nx[d];
        if(cells_[nid] < 0) {
          cells_[nid] = cells_[id];
          queue.push_back(nid);
        }
      }
    }
  }

  int cell_x(double x) const
  {
    const double t = (x - x0_) / cw_;
    return t <= 0 ? 0 : (t >= n_ - 1 ? n_ - 1 : static_cast<int>(t));
  }
  int cell_y(double y) const
  {
    const double t = (y - y0_) / ch_;
    return t <= 0 ? 0 : (t >= n_ - 1 ? n_ - 1 : static_cast<int>(t));
  }

  std::vector<int> cells_;
  int n_ = 1;
  double x0_ = 0, y0_ = 0, cw_ = 1, ch_ = 1;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_START_GRID_H
