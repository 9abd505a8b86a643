// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERIZER_3_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERIZER_3_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Chart_point.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/cones_along_seam.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/pipeline/embedding_pipeline.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/input/genus_cut.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/orbifold_enums.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/properties.h>

#include <chrono>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

/// \file Hyperbolic_orbifold_Tutte_parameterizer_3.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
the `Surface_mesh_parameterization::Error_code` nearest to `code`, for the drop-in
interface of `Hyperbolic_orbifold_Tutte_parameterizer_3`: `OK`, the empty-mesh and
non-triangle errors, `ERROR_NO_TOPOLOGICAL_BALL` (sphere type) or
`ERROR_NO_TOPOLOGICAL_DISC` (disk type) for a mesh of the wrong topology,
`ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, `ERROR_NO_1_TO_1_MAPPING` when no certified result
was found, and `ERROR_WRONG_PARAMETER` for everything else (landmarks, cut, parameters).
*/
inline Surface_mesh_parameterization::Error_code surface_mesh_parameterization_error_code(Error_code code,
                                                                                         Orbifold_type type)
{
  namespace SMP = Surface_mesh_parameterization;
  switch(code) {
  case OK: return SMP::OK;
  case ERROR_EMPTY_MESH: return SMP::ERROR_EMPTY_MESH;
  case ERROR_NON_TRIANGULAR_MESH: return SMP::ERROR_NON_TRIANGULAR_MESH;
  case ERROR_NON_MANIFOLD:
  case ERROR_SEVERAL_COMPONENTS:
  case ERROR_WRONG_TOPOLOGY:
    return type == Sphere_type ? SMP::ERROR_NO_TOPOLOGICAL_BALL : SMP::ERROR_NO_TOPOLOGICAL_DISC;
  case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  case ERROR_NOT_CONVERGED:
  case ERROR_NO_1_TO_1_MAPPING:
    return SMP::ERROR_NO_1_TO_1_MAPPING;
  default: return SMP::ERROR_WRONG_PARAMETER;
  }
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

computes a hyperbolic orbifold Tutte embedding (Aigerman and Lipman 2016, Algorithm 1)
of a cut mesh into the basic tile of a sphere-type or disk-type hyperbolic orbifold:
the critical point of the hyperbolic Dirichlet energy \f$ \frac12 \sum w_{ij} d(\Phi_i,\Phi_j)^2 \f$
with the landmarks fixed at the tile's cones and seam twins tied by the side pairings
(sphere type), or boundary vertices sliding on the tile's sides (disk type).

The result is written as Poincar&eacute;-disk coordinates, one `Point_2` per seam-mesh
vertex, and is certified: `parameterize()` returns `OK` only when
`Embedding_certificate::is_bijective()` holds for the written coordinates.

\tparam SeamMesh a `CGAL::Seam_mesh` whose seams cut the underlying closed genus-0 mesh
        into a disk along a simple path through the landmarks in order (sphere type), or a
        closed mesh of genus \f$ g \ge 1 \f$ along a cut graph through the landmarks (its tile
        is then the graph's polygon, `make_cut_graph_tile()`; \ref HOT_Genus),
        or a `Seam_mesh` without seams over a mesh with one boundary loop (disk type).
\tparam Traits a model of `HyperbolicOrbifoldTraits_2`, by default
        `Poincare_disk_traits_2` over the kernel of the mesh's points.
*/
template <class SeamMesh, class Traits_ = Default>
class Hyperbolic_orbifold_Tutte_parameterizer_3
{
public:
  /// the cut mesh type
  typedef SeamMesh Seam_mesh;
  /// the underlying mesh type
  typedef typename SeamMesh::TriangleMesh Triangle_mesh;
  /// the vertex point map of the underlying mesh (its internal `vertex_point` map)
  typedef typename boost::property_map<Triangle_mesh, boost::vertex_point_t>::const_type Vertex_point_map;
  /// the point type of the underlying mesh
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  /// the kernel of `Point_3`
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  /// the geometric traits: `Traits_`, or `Poincare_disk_traits_2<Kernel>` by default
  typedef typename Default::Get<Traits_, Poincare_disk_traits_2<Kernel> >::type Traits;
  /// the type of the output points (Poincar&eacute;-disk coordinates)
  typedef typename Traits::Point_2 Point_2;
  /// the orbifold tile type
  typedef Orbifold_tile<Traits> Tile;
  /// halfedge descriptor of the cut mesh
  typedef typename boost::graph_traits<SeamMesh>::halfedge_descriptor halfedge_descriptor;
  /// vertex descriptor of the cut mesh (the keys of the output map)
  typedef typename boost::graph_traits<SeamMesh>::vertex_descriptor vertex_descriptor;
  /// vertex descriptor of the underlying mesh (the landmarks)
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor TM_vertex_descriptor;
  /// edge descriptor of the underlying mesh
  typedef typename boost::graph_traits<Triangle_mesh>::edge_descriptor TM_edge_descriptor;
  /// user edge weights: a positive number per edge of the underlying mesh
  typedef std::function<double(const TM_edge_descriptor&)> Edge_weight_function;
  /// a progress report: the phase's name and the fraction of it done, see `set_progress()`
  typedef std::function<void(const char* phase, double fraction)> Progress_function;

  /// \param type the orbifold's topology
  /// \param weights the edge weights
  /// \param epsilon the lower clamp of cotangent weights
  /// \param traits the geometric traits
  explicit Hyperbolic_orbifold_Tutte_parameterizer_3(Orbifold_type type = Sphere_type, Weight_type weights = Cotangent,
                                                     double epsilon = 1e-6, const Traits& traits = Traits())
    : type_(type), traits_(traits)
  {
    settings_.weights = weights;
    settings_.epsilon = epsilon;
  }

  /// the constructor of CGAL's `Surface_mesh_parameterization::Orbifold_Tutte_parameterizer_3`,
  /// for a drop-in replacement: `Parameterizer p(Sphere_type, SMP::Cotangent)`
  /// \param type the orbifold's topology
  /// \param weights `SMP::Cotangent` (clamped below at \f$10^{-6}\f$) or `SMP::Mean_value`
  /// \param traits the geometric traits
  Hyperbolic_orbifold_Tutte_parameterizer_3(Orbifold_type type, Surface_mesh_parameterization::Weight_type weights,
                                            const Traits& traits = Traits())
    : Hyperbolic_orbifold_Tutte_parameterizer_3(
        type, weights == Surface_mesh_parameterization::Mean_value ? Mean_value : Cotangent, 1e-6, traits)
  {}

  /// the order \f$p_i\f$ of the cone of every landmark (cone angle \f$2\pi/p_i\f$), in the order
  /// of the landmarks given to `parameterize()` (along the seam); sphere type only. Empty (the
  /// default): 2 for every cone. With orders, 3 or more landmarks are accepted, as long as the
  /// orbifold is hyperbolic (\f$\sum_i (1 - 1/p_i) > 2\f$; otherwise `ERROR_NOT_HYPERBOLIC`).
  void set_cone_orders(const std::vector<int>& orders) { orders_ = orders; }
  /// the cone orders set by `set_cone_orders()`
  const std::vector<int>& cone_orders() const { return orders_; }

  /// the force imbalance (relative hyperbolic gradient norm, see `Embedding_statistics`) at which the solver stops (default \f$10^{-10}\f$)
  void set_gradient_tolerance(double t) { settings_.solver.gradient_tolerance = t; }
  /// the maximum number of Newton iterations (default 200)
  void set_maximum_number_of_iterations(int n) { settings_.solver.max_iterations = n; }
  /// prints the solver's progress on `std::cerr` when `v` is `true` (default `false`)
  void set_verbose(bool v) { settings_.solver.verbose = v; }
  /// From `n` vertices of the cut mesh on (default 400000), the solver does not factor its
  /// Laplacians: the Euclidean Tutte initialisation and Newton's systems are solved by
  /// conjugate gradients preconditioned by algebraic multigrid (smoothed aggregation), whose
  /// work grows linearly with the size where a sparse factorisation's grows like
  /// \f$n^{1.5}\f$. Both reach the same embedding (the energy has one minimiser); the
  /// certificate is the same. 0: always; `std::numeric_limits<std::size_t>::max()`: never.
  void set_multigrid_threshold(std::size_t n)
  {
    settings_.solver.multigrid_from = static_cast<Eigen::Index>(std::min<std::size_t>(n, static_cast<std::size_t>(std::numeric_limits<Eigen::Index>::max())));
  }
  /// uses `w(e)` as the weight of every edge `e` of the underlying mesh instead of the
  /// `Weight_type`; each must be positive and finite (else `ERROR_WRONG_PARAMETER`).
  /// An empty function restores the `Weight_type`.
  void set_edge_weights(const Edge_weight_function& w) { settings_.user_weights = w; }
  /// calls `f(phase, fraction)` during `parameterize()` (default: none), from the calling
  /// thread, for the phases `"initialization"` (the flat problem, its weights and the Euclidean
  /// Tutte initialisation), `"optimization"` (Newton) and `"certificate"` (the certificate and
  /// the mends where it fails), in this order. Each phase is told 0 when it starts and 1 when
  /// it ends; in between, `"optimization"` is told after every accepted Newton step the
  /// relative gradient norm's progress from its start value \f$g_0\f$ towards the tolerance
  /// \f$t\f$ on a log scale, \f$\log(g_0/g)/\log(g_0/t)\f$ clamped to \f$[0,1]\f$ and never less
  /// than before (so the fractions of a phase never decrease). A phase that fails (an error
  /// returned) is not told 1 and no later phase is told. The report only reads the state:
  /// the result is the same, to the bit, with or without it. An empty function: none.
  void set_progress(const Progress_function& f) { settings_.progress = f; }
  /// allows the result to be written in a moved frame (default `false`). A part of the mesh
  /// far from every landmark (a long protrusion) shrinks exponentially in the embedding, by
  /// a factor e per radius of a tube's length: past about 33 radii its triangles are below
  /// what `double` resolves in the tile, and the embedding is refused
  /// (`ERROR_NO_1_TO_1_MAPPING`). With recentring, it is then solved again in frames that
  /// move the squeezed region's deepest point to the origin, where `double` resolves far
  /// smaller triangles (16 more digits per round, one round per 30 radii or so, up to about
  /// 350 radii, where squared edge lengths underflow the range of `double`), and the
  /// certified result is returned in that frame: `Embedding_statistics::recentred` is
  /// `true` and the written point of a vertex is `Embedding_statistics::frame` applied to
  /// its position in the tile of `make_orbifold_tile()`. The tile of the written
  /// coordinates is then `tile.transformed(frame)`; `Embedding_locator` and the surface
  /// maps work with embeddings in the tile itself and refuse moved ones.
  void set_recentring(bool b) { settings_.recentring = b; }
  /// genus \f$ g \ge 1 \f$: the tile's corner 0 is the corner where the border of the cut mesh,
  /// running along the edge from `a` to `b` (the first edge of a cut graph given as paths), last
  /// left a corner, so that two meshes cut along corresponding graphs get the same tile; by
  /// default, the copy of the first landmark (else of the node with the smallest index) whose
  /// border side leaves it towards the smallest vertex index.
  void set_cut_graph_start(TM_vertex_descriptor a, TM_vertex_descriptor b)
  {
    start_[0] = a;
    start_[1] = b;
    has_start_ = true;
  }

  /*!
  computes the embedding.
  \tparam VertexUVMap a model of `WritablePropertyMap` with `vertex_descriptor` of `SeamMesh`
          as key type and `Point_2` as value type (typically a halfedge property map of
          the underlying mesh, as for `Surface_mesh_parameterization`).
  \param mesh the cut mesh
  \param bhd a border halfedge of `mesh`
  \param landmarks the landmark vertices of the underlying mesh, in cone order
  \param uvmap receives the Poincar&eacute; coordinates
  \param stats if not null, receives statistics, timings and the certificate
  \return `OK`, or the reason of the failure (`uvmap` is then left unchanged).
  */
  template <class VertexUVMap>
  Error_code parameterize(const SeamMesh& mesh, halfedge_descriptor bhd,
                          const std::vector<TM_vertex_descriptor>& landmarks, VertexUVMap uvmap,
                          Embedding_statistics* stats = nullptr) const
  {
    return parameterize(mesh, bhd, landmarks, uvmap, internal::No_chart_map(), stats);
  }

  /*!
  computes the embedding, allowing a part that converges onto cone images (a long
  protrusion ending at a landmark) to be written in charts around them (\ref HOT_Charts),
  where the other overload refuses it. `chartmap` receives the `Chart_point` of every
  vertex (`chart` -1 for the vertices written in the tile only), `stats` the charts
  (`Embedding_statistics::charts`); `uvmap` receives the tile points of all vertices (in a
  chart's region, rounded to `double`: the embedding there is the chart's).
  \tparam VertexChartMap a model of `WritablePropertyMap` with `vertex_descriptor` as key
          type and `Chart_point<Point_2>` as value type
  */
  template <class VertexUVMap, class VertexChartMap>
  Error_code parameterize(const SeamMesh& mesh, halfedge_descriptor bhd,
                          const std::vector<TM_vertex_descriptor>& landmarks, VertexUVMap uvmap,
                          VertexChartMap chartmap, Embedding_statistics* stats = nullptr) const
  {
    constexpr bool with_charts = !std::is_same<VertexChartMap, internal::No_chart_map>::value;
    Embedding_statistics local;
    Embedding_statistics& st = stats ? *stats : local;
    st = Embedding_statistics();
    st.type = type_;
    const int k = static_cast<int>(landmarks.size());
    Tile tile;
    const long long genus = type_ == Sphere_type ? closed_mesh_genus(mesh.mesh()) : 0;
    if(genus > 0) { // a surface of genus g >= 1: the tile is the polygon of the cut graph (the seams)
      const std::vector<int> orders = orders_.empty() ? std::vector<int>(k, 2) : orders_;
      Cone_order_check check; // (whether the orbifold is hyperbolic: cut_graph_tile())
      if(check_cone_orders(orders, static_cast<std::size_t>(k), &check) != OK) {
        st.message = check.problem == Cone_order_below_two
                       ? "the cone orders must be integers of at least 2 (a cone of order p has angle 2 pi / p)"
                       : check.message;
        return ERROR_WRONG_PARAMETER;
      }
      internal::Cut_polygon poly;
      std::pair<int, int> start(-1, -1);
      if(has_start_) {
        const internal::Dense_index<TM_vertex_descriptor> base_of(vertices(mesh.mesh()));
        const std::size_t a = base_of(start_[0]), b = base_of(start_[1]);
        if(a == base_of.npos || b == base_of.npos) {
          st.message = "the first edge of the cut graph is not an edge of the mesh";
          return ERROR_WRONG_PARAMETER;
        }
        start = std::make_pair(static_cast<int>(a), static_cast<int>(b));
      }
      const Status s = internal::cut_graph_tile(mesh, bhd, landmarks, static_cast<int>(genus), orders, start, tile, traits_, poly);
      if(!s) {
        st.message = s.message;
        return s.code;
      }
      st.cone_orders = orders;
      st.genus = static_cast<int>(genus);
      st.cut_corner_nodes = poly.corner_node;
      st.cut_node_vertices = poly.node_base;
      st.cut_node_cones = poly.node_cone;
      st.cut_paired_sides = poly.paired_side;
    } else if(orders_.empty()) {
      if(k < 5) {
        st.message = "at least 5 landmarks are needed, got " + std::to_string(k);
        return ERROR_TOO_FEW_LANDMARKS;
      }
      if(make_orbifold_tile(type_, k, tile, traits_) != OK) {
        st.message = error_message(ERROR_NOT_HYPERBOLIC);
        return ERROR_NOT_HYPERBOLIC;
      }
      st.cone_orders.assign(k, 2);
    } else {
      const Status s = internal::tile_of_cone_orders(type_, orders_, k, tile, traits_);
      if(!s) {
        st.message = s.message;
        return s.code;
      }
      st.cone_orders = orders_;
    }
    Settings settings = settings_;
    settings.charts = with_charts;
    if(genus > 0 && has_start_) {
      const internal::Dense_index<TM_vertex_descriptor> base_of(vertices(mesh.mesh()));
      settings.cut_graph_start = std::make_pair(static_cast<int>(base_of(start_[0])), static_cast<int>(base_of(start_[1])));
    }
    internal::Seam_mesh_embedding<SeamMesh, Tile> job(mesh, bhd, landmarks, tile, settings, st);
    const Error_code ec = internal::run_embedding_stage(job);
    if(ec != OK)
      return ec;
    for(std::size_t v = 0; v < job.cut_vertices().size(); ++v) {
      put(uvmap, job.cut_vertices()[v], Point_2(job.uv()[v].real(), job.uv()[v].imag()));
      if constexpr(with_charts) {
        const std::pair<int, std::complex<double> > cp = job.chart_point(v);
        Chart_point<Point_2> c;
        c.chart = cp.first;
        c.point = Point_2(cp.second.real(), cp.second.imag());
        put(chartmap, job.cut_vertices()[v], c);
      }
    }
    return OK;
  }

  /*!
  computes the embedding with the interface of CGAL's
  `Surface_mesh_parameterization::Orbifold_Tutte_parameterizer_3::parameterize()`: the
  landmarks are the cones of `cmap`, in their order along the seam (from the
  `First_unique_cone` to the `Second_unique_cone`, as `SMP::locate_cones()` tags them after
  a cut through the cones in the order of `read_cones()`), any number of at least 5.
  The result is certified as by the other overload; the specific reason of a failure,
  the statistics and the certificate of this call are then given by `last_status()` and
  `statistics()` (so calls of this overload on one object must not run concurrently).
  \tparam ConeMap an associative container (e.g. `std::unordered_map`) with
          `vertex_descriptor` as key type and `SMP::Cone_type` as value type
  \tparam VertexUVMap as in the other overload
  \tparam VertexIndexMap accepted for compatibility with CGAL's interface, not used (the
          package numbers the vertices itself)
  \return `SMP::OK` on success; otherwise the `SMP::Error_code` nearest to the reason
          (see `surface_mesh_parameterization_error_code()`).
  */
  template <class ConeMap, class VertexUVMap, class VertexIndexMap,
            class = std::enable_if_t<std::is_same<typename ConeMap::mapped_type,
                                                  Surface_mesh_parameterization::Cone_type>::value> >
  Surface_mesh_parameterization::Error_code parameterize(const SeamMesh& mesh, halfedge_descriptor bhd,
                                                         const ConeMap& cmap, VertexUVMap uvmap,
                                                         VertexIndexMap /* vimap */) const
  {
    std::vector<TM_vertex_descriptor> landmarks;
    last_status_ = internal::cones_along_seam(mesh, bhd, cmap, type_, landmarks);
    if(!last_status_) {
      last_statistics_ = Embedding_statistics();
      last_statistics_.message = last_status_.message;
    } else {
      last_status_.code = parameterize(mesh, bhd, landmarks, uvmap, &last_statistics_);
      last_status_.message = last_statistics_.message;
    }
    return surface_mesh_parameterization_error_code(last_status_.code, type_);
  }

  /// the outcome of the last call of the cone-map `parameterize()`: its `Error_code` and message
  const Status& last_status() const { return last_status_; }
  /// the statistics and the certificate of the last call of the cone-map `parameterize()`
  const Embedding_statistics& statistics() const { return last_statistics_; }

private:
  Orbifold_type type_;
  std::vector<int> orders_;
  TM_vertex_descriptor start_[2];
  bool has_start_ = false;
  Traits traits_;
  typedef internal::Embedding_settings<TM_edge_descriptor> Settings;
  Settings settings_;
  mutable Status last_status_;                   // (the cone-map overload)
  mutable Embedding_statistics last_statistics_; // (the cone-map overload)
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERIZER_3_H
