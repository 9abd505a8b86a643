// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_CORNER_TABLE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_CORNER_TABLE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Hyperbolic_orbifold_Tutte/internal/core/disk_models.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

// Points of the disk by their bits, and the point locator's table of corners by their
// points (Embedding_locator.h: a query given exactly at a corner's point is answered there).

namespace CGAL {
namespace Hyperbolic_orbifold_Tutte {
namespace internal {

// a pair of 64-bit words: the bits of a point, or the key of a lifted triangle in the search
struct Point_key
{
  std::uint64_t a, b;
  bool operator==(const Point_key& o) const { return a == o.a && b == o.b; }
};

struct Point_key_hash
{
  std::size_t operator()(const Point_key& k) const
  {
    std::size_t s = 0;
    boost::hash_combine(s, k.a);
    boost::hash_combine(s, k.b);
    return s;
  }
};

// the bits of z (-0.0 taken as +0.0)
inline Point_key point_key(const std::complex<double>& z)
{
  Point_key k;
  const double x = z.real() + 0.0, y = z.imag() + 0.0; // -0.0 -> +0.0
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
  void insert(const Point_key& k, int f, int j)
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
  bool find(const Point_key& k, std::pair<int, int>& out) const
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
    Point_key k{0, 0};
    int f = -1;
    int j = 0;
  };
  std::size_t probe(const Point_key& k) const // the slot holding k, or the empty one where it goes
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

} // namespace internal
} // namespace Hyperbolic_orbifold_Tutte
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_LOCATOR_CORNER_TABLE_H
