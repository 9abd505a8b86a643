// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_TILE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_TILE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_checks.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

/// \file Orbifold_tile.h

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

The basic tile of a hyperbolic orbifold in the Poincar&eacute; disk: a convex geodesic
polygon whose sides are glued in pairs by isometries (the side pairings), which
generate the orbifold's symmetry group; the images of the tile under the group tile
the whole disk.

The tile is plain data (corners, which cone each corner is a copy of, side pairings),
so any signature whose tile is convex, contains the origin in its interior, and whose
side pairings move points across a side closer to the origin can be represented;
`make_orbifold_tile()` builds the two families of the paper (Appendix C).

Conventions: corners are listed counterclockwise; side `i` goes from corner `i` to
corner `i+1` (modulo the number of corners); `side_pairing(i)` maps side `i` onto side
`paired_side(i)`, and the tile's neighbour across side `i` is the image of the tile by
`side_pairing(i).inverse()`.

\tparam Traits a model of `HyperbolicOrbifoldTraits_2`; `Poincare_disk_traits_2<>` by default.
*/
template <class Traits_ = Poincare_disk_traits_2<> >
class Orbifold_tile
{
public:
  /// the geometric traits
  typedef Traits_ Traits;
  /// the number type of the traits
  typedef typename Traits::FT FT;
  /// the point type of the traits (Poincar&eacute;-disk coordinates)
  typedef typename Traits::Point_2 Point_2;
  /// the isometry type of the traits: the side pairings and group elements
  typedef typename Traits::Isometry Isometry;

private:
  typedef Hyperbolic_isometry_2<long double> Isometry_ld;
  typedef typename Isometry_ld::Complex Complex_ld;

public:
  /// the result of `reduce_to_tile()`
  struct Reduction
  {
    Point_2 point;      ///< the image of the input point in the tile
    Isometry element;   ///< the group element used: `point` = `element(input)`
    std::size_t steps;  ///< the number of side pairings applied
  };

  Orbifold_tile() {}

  /// builds a tile from its data; see the class documentation for the conventions.
  Orbifold_tile(const Orbifold_signature& signature,
                const std::vector<Point_2>& corners,
                const std::vector<int>& corner_cones,
                const std::vector<double>& corner_angles,
                const std::vector<int>& paired_sides,
                const std::vector<Isometry>& side_pairings,
                const Traits& traits = Traits())
    : signature_(signature), corners_(corners), corner_cones_(corner_cones), corner_angles_(corner_angles),
      paired_sides_(paired_sides), side_pairings_(side_pairings), traits_(traits)
  {
    for(const Isometry& g : side_pairings_)
      side_pairings_ld_.push_back(Isometry_ld(g));
    cone_corners_.assign(signature_.number_of_cones(), -1);
    for(std::size_t i = 0; i < corners_.size(); ++i)
      if(corner_cones_[i] >= 0 && cone_corners_[corner_cones_[i]] < 0) // (-1: a corner that is no cone)
        cone_corners_[corner_cones_[i]] = static_cast<int>(i);
  }

  /// \name Access
  /// @{

  /// the orbifold's signature
  const Orbifold_signature& signature() const { return signature_; }
  /// sphere type or disk type
  Orbifold_type type() const { return signature_.type(); }
  /// the number of cones (sphere type) or boundary corners (disk type) of the orbifold
  int number_of_cones() const { return signature_.number_of_cones(); }
  /// the orbifold's hyperbolic area (Gauss-Bonnet), which is also the tile's
  double area() const { return signature_.area(); }

  /// the number of corners of the tile (\f$2k-2\f$ for sphere type, \f$k\f$ for disk type)
  int number_of_corners() const { return static_cast<int>(corners_.size()); }
  /// corner `i`
  const Point_2& corner(int i) const { return corners_[i]; }
  /// the corners, counterclockwise
  const std::vector<Point_2>& corners() const { return corners_; }
  /// the cone of which corner `i` is a copy; -1 for a corner that is no cone (a vertex of the
  /// cut graph of a surface of genus \f$ g \ge 1 \f$, where its copies' angles add up to \f$2\pi\f$)
  int corner_cone(int i) const { return corner_cones_[i]; }
  /// the tile's interior angle at corner `i`
  double corner_angle(int i) const { return corner_angles_[i]; }
  /// the first corner (in counterclockwise order from corner 0) that is a copy of cone `c`:
  /// where the embedding places landmark `c`
  int cone_corner(int c) const { return cone_corners_[c]; }
  /// the point of corner `cone_corner(c)`
  const Point_2& cone_point(int c) const { return corners_[cone_corners_[c]]; }

  /// the number of sides (equal to the number of corners)
  int number_of_sides() const { return number_of_corners(); }
  /// the corner where side `i` starts: `i`
  int side_source(int i) const { return i; }
  /// the corner where side `i` ends: `i+1` modulo the number of corners
  int side_target(int i) const { return (i + 1) % number_of_corners(); }
  /// the side glued to side `i` (side `i` itself for disk type)
  int paired_side(int i) const { return paired_sides_[i]; }
  /// the isometry mapping side `i` onto side `paired_side(i)`
  const Isometry& side_pairing(int i) const { return side_pairings_[i]; }
  /// the geometric traits
  const Traits& traits() const { return traits_; }
  /// @}

  /// \name Operations
  /// @{

  /// the image of the tile under the orientation-preserving isometry `m`: corners
  /// \f$ m(c_i) \f$, side pairings \f$ m\, g_i\, m^{-1} \f$ (the same orbifold, another
  /// fundamental domain of a conjugate group). `reduce_to_tile()` and `group_elements()`
  /// assume a tile around the origin: use them on the tile before it is moved.
  Orbifold_tile transformed(const Isometry& m) const
  {
    std::vector<Point_2> corners;
    for(const Point_2& c : corners_)
      corners.push_back(m(c));
    std::vector<Isometry> pairings;
    const Isometry mi = m.inverse();
    for(const Isometry& g : side_pairings_)
      pairings.push_back(m * g * mi);
    return Orbifold_tile(signature_, corners, corner_cones_, corner_angles_, paired_sides_, pairings, traits_);
  }

  /// position of `p` with respect to the tile, decided exactly on the coordinates of `p` and of the corners
  Bounded_side bounded_side(const Point_2& p) const
  {
    typename Traits::Hyperbolic_orientation_2 orient = traits_.hyperbolic_orientation_2_object();
    bool on_boundary = false;
    for(int i = 0; i < number_of_sides(); ++i) {
      const Orientation o = orient(corners_[side_source(i)], corners_[side_target(i)], p);
      if(o == NEGATIVE)
        return ON_UNBOUNDED_SIDE;
      if(o == ZERO)
        on_boundary = true;
    }
    return on_boundary ? ON_BOUNDARY : ON_BOUNDED_SIDE;
  }

  /// maps `p` into the tile by elements of the group: while `p` lies beyond a side
  /// (exact test), the side's pairing is applied. For the tiles of this package each
  /// step strictly decreases the hyperbolic distance to the origin, so the loop ends;
  /// once a step no longer decreases it in floating point (a point within rounding of
  /// the tile's boundary), the point before that step is returned.
  /// Works for points arbitrarily close to the unit circle (as long as \f$|p| < 1\f$ in double).
  /// \pre \f$ |p| < 1 \f$ and the tile is not empty
  Reduction reduce_to_tile(const Point_2& p) const
  {
    // The loop runs in long double (64-bit mantissa on x86-64): near the unit circle a
    // group element has large coefficients, and composing them in double would lose
    // the digits that the point's position needs.
    typename Traits::Hyperbolic_orientation_2 orient = traits_.hyperbolic_orientation_2_object();
    Complex_ld z(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    Isometry_ld element;
    std::size_t steps = 0;
    long double radius2 = internal::squared_modulus(z);
    const std::size_t max_steps = 100000; // far more than any point representable in double needs
    for(; steps < max_steps; ++steps) {
      int violated = -1;
      const Point_2 zp(static_cast<double>(z.real()), static_cast<double>(z.imag()));
      for(int i = 0; i < number_of_sides(); ++i) {
        if(orient(corners_[side_source(i)], corners_[side_target(i)], zp) == NEGATIVE) {
          violated = i;
          break;
        }
      }
      if(violated < 0)
        break;
      const Complex_ld w = side_pairings_ld_[violated].apply(z);
      const long double w2 = internal::squared_modulus(w);
      if(!(w2 < radius2))
        break; // rounding-level boundary point: keep the closest image
      z = w;
      radius2 = w2;
      element = side_pairings_ld_[violated] * element;
    }
    const Isometry e(element);
    return Reduction{Point_2(static_cast<double>(z.real()), static_cast<double>(z.imag())), e, steps};
  }

  /// the group elements that are products of at most `depth` side pairings, without
  /// repetitions (the identity first): the tiles around this one, as in the paper's Figure 4.
  std::vector<Isometry> group_elements(int depth) const
  {
    typedef typename Isometry::Complex C;
    std::vector<Isometry> result(1, Isometry());
    // Two elements are the same iff they move a generic interior point to the same place
    // (the group acts freely on the tile's interior).
    const C probe(0.0123, 0.0456);
    std::vector<C> images(1, probe);
    std::size_t begin = 0;
    for(int d = 0; d < depth; ++d) {
      const std::size_t end = result.size();
      for(std::size_t e = begin; e < end; ++e) {
        for(int i = 0; i < number_of_sides(); ++i) {
          const Isometry g = side_pairings_[i] * result[e];
          const C img = g.apply(probe);
          bool seen = false;
          for(const C& q : images)
            if(internal::squared_modulus(q - img) < 1e-20) { seen = true; break; }
          if(!seen) {
            result.push_back(g);
            images.push_back(img);
          }
        }
      }
      begin = end;
    }
    return result;
  }
  /// @}

private:
  Orbifold_signature signature_;
  std::vector<Point_2> corners_;
  std::vector<int> corner_cones_;
  std::vector<double> corner_angles_;
  std::vector<int> cone_corners_;
  std::vector<int> paired_sides_;
  std::vector<Isometry> side_pairings_;
  std::vector<Isometry_ld> side_pairings_ld_;
  Traits traits_;
};

namespace internal {

// The sphere-type tile of the paper's Appendix C from a convex k-gon p (counterclockwise, in
// Poincare coordinates) with interior angles alpha: the polygon moved so that the geodesic
// midpoint of p_k and p_1 is the origin (p_1 on the positive real axis, the polygon in the
// upper half-disk), united with its mirror image q_j = conj(p_j). Corners p_1 .. p_k,
// q_{k-1} .. q_2; p_j and q_j are copies of cone j-1, with angles 2 alpha at p_1 and p_k and
// alpha at the others (their two copies together: 2 alpha, the cone angle 2 pi / n when
// alpha = pi / n). Side p_j p_{j+1} is glued to side q_j q_{j+1} by "reflect in the geodesic
// p_j p_{j+1}, then conjugate" (orientation-preserving; it moves a point beyond a side closer
// to the origin, since the origin is inside the tile).
template <class Traits>
Error_code double_polygon_into_sphere_tile(const Orbifold_signature& signature, const std::vector<std::complex<double> >& p,
                                           const std::vector<double>& alpha, Orbifold_tile<Traits>& tile, const Traits& traits)
{
  typedef Orbifold_tile<Traits> Tile;
  typedef typename Tile::Isometry Isometry;
  typedef typename Isometry::Complex C;
  typedef typename Tile::Point_2 Point_2;
  typedef typename Tile::FT FT;
  const int k = static_cast<int>(p.size());
  auto to_point = [](const C& z) { return Point_2(FT(z.real()), FT(z.imag())); };

  // Sphere type: move the geodesic midpoint of p_k and p_1 to the origin, p_1 to the positive real axis.
  const Point_2 mid = traits.construct_hyperbolic_midpoint_2_object()(to_point(p[k - 1]), to_point(p[0]));
  const Isometry to0 = Isometry::translation_to_origin(C(CGAL::to_double(mid.x()), CGAL::to_double(mid.y())));
  const Isometry place = Isometry::rotation(-std::arg(to0.apply(p[0]))) * to0;
  std::vector<C> P(k);
  for(int j = 0; j < k; ++j)
    P[j] = place.apply(p[j]);
  // p_1 and p_k are on the real axis by construction; remove the rounding noise so that
  // the shared side is exactly the real diameter and q_1 = p_1, q_k = p_k exactly.
  const double x = 0.5 * (P[0].real() - P[k - 1].real());
  P[0] = C(x, 0.0);
  P[k - 1] = C(-x, 0.0);

  std::vector<Point_2> corners;
  std::vector<int> cones;
  std::vector<double> angles;
  for(int j = 0; j < k; ++j) { // p_1 .. p_k
    corners.push_back(to_point(P[j]));
    cones.push_back(j);
    angles.push_back((j == 0 || j == k - 1) ? 2 * alpha[j] : alpha[j]);
  }
  for(int j = k - 2; j >= 1; --j) { // q_{k-1} .. q_2
    corners.push_back(to_point(std::conj(P[j])));
    cones.push_back(j);
    angles.push_back(alpha[j]);
  }
  const int n = 2 * k - 2;
  std::vector<int> paired(n);
  std::vector<Isometry> pairings(n);
  const Isometry conj = Isometry::complex_conjugation();
  for(int j = 1; j <= k - 1; ++j) {
    // side j-1 is p_j p_{j+1}; side 2k-2-j is q_{j+1} q_j.
    const Isometry m = conj * Isometry::reflection_in_geodesic(P[j - 1], P[j]);
    paired[j - 1] = 2 * k - 2 - j;
    paired[2 * k - 2 - j] = j - 1;
    pairings[j - 1] = m;
    pairings[2 * k - 2 - j] = m.inverse();
  }
  tile = Tile(signature, corners, cones, angles, paired, pairings, traits);
  return OK;
}


// The convex k-gon with interior angles alpha_j (sum below (k - 2) pi) whose sides touch the
// circle of hyperbolic radius r about the origin (a tangential polygon; it exists for any such
// angles, and is the regular one for equal angles). In the right triangle (origin, corner j,
// touching point) the angle at the origin theta_j satisfies cos(alpha_j / 2) = cosh(r)
// sin(theta_j), and the corner's distance d_j to the origin cosh(d_j) = cot(alpha_j / 2)
// cot(theta_j); r is where the angles theta_j, each counted twice, go once around the origin.
// Corner 1 at angle theta_1 (the side from corner k to corner 1 touches the circle at angle 0).
inline std::vector<std::complex<double> > tangential_polygon(const std::vector<double>& alpha)
{
  const int k = static_cast<int>(alpha.size());
  auto theta = [&](int j, double cosh_r) { return std::asin((std::min)(1.0, std::cos(alpha[j] / 2) / cosh_r)); };
  auto turn = [&](double cosh_r) {
    double t = 0;
    for(int j = 0; j < k; ++j)
      t += 2 * theta(j, cosh_r);
    return t;
  };
  // turn() decreases from sum(pi - alpha_j) > 2 pi at r = 0 to 0 as r grows
  double lo = 1.0, hi = 2.0;
  while(turn(hi) > 2 * CGAL_PI)
    hi *= 2;
  for(int it = 0; it < 200 && hi - lo > 1e-16 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (turn(mid) > 2 * CGAL_PI ? lo : hi) = mid;
  }
  const double cosh_r = 0.5 * (lo + hi);
  std::vector<std::complex<double> > p(k);
  double phi = 0;
  for(int j = 0; j < k; ++j) {
    const double t = theta(j, cosh_r);
    phi += (j == 0) ? t : theta(j - 1, cosh_r) + t;
    const double cosh_d = 1.0 / (std::tan(alpha[j] / 2) * std::tan(t));
    p[j] = std::polar(std::sqrt((cosh_d - 1.0) / (cosh_d + 1.0)), phi); // tanh(d / 2)
  }
  return p;
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

builds the basic tile of the sphere-type (`k` cones of angle \f$\pi\f$) or disk-type
(`k` corners of angle \f$\pi/2\f$) hyperbolic orbifold, following the paper's Appendix C.

Disk type: the regular right-angled `k`-gon centred at the origin, corners
\f$ p_j = \tanh(l/2)\, e^{2\pi i j/k} \f$, \f$ j = 1..k \f$, with \f$ \cosh l = \cot(\pi/k) \f$;
corner `j-1` is cone `j-1`; each side is paired with itself by the reflection in it.

Sphere type: that `k`-gon moved so that the geodesic midpoint of \f$p_k, p_1\f$ is the
origin, \f$p_1\f$ on the positive and \f$p_k\f$ on the negative real axis (so the polygon lies
in the upper half-disk), united with its mirror image \f$q_j = \bar p_j\f$. The corners,
counterclockwise, are \f$ p_1, \dots, p_k, q_{k-1}, \dots, q_2 \f$ (\f$2k-2\f$ of them);
\f$p_j\f$ and \f$q_j\f$ are copies of cone `j-1`. Side \f$p_j p_{j+1}\f$ is glued to side
\f$q_j q_{j+1}\f$ by the orientation-preserving isometry "reflect in the geodesic
\f$p_j p_{j+1}\f$, then conjugate".

\tparam Traits a model of `HyperbolicOrbifoldTraits_2`
\param type sphere type or disk type
\param k the number of cones (sphere type) or corners (disk type)
\param tile receives the tile
\param traits the geometric traits stored in the tile

\return `OK`, or `ERROR_NOT_HYPERBOLIC` when `k < 5` (the tile is left unchanged then).
*/
template <class Traits>
Error_code make_orbifold_tile(Orbifold_type type, int k, Orbifold_tile<Traits>& tile,
                              const Traits& traits = Traits())
{
  typedef Orbifold_tile<Traits> Tile;
  typedef typename Tile::Isometry Isometry;
  typedef typename Isometry::Complex C;
  typedef typename Tile::Point_2 Point_2;
  typedef typename Tile::FT FT;

  const Orbifold_signature signature =
    (type == Sphere_type) ? Orbifold_signature::sphere(k) : Orbifold_signature::disk(k);
  if(k < 5 || !signature.is_hyperbolic())
    return ERROR_NOT_HYPERBOLIC;

  // Regular right-angled k-gon: cosh(l) = cot(pi/k), Euclidean radius tanh(l/2).
  const double cosh_l = 1.0 / std::tan(CGAL_PI / k);
  const double radius = std::sqrt((cosh_l - 1.0) / (cosh_l + 1.0));
  std::vector<C> p(k);
  for(int j = 1; j <= k; ++j)
    p[j - 1] = std::polar(radius, 2.0 * CGAL_PI * j / k);

  auto to_point = [](const C& z) { return Point_2(FT(z.real()), FT(z.imag())); };

  if(type == Disk_type) {
    std::vector<Point_2> corners;
    std::vector<int> cones, paired;
    std::vector<double> angles;
    std::vector<Isometry> pairings;
    for(int i = 0; i < k; ++i) {
      corners.push_back(to_point(p[i]));
      cones.push_back(i);
      angles.push_back(CGAL_PI / 2);
      paired.push_back(i);
      pairings.push_back(Isometry::reflection_in_geodesic(p[i], p[(i + 1) % k]));
    }
    tile = Tile(signature, corners, cones, angles, paired, pairings, traits);
    return OK;
  }

  return internal::double_polygon_into_sphere_tile(signature, p, std::vector<double>(k, CGAL_PI / 2), tile, traits);
}

/// \ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
/// builds the tile of the signature `signature` (see the other overload).
/// \tparam Traits a model of `HyperbolicOrbifoldTraits_2`
/// \param signature a signature whose orders are all 2
/// \param tile receives the tile
/// \param traits the geometric traits stored in the tile
/// \return `OK`, `ERROR_WRONG_PARAMETER` when an order is below 2, for disk type when an
/// order is not 2 (not built yet), and for genus \f$ g \ge 1 \f$ (see `make_cut_graph_tile()`),
/// or `ERROR_NOT_HYPERBOLIC` when the orbifold is not hyperbolic
template <class Traits>
Error_code make_orbifold_tile(const Orbifold_signature& signature, Orbifold_tile<Traits>& tile,
                              const Traits& traits = Traits())
{
  if(signature.genus() > 0)
    return ERROR_WRONG_PARAMETER; // a surface of genus g >= 1: its tile is the polygon of a cut graph (make_cut_graph_tile())
  const int k = signature.number_of_cones();
  const Error_code ec = check_cone_orders(signature, static_cast<std::size_t>(k)); // (orders of at least 2, hyperbolic)
  if(ec != OK)
    return ec;
  bool all_two = true;
  for(int i = 0; i < k; ++i)
    all_two = all_two && signature.order(i) == 2;
  if(all_two)
    return make_orbifold_tile(signature.type(), k, tile, traits); // (the paper's regular tiles, as they always were)
  if(signature.type() != Sphere_type)
    return ERROR_WRONG_PARAMETER; // not built yet: disk corners other than right angles
  std::vector<double> alpha(k);
  for(int i = 0; i < k; ++i)
    alpha[i] = CGAL_PI / signature.order(i);
  return internal::double_polygon_into_sphere_tile(signature, internal::tangential_polygon(alpha), alpha, tile, traits);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

builds the tile of a closed orbifold of genus \f$ g \ge 1 \f$ (`signature`) cut open along a
graph into a disk: the polygon whose corners, counterclockwise, are the copies of the graph's
nodes along the disk's border (a node is a vertex of the cut graph whose degree is not 2, or
a cone), and whose sides, the copies of the graph's edges between nodes, are glued in pairs.

Corner `i` is a copy of node `corner_node[i]`; `node_cone[n]` is the cone of node `n` (an
index into the signature's orders) or -1; side `i` (from corner `i` to corner `i+1`) is a copy
of the edge that side `paired_side[i]` runs along in the opposite direction, so corner `i` is
a copy of the node of corner `paired_side[i] + 1` and corner `i+1` of that of corner
`paired_side[i]`.

The polygon: every copy of a node with \f$ d \f$ copies and order \f$ p \f$ (1 when it is no
cone) has the angle \f$ 2\pi/(p\,d) \f$, so that the copies of a node add up to its cone angle
(\f$2\pi\f$ for a regular point); the polygon with these angles whose sides touch a circle about
the origin (tangential) has equal lengths on paired sides, which the side pairings (the
orientation-preserving isometries mapping side `i` onto side `paired_side[i]` reversed)
therefore glue. By Poincar&eacute;'s polygon theorem they generate a Fuchsian group for which
the polygon is a fundamental domain of the orbifold. Its area is the signature's
(Gauss-Bonnet), which is how a cut graph that does not fit the signature is recognised.

\return `OK`; `ERROR_NOT_HYPERBOLIC` when the signature is not hyperbolic;
`ERROR_WRONG_PARAMETER` when the data are inconsistent (sizes, a pairing that is not an
involution or whose corners are not copies of the same nodes, a cone without a node, a node
of one copy that is no cone, or a polygon whose area is not the signature's). The tile is left
unchanged on failure.
*/
template <class Traits>
Error_code make_cut_graph_tile(const Orbifold_signature& signature, const std::vector<int>& corner_node,
                               const std::vector<int>& node_cone, const std::vector<int>& paired_side,
                               Orbifold_tile<Traits>& tile, const Traits& traits = Traits())
{
  typedef Orbifold_tile<Traits> Tile;
  typedef typename Tile::Isometry Isometry;
  typedef typename Isometry::Complex C;
  typedef typename Tile::Point_2 Point_2;
  typedef typename Tile::FT FT;
  if(signature.type() != Sphere_type || !signature.is_hyperbolic())
    return ERROR_NOT_HYPERBOLIC;
  const int n = static_cast<int>(corner_node.size());
  const int nodes = static_cast<int>(node_cone.size());
  if(n < 3 || static_cast<int>(paired_side.size()) != n)
    return ERROR_WRONG_PARAMETER;
  std::vector<int> copies(nodes, 0), cone_seen(signature.number_of_cones(), 0);
  for(int c : corner_node) {
    if(c < 0 || c >= nodes)
      return ERROR_WRONG_PARAMETER;
    ++copies[c];
  }
  for(int m = 0; m < nodes; ++m) {
    const int cone = node_cone[m];
    if(cone >= signature.number_of_cones() || (cone >= 0 && cone_seen[cone]++ > 0) || copies[m] == 0 ||
       (cone < 0 && copies[m] < 2))
      return ERROR_WRONG_PARAMETER;
  }
  for(int seen : cone_seen)
    if(seen != 1)
      return ERROR_WRONG_PARAMETER;
  for(int i = 0; i < n; ++i) {
    const int j = paired_side[i];
    if(j < 0 || j >= n || j == i || paired_side[j] != i || corner_node[i] != corner_node[(j + 1) % n] ||
       corner_node[(i + 1) % n] != corner_node[j])
      return ERROR_WRONG_PARAMETER;
  }
  std::vector<double> alpha(n);
  std::vector<int> cones(n);
  double turn = 0;
  for(int i = 0; i < n; ++i) {
    const int m = corner_node[i];
    const int p = node_cone[m] >= 0 ? signature.order(node_cone[m]) : 1;
    alpha[i] = 2 * CGAL_PI / (p * copies[m]);
    cones[i] = node_cone[m];
    turn += CGAL_PI - alpha[i];
  }
  const double area = turn - 2 * CGAL_PI; // (n - 2) pi minus the angles
  if(!(std::abs(area - signature.area()) <= 1e-9 * (1.0 + signature.area())))
    return ERROR_WRONG_PARAMETER; // the cut graph's Euler characteristic is not the signature's
  const std::vector<C> p = internal::tangential_polygon(alpha);
  auto to_point = [](const C& z) { return Point_2(FT(z.real()), FT(z.imag())); };
  // the isometry taking a to the origin and b onto the positive real axis
  auto frame = [](const C& a, const C& b) {
    const Isometry to0 = Isometry::translation_to_origin(a);
    return Isometry(Isometry::rotation(-std::arg(to0.apply(b))) * to0);
  };
  std::vector<Point_2> corners;
  std::vector<Isometry> pairings;
  for(int i = 0; i < n; ++i) {
    corners.push_back(to_point(p[i]));
    const int j = paired_side[i];
    // side i (p_i -> p_{i+1}) onto side j reversed (p_{j+1} -> p_j)
    pairings.push_back(frame(p[(j + 1) % n], p[j]).inverse() * frame(p[i], p[(i + 1) % n]));
  }
  tile = Tile(signature, corners, cones, alpha, paired_side, pairings, traits);
  return OK;
}

namespace internal {

// The tile of `type` with cones of orders `orders` (one per landmark, in the order of the
// cut), for `k` landmarks, with a message that names the signature when there is none.
template <class Traits>
Status tile_of_cone_orders(Orbifold_type type, const std::vector<int>& orders, int k, Orbifold_tile<Traits>& tile,
                           const Traits& traits)
{
  const Orbifold_signature sig(type, orders);
  Cone_order_check check;
  const Error_code checked = check_cone_orders(sig, static_cast<std::size_t>(k < 0 ? 0 : k), &check);
  if(checked != OK)
    return Status::failure(checked, check.message);
  const Error_code ec = make_orbifold_tile(sig, tile, traits);
  if(ec == OK)
    return Status();
  return Status::failure(ec, "cone orders other than 2 are built for sphere-type orbifolds only (disk corners are right angles)");
}

} // namespace internal

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_TILE_H
