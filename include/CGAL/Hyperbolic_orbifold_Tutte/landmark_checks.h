// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_CHECKS_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_CHECKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

/// \file landmark_checks.h
/// The checks of the landmarks' number and of their cone orders, written once for every entry
/// point (the one-call function, the parameterizer, the tiles, the collection, the certifiers);
/// the checks of the landmark vertices themselves (in range, distinct, on the border) are
/// `check_landmarks()` of `check_input.h`, which uses the minimum numbers below.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
the number of landmarks (cones or corners) the orbifolds need at least.
*/
inline constexpr std::size_t minimum_number_of_landmarks = 5;

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions
the fewest landmarks (cones) that make the orbifold of a mesh hyperbolic: on a closed mesh of
genus 0, 5 cones of angle \f$\pi\f$, or 3 when cone orders are given (\f$(2,3,7)\f$...); on a
closed mesh of genus 1, one cone; of genus 2 or more, none; on a disk, 5 right-angled corners.
*/
inline std::size_t minimum_number_of_landmarks_for(Orbifold_type type, long long genus, bool cone_orders_given)
{
  if(type == Sphere_type && genus >= 2)
    return 0;
  if(type == Sphere_type && genus == 1)
    return 1;
  return (cone_orders_given && type == Sphere_type) ? 3 : minimum_number_of_landmarks;
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteEnums
which check of `check_cone_orders()` failed.
*/
enum Cone_order_problem
{
  No_cone_order_problem,       ///< the orders passed the checks
  Wrong_number_of_cone_orders, ///< not one order per landmark
  Cone_order_below_two,        ///< an order below 2
  Cone_orders_not_hyperbolic   ///< the orbifold is not hyperbolic
};

/*!
\ingroup PkgHyperbolicOrbifoldTutteMainClasses
what `check_cone_orders()` found.
*/
struct Cone_order_check
{
  Cone_order_problem problem = No_cone_order_problem; ///< the failed check
  std::size_t index = 0;  ///< `Cone_order_below_two`: the first order below 2
  double sum = 0;         ///< `Cone_orders_not_hyperbolic`, genus 0: \f$\sum (1 - 1/p)\f$ over the cones
  std::string message;    ///< why, in one line (empty when the orders passed)
};

namespace internal {

// the orders as "p1,p2,..."
inline std::string cone_order_list(const std::vector<int>& orders)
{
  std::string list;
  for(int p : orders)
    list += (list.empty() ? "" : ",") + std::to_string(p);
  return list;
}

// the count and the orders of at least 2, as check_cone_orders() checks them
inline Error_code check_cone_order_values(const std::vector<int>& orders, std::size_t number_of_landmarks,
                                          Cone_order_check& c)
{
  std::ostringstream os;
  if(orders.size() != number_of_landmarks) {
    c.problem = Wrong_number_of_cone_orders;
    os << orders.size() << " cone orders are given for " << number_of_landmarks << " landmarks (one per landmark is needed)";
    c.message = os.str();
    return ERROR_WRONG_PARAMETER;
  }
  for(std::size_t i = 0; i < orders.size(); ++i)
    if(orders[i] < 2) {
      c.problem = Cone_order_below_two;
      c.index = i;
      os << "the cone orders (" << cone_order_list(orders)
         << ") must be integers of at least 2 (a cone of order p has angle 2 pi / p)";
      c.message = os.str();
      return ERROR_WRONG_PARAMETER;
    }
  return OK;
}

} // namespace internal

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

checks cone orders given for `number_of_landmarks` landmarks (one per landmark, in the
landmarks' order), in this order: one order per landmark, every order at least 2 (a cone of
order \f$ p \f$ has angle \f$ 2\pi/p \f$); `ERROR_WRONG_PARAMETER` otherwise. This is the check
every entry point of the package runs on the parameter `cone_orders`.

\param orders the cone orders
\param number_of_landmarks the number of landmarks
\param check receives which check failed and why (its `message`), when not null
\return `OK` or `ERROR_WRONG_PARAMETER`
*/
inline Error_code check_cone_orders(const std::vector<int>& orders, std::size_t number_of_landmarks,
                                    Cone_order_check* check = nullptr)
{
  Cone_order_check local;
  Cone_order_check& c = check ? *check : local;
  c = Cone_order_check();
  return internal::check_cone_order_values(orders, number_of_landmarks, c);
}

/*!
\ingroup PkgHyperbolicOrbifoldTutteHelperFunctions

checks the signature `signature` for `number_of_landmarks` landmarks as the other overload
does (one order per landmark, every order at least 2: `ERROR_WRONG_PARAMETER`), then that its
orbifold is hyperbolic (`ERROR_NOT_HYPERBOLIC`): of negative Euler characteristic, on a closed
surface of genus 0 when \f$\sum_i (1 - 1/p_i) > 2\f$ (e.g. (2,3,7), (2,2,2,3), or 5 cones of
order 2), of genus 1 with at least one cone, of genus 2 or more always; disk type with corners
of angle \f$\pi/2\f$ when there are 5 or more. (Disk corners of other angles are not checked
here: `make_orbifold_tile()` does not build them.)

\param signature the orbifold's type, genus and cone orders
\param number_of_landmarks the number of landmarks
\param check receives which check failed and why (its `message`), when not null
\return `OK`, `ERROR_WRONG_PARAMETER` or `ERROR_NOT_HYPERBOLIC`
*/
inline Error_code check_cone_orders(const Orbifold_signature& signature, std::size_t number_of_landmarks,
                                    Cone_order_check* check = nullptr)
{
  Cone_order_check local;
  Cone_order_check& c = check ? *check : local;
  c = Cone_order_check();
  std::vector<int> orders;
  bool all_two = true;
  for(int i = 0; i < signature.number_of_cones(); ++i) {
    orders.push_back(signature.order(i));
    all_two = all_two && orders.back() == 2;
  }
  const Error_code ec = internal::check_cone_order_values(orders, number_of_landmarks, c);
  if(ec != OK)
    return ec;
  if((signature.type() != Sphere_type && !all_two) || signature.is_hyperbolic())
    return OK;
  c.problem = Cone_orders_not_hyperbolic;
  std::ostringstream os;
  if(signature.genus() > 0) {
    os << "the orbifold of genus " << signature.genus() << " with " << orders.size()
       << " cones is not hyperbolic (genus 1 needs at least one cone)";
  } else {
    for(int p : orders)
      c.sum += 1.0 - 1.0 / p;
    os << "the orbifold with cones of orders (" << internal::cone_order_list(orders)
       << ") is not hyperbolic: the sum of 1 - 1/p over its cones is " << c.sum
       << ", it must exceed 2 (e.g. (2,3,7), (2,2,2,3), or 5 cones of order 2)";
  }
  c.message = os.str();
  return ERROR_NOT_HYPERBOLIC;
}

} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_LANDMARK_CHECKS_H
