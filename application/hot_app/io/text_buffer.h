// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_TEXT_BUFFER_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_TEXT_BUFFER_H

// Fast text output for the tool's large files (the embedding OBJ): numbers formatted with
// std::to_chars into a growing character buffer, and files of many lines formatted by blocks,
// in parallel with TBB when the build has it, and written in order with one write per block.
//
// Doubles are written as printf("%.17g") writes them (what an std::ostream with precision 17
// and the default float format writes, the files' format so far), and 17 digits give back the
// exact double (strtod, std::from_chars): std::to_chars in the general format with 17
// significant digits, which is specified as that printf conversion in the C locale, or for
// 1e-6 <= |x| < 1e17 (every coordinate of the files in practice) the same digits computed
// exactly with 128-bit integers, 2-5 times faster. The test suite checks the bytes against
// snprintf("%.17g") on random bit patterns, random values of every exponent in that range,
// ties and edge cases (test_input_checks.number_writer).

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <ostream>
#include <string_view>
#include <type_traits>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

/// \file text_buffer.h

namespace hot_tools {
namespace io_impl {

/// at most this many characters for one double written by `write_double()` ("-1.2345678901234567e-308")
constexpr std::size_t max_double_chars = 32;

/// writes the 8 decimal digits of `v` < 10^8 (leading zeros written) at `p`
inline void write_8_digits(char* p, std::uint32_t v)
{
  static const char pairs[] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                              "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                              "8081828384858687888990919293949596979899";
  const std::uint32_t hi = v / 10000, lo = v % 10000;
  std::memcpy(p, pairs + 2 * (hi / 100), 2);
  std::memcpy(p + 2, pairs + 2 * (hi % 100), 2);
  std::memcpy(p + 4, pairs + 2 * (lo / 100), 2);
  std::memcpy(p + 6, pairs + 2 * (lo % 100), 2);
}

/// The fast path of `write_double()`, for 1e-6 <= |x| < 1e17 (the coordinates of meshes and of
/// the disk): the 17 significant digits are x * 10^k (k = 16 - X, X = floor(log10 |x|), 0 <= k
/// <= 22) rounded to the nearest integer, ties to even, computed exactly as m * 5^k * 2^(e + k)
/// (x = m 2^e, m < 2^53, 5^k < 2^52: below 2^105) in 128 bits (X is right when the truncated
/// x 10^k has 17 digits; a rounding up to 10^17 gives 10^(X+1)); then printf's "%g" layout with
/// precision 17: fixed notation for -4 <= X < 17, scientific below, trailing zeros of the
/// fraction removed. Returns nullptr (nothing written) for the other values.
inline char* write_double_17g_fast(char* p, double x)
{
#ifdef __SIZEOF_INT128__
  typedef unsigned __int128 U128;
  std::uint64_t bits;
  std::memcpy(&bits, &x, 8);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if(biased == 0 || biased == 0x7ff) // zero, subnormal, infinite, NaN
    return nullptr;
  const double ax = x < 0 ? -x : x;
  if(!(ax >= 1e-6 && ax < 1e17))
    return nullptr;
  static const std::uint64_t pow5[23] = {
    1ull, 5ull, 25ull, 125ull, 625ull, 3125ull, 15625ull, 78125ull, 390625ull, 1953125ull, 9765625ull, 48828125ull,
    244140625ull, 1220703125ull, 6103515625ull, 30517578125ull, 152587890625ull, 762939453125ull, 3814697265625ull,
    19073486328125ull, 95367431640625ull, 476837158203125ull, 2384185791015625ull };
  const std::uint64_t m = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
  const int e = biased - 1075; // x = m 2^e
  const std::uint64_t lo17 = 10000000000000000ull, hi17 = 100000000000000000ull;
  // X: floor(log10 |x|), first estimated from the binary exponent (it is that or one more)
  int X = ((e + 52) * 78913) >> 18; // floor((e + 52) log10(2)) (arithmetic shift: floor for negative values too)
  static const double powers_of_10[] = { 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6,
                                         1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18 };
  if(X >= -7 && X <= 16 && ax >= powers_of_10[X + 8]) // (a guess: the digits below decide)
    ++X;
  std::uint64_t n = 0;
  for(int attempt = 0;; ++attempt) {
    const int k = 16 - X;
    if(k < 0 || k > 22 || attempt == 3)
      return nullptr;
    const U128 P = U128(m) * pow5[k];
    const int shift = e + k;
    U128 t, q; // x 10^k truncated and rounded
    if(shift >= 0) {
      if(shift > 20) // (cannot happen: |x| < 1e17 gives at most 4)
        return nullptr;
      t = q = P << shift;
    } else {
      const int s = -shift;
      if(s >= 127)
        return nullptr;
      t = q = P >> s;
      const U128 r = P - (t << s), half = U128(1) << (s - 1);
      if(r > half || (r == half && (t & 1) != 0))
        ++q;
    }
    if(t < lo17) { // x 10^k < 10^16: X is too large
      --X;
      continue;
    }
    if(t >= hi17) { // X is too small
      ++X;
      continue;
    }
    if(q == hi17) { // rounded up to the next power of 10: 1.0000000000000000 10^(X+1), as printf says it
      n = lo17;
      ++X;
      break;
    }
    n = static_cast<std::uint64_t>(q);
    break;
  }
  int last = 16; // the last digit kept: trailing zeros go (n >= 10^16: the loop ends)
  for(std::uint64_t r = n; r % 10 == 0; r /= 10)
    --last;
  char d[17];
  d[0] = static_cast<char>('0' + n / lo17);
  n %= lo17;
  write_8_digits(d + 1, static_cast<std::uint32_t>(n / 100000000));
  write_8_digits(d + 9, static_cast<std::uint32_t>(n % 100000000));
  if(x < 0)
    *p++ = '-';
  if(X < -4) { // d.ddde-0X (X is -5 or -6 here)
    *p++ = d[0];
    if(last > 0) {
      *p++ = '.';
      std::memcpy(p, d + 1, static_cast<std::size_t>(last));
      p += last;
    }
    std::memcpy(p, "e-0", 3);
    p[3] = static_cast<char>('0' - X);
    return p + 4;
  }
  if(X < 0) { // 0.000ddd
    *p++ = '0';
    *p++ = '.';
    for(int z = -1; z > X; --z)
      *p++ = '0';
    std::memcpy(p, d, static_cast<std::size_t>(last + 1));
    return p + last + 1;
  }
  std::memcpy(p, d, static_cast<std::size_t>(X + 1)); // the integer part
  p += X + 1;
  if(last > X) {
    *p++ = '.';
    std::memcpy(p, d + X + 1, static_cast<std::size_t>(last - X));
    p += last - X;
  }
  return p;
#else
  (void)p;
  (void)x;
  return nullptr;
#endif
}

/// writes `x` at `p` as printf("%.17g", x) does and returns the end (at most
/// `max_double_chars` characters; "inf", "-inf", "nan", "-nan" for the non-finite values)
inline char* write_double(char* p, double x)
{
  if(char* end = write_double_17g_fast(p, x))
    return end;
  return std::to_chars(p, p + max_double_chars, x, std::chars_format::general, 17).ptr;
}

/// A growing character buffer to format text into (no locale, no stream state).
class Text_buffer
{
public:
  Text_buffer() = default;
  Text_buffer(Text_buffer&&) = default;
  Text_buffer& operator=(Text_buffer&&) = default;

  const char* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  void clear() { size_ = 0; }

  /// room for `n` more characters: returns where to write them; `advance_to()` the end
  char* room(std::size_t n)
  {
    if(capacity_ - size_ < n) {
      const std::size_t c = (std::max)(2 * capacity_, size_ + n + 4096);
      std::unique_ptr<char[]> d(new char[c]);
      if(size_ > 0)
        std::memcpy(d.get(), data_.get(), size_);
      data_.swap(d);
      capacity_ = c;
    }
    return data_.get() + size_;
  }
  void advance_to(char* end) { size_ = static_cast<std::size_t>(end - data_.get()); }

  Text_buffer& put(char c)
  {
    *room(1) = c;
    ++size_;
    return *this;
  }
  Text_buffer& put(std::string_view s)
  {
    char* p = room(s.size());
    if(!s.empty())
      std::memcpy(p, s.data(), s.size());
    size_ += s.size();
    return *this;
  }
  /// `x` as printf("%.17g")
  Text_buffer& put(double x)
  {
    advance_to(write_double(room(max_double_chars), x));
    return *this;
  }
  /// an integer, in decimal
  template <class Integer, std::enable_if_t<std::is_integral<Integer>::value && !std::is_same<Integer, bool>::value &&
                                                !std::is_same<Integer, char>::value, int> = 0>
  Text_buffer& put(Integer i)
  {
    char* p = room(24);
    advance_to(std::to_chars(p, p + 24, i).ptr);
    return *this;
  }
  Text_buffer& put(const char* s) { return put(std::string_view(s)); }

  /// writes the buffer to `os` and empties it
  void flush_to(std::ostream& os)
  {
    if(size_ > 0)
      os.write(data_.get(), static_cast<std::streamsize>(size_));
    size_ = 0;
  }

private:
  std::unique_ptr<char[]> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

/// Writes `n` lines to `os`, `line(i, buffer)` appending line i (with its end of line) to a
/// Text_buffer: by blocks of lines, formatted in parallel (TBB) a group of blocks at a time
/// and written in order, so the file is the same as line by line, in bounded memory.
template <class LineFormatter>
void write_lines(std::ostream& os, std::size_t n, const LineFormatter& line)
{
  const std::size_t block = 4096;
  const std::size_t blocks = (n + block - 1) / block;
#ifdef CGAL_LINKED_WITH_TBB
  if(blocks > 1) {
    const std::size_t group = 32; // blocks in memory at once
    std::vector<Text_buffer> buffers((std::min)(group, blocks));
    for(std::size_t g0 = 0; g0 < blocks; g0 += group) {
      const std::size_t g1 = (std::min)(blocks, g0 + group);
      tbb::parallel_for(g0, g1, [&](std::size_t b) {
        Text_buffer& t = buffers[b - g0];
        t.clear();
        const std::size_t e = (std::min)(n, (b + 1) * block);
        for(std::size_t i = b * block; i < e; ++i)
          line(i, t);
      });
      for(std::size_t b = g0; b < g1; ++b)
        buffers[b - g0].flush_to(os);
    }
    return;
  }
#endif
  Text_buffer t;
  for(std::size_t i = 0; i < n; ++i) {
    line(i, t);
    if(t.size() >= (std::size_t(1) << 20))
      t.flush_to(os);
  }
  t.flush_to(os);
}

} // namespace io_impl
} // namespace hot_tools

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_TEXT_BUFFER_H
