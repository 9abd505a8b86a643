// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERIZER_3_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERIZER_3_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/flat_problem.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/orbifold_solver.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/properties.h>

#include <chrono>
#include <functional>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

/// \file Hyperbolic_orbifold_Tutte_parameterizer_3.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
What a parameterization did: solver statistics, timings (seconds) and the certificate.
*/
struct Embedding_statistics
{
  int number_of_vertices = 0;         ///< vertices of the cut (seam) mesh
  int number_of_variables = 0;        ///< unknowns after eliminating seam twins
  int iterations = 0;                 ///< steps of the solver (preconditioned gradient steps, then Newton steps)
  int cg_iterations = 0;              ///< conjugate-gradient iterations of the Newton steps, in all
  int preconditioner_factorizations = 0; ///< factorisations of the connection-Laplacian preconditioner after the first
  /// `true` when the initialisation solved its Tutte system with the leading block of the
  /// solver's factorisation, so that one factorisation served both (with CHOLMOD, from 50K
  /// vertices of the cut mesh on, where the order this needs fills the factor no more than
  /// CHOLMOD's own; otherwise each factors a matrix of its own)
  bool shared_factorization = false;
  double initial_energy = 0;          ///< Dirichlet energy of the Euclidean Tutte initialisation
  double energy = 0;                  ///< final Dirichlet energy \f$ \frac12\sum w_{ij} d_{ij}^2 \f$
  double gradient_norm = 0;           ///< final hyperbolic norm of the energy's gradient
  double relative_gradient_norm = 0;  ///< the same, relative to the norm of the sums of the absolute values of the edges' contributions (the forces' imbalance; its floor is the rounding error)
  /// the force imbalance that rounding the coordinates to `double` alone would cause (an
  /// estimate from each edge's length and how many digits its ends' coordinates give it):
  /// about \f$10^{-15}\f$ on ordinary meshes, far more where cotangent weights are huge
  /// (needle triangles) or vertices crowd towards the circle
  double rounding_floor = 0;
  /// `true` when the tolerance was out of reach of `double` and the solver stopped at the
  /// floor instead: Newton's steps no longer reduced the imbalance and it is within
  /// \f$10\times\f$ `rounding_floor` (the coordinates are then as accurate as `double` allows)
  bool converged_at_rounding_floor = false;
  /// `true` when the solver reached the gradient tolerance, or the rounding floor above it
  bool converged = false;
  /// Newton steps taken after the force imbalance reached the tolerance, because some vertex's
  /// own forces were still out of balance by more than \f$10^{-8}\f$ of their sizes (beyond
  /// what rounding explains), or because the certificate found a flipped face: the force
  /// imbalance is a global measure, blind to a region squeezed so small (a protrusion
  /// without landmarks, \f$10^{-12}\f$ across) that its forces are below the tolerance
  /// times the largest ones; such a region is solved to the precision of `double` (steps
  /// until rounding stops them), before the one-ring repair is tried
  int polishing_iterations = 0;
  int repaired_vertices = 0;          ///< vertices moved by the one-ring repair (paper, section 5)
  /// `true` when the coordinates were written in a moved frame (recentring allowed, and the
  /// embedding in the canonical tile had triangles below what `double` resolves): the
  /// written point of a vertex is `frame(z)`, where `z` is its position in the tile of
  /// `make_orbifold_tile()`, and the embedding fills `tile.transformed(frame)`
  bool recentred = false;
  /// the isometry of the frame (the identity unless `recentred`): the translation that
  /// moves the most squeezed region of the embedding to the origin
  Hyperbolic_isometry_2<double> frame;
  bool landmark_order_reversed = false; ///< disk type: landmarks were given clockwise
  std::vector<std::size_t> landmark_order; ///< one-call function: indices of the landmarks in the order used
  /// \var time_setup
  /// seconds spent checking the input, cutting the mesh and setting up the problem
  /// \var time_initialization
  /// seconds spent in the Euclidean Tutte initialisation (with `shared_factorization`, the
  /// solver's factorisation is made there and counted there)
  /// \var time_optimization
  /// seconds spent in Newton's method
  /// \var time_certificate
  /// seconds spent certifying the result (and repairing one-rings)
  double time_setup = 0, time_initialization = 0, time_optimization = 0, time_certificate = 0;
  /// \var time_assembly
  /// seconds spent assembling the Newton systems (part of `time_optimization`)
  /// \var time_factorization
  /// seconds spent factoring the Newton matrices (part of `time_optimization`)
  double time_assembly = 0, time_factorization = 0, time_line_search = 0; ///< parts of `time_optimization` (factorisation: the preconditioner's and the conjugate gradients)
  /// the bijectivity certificate of the computed coordinates
  Embedding_certificate certificate;
  std::string message;                ///< one-line reason when the result is an error
  /// mesh vertices named by the error, as indices in the order of `vertices(tm)`
  /// (`ERROR_BOUNDARY_CHORD`: the ends of the offending edge)
  std::vector<std::size_t> problem_vertices;
};

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
        into a disk along a simple path through the landmarks in order (sphere type),
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

  /// \param type the orbifold's topology
  /// \param weights the edge weights
  /// \param epsilon the lower clamp of cotangent weights
  /// \param traits the geometric traits
  explicit Hyperbolic_orbifold_Tutte_parameterizer_3(Orbifold_type type = Sphere_type, Weight_type weights = Cotangent,
                                                     double epsilon = 1e-6, const Traits& traits = Traits())
    : type_(type), weights_(weights), epsilon_(epsilon), traits_(traits)
  {}

  /// the force imbalance (relative hyperbolic gradient norm, see `Embedding_statistics`) at which the solver stops (default \f$10^{-10}\f$)
  void set_gradient_tolerance(double t) { options_.gradient_tolerance = t; }
  /// the maximum number of Newton iterations (default 200)
  void set_maximum_number_of_iterations(int n) { options_.max_iterations = n; }
  /// prints the solver's progress on `std::cerr` when `v` is `true` (default `false`)
  void set_verbose(bool v) { options_.verbose = v; }
  /// uses `w(e)` as the weight of every edge `e` of the underlying mesh instead of the
  /// `Weight_type`; each must be positive and finite (else `ERROR_WRONG_PARAMETER`).
  /// An empty function restores the `Weight_type`.
  void set_edge_weights(const Edge_weight_function& w) { user_weights_ = w; }
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
  void set_recentring(bool b) { recentring_ = b; }

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
    Embedding_statistics local;
    Embedding_statistics& st = stats ? *stats : local;
    st = Embedding_statistics();
    typedef std::chrono::steady_clock Clock;
    auto t0 = Clock::now();
    auto fail = [&](Error_code ec, const std::string& msg) {
      st.message = msg.empty() ? std::string(error_message(ec)) : msg;
      return ec;
    };

    const int k = static_cast<int>(landmarks.size());
    if(k < 5)
      return fail(ERROR_TOO_FEW_LANDMARKS, "at least 5 landmarks are needed, got " + std::to_string(k));
    Tile tile;
    if(make_orbifold_tile(type_, k, tile, traits_) != OK)
      return fail(ERROR_NOT_HYPERBOLIC, "");

    internal::Flat_problem P;
    std::vector<TM_vertex_descriptor> base_vertex;
    std::vector<vertex_descriptor> cut_vertices;
    std::string msg;
    Error_code ec = internal::build_flat_topology(mesh, bhd, landmarks, tile, P, base_vertex, cut_vertices, msg);
    if(ec != OK) {
      st.problem_vertices.assign(P.problem_vertices.begin(), P.problem_vertices.end());
      return fail(ec, msg);
    }
    st.number_of_vertices = P.n;
    st.number_of_variables = P.n_vars;
    st.landmark_order_reversed = P.landmark_order_reversed;

    const Triangle_mesh& tm = mesh.mesh();
    Vertex_point_map vpm = get(vertex_point, tm);
    std::vector<Point_3> base_points(P.n_base);
    for(int i = 0; i < P.n_base; ++i)
      base_points[i] = get(vpm, base_vertex[i]);
    if(user_weights_) {
      // each base edge once in total: its copies (two along a seam) share the weight
      std::unordered_map<long long, int> copies;
      auto key = [](int a, int b) { return (static_cast<long long>(std::min(a, b)) << 32) | std::max(a, b); };
      for(const auto& e : P.edges)
        ++copies[key(P.base[e[0]], P.base[e[1]])];
      P.edge_weight.resize(P.edges.size());
      for(std::size_t i = 0; i < P.edges.size(); ++i) {
        const int a = P.base[P.edges[i][0]], b = P.base[P.edges[i][1]];
        const auto e = edge(base_vertex[a], base_vertex[b], tm);
        const double w = e.second ? user_weights_(e.first) : 0.0;
        if(!(w > 0) || !std::isfinite(w))
          return fail(ERROR_WRONG_PARAMETER, "the user weight of the edge between mesh vertices " + std::to_string(a) +
                                               " and " + std::to_string(b) + " is not a positive finite number");
        P.edge_weight[i] = w / copies[key(a, b)];
      }
    } else {
      internal::compute_edge_weights(P, base_points, weights_, epsilon_);
    }
    st.time_setup = std::chrono::duration<double>(Clock::now() - t0).count();

    auto t1 = Clock::now();
    std::vector<double> x;
    internal::Interior_laplacian interior; // factored by the initialisation, reused by the solver
    ec = internal::initialize_embedding(P, tile, base_points, x, &interior);
    st.time_initialization = std::chrono::duration<double>(Clock::now() - t1).count();
    st.shared_factorization = interior.connection != nullptr;
    if(ec != OK)
      return fail(ec, "the Euclidean Tutte initialisation failed");

    auto t2 = Clock::now();
    internal::Solver_statistics ss;
    ec = internal::minimize_energy(P, x, options_, ss, &interior);
    st.iterations = ss.iterations;
    st.cg_iterations = ss.cg_iterations;
    st.preconditioner_factorizations = ss.preconditioner_factorizations;
    st.initial_energy = ss.initial_energy;
    st.energy = ss.energy;
    st.gradient_norm = ss.gradient;
    st.relative_gradient_norm = ss.relative_gradient;
    st.converged = ss.converged;
    st.polishing_iterations = ss.polishing_iterations;
    st.rounding_floor = ss.rounding_floor;
    st.converged_at_rounding_floor = ss.at_rounding_floor;
    st.time_assembly = ss.time_assemble;
    st.time_factorization = ss.time_factor;
    st.time_line_search = ss.time_line_search;
    st.time_optimization = std::chrono::duration<double>(Clock::now() - t2).count();

    std::vector<C> uv(P.n);
    auto t3 = Clock::now();
    certify(P, tile, x, uv, st);
    if(ec == OK && flipped_only(st)) {
      // a region too small for the stopping test to see: Newton to the floor of double
      const auto t4 = Clock::now();
      polish_to_floor(P, x, interior, st);
      const auto dt = Clock::now() - t4; // solver time, not certificate time
      st.time_optimization += std::chrono::duration<double>(dt).count();
      t3 += dt;
      certify(P, tile, x, uv, st);
    }
    Unresolved_faces tiny = unresolved_faces(P, uv, false);
    // (triangles below what double resolves have unreliable angles too: angle-sum failures)
    const Embedding_certificate& c = st.certificate;
    const bool local_failure = !c.is_bijective() && c.points_outside_disk == 0 && c.twin_failures == 0 &&
                               c.cone_failures == 0 && c.border_failures == 0;
    const bool recentring_tried = ec == OK && local_failure && tiny.count > 0 && recentring_;
    if(recentring_tried) {
      const auto t4 = Clock::now();
      recentre(mesh, bhd, landmarks, cut_vertices, tile, P, uv, st);
      const auto dt = Clock::now() - t4;
      st.time_optimization += std::chrono::duration<double>(dt).count();
      t3 += dt;
    } else {
      repair(P, tile, x, uv, st);
    }
    st.time_certificate = std::chrono::duration<double>(Clock::now() - t3).count();
    if(ec != OK) {
      std::ostringstream os;
      os << "the solver stopped at relative gradient norm " << ss.relative_gradient << " after " << ss.iterations
         << " iterations (tolerance " << options_.gradient_tolerance << ", rounding floor " << ss.rounding_floor << ")";
      return fail(ec, os.str());
    }
    if(!st.certificate.is_bijective()) {
      std::ostringstream os;
      os << "the embedding failed the certificate: " << st.certificate;
      // triangles double cannot resolve: their edges within a few hundred units in the last
      // place of their coordinates (a protrusion without landmarks shrinks exponentially
      // along its length, by e per radius for a tube: about 33 radii exhaust double)
      if(tiny.count > 0) {
        os << "; " << tiny.count << " triangles are below what double resolves (smallest edge " << tiny.smallest
           << "): a part of the mesh far from every landmark (a long protrusion) shrinks exponentially"
              " in the embedding; put a landmark on it";
        if(recentring_tried)
          os << " (solving it again with its deepest point at the origin did not suffice)";
        else if(!recentring_)
          os << ", or allow recentring (parameters::recentring(true); command line: --recentre)";
      }
      return fail(ERROR_NO_1_TO_1_MAPPING, os.str());
    }
    for(int v = 0; v < P.n; ++v)
      put(uvmap, cut_vertices[v], Point_2(uv[v].re, uv[v].im));
    return OK;
  }

private:
  typedef internal::Complex<double> C;
  typedef Hyperbolic_isometry_2<double> Isometry;

  // the certificate of the coordinates xq (written to uvq)
  static void certify(const internal::Flat_problem& Q, const Tile& T, const std::vector<double>& xq,
                      std::vector<C>& uvq, Embedding_statistics& st)
  {
    for(int v = 0; v < Q.n; ++v)
      uvq[v] = internal::position(Q, xq, v);
    st.certificate = internal::certify_flat(Q, T, uvq);
  }

  // the certificate fails on flipped or flat faces only
  static bool flipped_only(const Embedding_statistics& st)
  {
    return !st.certificate.is_bijective() && st.certificate.points_outside_disk == 0 &&
           (st.certificate.flipped_faces > 0 || st.certificate.degenerate_faces > 0);
  }

  // the paper's one-ring repair for vertices left outside the hull of their neighbours,
  // then (at the resolution of double) a valid position a few ulps away
  static void repair(const internal::Flat_problem& Q, const Tile& T, std::vector<double>& xq, std::vector<C>& uvq,
                     Embedding_statistics& st)
  {
    if(!flipped_only(st))
      return;
    st.repaired_vertices += internal::repair_one_rings(Q, xq);
    certify(Q, T, xq, uvq, st);
    if(flipped_only(st)) {
      st.repaired_vertices += internal::snap_one_rings(Q, xq);
      certify(Q, T, xq, uvq, st);
    }
  }

  // Newton until rounding stops it, with every vertex's forces balanced to the floor
  void polish_to_floor(const internal::Flat_problem& Q, std::vector<double>& xq,
                       const internal::Interior_laplacian& interior, Embedding_statistics& st) const
  {
    internal::Solver_options polish = options_;
    polish.polish = true;
    polish.vertex_imbalance = 0;
    internal::Solver_statistics ps;
    internal::minimize_energy(Q, xq, polish, ps, &interior); // only accepted (descent) steps change xq
    st.polishing_iterations += ps.iterations;
    st.cg_iterations += ps.cg_iterations;
    st.energy = ps.energy;
    st.gradient_norm = ps.gradient;
    st.relative_gradient_norm = ps.relative_gradient;
  }

  struct Unresolved_faces
  {
    std::size_t count = 0;                                      // the faces flagged
    double smallest = std::numeric_limits<double>::infinity(); // the shortest edge of all
    C where;                    // the deepest vertex of the flagged faces (most face steps from the others)
    std::vector<char> flag;     // per face
  };

  // Faces that double cannot resolve (an edge within 256 units in the last place of its
  // ends), and with `not_positive` also the faces that are not positive (exact test).
  static Unresolved_faces unresolved_faces(const internal::Flat_problem& Q, const std::vector<C>& uv, bool not_positive)
  {
    Unresolved_faces u;
    u.flag.assign(Q.faces.size(), 0);
    for(std::size_t fi = 0; fi < Q.faces.size(); ++fi) {
      const auto& f = Q.faces[fi];
      for(int i = 0; i < 3; ++i) {
        const C a = uv[f[i]], b = uv[f[(i + 1) % 3]];
        const double len = abs(a - b), ulp = std::numeric_limits<double>::epsilon() * (std::max)(abs(a), abs(b));
        u.smallest = (std::min)(u.smallest, len);
        u.flag[fi] = u.flag[fi] || len < 256 * ulp;
      }
      if(not_positive && !u.flag[fi])
        u.flag[fi] = !internal::positive_triangle(uv[f[0]], uv[f[1]], uv[f[2]]);
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
  template <class Landmarks, class Cut_vertices>
  void recentre(const SeamMesh& mesh, halfedge_descriptor bhd, const Landmarks& landmarks,
                const Cut_vertices& cut_vertices, const Tile& tile, const internal::Flat_problem& P,
                std::vector<C>& uv, Embedding_statistics& st) const
  {
    const Embedding_certificate canonical = st.certificate;
    Isometry frame;
    Tile moved = tile;
    internal::Flat_problem Q;
    std::vector<C> uvq = uv;
    std::vector<double> xq;
    Unresolved_faces left = unresolved_faces(P, uvq, true);
    std::size_t best = left.count;
    for(int round = 0, idle = 0; round < max_recentring_rounds && left.count > 0 && idle < 4; ++round) {
      const Isometry step = Isometry::translation_to_origin(left.where);
      frame = step * frame;
      moved = tile.transformed(frame);
      internal::Flat_problem R;
      std::vector<TM_vertex_descriptor> base_vertex;
      Cut_vertices cut_vertices_r;
      std::string msg;
      if(internal::build_flat_topology(mesh, bhd, landmarks, moved, R, base_vertex, cut_vertices_r, msg) != OK ||
         cut_vertices_r != cut_vertices)
        return; // (the same mesh and landmarks as the first time: not expected)
      R.edge_weight = P.edge_weight;
      xq.assign(R.n_vars, 0.0);
      for(int v = 0; v < R.n; ++v) {
        const C z = step.apply(uvq[v]);
        if(R.kind[v] == internal::Free) {
          xq[R.var[v]] = z.re;
          xq[R.var[v] + 1] = z.im;
        } else if(R.kind[v] == internal::On_line) { // its Klein segment's parameter
          const C k = z * (2.0 / (1.0 + norm(z))), d = k - R.line_k0[v];
          xq[R.var[v]] = (d.re * R.line_D[v].re + d.im * R.line_D[v].im) / norm(R.line_D[v]);
        }
      }
      Q = std::move(R);
      // the faces left, and two rings around them (marked at the owners of the variables)
      auto owner = [&](int v) { return internal::owner_vertex(Q, v); };
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
      internal::Solver_options opt = options_;
      opt.max_iterations = (std::min)(opt.max_iterations, 50);
      internal::Solver_statistics rs;
      internal::minimize_energy_on_region(Q, xq, region, opt, rs);
      st.polishing_iterations += rs.iterations;
      st.cg_iterations += rs.cg_iterations;
      for(int v = 0; v < Q.n; ++v)
        uvq[v] = internal::position(Q, xq, v);
      left = unresolved_faces(Q, uvq, true);
      if(options_.verbose)
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

  Orbifold_type type_;
  Weight_type weights_;
  double epsilon_;
  Traits traits_;
  internal::Solver_options options_;
  Edge_weight_function user_weights_;
  bool recentring_ = false;
  static const int max_recentring_rounds = 24;
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_HYPERBOLIC_ORBIFOLD_TUTTE_PARAMETERIZER_3_H
