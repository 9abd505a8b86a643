// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_COLLECTION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_COLLECTION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/maps/collection_support.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/input_stage.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/refine_orbifold_map.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/dense_index.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

/// \file Orbifold_collection.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

a collection of meshes with corresponding landmarks (landmark `i` of every mesh is the
same feature), embedded into one hyperbolic orbifold with one cone order, so that maps
between any two of them are bijective, seamless, interpolate the landmarks and are
cycle consistent (the paper's section 7).

Landmarks may be given in a class-wide order: the collection orders them once and uses that
order for all meshes. Sphere-type meshes are cut through the landmarks in the order of one of
the meshes' tours (the paper's section 7, `compute_landmark_tour()`): the tour whose cut is the
least longer than each mesh's own best, on the mesh where it is the most so
(`rank_landmark_tours()`; mesh 0's on ties). A tour that is short on one mesh can run back and
forth on another and squeeze its embedding below what double resolves; so when a mesh's
embedding is refused for a reason the order may cause (`is_landmark_order_failure()`), every
mesh is embedded again in the next candidate's order, and `embed()` fails only when no
candidate works (`order_attempts()` says which orders were tried and why each failed).
`set_landmark_order_choice()` restores the tour of mesh 0 alone, or the given order. Disk-type
meshes keep the given order (their landmarks follow the boundary).
Embeddings are computed by `embed()`, in parallel with `ConcurrencyTag = CGAL::Parallel_tag`
when CGAL is linked with TBB (the results do not depend on the number of threads); maps
are computed on demand and cached, or in parallel by `compute_maps()` and `compute_all_maps()`.
An optional progress callback is told of every mesh embedded and every pair mapped.

\tparam TriangleMesh a model of `FaceGraph` with triangular faces, copy constructible
        (e.g. `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`); the embeddings are stored in
        dynamic halfedge property maps (`CGAL::dynamic_halfedge_property_t`) of the
        collection's copies of the meshes
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
  /// a point of the Poincar&eacute; disk
  typedef typename Kernel::Point_2 Point_2;
  /// the per-corner Poincar&eacute; map of each mesh (a dynamic halfedge property map of the mesh)
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<Point_2> >::type UV_map;
  /// the per-corner chart points of each mesh (a dynamic halfedge property map; see `Chart_point`)
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<Chart_point<Point_2> > >::type Chart_map;
  /// the locator of each embedding
  typedef Embedding_locator<TriangleMesh, UV_map> Locator;
  /// the embedding of each mesh as a result object (`embedding()`)
  typedef Orbifold_embedding<TriangleMesh, UV_map, Chart_map> Embedding;
  /// a location on a mesh
  typedef typename Locator::Location Location;

  /// what the progress callback is told: a mesh embedded or a pair mapped
  struct Progress
  {
    /// the step that just ended
    enum Stage
    {
      Mesh_embedded, ///< mesh `source` was embedded (`code` tells how it went)
      Pair_mapped    ///< the map from mesh `source` to mesh `target` was computed
    };
    Stage stage;         ///< the step
    std::size_t done;    ///< the number of steps of this stage ended so far in this call (this one included)
    std::size_t total;   ///< the number of steps of this stage in this call
    std::size_t source;  ///< the mesh embedded, or the source of the map
    std::size_t target;  ///< the target of the map (the mesh itself for `Mesh_embedded`)
    double seconds;      ///< the step's wall-clock time
    Error_code code;     ///< `OK`, or the embedding's error
  };
  /// the progress callback: called from one thread at a time (the collection serialises the calls)
  typedef std::function<void(const Progress&)> Progress_callback;

  /// how `embed()` orders the landmarks of sphere-type meshes (disk type: always as given)
  enum Landmark_order_choice
  {
    Tour_of_any_mesh,   ///< (default) the meshes' tours, best first by `rank_landmark_tours()`, the next one tried when an embedding is refused
    Tour_of_first_mesh, ///< the tour of mesh 0 only (the paper's section 7), not another one when it is refused
    Given_landmark_order ///< the class-wide order as given
  };

  /// an order `embed()` tried, and how it went
  struct Order_attempt
  {
    std::vector<std::size_t> order;  ///< landmark `order[c]` of every mesh at cone `c`
    /// the mesh whose tour it is (the first one if several), or `number_of_meshes()` for the given order
    std::size_t mesh;
    double longest_ratio;            ///< see `Landmark_order_candidate` (1 for the given order)
    Error_code code;                 ///< `OK`, or the first failure
    std::string message;             ///< the first failure's reason, naming the mesh
  };

  /// adds a mesh (copied) with its landmarks in the class-wide order; returns its index
  std::size_t add_mesh(const TriangleMesh& mesh, const std::vector<vertex_descriptor>& landmarks)
  {
    Item it;
    it.mesh.reset(new TriangleMesh(mesh));
    // the copy lists its vertices in the original's order: a landmark is the copy's vertex
    // at the original's position
    const internal::Dense_index<vertex_descriptor> index(vertices(mesh));
    const std::vector<vertex_descriptor> copied(vertices(*it.mesh).begin(), vertices(*it.mesh).end());
    for(vertex_descriptor v : landmarks) {
      const std::size_t i = index(v);
      it.landmarks.push_back(i < copied.size() ? copied[i] : v);
    }
    items_.push_back(std::move(it));
    return items_.size() - 1;
  }

  /// the number of meshes
  std::size_t number_of_meshes() const { return items_.size(); }
  /// mesh `i` (the collection's copy, which holds the embedding's property map)
  const TriangleMesh& mesh(std::size_t i) const { return *items_[i].mesh; }
  /// the landmarks of mesh `i` (vertices of `mesh(i)`), in the class-wide order
  const std::vector<vertex_descriptor>& landmarks(std::size_t i) const { return items_[i].landmarks; }
  /// the embedding of mesh `i` (valid after `embed()` returned `OK`)
  const UV_map& uv_map(std::size_t i) const { return items_[i].uv; }
  /// the chart points of the embedding of mesh `i` (\ref HOT_Charts; `chart` -1 everywhere unless
  /// `statistics(i).charted_faces` is not 0, the charts being `statistics(i).charts`)
  const Chart_map& chart_map(std::size_t i) const { return items_[i].charts; }
  /// the statistics and certificate of the embedding of mesh `i`, with its timings
  const Embedding_statistics& statistics(std::size_t i) const { return items_[i].stats; }
  /// the embedding of mesh `i` as the library's result type: its coordinates, their layout and
  /// its landmarks in cone order, which the locator, the maps and the certificate take
  /// \pre `embed()` returned `OK`
  Embedding embedding(std::size_t i) const
  {
    const Item& it = items_[i];
    Embedding e(*it.mesh, it.uv, it.charts);
    e.layout() = it.stats;
    std::vector<vertex_descriptor> ordered;
    for(std::size_t c : order_) ordered.push_back(it.landmarks[c]);
    e.set_landmarks(ordered);
    e.set_valid();
    return e;
  }
  /// the cone order used: landmark `order()[c]` of every mesh is at cone `c`
  const std::vector<std::size_t>& order() const { return order_; }
  /// the orders `embed()` tried, in turn (the last one is `order()`); after a success the last
  /// one has code `OK`
  const std::vector<Order_attempt>& order_attempts() const { return attempts_; }
  /// sets how `embed()` orders the landmarks (default `Tour_of_any_mesh`); set before `embed()`
  void set_landmark_order_choice(Landmark_order_choice choice) { order_choice_ = choice; }
  /// how `embed()` orders the landmarks
  Landmark_order_choice landmark_order_choice() const { return order_choice_; }
  /// the one-line reason of the last failure
  const std::string& message() const { return message_; }
  /// the order \f$p\f$ of the cone of every landmark (cone angle \f$2\pi/p\f$), in the class-wide
  /// order of the landmarks, the same for every mesh (sphere type; default, or empty: 2 for
  /// every cone). Set before `embed()`. Maps join cones of equal orders only: they are the
  /// collection's.
  void set_cone_orders(const std::vector<int>& orders) { orders_ = orders; }
  /// the cone orders of `set_cone_orders()`
  const std::vector<int>& cone_orders() const { return orders_; }
  /// sets the progress callback (an empty function: none)
  void set_progress_callback(const Progress_callback& callback) { progress_ = callback; }

  /// embeds every mesh in one landmark order (see the class's description and
  /// `set_landmark_order_choice()`), trying the next candidate order when an embedding is
  /// refused for a reason the order may cause; returns `OK` or the failure (see `message()`:
  /// when several orders were tried, each of them and its first failure)
  Error_code embed()
  {
    Orbifold_type type = Sphere_type;
    Error_code ec = check_meshes(type);
    if(ec != OK)
      return ec;
    type_ = type;
    std::vector<Order_attempt> candidates;
    ec = compute_orders(candidates);
    if(ec != OK)
      return ec;
    attempts_.clear();
    for(const Order_attempt& c : candidates) {
      order_ = c.order;
      bool order_failure = false;
      ec = embed_all(order_failure);
      attempts_.push_back(c);
      attempts_.back().code = ec;
      attempts_.back().message = ec == OK ? std::string() : message_;
      if(ec == OK || !order_failure)
        break;
    }
    if(ec != OK && attempts_.size() > 1)
      message_ = attempts_message();
    if(ec != OK)
      return ec;
    locators_.clear();
    maps_.clear();
    map_seconds_.clear();
    refinement_.clear();
    embedded_ = true;
    return OK;
  }

  /// refines the embedding of every mesh but `reference` towards an isometric map onto
  /// `reference` (`refine_orbifold_map()`, at most `iterations` each, in parallel with
  /// `CGAL::Parallel_tag`). Each mesh keeps one embedding: the maps stay compositions through
  /// the one orbifold (cycle consistent), fitted to one metric. Drops the cached maps and the
  /// refined meshes' locators. Returns `OK` or the first failure (`message()`; a mesh embedded
  /// partly in charts is refused). \pre `embed()` returned `OK`
  Error_code refine(int iterations, std::size_t reference = 0)
  {
    const std::size_t N = items_.size();
    if(!embedded_ || reference >= N || iterations < 0) {
      message_ = !embedded_ ? "refine() needs the embeddings: call embed() first"
                 : reference >= N ? "the reference mesh " + std::to_string(reference) + " is not in the collection"
                                  : "the number of refinement iterations must be at least 0";
      return ERROR_WRONG_PARAMETER;
    }
    for(std::size_t i = 0; i < N; ++i)
      if(!items_[i].stats.charts.empty()) {
        message_ = "mesh " + std::to_string(i) + " is embedded partly in charts around cone images, which refine() does not handle";
        return ERROR_WRONG_PARAMETER;
      }
    const Locator& lr = locator(reference);
    refinement_.assign(N, Map_refinement_statistics());
    std::vector<Error_code> codes(N, OK);
    for_each_index(N, [&](std::size_t i) {
      if(i == reference)
        return;
      Item& it = items_[i];
      std::vector<vertex_descriptor> ordered;
      for(std::size_t c : order_) ordered.push_back(it.landmarks[c]);
      codes[i] = refine_orbifold_map(*it.mesh, ordered, it.uv, *items_[reference].mesh, lr, refinement_[i],
        parameters::refine(iterations, parameters::frame(it.stats.frame, parameters::cone_orders(ordered_orders(), parameters::orbifold_type(type_)))));
    });
    for(std::size_t i = 0; i < N; ++i)
      if(codes[i] != OK) {
        message_ = "mesh " + std::to_string(i) + ": " + refinement_[i].message;
        return codes[i];
      }
    for(auto it = locators_.begin(); it != locators_.end();)
      it = it->first == reference ? std::next(it) : locators_.erase(it);
    maps_.clear();
    map_seconds_.clear();
    return OK;
  }

  /// what `refine()` did to mesh `i` (`Refinement_not_run` for the reference, or before `refine()`)
  Map_refinement_statistics refinement_statistics(std::size_t i) const { return i < refinement_.size() ? refinement_[i] : Map_refinement_statistics(); }

  /// the locator of mesh `i` (built on first use)
  const Locator& locator(std::size_t i)
  {
    auto it = locators_.find(i);
    if(it == locators_.end())
      it = locators_.emplace(i, new_locator(i)).first;
    return *it->second;
  }

  /// the map from mesh `a` to mesh `b`: one location on `b` per vertex of `a` (cached)
  /// \pre `embed()` returned `OK`
  const std::vector<Location>& map(std::size_t a, std::size_t b)
  {
    const std::pair<std::size_t, std::size_t> ab(a, b);
    auto it = maps_.find(ab);
    if(it == maps_.end()) {
      const Locator& lb = locator(b);
      const Clock::time_point t0 = Clock::now();
      it = maps_.emplace(ab, map_vertices(embedding(a), lb)).first;
      map_seconds_[ab] = seconds_since(t0);
      Reporter report(progress_, 1);
      report(Progress::Pair_mapped, a, b, map_seconds_[ab], OK);
    }
    return it->second;
  }

  /// the wall-clock seconds spent computing the map from mesh `a` to mesh `b` (0 if not computed)
  double map_seconds(std::size_t a, std::size_t b) const
  {
    auto it = map_seconds_.find(std::make_pair(a, b));
    return it == map_seconds_.end() ? 0.0 : it->second;
  }

  /// computes the maps of the given ordered pairs of distinct meshes (and the locators they
  /// need), in parallel with `CGAL::Parallel_tag`; afterwards `map()` only reads its cache for
  /// them. The maps are the same, bit for bit, whatever the number of threads.
  /// \pre `embed()` returned `OK`
  void compute_maps(const std::vector<std::pair<std::size_t, std::size_t> >& requested)
  {
    std::vector<std::pair<std::size_t, std::size_t> > pairs;
    std::set<std::pair<std::size_t, std::size_t> > seen;
    for(const auto& p : requested)
      if(p.first != p.second && maps_.find(p) == maps_.end() && seen.insert(p).second)
        pairs.push_back(p);
    build_locators(pairs);
    std::vector<std::vector<Location> > results(pairs.size());
    std::vector<double> seconds(pairs.size(), 0);
    Reporter report(progress_, pairs.size());
    auto run = [&](std::size_t p) {
      const Clock::time_point t0 = Clock::now();
      results[p] = map_vertices(embedding(pairs[p].first), *locators_.find(pairs[p].second)->second);
      seconds[p] = seconds_since(t0);
      report(Progress::Pair_mapped, pairs[p].first, pairs[p].second, seconds[p], OK);
    };
    for_each_index(pairs.size(), run);
    for(std::size_t p = 0; p < pairs.size(); ++p) {
      maps_.emplace(pairs[p], std::move(results[p]));
      map_seconds_[pairs[p]] = seconds[p];
    }
  }

  /// computes the maps between all ordered pairs of distinct meshes (see `compute_maps()`)
  /// \pre `embed()` returned `OK`
  void compute_all_maps()
  {
    const std::size_t N = items_.size();
    std::vector<std::pair<std::size_t, std::size_t> > pairs;
    for(std::size_t a = 0; a < N; ++a)
      for(std::size_t b = 0; b < N; ++b)
        if(a != b)
          pairs.emplace_back(a, b);
    compute_maps(pairs);
  }

  /// the largest distance, over the vertices `x` of `a`, between `f_bc(f_ab(x))` and `f_ac(x)` on
  /// mesh `c`, relative to `c`'s bounding-box diagonal (0 up to rounding: the maps are cycle
  /// consistent); infinite if a point could not be located
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
  typedef std::chrono::steady_clock Clock;

  struct Item
  {
    std::unique_ptr<TriangleMesh> mesh;
    std::vector<vertex_descriptor> landmarks;
    UV_map uv;         // destroyed before the mesh that holds it
    Chart_map charts;  // (likewise)
    Embedding_statistics stats;
  };

  typedef internal::Collection_reporter<Progress> Reporter;

  static double seconds_since(const Clock::time_point& t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

  template <class F>
  static void for_each_index(std::size_t n, const F& f) { internal::for_each_index<ConcurrencyTag>(n, f); }

  std::unique_ptr<Locator> new_locator(std::size_t i) const { return std::unique_ptr<Locator>(new Locator(embedding(i))); }

  // the locators of the pairs' targets that are not built yet, in parallel
  void build_locators(const std::vector<std::pair<std::size_t, std::size_t> >& pairs)
  {
    std::vector<std::size_t> targets;
    std::vector<char> wanted(items_.size(), 0);
    for(const auto& p : pairs)
      if(!wanted[p.second] && locators_.find(p.second) == locators_.end()) {
        wanted[p.second] = 1;
        targets.push_back(p.second);
      }
    std::vector<std::unique_ptr<Locator> > built(targets.size());
    for_each_index(targets.size(), [&](std::size_t t) { built[t] = new_locator(targets[t]); });
    for(std::size_t t = 0; t < targets.size(); ++t)
      locators_.emplace(targets[t], std::move(built[t]));
  }

  // every mesh has the first one's topology and number of landmarks
  Error_code check_meshes(Orbifold_type& type)
  {
    const std::size_t N = items_.size();
    if(N == 0) { message_ = "the collection is empty"; return ERROR_WRONG_PARAMETER; }
    const std::size_t k = items_[0].landmarks.size();
    if(!detect_orbifold_type(*items_[0].mesh, type)) { message_ = "mesh 0 is neither closed nor a disk"; return ERROR_WRONG_TOPOLOGY; }
    for(std::size_t i = 0; i < N; ++i) {
      Orbifold_type t;
      if(items_[i].landmarks.size() != k || !detect_orbifold_type(*items_[i].mesh, t) || t != type) {
        message_ = "mesh " + std::to_string(i) + " differs from mesh 0 in topology or number of landmarks";
        return ERROR_WRONG_PARAMETER;
      }
    }
    return OK;
  }

  // the cone orders in the order of the cut
  std::vector<int> ordered_orders() const
  {
    std::vector<int> o;
    if(!orders_.empty())
      for(std::size_t c : order_)
        o.push_back(orders_[c]);
    return o;
  }

  // the orders to try, best first: the meshes' tours ranked by rank_landmark_tours() (sphere
  // type; only mesh 0's with Tour_of_first_mesh), the given order (disk type, Given_landmark_order)
  Error_code compute_orders(std::vector<Order_attempt>& candidates)
  {
    const std::size_t N = items_.size(), k = items_[0].landmarks.size();
    Cone_order_check check; // (here their number; the orders themselves: the embeddings' tiles)
    if(!orders_.empty() && check_cone_orders(orders_, k, &check) != OK && check.problem == Wrong_number_of_cone_orders) {
      message_ = check.message;
      return ERROR_WRONG_PARAMETER;
    }
    Order_attempt given{std::vector<std::size_t>(k), N, 1., OK, std::string()};
    for(std::size_t i = 0; i < k; ++i) given.order[i] = i;
    if(type_ != Sphere_type || order_choice_ == Given_landmark_order) {
      candidates.assign(1, given);
      return OK;
    }
    // (the pipeline's landmark checks: on mesh 0 they fail here; another mesh whose landmarks
    // fail them, or are not all connected, leaves mesh 0's tour alone, and its embedding then
    // says why it is refused)
    std::vector<std::vector<std::vector<double> > > D;
    for(std::size_t i = 0; i < (order_choice_ == Tour_of_first_mesh ? 1 : N); ++i) {
      const TriangleMesh& m = *items_[i].mesh;
      const Status r = check_landmark_vertices(m, items_[i].landmarks, type_, orders_.empty() ? minimum_number_of_landmarks : 3);
      if(!r && i == 0) { message_ = "mesh 0: " + r.message; return r.code; }
      if(r)
        D.push_back(compute_landmark_distances(m, items_[i].landmarks, get(CGAL::vertex_point, m)));
      if(!r || (i > 0 && !internal::is_finite_distance_matrix(D.back()))) {
        D.resize(1);
        break;
      }
    }
    const std::vector<Landmark_order_candidate> ranked = rank_landmark_tours(D);
    if(ranked.empty()) {
      order_.clear();
      message_ = "mesh 0: the landmark tour could not be computed";
      return ERROR_CUT_FAILED;
    }
    candidates.clear();
    for(const Landmark_order_candidate& c : ranked)
      candidates.push_back(Order_attempt{c.order, c.mesh, c.longest_ratio, OK, std::string()});
    return OK;
  }

  // the message when no order works: each order tried and why it failed
  std::string attempts_message() const
  {
    std::string m = "no landmark order works for every mesh (" + std::to_string(attempts_.size()) + " tried):";
    for(std::size_t a = 0; a < attempts_.size(); ++a) {
      const Order_attempt& t = attempts_[a];
      m += (a ? "; " : " ") + (t.mesh < items_.size() ? "mesh " + std::to_string(t.mesh) + "'s tour (" : std::string("the given order ("));
      for(std::size_t i = 0; i < t.order.size(); ++i) m += (i ? " " : "") + std::to_string(t.order[i]);
      m += "): " + t.message;
    }
    return m;
  }

  // the embeddings in the order order_, in parallel with Parallel_tag; the first failure in
  // mesh order, and whether every failure is one another order may avoid
  Error_code embed_all(bool& order_failure)
  {
    order_failure = false;
    const std::size_t N = items_.size();
    std::vector<Error_code> codes(N, OK);
    const std::vector<int> cut_orders = ordered_orders(); // (empty: all 2)
    for(std::size_t i = 0; i < N && type_ == Sphere_type; ++i) {
      const long long genus = closed_mesh_genus(*items_[i].mesh);
      if(genus > 0) { // (its tile depends on its cut graph, which the collection does not match yet)
        message_ = "mesh " + std::to_string(i) + " has genus " + std::to_string(genus) +
                   ": collections of closed meshes of genus 1 or more are not built yet; map them in pairs along"
                   " corresponding cut graphs (hyperbolic_orbifold_Tutte_embedding() with cut_graph)";
        return ERROR_WRONG_TOPOLOGY;
      }
    }
    Reporter report(progress_, N);
    auto run = [&](std::size_t i) {
      Item& it = items_[i];
      std::vector<vertex_descriptor> ordered;
      for(std::size_t c : order_) ordered.push_back(it.landmarks[c]);
      it.uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), *it.mesh);
      it.charts = get(CGAL::dynamic_halfedge_property_t<Chart_point<Point_2> >(), *it.mesh);
      for(halfedge_descriptor h : halfedges(*it.mesh)) { // every key present: reads never insert
        put(it.uv, h, Point_2(0, 0));
        put(it.charts, h, Chart_point<Point_2>());
      }
      const Clock::time_point t0 = Clock::now();
      codes[i] = hyperbolic_orbifold_Tutte_embedding(
        *it.mesh, ordered, it.uv,
        parameters::cone_orders(cut_orders, parameters::chart_map(it.charts, parameters::orbifold_type(type_, parameters::embedding_statistics(&it.stats)))));
      report(Progress::Mesh_embedded, i, i, seconds_since(t0), codes[i]);
    };
    for_each_index(N, run);
    order_failure = true;
    for(std::size_t i = 0; i < N; ++i)
      order_failure = order_failure && (codes[i] == OK || is_landmark_order_failure(codes[i]));
    for(std::size_t i = 0; i < N; ++i)
      if(codes[i] != OK) { message_ = "mesh " + std::to_string(i) + ": " + items_[i].stats.message; return codes[i]; }
    order_failure = false;
    for(std::size_t i = 1; i < N; ++i)
      if(items_[i].stats.landmark_order_reversed != items_[0].stats.landmark_order_reversed) {
        message_ = "mesh " + std::to_string(i) + ": its landmarks run around the boundary the other way than mesh 0's";
        return ERROR_WRONG_PARAMETER;
      }
    return OK;
  }

  std::vector<Item> items_;
  std::vector<std::size_t> order_;
  std::vector<Order_attempt> attempts_;
  Landmark_order_choice order_choice_ = Tour_of_any_mesh;
  std::vector<int> orders_; // per landmark, in the class-wide order (empty: all 2)
  Orbifold_type type_ = Sphere_type;
  bool embedded_ = false;
  std::string message_;
  Progress_callback progress_;
  std::map<std::size_t, std::unique_ptr<Locator> > locators_;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<Location> > maps_;
  std::map<std::pair<std::size_t, std::size_t>, double> map_seconds_;
  std::vector<Map_refinement_statistics> refinement_;
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_COLLECTION_H
