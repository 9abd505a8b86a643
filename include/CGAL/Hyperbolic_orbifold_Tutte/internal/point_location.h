// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_POINT_LOCATION_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_POINT_LOCATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/Complex.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/internal/dense_index.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/barycenter.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Sparse>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <queue>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

// Exact point location in a hyperbolic orbifold embedding, and the vertex maps between
// two surfaces embedded into the same orbifold (paper, section 7).
//
// An embedding Phi_B of a mesh B (one copy of the fundamental domain: the cut mesh,
// whose boundary is the curved image of the cut, not the tile) and its images under the
// orbifold group tile the Poincare disk. The locator finds, for a point z of the disk, a
// triangle f of B and a group element g with g(z) in f, and the barycentric coordinates
// of g(z) in f in the Klein model (where geodesic triangles are straight).
//
// Algorithm (Embedding_point_locator::locate):
//  1. z is reduced into the tile (Orbifold_tile::reduce_to_tile, exact side tests):
//     q = r(z).
//  2. A start triangle near q is read from a uniform grid over B's triangle centroids
//     (built in linear time); its Klein centroid p is strictly inside it (checked
//     exactly when the grid is built).
//  3. Straight walk from p to q in the lifted triangulation (B's triangles and their
//     images by the group, which tile the disk when Phi_B is bijective). The segment
//     [p, q] is fixed; the walk carries the group element h of the current copy. When it
//     crosses a cut edge (sphere type: the side pairing that glues the two sides, found
//     once per edge from the corner coordinates) or a border edge (disk type: the
//     reflection in the tile side holding it), h is composed with that element and only
//     the new triangle's third corner is computed as h(uv); the two corners of the
//     crossed edge are reused bit for bit, so consecutive triangles share their edge
//     exactly and no sliver opens between copies. All side tests use the exact
//     predicate Poincare_disk_traits_2<>::Hyperbolic_orientation_2 on these doubles; a
//     vertex on the line (p, q) counts as left of it (a symbolic perturbation of the
//     line), so the walk is the straight walk of a segment that meets no vertex.
//     Termination: every new triangle is checked to be positively oriented, so the exit
//     point along [p, q] strictly advances at each step; no triangle is entered twice,
//     and only the finitely many lifted triangles meeting the segment are visited. The
//     walk ends in the (closed) triangle containing q.
//  4. Safety net, for inputs where a check of step 3 fails (a rounded third corner
//     flipping a needle triangle, an embedding that is not bijective, a step count
//     beyond 4 x (number of faces) + 1000): a best-first search over lifted triangles
//     (face, group element), ordered by hyperbolic distance from q to the triangle's
//     centroid, with a visited set. Before the triangle containing q is expanded only
//     triangles closer than the farthest one along some path from the start to it can
//     be expanded, a finite set (the group acts properly discontinuously), so it ends.
//     (Capped at 64 x (number of faces) + 100000 expansions for input that is not an
//     embedding; then the candidate with the largest smallest coordinate is returned,
//     with success only if that coordinate is above -1e-9.)
//
// The reported element is g = h^{-1} r (g(z) is in the face); the barycentric coordinates
// are those of g(z) = h^{-1}(q) w.r.t. the face's stored corners, in Klein coordinates of
// B's own frame (isometries are projective, not affine, maps of the Klein disk, so the
// coordinates w.r.t. the developed corners h(uv) would be different ones), or, on request,
// in the hyperboloid model, where they are invariant under the group (Interpolation_model).
// Points given exactly at a corner's coordinates are returned at that corner with the
// barycentric coordinates (1, 0, 0) (up to the corner's position), exactly.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

inline Complex<double> poincare_to_klein(const Complex<double>& z)
{
  return z * (2.0 / (1.0 + norm(z)));
}

inline Complex<double> klein_to_poincare(const Complex<double>& k)
{
  const double s = 1.0 - norm(k);
  return k / (1.0 + std::sqrt(s > 0 ? s : 0.0));
}

// sinh^2(d/2) of the hyperbolic distance d of two Poincare points: a monotone function of d
inline double hyperbolic_proximity(const Complex<double>& a, const Complex<double>& b)
{
  const double den = (1.0 - norm(a)) * (1.0 - norm(b));
  return norm(a - b) / (den > 0 ? den : std::numeric_limits<double>::min());
}

// Barycentric coordinates of q in the triangle (a, b, c), all Poincare points, computed in
// the Klein model. Independent of the triangle's orientation. When q is bitwise one of the
// corners the result is exactly the corresponding unit vector.
inline std::array<double, 3> klein_barycentric(const Complex<double>& a, const Complex<double>& b,
                                               const Complex<double>& c, const Complex<double>& q)
{
  typedef Complex<double> C;
  const C K[3] = {poincare_to_klein(a), poincare_to_klein(b), poincare_to_klein(c)};
  const C kq = poincare_to_klein(q);
  auto cross = [](const C& u, const C& v) { return u.re * v.im - u.im * v.re; };
  std::array<double, 3> l;
  for(int i = 0; i < 3; ++i) {
    const C& u = K[(i + 1) % 3];
    const C& v = K[(i + 2) % 3];
    // the sub-triangle opposite corner i, over the whole triangle (same expression when q = K[i])
    l[i] = cross(u - kq, v - kq) / cross(u - K[i], v - K[i]);
  }
  return l;
}

// How a point of a face is parameterised by the face's geodesic triangle. Both map the
// face onto the same geodesic triangle (straight in Klein), vertices onto corners.
enum Interpolation_model
{
  // barycentric coordinates of the Klein points: the map is affine in the Klein model of
  // B's own frame. Isometries are projective, not affine, maps of the Klein disk, so the
  // two faces on either side of a cut edge (stored in frames related by a side pairing)
  // parameterise the common edge differently: a surface point on the cut, other than a
  // vertex, has two slightly different disk points (the map is not seamless there), and
  // the coordinates depend on where the cut runs.
  Klein_linear,
  // barycentric coordinates of the points of the hyperboloid model (Minkowski space),
  // where isometries are linear maps: invariant under the group, hence seamless across
  // the cut and independent of it. Related to the Klein coordinates mu by
  // lambda_i ~ mu_i (1 - |z_i|^2) / (1 + |z_i|^2), z_i the Poincare corners.
  Hyperboloid_linear
};

// 1 / (hyperboloid height) of a Poincare point: (1 - |z|^2) / (1 + |z|^2)
inline double hyperboloid_weight(const Complex<double>& z)
{
  const double n = norm(z);
  return (1.0 - n) / (1.0 + n);
}

/*
A point locator over the embedding of a triangle mesh B into a hyperbolic orbifold,
given as the corner map written by `hyperbolic_orbifold_Tutte_embedding()` (for every
halfedge `h` of a face, the Poincare point of corner `target(h)` in `face(h)`).

Built once in linear time; `locate()` is then thread-safe (const, no shared state).

\tparam TriangleMesh a model of `FaceGraph` with triangular faces
\tparam HalfedgeUVMap a readable property map from halfedges to a point type with `x()`, `y()`
*/
template <class TriangleMesh, class HalfedgeUVMap>
class Embedding_point_locator
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef Poincare_disk_traits_2<> Traits;
  typedef Traits::Point_2 Point_2;
  typedef Orbifold_tile<Traits> Tile;
  typedef Hyperbolic_isometry_2<double> Isometry;
  typedef Complex<double> C;

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  /// the answer of `locate()`
  struct Location
  {
    std::size_t face_index = npos;         ///< index of the face in `faces(B)` order
    face_descriptor face;                  ///< the face
    /// barycentric coordinates (Klein model) w.r.t. the corners of the face in the order of
    /// `halfedges_around_face(halfedge(face))`, clamped to be >= 0 and renormalised
    std::array<double, 3> barycentric{{0.0, 0.0, 0.0}};
    Isometry element;                      ///< g with g(z) in the face
    double min_raw_barycentric = 0;        ///< the smallest coordinate before clamping
    bool success = false;
    std::size_t steps = 0;                 ///< triangles visited
    bool used_search = false;              ///< the walk failed a check; the fallback search answered
  };

  Embedding_point_locator() {}

  /// builds the locator of the embedding `uv` of `tm` into the orbifold of `tile`
  Embedding_point_locator(const TriangleMesh& tm, HalfedgeUVMap uv, const Tile& tile,
                          Interpolation_model model = Hyperboloid_linear)
    : model_(model)
  {
    build(tm, uv, tile);
  }

  /// builds the locator of the embedding `uv` of `tm` into the orbifold of the given type with `k` cones
  Embedding_point_locator(const TriangleMesh& tm, HalfedgeUVMap uv, Orbifold_type type, int k,
                          Interpolation_model model = Hyperboloid_linear)
    : model_(model)
  {
    Tile tile;
    if(make_orbifold_tile(type, k, tile) != OK) {
      valid_ = false;
      message_ = "the orbifold with " + std::to_string(k) + " cones is not hyperbolic";
      return;
    }
    build(tm, uv, tile);
  }

  /// \name Access
  /// @{
  bool is_valid() const { return valid_; }
  /// how barycentric coordinates are defined (see `Interpolation_model`)
  Interpolation_model interpolation_model() const { return model_; }
  const std::string& message() const { return message_; }
  const Tile& tile() const { return tile_; }
  std::size_t number_of_faces() const { return faces_.size(); }
  std::size_t number_of_vertices() const { return vertices_.size(); }
  face_descriptor face(std::size_t i) const { return faces_[i]; }
  vertex_descriptor vertex(std::size_t i) const { return vertices_[i]; }
  /// index (in `vertices(B)` order) of corner `j` of face `i`
  std::size_t corner_vertex_index(std::size_t i, int j) const { return static_cast<std::size_t>(fd_[i].v[j]); }
  /// the stored Poincare point of corner `j` of face `i`
  Point_2 corner_point(std::size_t i, int j) const { return Point_2(fd_[i].z[j].re, fd_[i].z[j].im); }
  /// edges whose two sides carry different corner points (sphere type)
  std::size_t number_of_cut_edges() const { return n_cut_edges_; }
  /// mesh border edges (disk type), glued to themselves by the reflection in a tile side
  std::size_t number_of_border_edges() const { return n_border_edges_; }
  /// faces not positively oriented (exact test): zero for a bijective embedding
  std::size_t number_of_inverted_faces() const { return n_inverted_; }
  /// @}

  /// the Poincare point of face `i` with barycentric coordinates `b` (Klein combination of its corners)
  Point_2 disk_point(std::size_t i, const std::array<double, 3>& b) const
  {
    const Face_data& F = fd_[i];
    for(int j = 0; j < 3; ++j)
      if(b[(j + 1) % 3] == 0.0 && b[(j + 2) % 3] == 0.0)
        return Point_2(F.z[j].re, F.z[j].im); // a corner: its own point, bitwise
    C k;
    double s = 0;
    for(int j = 0; j < 3; ++j) {
      // Klein weights: the coordinates themselves, or lambda_j / w_j (hyperboloid)
      const double mu = (model_ == Klein_linear) ? b[j] : b[j] / hyperboloid_weight(F.z[j]);
      k += mu * poincare_to_klein(F.z[j]);
      s += mu;
    }
    const C z = klein_to_poincare(k / s);
    return Point_2(z.re, z.im);
  }
  Point_2 disk_point(const Location& l) const { return disk_point(l.face_index, l.barycentric); }

  /// locates `z` (Poincare coordinates, \f$|z| < 1\f$)
  Location locate(const Point_2& z) const
  {
    Location loc;
    if(!valid_ || fd_.empty())
      return loc;
    const C z0(CGAL::to_double(z.x()), CGAL::to_double(z.y()));
    if(!(norm(z0) < 1.0) || !std::isfinite(z0.re) || !std::isfinite(z0.im))
      return loc;
    // a corner's point, bitwise (before reduction: a vertex of B outside the tile is found too)
    if(corner_hit(z0, Isometry(), loc))
      return loc;
    const typename Tile::Reduction r = tile_.reduce_to_tile(Point_2(z0.re, z0.im));
    const C q(CGAL::to_double(r.point.x()), CGAL::to_double(r.point.y()));
    if(corner_hit(q, r.element, loc))
      return loc;

    const int start = start_face(q);
    Isometry h;
    if(walk(q, start, loc, h)) {
      loc.element = h.inverse() * r.element;
      return loc;
    }
    // safety net
    const std::size_t steps = loc.steps;
    loc = Location();
    search(q, start, loc, h);
    loc.steps += steps;
    loc.used_search = true;
    loc.element = h.inverse() * r.element;
    return loc;
  }

  /// locates `z` with the fallback search only (for testing it; much slower than `locate()`)
  Location locate_by_search(const Point_2& z) const
  {
    Location loc;
    if(!valid_ || fd_.empty())
      return loc;
    const typename Tile::Reduction r = tile_.reduce_to_tile(z);
    const C q(CGAL::to_double(r.point.x()), CGAL::to_double(r.point.y()));
    Isometry h;
    search(q, start_face(q), loc, h);
    loc.used_search = true;
    loc.element = h.inverse() * r.element;
    return loc;
  }

private:
  struct Face_data
  {
    C z[3];          // corner points (Poincare)
    int v[3];        // corner vertex indices
    int nf[3];       // neighbour face across edge j (corner j -> corner j+1)
    int ne[3];       // the edge's index in the neighbour face
    int tr[3];       // index of the transition element in transitions_ (0: identity, -1: none)
    bool mirror[3];  // border edge glued to itself by a reflection: the neighbour is this face, reflected
  };

  struct Key
  {
    std::uint64_t a, b;
    bool operator==(const Key& o) const { return a == o.a && b == o.b; }
  };
  struct Key_hash
  {
    std::size_t operator()(const Key& k) const
    {
      std::size_t s = 0;
      boost::hash_combine(s, k.a);
      boost::hash_combine(s, k.b);
      return s;
    }
  };
  static Key key(const C& z)
  {
    Key k;
    const double x = z.re + 0.0, y = z.im + 0.0; // -0.0 -> +0.0
    std::memcpy(&k.a, &x, sizeof(double));
    std::memcpy(&k.b, &y, sizeof(double));
    return k;
  }

  // The corners by their points' bits (open addressing, linear probing): for a point, the
  // first corner (face, j), in face order, at exactly that point
  class Corner_table
  {
  public:
    // empty, with room for about n points
    void reset(std::size_t n)
    {
      std::size_t capacity = 16;
      while(capacity < 2 * n)
        capacity *= 2;
      slots_.assign(capacity, Slot());
      size_ = 0;
    }
    // keeps the first corner inserted at a point
    void insert(const Key& k, int f, int j)
    {
      if(2 * (size_ + 1) > slots_.size())
        grow();
      Slot& s = slots_[probe(k)];
      if(s.f < 0) {
        s.k = k;
        s.f = f;
        s.j = j;
        ++size_;
      }
    }
    // the corner at k, if any
    bool find(const Key& k, std::pair<int, int>& out) const
    {
      if(slots_.empty())
        return false;
      const Slot& s = slots_[probe(k)];
      if(s.f < 0)
        return false;
      out = std::make_pair(s.f, s.j);
      return true;
    }

  private:
    struct Slot
    {
      Key k{0, 0};
      int f = -1;
      int j = 0;
    };
    std::size_t probe(const Key& k) const // the slot holding k, or the empty one where it goes
    {
      const std::size_t mask = slots_.size() - 1;
      std::uint64_t h = k.a * 0x9e3779b97f4a7c15ULL ^ (k.b + 0x632be59bd9b4e019ULL) * 0xff51afd7ed558ccdULL;
      h ^= h >> 29;
      std::size_t i = static_cast<std::size_t>(h) & mask;
      while(slots_[i].f >= 0 && !(slots_[i].k == k))
        i = (i + 1) & mask;
      return i;
    }
    void grow()
    {
      std::vector<Slot> old;
      old.swap(slots_);
      slots_.assign((std::max)(std::size_t(16), 2 * old.size()), Slot());
      for(const Slot& s : old)
        if(s.f >= 0)
          slots_[probe(s.k)] = s;
    }
    std::vector<Slot> slots_;
    std::size_t size_ = 0;
  };

  static int orient(const C& a, const C& b, const C& c)
  {
    const Traits::Hyperbolic_orientation_2 o;
    return static_cast<int>(o(Point_2(a.re, a.im), Point_2(b.re, b.im), Point_2(c.re, c.im)));
  }

  // the face edge joining corners a and b (edge j joins corners j and j+1)
  static int edge_index(int a, int b) { return ((a + 1) % 3 == b) ? a : b; }

  template <class PointT>
  static C to_c(const PointT& p) { return C(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

  void fail(const std::string& m)
  {
    valid_ = false;
    message_ = m;
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
    for(std::size_t i = 1; i < transitions_.size(); ++i) {
      const double e = error(transitions_[i]);
      if(e < best_err) {
        best_err = e;
        best = static_cast<int>(i);
      }
    }
    if(best >= 0)
      return best;
    const int ns = tile_.number_of_sides();
    for(int i = 0; i < ns; ++i)
      for(int j = 0; j < ns; ++j) {
        const Isometry g = tile_.side_pairing(i) * tile_.side_pairing(j);
        if(g.is_identity(1e-9))
          continue;
        if(error(g) < tol) {
          transitions_.push_back(g);
          return static_cast<int>(transitions_.size()) - 1;
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
    for(int s = 0; s < tile_.number_of_sides(); ++s) {
      if(tile_.paired_side(s) != s || tile_.side_pairing(s).is_orientation_preserving())
        continue;
      const C k0 = poincare_to_klein(to_c(tile_.corner(tile_.side_source(s))));
      const C k1 = poincare_to_klein(to_c(tile_.corner(tile_.side_target(s))));
      const C d = k1 - k0;
      const double len = abs(d);
      auto dist = [&](const C& p) { return std::abs(d.re * (p.im - k0.im) - d.im * (p.re - k0.re)) / len; };
      const double e = (std::max)(dist(ka), dist(kb));
      if(e < best_err) {
        best_err = e;
        best = 1 + s;
      }
    }
    return best;
  }

  void build(const TriangleMesh& tm, HalfedgeUVMap uv, const Tile& tile)
  {
    tile_ = tile;
    valid_ = true;
    message_.clear();
    transitions_.assign(1, Isometry());
    corner_table_.reset(num_vertices(tm) + num_vertices(tm) / 8); // cut vertices have several points
    for(int s = 0; s < tile_.number_of_sides(); ++s)
      transitions_.push_back(tile_.side_pairing(s)); // index 1 + s

    const Dense_index<vertex_descriptor> vindex(vertices(tm));
    vertices_.assign(vertices(tm).begin(), vertices(tm).end());
    std::vector<std::array<halfedge_descriptor, 3> > fh;
    fh.reserve(num_faces(tm));
    faces_.reserve(num_faces(tm));
    fd_.reserve(num_faces(tm));
    // per halfedge of a face: (the face's index, the edge's index in it)
    const Dense_index<halfedge_descriptor> hindex(halfedges(tm));
    std::vector<std::pair<int, int> > edge_of(hindex.size(), std::make_pair(-1, -1));
    for(face_descriptor f : faces(tm)) {
      const halfedge_descriptor h0 = halfedge(f, tm), h1 = next(h0, tm), h2 = next(h1, tm);
      if(next(h2, tm) != h0)
        return fail("the mesh has a face that is not a triangle");
      const int fi = static_cast<int>(faces_.size());
      faces_.push_back(f);
      fh.push_back({{h0, h1, h2}});
      Face_data F;
      for(int j = 0; j < 3; ++j) {
        F.z[j] = to_c(get(uv, fh.back()[j]));
        if(!std::isfinite(F.z[j].re) || !std::isfinite(F.z[j].im) || !(norm(F.z[j]) < 1.0))
          return fail("a corner point is not inside the unit disk");
        F.v[j] = static_cast<int>(vindex(target(fh.back()[j], tm)));
        F.nf[j] = -1;
        F.ne[j] = -1;
        F.tr[j] = -1;
        F.mirror[j] = false;
        edge_of[hindex(fh.back()[(j + 1) % 3])] = std::make_pair(fi, j); // edge j is halfedge h_{j+1}
      }
      fd_.push_back(F);
    }

    // adjacency and the group element across every edge
    for(std::size_t fi = 0; fi < fd_.size(); ++fi) {
      Face_data& F = fd_[fi];
      for(int j = 0; j < 3; ++j) {
        const halfedge_descriptor h = fh[fi][(j + 1) % 3];
        const halfedge_descriptor o = opposite(h, tm);
        const C& a = F.z[j];            // source(h)
        const C& b = F.z[(j + 1) % 3];  // target(h)
        if(is_border(o, tm)) {
          const int t = find_mirror(a, b);
          if(t < 0)
            return fail("a border edge of the mesh does not lie on a mirror side of the tile");
          F.nf[j] = static_cast<int>(fi);
          F.ne[j] = j;
          F.tr[j] = t;
          F.mirror[j] = true;
          ++n_border_edges_;
          continue;
        }
        const std::pair<int, int> n = edge_of[hindex(o)];
        if(n.first < 0)
          return fail("the mesh's halfedges are not consistent");
        F.nf[j] = n.first;
        F.ne[j] = n.second;
        const Face_data& G = fd_[n.first];
        // G's corner ne is target(h) = b, its corner ne+1 is source(h) = a
        const C& gb = G.z[n.second];
        const C& ga = G.z[(n.second + 1) % 3];
        if(ga == a && gb == b) {
          F.tr[j] = 0;
          continue;
        }
        // a cut edge: the neighbour's copy across it is g(G) with g(ga) = a, g(gb) = b
        const int t = find_transition(ga, a, gb, b);
        if(t < 0)
          return fail("the corner points on the two sides of a cut edge are not related by a side pairing of the tile");
        F.tr[j] = t;
        ++n_cut_edges_;
      }
    }
    n_cut_edges_ /= 2;

    // start points: Klein centroids strictly inside positively oriented faces (exact tests)
    centroid_.resize(fd_.size());
    std::vector<char> good(fd_.size(), 0);
    double xmin = 1, xmax = -1, ymin = 1, ymax = -1;
    std::size_t n_good = 0;
    for(std::size_t fi = 0; fi < fd_.size(); ++fi) {
      const Face_data& F = fd_[fi];
      const C c = klein_to_poincare((poincare_to_klein(F.z[0]) + poincare_to_klein(F.z[1]) + poincare_to_klein(F.z[2])) / 3.0);
      centroid_[fi] = c;
      if(orient(F.z[0], F.z[1], F.z[2]) <= 0) {
        ++n_inverted_;
        continue;
      }
      if(orient(F.z[0], F.z[1], c) > 0 && orient(F.z[1], F.z[2], c) > 0 && orient(F.z[2], F.z[0], c) > 0) {
        good[fi] = 1;
        ++n_good;
        xmin = (std::min)(xmin, c.re);
        xmax = (std::max)(xmax, c.re);
        ymin = (std::min)(ymin, c.im);
        ymax = (std::max)(ymax, c.im);
      }
      for(int j = 0; j < 3; ++j)
        corner_table_.insert(key(F.z[j]), static_cast<int>(fi), j);
    }
    if(n_good == 0)
      return fail("no face of the embedding is positively oriented with an inner centroid");
    if(n_inverted_ > 0)
      message_ = std::to_string(n_inverted_) + " faces are not positively oriented: the embedding is not bijective";

    // the grid: in each cell the good face whose centroid is nearest to the cell's centre;
    // empty cells take a neighbour's face (multi-source breadth-first fill)
    grid_n_ = (std::max)(1, static_cast<int>(std::sqrt(static_cast<double>(n_good) / 2.0)));
    grid_x0_ = xmin;
    grid_y0_ = ymin;
    grid_cw_ = (std::max)((xmax - xmin), 1e-300) / grid_n_;
    grid_ch_ = (std::max)((ymax - ymin), 1e-300) / grid_n_;
    const std::size_t nc = static_cast<std::size_t>(grid_n_) * grid_n_;
    grid_.assign(nc, -1);
    std::vector<double> best(nc, std::numeric_limits<double>::infinity());
    for(std::size_t fi = 0; fi < fd_.size(); ++fi) {
      if(!good[fi])
        continue;
      const C& c = centroid_[fi];
      const int cx = cell_x(c.re), cy = cell_y(c.im);
      const std::size_t id = static_cast<std::size_t>(cy) * grid_n_ + cx;
      const double dx = c.re - (grid_x0_ + (cx + 0.5) * grid_cw_), dy = c.im - (grid_y0_ + (cy + 0.5) * grid_ch_);
      const double d = dx * dx + dy * dy;
      if(d < best[id]) {
        best[id] = d;
        grid_[id] = static_cast<int>(fi);
      }
    }
    std::vector<std::size_t> queue;
    queue.reserve(nc);
    for(std::size_t id = 0; id < nc; ++id)
      if(grid_[id] >= 0)
        queue.push_back(id);
    for(std::size_t qi = 0; qi < queue.size(); ++qi) {
      const std::size_t id = queue[qi];
      const int cx = static_cast<int>(id % grid_n_), cy = static_cast<int>(id / grid_n_);
      const int nx[4] = {cx - 1, cx + 1, cx, cx};
      const int ny[4] = {cy, cy, cy - 1, cy + 1};
      for(int d = 0; d < 4; ++d) {
        if(nx[d] < 0 || ny[d] < 0 || nx[d] >= grid_n_ || ny[d] >= grid_n_)
          continue;
        const std::size_t nid = static_cast<std::size_t>(ny[d]) * grid_n_ + nx[d];
        if(grid_[nid] < 0) {
          grid_[nid] = grid_[id];
          queue.push_back(nid);
        }
      }
    }
  }

  int cell_x(double x) const
  {
    const double t = (x - grid_x0_) / grid_cw_;
    return t <= 0 ? 0 : (t >= grid_n_ - 1 ? grid_n_ - 1 : static_cast<int>(t));
  }
  int cell_y(double y) const
  {
    const double t = (y - grid_y0_) / grid_ch_;
    return t <= 0 ? 0 : (t >= grid_n_ - 1 ? grid_n_ - 1 : static_cast<int>(t));
  }
  int start_face(const C& q) const { return grid_[static_cast<std::size_t>(cell_y(q.im)) * grid_n_ + cell_x(q.re)]; }

  bool corner_hit(const C& q, const Isometry& element, Location& loc) const
  {
    std::pair<int, int> c;
    if(!corner_table_.find(key(q), c))
      return false;
    loc.face_index = static_cast<std::size_t>(c.first);
    loc.face = faces_[loc.face_index];
    loc.barycentric = {{0.0, 0.0, 0.0}};
    loc.barycentric[c.second] = 1.0;
    loc.min_raw_barycentric = 0.0;
    loc.element = element;
    loc.success = true;
    loc.steps = 0;
    return true;
  }

  // The barycentric coordinates of q in the triangle h(f), in the Klein model of B's own
  // frame: those of h^{-1}(q) w.r.t. the stored corners. (An isometry is a projective,
  // not an affine, map of the Klein disk: the coordinates w.r.t. the developed corners
  // would differ.)
  void finish(const C& q, int f, const C* D, bool identity, const Isometry& h, Location& loc) const
  {
    std::array<double, 3> l;
    if(identity) {
      l = klein_barycentric(D[0], D[1], D[2], q);
    } else {
      const Hyperbolic_isometry_2<long double> hi(h.inverse());
      const Complex<long double> w = hi.apply(Complex<long double>(q.re, q.im));
      const Face_data& F = fd_[f];
      l = klein_barycentric(F.z[0], F.z[1], F.z[2], C(static_cast<double>(w.re), static_cast<double>(w.im)));
    }
    loc.face_index = static_cast<std::size_t>(f);
    loc.face = faces_[f];
    if(!std::isfinite(l[0]) || !std::isfinite(l[1]) || !std::isfinite(l[2])) {
      // a needle too thin for double Klein coordinates: the nearest corner
      int best = 0;
      for(int j = 1; j < 3; ++j)
        if(norm(D[j] - q) < norm(D[best] - q))
          best = j;
      l = {{0.0, 0.0, 0.0}};
      l[best] = 1.0;
    }
    if(model_ == Hyperboloid_linear) {
      const Face_data& F = fd_[f];
      double t = 0;
      for(int j = 0; j < 3; ++j) {
        l[j] *= hyperboloid_weight(F.z[j]);
        t += l[j];
      }
      for(int j = 0; j < 3; ++j)
        l[j] /= t;
    }
    loc.min_raw_barycentric = (std::min)(l[0], (std::min)(l[1], l[2]));
    double s = 0;
    for(int j = 0; j < 3; ++j) {
      loc.barycentric[j] = l[j] > 0 ? l[j] : 0.0;
      s += loc.barycentric[j];
    }
    for(int j = 0; j < 3; ++j)
      loc.barycentric[j] /= s;
  }

  // The straight walk from the centroid of `start` to q (see the file's comment).
  // Returns false when a check fails (then the search answers); h: the copy's element.
  bool walk(const C& q, int start, Location& loc, Isometry& h) const
  {
    h = Isometry();
    bool identity = true;
    int f = start;
    C D[3] = {fd_[f].z[0], fd_[f].z[1], fd_[f].z[2]}; // developed corners, face corner order
    const C p = centroid_[f];
    std::size_t steps = 1;
    loc.steps = steps;
    // the start triangle is positively oriented in face corner order, p strictly inside
    int o[3];
    for(int j = 0; j < 3; ++j)
      o[j] = orient(D[j], D[(j + 1) % 3], q);
    if(o[0] >= 0 && o[1] >= 0 && o[2] >= 0) {
      finish(q, f, D, true, h, loc);
      loc.success = true;
      return true;
    }
    bool left[3];
    for(int j = 0; j < 3; ++j)
      left[j] = orient(p, q, D[j]) >= 0;
    // exit edge (u, v), counterclockwise, u right of the line p->q and v left of it
    int u = -1, v = -1;
    for(int j = 0; j < 3; ++j)
      if(!left[j] && left[(j + 1) % 3]) {
        u = j;
        v = (j + 1) % 3;
      }
    if(u < 0 || o[u] >= 0) // (edge u is the edge (u, u+1) = (u, v))
      return false;
    const std::size_t max_steps = 4 * fd_.size() + 1000;
    for(;;) {
      if(++steps > max_steps)
        return false;
      loc.steps = steps;
      // cross the edge (u, v) of face f
      const Face_data& F = fd_[f];
      const int j = edge_index(u, v);
      const int t = F.tr[j];
      if(t < 0)
        return false;
      const int nf = F.nf[j], nj = F.ne[j];
      // corner c of f on edge j -> corner of nf
      auto map_corner = [&](int c) { return F.mirror[j] ? c : (c == j ? (nj + 1) % 3 : nj); };
      const int u2 = map_corner(u), v2 = map_corner(v), s2 = 3 - u2 - v2;
      C E[3];
      E[u2] = D[u];
      E[v2] = D[v];
      if(t != 0) {
        h = h * transitions_[t];
        identity = false;
      }
      E[s2] = identity ? fd_[nf].z[s2] : h.apply(fd_[nf].z[s2]);
      // the new triangle (v, u, s) must be positively oriented
      if(orient(E[v2], E[u2], E[s2]) <= 0)
        return false;
      f = nf;
      D[0] = E[0];
      D[1] = E[1];
      D[2] = E[2];
      u = u2;
      v = v2;
      const int s = s2;
      // q is strictly beyond the entry edge (u, v): orient(v, u, q) > 0 by construction
      const int ous = orient(D[u], D[s], q), osv = orient(D[s], D[v], q);
      if(ous >= 0 && osv >= 0) {
        finish(q, f, D, identity, h, loc);
        loc.success = true;
        return true;
      }
      if(orient(p, q, D[s]) >= 0) { // s left: exit through (u, s)
        if(ous >= 0)
          return false;
        v = s;
      } else { // s right: exit through (s, v)
        if(osv >= 0)
          return false;
        u = s;
      }
    }
  }

  // Best-first search over lifted triangles (face, element), by distance from q to the
  // triangle's centroid, with a visited set keyed by the face and the image of a probe point.
  void search(const C& q, int start, Location& loc, Isometry& h_out) const
  {
    struct Node
    {
      double prio;
      int f;
      Isometry h;
    };
    struct Cmp
    {
      bool operator()(const std::pair<double, std::size_t>& a, const std::pair<double, std::size_t>& b) const
      {
        return a.first > b.first;
      }
    };
    const C probe(0.0123, 0.0456);
    auto node_key = [&](int f, const Isometry& h) {
      const C w = h.apply(probe);
      Key k;
      k.a = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(w.re * 1e9))) * 1000003u +
            static_cast<std::uint64_t>(f);
      k.b = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(w.im * 1e9)));
      return k;
    };
    std::vector<Node> nodes;
    std::priority_queue<std::pair<double, std::size_t>, std::vector<std::pair<double, std::size_t> >, Cmp> heap;
    std::unordered_set<Key, Key_hash> visited;
    auto push = [&](int f, const Isometry& h) {
      if(!visited.insert(node_key(f, h)).second)
        return;
      const double pr = hyperbolic_proximity(q, h.apply(centroid_[f]));
      nodes.push_back(Node{pr, f, h});
      heap.push(std::make_pair(pr, nodes.size() - 1));
    };
    push(start, Isometry());
    const std::size_t max_nodes = 64 * fd_.size() + 100000;
    double best_min = -std::numeric_limits<double>::infinity();
    Location best;
    Isometry best_h;
    std::size_t expanded = 0;
    while(!heap.empty() && expanded < max_nodes) {
      const Node nd = nodes[heap.top().second];
      heap.pop();
      ++expanded;
      const Face_data& F = fd_[nd.f];
      C D[3];
      const bool id = nd.h.is_identity(0.0);
      for(int j = 0; j < 3; ++j)
        D[j] = id ? F.z[j] : nd.h.apply(F.z[j]);
      const int o = orient(D[0], D[1], D[2]);
      if(o != 0) {
        bool inside = true;
        for(int j = 0; j < 3 && inside; ++j)
          inside = o * orient(D[j], D[(j + 1) % 3], q) >= 0;
        Location l;
        finish(q, nd.f, D, id, nd.h, l);
        if(inside) {
          loc = l;
          loc.success = true;
          loc.steps = expanded;
          h_out = nd.h;
          return;
        }
        if(l.min_raw_barycentric > best_min) {
          best_min = l.min_raw_barycentric;
          best = l;
          best_h = nd.h;
        }
      }
      for(int j = 0; j < 3; ++j) {
        const int t = F.tr[j];
        if(t < 0)
          continue;
        push(F.nf[j], t == 0 ? nd.h : nd.h * transitions_[t]);
      }
    }
    // not found exactly (an embedding that is not bijective, or rounding gaps between
    // copies): the best candidate, accepted if within rounding
    loc = best;
    loc.steps = expanded;
    loc.success = best.face_index != npos && best_min > -1e-9;
    h_out = best_h;
  }

  Interpolation_model model_ = Klein_linear;
  bool valid_ = false;
  std::string message_;
  Tile tile_;
  std::vector<Isometry> transitions_;
  std::vector<face_descriptor> faces_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<Face_data> fd_;
  std::vector<C> centroid_;
  Corner_table corner_table_;
  std::vector<int> grid_;
  int grid_n_ = 1;
  double grid_x0_ = 0, grid_y0_ = 0, grid_cw_ = 1, grid_ch_ = 1;
  std::size_t n_cut_edges_ = 0, n_border_edges_ = 0, n_inverted_ = 0;
};

/*
The vertex map f_AB of section 7: for every vertex of `A` in `vertices(A)` order, where
it lands on `B`: the face of `B` (`face_index` in `faces(B)` order) and the barycentric
coordinates there. The vertex's point is the point of one of its corners in `uvA` (the
corners of a cut vertex are in one orbit, so any one will do); `A` and `B` must be
embedded into the same orbifold with corresponding landmarks (landmark i at cone i).
The vertices are located in parallel when CGAL is linked with TBB (each location is
independent of the others: the same result whatever the number of threads).
*/
template <class TriangleMeshA, class HalfedgeUVMapA, class Locator>
std::vector<typename Locator::Location> map_vertices(const TriangleMeshA& A, HalfedgeUVMapA uvA, const Locator& locB)
{
  typedef typename boost::graph_traits<TriangleMeshA>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMeshA>::halfedge_descriptor halfedge_descriptor;
  typedef typename Locator::Point_2 Point_2;
  // the point of one corner of each vertex (none for an isolated vertex: not located)
  std::vector<Point_2> points;
  std::vector<char> has_point;
  points.reserve(num_vertices(A));
  has_point.reserve(num_vertices(A));
  for(vertex_descriptor v : vertices(A)) {
    halfedge_descriptor corner = boost::graph_traits<TriangleMeshA>::null_halfedge();
    const halfedge_descriptor h0 = halfedge(v, A);
    if(h0 != boost::graph_traits<TriangleMeshA>::null_halfedge())
      for(halfedge_descriptor h : halfedges_around_target(h0, A))
        if(!is_border(h, A)) {
          corner = h;
          break;
        }
    if(corner == boost::graph_traits<TriangleMeshA>::null_halfedge()) {
      points.push_back(Point_2(0, 0));
      has_point.push_back(0);
      continue;
    }
    const auto p = get(uvA, corner);
    points.push_back(Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
    has_point.push_back(1);
  }
  std::vector<typename Locator::Location> result(points.size());
  auto run = [&](std::size_t i) {
    if(has_point[i])
      result[i] = locB.locate(points[i]);
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(points.size() > 10000) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i)
        run(i);
    });
    return result;
  }
#endif
  for(std::size_t i = 0; i < points.size(); ++i)
    run(i);
  return result;
}

/*
The sparse transfer matrix of a vertex map computed by `map_vertices()`: one row per
vertex of A, one column per vertex of B (in `vertices(B)` order), the three barycentric
coordinates of the row's location at the columns of the face's corners (summed when
corners coincide). Attributes transfer as `attr_A = T * attr_B`. Rows of locations that
failed are empty.
*/
template <class Locator>
Eigen::SparseMatrix<double> transfer_matrix(const std::vector<typename Locator::Location>& locations, const Locator& locB)
{
  std::vector<Eigen::Triplet<double> > triplets;
  triplets.reserve(3 * locations.size());
  for(std::size_t i = 0; i < locations.size(); ++i) {
    const typename Locator::Location& l = locations[i];
    if(!l.success)
      continue;
    for(int j = 0; j < 3; ++j)
      if(l.barycentric[j] != 0.0)
        triplets.emplace_back(static_cast<int>(i), static_cast<int>(locB.corner_vertex_index(l.face_index, j)),
                              l.barycentric[j]);
  }
  Eigen::SparseMatrix<double> T(static_cast<Eigen::Index>(locations.size()),
                                static_cast<Eigen::Index>(locB.number_of_vertices()));
  T.setFromTriplets(triplets.begin(), triplets.end());
  T.makeCompressed();
  return T;
}

/*
The value of a vertex property of B at a location: the barycentric combination
`b0 * value(v0) + b1 * value(v1) + b2 * value(v2)` of the face's corners (the value type
needs `+` and multiplication by a `double` on the left, e.g. `double`, `Vector_3`, Eigen vectors).
*/
template <class Locator, class VertexMapB>
typename boost::property_traits<VertexMapB>::value_type
interpolate_vertex_property(const typename Locator::Location& l, const Locator& locB, VertexMapB valuesB)
{
  typedef typename boost::property_traits<VertexMapB>::value_type Value;
  const Value v0 = get(valuesB, locB.vertex(locB.corner_vertex_index(l.face_index, 0)));
  const Value v1 = get(valuesB, locB.vertex(locB.corner_vertex_index(l.face_index, 1)));
  const Value v2 = get(valuesB, locB.vertex(locB.corner_vertex_index(l.face_index, 2)));
  return l.barycentric[0] * v0 + l.barycentric[1] * v1 + l.barycentric[2] * v2;
}

/*
transfers a vertex property of B to A through a vertex map computed by `map_vertices(A, ...)`:
`put(valuesA, v, interpolate_vertex_property(location of v))` for every vertex `v` of A whose
location succeeded. Returns the number of vertices written.
*/
template <class TriangleMeshA, class Locator, class VertexMapB, class VertexMapA>
std::size_t transfer_vertex_property(const TriangleMeshA& A, const std::vector<typename Locator::Location>& locations,
                                     const Locator& locB, VertexMapB valuesB, VertexMapA valuesA)
{
  std::size_t i = 0, written = 0;
  for(auto v : vertices(A)) {
    if(i >= locations.size())
      break;
    const typename Locator::Location& l = locations[i++];
    if(!l.success)
      continue;
    put(valuesA, v, interpolate_vertex_property(l, locB, valuesB));
    ++written;
  }
  return written;
}

/*
the point of B's surface at a location, for a vertex point map of B whose points have a
CGAL kernel (`CGAL::barycenter` of the face's corners)
*/
template <class Locator, class VertexPointMapB>
typename boost::property_traits<VertexPointMapB>::value_type
surface_point(const typename Locator::Location& l, const Locator& locB, VertexPointMapB vpmB)
{
  const auto& p0 = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, 0)));
  const auto& p1 = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, 1)));
  const auto& p2 = get(vpmB, locB.vertex(locB.corner_vertex_index(l.face_index, 2)));
  return CGAL::barycenter(p0, l.barycentric[0], p1, l.barycentric[1], p2, l.barycentric[2]);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_POINT_LOCATION_H
