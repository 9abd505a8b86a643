// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_HANDLE_LOOPS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_HANDLE_LOOPS_H

// Short non-separating loops of a closed triangle mesh of genus g >= 1, and the cut along one
// (the preparation's removal of handles: topological noise of scans, such as an arm touching
// the body). A loop is a simple cycle of edges.
//
// From a root r: the tree T of shortest paths (Dijkstra, edge lengths), then a spanning tree
// C of the dual graph among the edges not in T, of maximum weight, the weight of an edge uv
// being the length of its loop d(u) + |uv| + d(v) (Kruskal). The 2g edges in neither tree
// each close a loop (the tree paths from their ends to their lowest common ancestor, and the
// edge) whose classes form a basis of the first homology group (Eppstein's tree-cotree
// decomposition; with these weights the greedy system of Erickson and Whittlesey): every one
// of them is non-zero in homology with Z/2 coefficients, so it does not separate the surface.
// The shortest of them is the answer from r; the shortest non-separating cycle is found from
// a root on it (Erickson and Har-Peled), so the roots are spread by farthest-point sampling
// and then taken on the best loop found.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {
namespace handles {

template <class Mesh>
struct Loop
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> cycle; // consecutive vertices joined by edges, closed
  double length = HUGE_VAL;
};

// the handle loops' search on one closed mesh (vertex and edge indices dense: no garbage)
template <class Mesh>
class Loop_finder
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  static constexpr std::size_t npos = std::size_t(-1);

public:
  // `avoided` (per vertex in vertices() order, optional): the edges at these vertices count a
  // million times their length, so that a loop goes through them only if no other does
  explicit Loop_finder(const Mesh& m, const std::vector<char>& avoided = std::vector<char>())
    : m_(m), verts_(vertices(m).begin(), vertices(m).end()), nv_(verts_.size())
  {
    for(auto e : edges(m)) {
      const halfedge_descriptor h = halfedge(e, m);
      edge_h_.push_back(h);
      double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(source(h, m)), m.point(target(h, m)))));
      if(!avoided.empty() && (avoided[source(h, m).idx()] || avoided[target(h, m).idx()])) l *= 1e6;
      edge_length_.push_back(l);
    }
  }

  // The shortest loop found: from the roots of farthest-point sampling (`roots`), from the
  // vertices of the 2g loops of the first root's system (the shortest non-separating cycle C
  // crosses one of them, so shares a vertex with it: a root there finds C), then from the
  // vertices of the best loop; at most `budget` edge visits in all (the roots on the system's
  // loops are spread evenly over them when they are too many). An empty cycle: genus 0.
  Loop<Mesh> shortest(std::size_t roots = 8, double budget = 2e7) const
  {
    Loop<Mesh> best;
    if(nv_ == 0) return best;
    const std::size_t per_root = (std::max)(std::size_t(1), edge_h_.size());
    std::size_t left = (std::max)(std::size_t(4 * roots), static_cast<std::size_t>(budget / static_cast<double>(per_root)));
    std::vector<char> done(nv_, 0);
    std::vector<double> nearest(nv_, HUGE_VAL); // (farthest-point sampling)
    auto from = [&](std::size_t r, std::vector<Loop<Mesh> >* system, bool sampling = false) {
      if(done[r] || left == 0) return;
      done[r] = 1;
      --left;
      std::vector<double> dist;
      std::vector<std::size_t> parent;
      tree(r, dist, parent);
      if(sampling)
        for(std::size_t i = 0; i < nv_; ++i) nearest[i] = (std::min)(nearest[i], dist[i]);
      std::vector<Loop<Mesh> > loops = loops_from(dist, parent, system != nullptr);
      if(!loops.empty() && loops.front().length < best.length) best = loops.front();
      if(system) *system = std::move(loops);
    };
    // the first root's system, then farthest-point samples
    std::vector<Loop<Mesh> > system;
    from(0, &system, true);
    if(best.cycle.empty()) return best; // genus 0
    for(std::size_t k = 1; k < roots && k < nv_; ++k) {
      const std::size_t r = static_cast<std::size_t>(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
      if(!(nearest[r] > 0)) break;
      from(r, nullptr, true);
    }
    // the vertices of the system's loops, spread evenly within the budget (half of what is left)
    std::vector<std::size_t> crossing;
    for(const Loop<Mesh>& l : system)
      for(vertex_descriptor v : l.cycle) crossing.push_back(static_cast<std::size_t>(v.idx()));
    const std::size_t take = (std::min)(crossing.size(), (std::max)(std::size_t(1), left / 2));
    for(std::size_t k = 0; k < take; ++k) from(crossing[k * crossing.size() / take], nullptr);
    // the best loop's vertices, until the budget is spent
    for(bool improved = true; improved && left > 0;) {
      const double before = best.length;
      const std::vector<vertex_descriptor> on = best.cycle;
      for(vertex_descriptor v : on) from(static_cast<std::size_t>(v.idx()), nullptr);
      improved = best.length < before;
    }
    return best;
  }

private:
  // shortest paths from root: distances and, per vertex, the edge to its parent (npos: root)
  void tree(std::size_t root, std::vector<double>& dist, std::vector<std::size_t>& parent) const
  {
    dist.assign(nv_, HUGE_VAL);
    parent.assign(nv_, npos);
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > q;
    dist[root] = 0;
    q.emplace(0.0, root);
    while(!q.empty()) {
      const Item it = q.top();
      q.pop();
      if(it.first > dist[it.second]) continue;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(verts_[it.second], m_), m_)) {
        const std::size_t u = source(h, m_).idx(), e = edge(h, m_).idx();
        const double d = it.first + edge_length_[e];
        if(d < dist[u]) {
          dist[u] = d;
          parent[u] = e;
          q.emplace(d, u);
        }
      }
    }
  }

  std::size_t other_end(std::size_t e, std::size_t v) const
  {
    const halfedge_descriptor h = edge_h_[e];
    const std::size_t a = source(h, m_).idx();
    return a == v ? static_cast<std::size_t>(target(h, m_).idx()) : a;
  }

  // the loops of the tree-cotree system of this tree, shortest first (all 2g of them, or the
  // shortest only)
  std::vector<Loop<Mesh> > loops_from(const std::vector<double>& dist, const std::vector<std::size_t>& parent, bool all) const
  {
    const std::size_t ne = edge_h_.size();
    std::vector<char> in_tree(ne, 0);
    for(std::size_t v = 0; v < nv_; ++v)
      if(parent[v] != npos) in_tree[parent[v]] = 1;
    auto loop_length = [&](std::size_t e) {
      const halfedge_descriptor h = edge_h_[e];
      return dist[source(h, m_).idx()] + edge_length_[e] + dist[target(h, m_).idx()];
    };
    std::vector<std::size_t> others;
    for(std::size_t e = 0; e < ne; ++e)
      if(!in_tree[e] && std::isfinite(loop_length(e))) others.push_back(e);
    std::sort(others.begin(), others.end(), [&](std::size_t a, std::size_t b) { return loop_length(a) > loop_length(b); });
    // the dual spanning tree of maximum weight (Kruskal on the faces); the edges it leaves out
    std::vector<std::size_t> uf(num_faces(m_));
    std::iota(uf.begin(), uf.end(), std::size_t(0));
    auto find = [&uf](std::size_t x) {
      while(uf[x] != x) x = uf[x] = uf[uf[x]];
      return x;
    };
    std::vector<std::size_t> handle_edges;
    for(std::size_t e : others) {
      const halfedge_descriptor h = edge_h_[e];
      const std::size_t a = find(face(h, m_).idx()), b = find(face(opposite(h, m_), m_).idx());
      if(a != b) uf[a] = b; // in the cotree
      else handle_edges.push_back(e);
    }
    std::vector<Loop<Mesh> > r;
    for(std::size_t e : handle_edges) r.push_back(cycle_of(e, dist, parent, loop_length(e)));
    std::sort(r.begin(), r.end(), [](const Loop<Mesh>& a, const Loop<Mesh>& b) { return a.length < b.length; });
    if(!all && r.size() > 1) r.resize(1);
    return r;
  }

  // the cycle of a non-tree edge: from its source up to the lowest common ancestor of its ends
  // and down to its target
  Loop<Mesh> cycle_of(std::size_t e, const std::vector<double>& dist, const std::vector<std::size_t>& parent, double lasso) const
  {
    Loop<Mesh> r;
    const halfedge_descriptor h = edge_h_[e];
    std::vector<std::size_t> up_u, up_v;
    for(std::size_t x = source(h, m_).idx(); ; x = other_end(parent[x], x)) { up_u.push_back(x); if(parent[x] == npos) break; }
    for(std::size_t x = target(h, m_).idx(); ; x = other_end(parent[x], x)) { up_v.push_back(x); if(parent[x] == npos) break; }
    while(up_u.size() >= 2 && up_v.size() >= 2 && up_u[up_u.size() - 2] == up_v[up_v.size() - 2]) { // above the ancestor
      up_u.pop_back();
      up_v.pop_back();
    }
    for(std::size_t x : up_u) r.cycle.push_back(verts_[x]);              // u .. ancestor
    for(std::size_t i = up_v.size() - 1; i-- > 0;) r.cycle.push_back(verts_[up_v[i]]); // .. v (closed by v -> u)
    r.length = lasso - 2 * dist[up_u.back()];
    return r;
  }

  const Mesh& m_;
  std::vector<vertex_descriptor> verts_;
  std::size_t nv_;
  std::vector<halfedge_descriptor> edge_h_;
  std::vector<double> edge_length_;
};

// The cut of a closed mesh along a loop: per face corner (3 per face, in faces() order and
// halfedges_around_face(halfedge(f)) order) whether it moves to the copy of its loop vertex.
// A corner moves when its face lies on the left of the loop at that vertex (between the
// incoming and the outgoing loop edge, turning around the vertex).
template <class Mesh>
std::vector<char> left_corners(const Mesh& m, const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& cycle,
                               bool& ok)
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  std::vector<char> moved(3 * num_faces(m), 0);
  ok = cycle.size() >= 3;
  const std::size_t k = cycle.size();
  std::vector<std::pair<face_descriptor, std::size_t> > left; // (face, vertex index) pairs
  for(std::size_t i = 0; ok && i < k; ++i) {
    const auto in = halfedge(cycle[(i + k - 1) % k], cycle[i], m);
    const auto out = halfedge(cycle[i], cycle[(i + 1) % k], m);
    if(!in.second || !out.second) { ok = false; break; }
    halfedge_descriptor g = in.first; // target cycle[i]; its face is on the left of the loop
    for(std::size_t guard = 0;; ++guard) {
      if(is_border(g, m) || guard > num_halfedges(m)) { ok = false; break; }
      left.emplace_back(face(g, m), static_cast<std::size_t>(cycle[i].idx()));
      if(next(g, m) == out.first) break;
      g = opposite(next(g, m), m); // the next face around cycle[i], turning towards `out`
    }
  }
  if(!ok) return moved;
  std::vector<std::size_t> position(num_faces(m) + m.number_of_removed_faces(), 0);
  std::size_t j = 0;
  for(face_descriptor f : faces(m)) position[f.idx()] = j++;
  for(const auto& fv : left) {
    std::size_t c = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(fv.first, m), m)) {
      if(static_cast<std::size_t>(target(h, m).idx()) == fv.second) moved[3 * position[fv.first.idx()] + c] = 1;
      ++c;
    }
  }
  return moved;
}

} // namespace handles
} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PREPARATION_HANDLE_LOOPS_H
