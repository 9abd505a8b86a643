// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_STATISTICS_PARAMETER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_STATISTICS_PARAMETER_H

#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <string>

// The statistics a one-call embedding function fills and its failures recorded there, the
// same for each of them.

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// the statistics of the `embedding_statistics` named parameter, or `local` when it is not
// given; reset either way
template <class NamedParameters>
Embedding_statistics& statistics_parameter(const NamedParameters& np, Embedding_statistics& local)
{
  Embedding_statistics* stp = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::embedding_statistics), static_cast<Embedding_statistics*>(nullptr));
  Embedding_statistics& st = stp ? *stp : local;
  st = Embedding_statistics();
  return st;
}

// `ec`, with its reason in `st.message`: `message`, or `error_message(ec)` when it is empty
inline Error_code record_failure(Embedding_statistics& st, Error_code ec, const std::string& message)
{
  st.message = message.empty() ? std::string(error_message(ec)) : message;
  return ec;
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_PIPELINE_STATISTICS_PARAMETER_H
