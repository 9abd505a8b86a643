// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SURFACE_MAPS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SURFACE_MAPS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/cut_graph.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/point_location.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <map>
#include <memory>
#include <vector>

/// \file surface_maps.h
/// Maps between surfaces embedded into one orbifold (paper, section 7).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/// \ingroup PkgHyperbolicOrbifoldTutteMainClasses
/// how barycentric coordinates in a face of an embedding are defined:
/// `Hyperboloid_linear` (default: invariant under the orbifold group, so maps are seamless
/// across the cut) or `Klein_linear` (affine in the Klein model of the mesh's own copy)
using internal::Interpolation_model;
using internal::Hyperboloid_linear;
using internal::Klein_linear;

/// \ingroup PkgHyperbolicOrbifoldTutteMainClasses
/// exact point location in the embedding of a mesh `B` given as a per-corner map (the
/// output of `hyperbolic_orbifold_Tutte_embedding()`): `locate(z)` returns, for any point `z`
/// of the Poincar&eacute; disk, the face of `B` and the barycentric coordinates of the copy
/// `g(z)` of `z` under the orbifold group that lies in that face's triangle, and `g`. It
/// never gives up on a bijective embedding (a straight walk through `B`'s triangles and their
/// images, with an exhaustive best-first search as a safety net).
template <class TriangleMesh, class HalfedgeUVMap>
using Embedding_locator = internal::Embedding_point_locator<TriangleMesh, HalfedgeUVMap>;

/// \ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
/// the vertex map: for every vertex of `A`, its location on `B` (face and barycentric coordinates)
using internal::map_vertices;
/// \ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
/// the sparse matrix `T` (rows: vertices of `A`, columns: vertices of `B`) with `attr_A = T * attr_B`
using internal::transfer_matrix;
/// \ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
/// transfers a vertex property map of `B` to `A` through a vertex map
using internal::transfer_vertex_property;
/// \ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
/// the 3D point of `B` at a location
using internal::surface_point;

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

a collection of meshes with corresponding landmarks (landmark `i` of every mesh is the
same feature), embedded into one hyperbolic orbifold with one cone order, so that maps
between any two of them are bijective, seamless, interpolate the landmarks and are
cycle consistent (the paper's section 7).

Landmarks may be given in a class-wide order: the collection orders them once (the
paper's tour on the first mesh, for sphere-type meshes) and uses that order for all.
Embeddings are computed by `embed()`, in parallel with `ConcurrencyTag = CGAL::Parallel_tag`
when CGAL is linked with TBB (the results do not depend on the number of threads); maps
are computed on demand and cached.

\tparam TriangleMesh `CGAL::Surface_mesh` (the embeddings are stored in its property maps)
\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
*/
template <class TriangleMesh, class ConcurrencyTag = CGAL::Sequential_tag>
class Orbifold_collection
{
public:
  /// vertex of a mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// halfedge of a mesh
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  /// the meshes' vertex point map
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type Vertex_point_map;
  /// the kernel of the meshes' points
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<Vertex_point_map>::value_type>::Kernel Kernel;
  /// the per-corner Poincar&eacute; map of each mesh
  typedef typename TriangleMesh::template Property_map<halfedge_descriptor, typename Kernel::Point_2> UV_map;
  /// the locator of each embedding
  typedef Embedding_locator<TriangleMesh, UV_map> Locator;
  /// a location on a mesh
  typedef typename Locator::Location Location;

  /// adds a mesh (copied) with its landmarks in the class-wide order; returns its index
  std::size_t add_mesh(const TriangleMesh& mesh, const std::vector<vertex_descriptor>& landmarks)
  {
    Item it;
    it.mesh.reset(new TriangleMesh(mesh));
    it.landmarks = landmarks;
    items_.push_back(std::move(it));
    return items_.size() - 1;
  }

  /// the number of meshes
  std::size_t number_of_meshes() const { return items_.size(); }
  /// mesh `i` (the collection's copy, which holds the embedding's property map)
  const TriangleMesh& mesh(std::size_t i) const { return *items_[i].mesh; }
  /// the embedding of mesh `i` (valid after `embed()` returned `OK`)
  const UV_map& uv_map(std::size_t i) const { return items_[i].uv; }
  /// the statistics and certificate of the embedding of mesh `i`
  const Embedding_statistics& statistics(std::size_t i) const { return items_[i].stats; }
  /// the cone order used: landmark `order()[c]` of every mesh is at cone `c`
  const std::vector<std::size_t>& order() const { return order_; }
  /// the one-line reason of the last failure
  const std::string& message() const { return message_; }

  /// embeds every mesh; returns `OK` or the first failure (see `message()`)
  Error_code embed()
  {
    const std::size_t N = items_.size();
    if(N == 0) { message_ = "the collection is empty"; return ERROR_WRONG_PARAMETER; }
    const std::size_t k = items_[0].landmarks.size();
    Orbifold_type type = Sphere_type;
    if(!internal::detect_orbifold_type(*items_[0].mesh, type)) { message_ = "mesh 0 is neither closed nor a disk"; return ERROR_WRONG_TOPOLOGY; }
    for(std::size_t i = 0; i < N; ++i) {
      Orbifold_type t;
      if(items_[i].landmarks.size() != k || !internal::detect_orbifold_type(*items_[i].mesh, t) || t != type) {
        message_ = "mesh " + std::to_string(i) + " differs from mesh 0 in topology or number of landmarks";
        return ERROR_WRONG_PARAMETER;
      }
    }
    type_ = type;
    order_.resize(k);
    for(std::size_t c = 0; c < k; ++c) order_[c] = c;
    if(type == Sphere_type) {
      const internal::Check_result r = internal::check_landmark_vertices(*items_[0].mesh, items_[0].landmarks, type);
      if(!r) { message_ = "mesh 0: " + r.message; return r.code; }
      order_ = internal::compute_tsp_landmark_order(*items_[0].mesh, items_[0].landmarks, get(CGAL::vertex_point, *items_[0].mesh));
      if(order_.size() != k) { message_ = "the landmark tour could not be computed on mesh 0"; return ERROR_CUT_FAILED; }
    }
    std::vector<Error_code> codes(N, OK);
    auto run = [&](std::size_t i) {
      Item& it = items_[i];
      std::vector<vertex_descriptor> ordered;
      for(std::size_t c : order_) ordered.push_back(it.landmarks[c]);
      it.uv = it.mesh->template add_property_map<halfedge_descriptor, typename Kernel::Point_2>("h:hot_uv").first;
      codes[i] = hyperbolic_orbifold_Tutte_embedding(*it.mesh, ordered, it.uv,
                                                     parameters::orbifold_type(type, parameters::embedding_statistics(&it.stats)));
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value)
      tbb::parallel_for(std::size_t(0), N, [&](std::size_t i) { run(i); });
    else
#endif
      for(std::size_t i = 0; i < N; ++i) run(i);
    for(std::size_t i = 0; i < N; ++i)
      if(codes[i] != OK) { message_ = "mesh " + std::to_string(i) + ": " + items_[i].stats.message; return codes[i]; }
    for(std::size_t i = 1; i < N; ++i)
      if(items_[i].stats.landmark_order_reversed != items_[0].stats.landmark_order_reversed) {
        message_ = "mesh " + std::to_string(i) + ": its landmarks run around the boundary the other way than mesh 0's";
        return ERROR_WRONG_PARAMETER;
      }
    locators_.clear();
    maps_.clear();
    embedded_ = true;
    return OK;
  }

  /// the locator of mesh `i` (built on first use)
  const Locator& locator(std::size_t i)
  {
    auto it = locators_.find(i);
    if(it == locators_.end())
      it = locators_.emplace(i, std::unique_ptr<Locator>(new Locator(*items_[i].mesh, items_[i].uv, type_,
                                                                   static_cast<int>(order_.size())))).first;
    return *it->second;
  }

  /// the map from mesh `a` to mesh `b`: one location on `b` per vertex of `a` (cached)
  /// \pre `embed()` returned `OK`
  const std::vector<Location>& map(std::size_t a, std::size_t b)
  {
    auto it = maps_.find(std::make_pair(a, b));
    if(it == maps_.end())
      it = maps_.emplace(std::make_pair(a, b), map_vertices(*items_[a].mesh, items_[a].uv, locator(b))).first;
    return it->second;
  }

  /// computes the maps between all ordered pairs of distinct meshes (and every locator), in
  /// parallel with `CGAL::Parallel_tag`; afterwards `map()` only reads its cache. The maps are
  /// the same, bit for bit, whatever the number of threads.
  /// \pre `embed()` returned `OK`
  void compute_all_maps()
  {
    const std::size_t N = items_.size();
    std::vector<std::unique_ptr<Locator> > locs(N);
    std::vector<std::pair<std::size_t, std::size_t> > pairs;
    for(std::size_t a = 0; a < N; ++a)
      for(std::size_t b = 0; b < N; ++b)
        if(a != b && maps_.find(std::make_pair(a, b)) == maps_.end())
          pairs.emplace_back(a, b);
    std::vector<std::vector<Location> > results(pairs.size());
    auto build = [&](std::size_t i) {
      if(locators_.find(i) == locators_.end())
        locs[i].reset(new Locator(*items_[i].mesh, items_[i].uv, type_, static_cast<int>(order_.size())));
    };
    auto locator_of = [&](std::size_t i) -> const Locator& {
      return locs[i] ? *locs[i] : *locators_.find(i)->second;
    };
    auto run = [&](std::size_t p) {
      results[p] = map_vertices(*items_[pairs[p].first].mesh, items_[pairs[p].first].uv, locator_of(pairs[p].second));
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value) {
      tbb::parallel_for(std::size_t(0), N, [&](std::size_t i) { build(i); });
      tbb::parallel_for(std::size_t(0), pairs.size(), [&](std::size_t p) { run(p); });
    } else
#endif
    {
      for(std::size_t i = 0; i < N; ++i) build(i);
      for(std::size_t p = 0; p < pairs.size(); ++p) run(p);
    }
    for(std::size_t i = 0; i < N; ++i)
      if(locs[i]) locators_.emplace(i, std::move(locs[i]));
    for(std::size_t p = 0; p < pairs.size(); ++p)
      maps_.emplace(pairs[p], std::move(results[p]));
  }

  /// the largest distance, over the vertices `x` of `a`, between `f_bc(f_ab(x))` and `f_ac(x)` on
  /// mesh `c`, relative to `c`'s bounding-box diagonal (0 up to rounding: the maps are cycle consistent)
  double cycle_consistency_error(std::size_t a, std::size_t b, std::size_t c)
  {
    const std::vector<Location>& fab = map(a, b);
    const std::vector<Location>& fac = map(a, c);
    const Locator& lb = locator(b);
    const Locator& lc = locator(c);
    const CGAL::Bbox_3 bb = CGAL::Polygon_mesh_processing::bbox(*items_[c].mesh);
    const double diag = std::sqrt(CGAL::square(bb.xmax() - bb.xmin()) + CGAL::square(bb.ymax() - bb.ymin()) +
                                  CGAL::square(bb.zmax() - bb.zmin()));
    double worst = 0;
    for(std::size_t v = 0; v < fab.size(); ++v) {
      if(!fab[v].success || !fac[v].success) return std::numeric_limits<double>::infinity();
      const Location l = lc.locate(lb.disk_point(fab[v]));
      if(!l.success) return std::numeric_limits<double>::infinity();
      const auto p = surface_point(l, lc, get(CGAL::vertex_point, *items_[c].mesh));
      const auto q = surface_point(fac[v], lc, get(CGAL::vertex_point, *items_[c].mesh));
      worst = std::max(worst, std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q))) / diag);
    }
    return worst;
  }

private:
  struct Item
  {
    std::unique_ptr<TriangleMesh> mesh;
    std::vector<vertex_descriptor> landmarks;
    UV_map uv;
    Embedding_statistics stats;
  };
  std::vector<Item> items_;
  std::vector<std::size_t> order_;
  Orbifold_type type_ = Sphere_type;
  bool embedded_ = false;
  std::string message_;
  std::map<std::size_t, std::unique_ptr<Locator> > locators_;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<Location> > maps_;
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_SURFACE_MAPS_H
