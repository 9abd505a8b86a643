// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_COLLECTION_SUPPORT_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_COLLECTION_SUPPORT_H

// What Orbifold_collection runs its steps with: the progress reports, serialised, and the loop
// over the meshes or pairs, in parallel with Parallel_tag and TBB.

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <functional>
#include <mutex>
#include <type_traits>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// calls the progress callback, one thread at a time, counting the steps (`Progress` is an
// aggregate {stage, done, total, source, target, seconds, code})
template <class Progress>
class Collection_reporter
{
public:
  typedef std::function<void(const Progress&)> Callback;
  Collection_reporter(const Callback& callback, std::size_t total) : callback_(callback), total_(total) {}
  template <class Stage, class Code>
  void operator()(Stage stage, std::size_t source, std::size_t target, double seconds, Code code)
  {
    if(!callback_)
      return;
    std::lock_guard<std::mutex> lock(mutex_);
    callback_(Progress{stage, ++done_, total_, source, target, seconds, code});
  }

private:
  const Callback& callback_;
  std::size_t total_, done_ = 0;
  std::mutex mutex_;
};

// f(i) for i in [0, n), in parallel with Parallel_tag and TBB
template <class ConcurrencyTag, class F>
void for_each_index(std::size_t n, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value) {
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { f(i); });
    return;
  }
#endif
  for(std::size_t i = 0; i < n; ++i)
    f(i);
}

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_MAPS_COLLECTION_SUPPORT_H
