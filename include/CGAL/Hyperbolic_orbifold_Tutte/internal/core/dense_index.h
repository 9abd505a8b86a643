// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_DENSE_INDEX_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_DENSE_INDEX_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// ---------------------------------------------------------------------------
// Dense indices of descriptors (position in the iteration order of a range)
// ---------------------------------------------------------------------------

template <class D, class = void>
struct Has_idx_member : std::false_type {};

template <class D>
struct Has_idx_member<D, std::void_t<decltype(std::declval<const D&>().idx())> > : std::true_type {};

/// Maps each descriptor of a range to its position in that range (`npos` for others).
template <class Descriptor, bool use_idx = Has_idx_member<Descriptor>::value>
class Dense_index;

// descriptors with an `idx()` member (Surface_mesh): a vector indexed by idx()
template <class Descriptor>
class Dense_index<Descriptor, true>
{
public:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  template <class Range>
  explicit Dense_index(const Range& range)
  {
    std::size_t end_idx = 0;
    for(const Descriptor d : range)
      end_idx = (std::max)(end_idx, static_cast<std::size_t>(d.idx()) + 1);
    pos_.assign(end_idx, npos);
    for(const Descriptor d : range)
      pos_[static_cast<std::size_t>(d.idx())] = n_++;
  }

  std::size_t operator()(const Descriptor& d) const
  {
    const std::size_t i = static_cast<std::size_t>(d.idx());
    return i < pos_.size() ? pos_[i] : npos;
  }

  std::size_t size() const { return n_; }

private:
  std::vector<std::size_t> pos_;
  std::size_t n_ = 0;
};

// other descriptors (Polyhedron_3 handles): an open-addressing hash table on
// std::hash (several times faster than std::unordered_map for this use)
template <class Descriptor>
class Dense_index<Descriptor, false>
{
public:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  template <class Range>
  explicit Dense_index(const Range& range)
  {
    std::size_t n = 0;
    for(auto it = range.begin(); it != range.end(); ++it)
      ++n;
    std::size_t capacity = 16;
    while(capacity < 2 * n)
      capacity *= 2;
    mask_ = capacity - 1;
    keys_.resize(capacity);
    pos_.assign(capacity, npos);
    for(const Descriptor d : range) {
      std::size_t s = slot(d);
      while(pos_[s] != npos && !(keys_[s] == d))
        s = (s + 1) & mask_;
      if(pos_[s] == npos) {
        keys_[s] = d;
        pos_[s] = n_++;
      }
    }
  }

  std::size_t operator()(const Descriptor& d) const
  {
    std::size_t s = slot(d);
    while(pos_[s] != npos) {
      if(keys_[s] == d)
        return pos_[s];
      s = (s + 1) & mask_;
    }
    return npos;
  }

  std::size_t size() const { return n_; }

private:
  std::size_t slot(const Descriptor& d) const
  {
    std::uint64_t h = static_cast<std::uint64_t>(std::hash<Descriptor>()(d));
    h ^= h >> 33; // mix: std::hash of a handle is often its address
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    return static_cast<std::size_t>(h) & mask_;
  }

  std::vector<Descriptor> keys_;
  std::vector<std::size_t> pos_;
  std::size_t mask_ = 0;
  std::size_t n_ = 0;
};

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CORE_DENSE_INDEX_H
