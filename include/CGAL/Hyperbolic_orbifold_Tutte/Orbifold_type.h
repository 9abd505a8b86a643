// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_TYPE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_TYPE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/number_type_config.h> // CGAL_PI

#include <utility>
#include <vector>

/// \file Orbifold_type.h
/// The vocabulary of the orbifolds: their type (`Orbifold_type`) and their signature
/// (`Orbifold_signature`: genus and cone orders, Euler characteristic, hyperbolicity), without
/// the tiles (`Orbifold_tile.h`) and their geometry.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums
The topology of the target orbifold.
*/
enum Orbifold_type
{
  Sphere_type, ///< a closed surface with cone points (for closed meshes: a sphere for genus 0, a surface of genus g otherwise)
  Disk_type,   ///< a disk with corner points on its boundary (for meshes with one boundary loop)
  Closed_type = Sphere_type ///< another name of `Sphere_type`, for closed meshes of any genus
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses

The signature of an orientable orbifold: a closed surface of genus \f$ g \f$ with cone
points of orders \f$ n_i \f$ (cone angle \f$ 2\pi/n_i \f$), or a disk (genus 0, one boundary
loop) with corner reflectors of orders \f$ m_j \f$ (corner angle \f$ \pi/m_j \f$) on its
boundary, in Conway's notation. Its orbifold Euler characteristic is
\f$ \chi = 2 - 2g - \sum_i (1 - 1/n_i) \f$ without boundary and
\f$ \chi = 1 - \sum_i (1 - 1/n_i) - \frac12 \sum_j (1 - 1/m_j) \f$ with one boundary;
it is hyperbolic if and only if \f$ \chi < 0 \f$, and its hyperbolic area is then
\f$ -2\pi\chi \f$ (Gauss-Bonnet).

The package builds tiles for: sphere type (genus 0) with cones of any orders, the paper's
families (section 3) with \f$k \ge 5\f$ cones of angle \f$\pi\f$ among them; disk type with
\f$k \ge 5\f$ corners of angle \f$\pi/2\f$; and closed surfaces of genus \f$ g \ge 1 \f$ with
cones of any orders, whose tile is the polygon of a cut graph (`make_cut_graph_tile()`).
*/
class Orbifold_signature
{
public:
  Orbifold_signature() : type_(Sphere_type) {}
  /// the signature of the given type with cone (sphere type) or corner (disk type) orders `orders`
  Orbifold_signature(Orbifold_type type, std::vector<int> orders) : type_(type), orders_(std::move(orders)) {}
  /// the closed surface of genus `genus` with cones of orders `orders` (`Sphere_type`; genus 0: a sphere)
  Orbifold_signature(int genus, std::vector<int> orders)
    : type_(Sphere_type), genus_(genus < 0 ? 0 : genus), orders_(std::move(orders)) {}

  /// sphere type with `k` cones of angle \f$\pi\f$
  static Orbifold_signature sphere(int k) { return Orbifold_signature(Sphere_type, std::vector<int>(k < 0 ? 0 : k, 2)); }
  /// disk type with `k` boundary corners of angle \f$\pi/2\f$
  static Orbifold_signature disk(int k) { return Orbifold_signature(Disk_type, std::vector<int>(k < 0 ? 0 : k, 2)); }

  /// sphere type or disk type
  Orbifold_type type() const { return type_; }
  /// the genus of the underlying surface (0 for disk type)
  int genus() const { return genus_; }
  /// number of cones (sphere type) or boundary corners (disk type)
  int number_of_cones() const { return static_cast<int>(orders_.size()); }
  /// the order \f$ n \f$ of cone `i`
  int order(int i) const { return orders_[i]; }
  /// the angle of cone `i`: \f$ 2\pi/n \f$ for a cone point, \f$ \pi/n \f$ for a boundary corner
  double cone_angle(int i) const { return (type_ == Sphere_type ? 2.0 : 1.0) * CGAL_PI / orders_[i]; }

  /// the orbifold Euler characteristic
  double euler_characteristic() const
  {
    double chi = (type_ == Sphere_type) ? 2.0 - 2.0 * genus_ : 1.0;
    for(int n : orders_)
      chi -= (type_ == Sphere_type ? 1.0 : 0.5) * (1.0 - 1.0 / n);
    return chi;
  }
  /// `true` when the orbifold is hyperbolic (negative Euler characteristic)
  bool is_hyperbolic() const { return euler_characteristic() < -1e-12; }
  /// the hyperbolic area \f$ -2\pi\chi \f$ of a hyperbolic orbifold
  double area() const { return -2.0 * CGAL_PI * euler_characteristic(); }

private:
  Orbifold_type type_;
  int genus_ = 0;
  std::vector<int> orders_;
};

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_ORBIFOLD_TYPE_H
