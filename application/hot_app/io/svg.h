// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_SVG_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_SVG_H

// The command-line tool's SVG pictures of the Poincare disk: tiles and their images.

#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <CGAL/disable_warnings.h>

/// \file svg.h

namespace hot_tools {

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

// |z|^2 as x^2 + y^2 (std::norm of libstdc++ squares a hypot)
inline double squared_modulus(const std::complex<double>& z) { return z.real() * z.real() + z.imag() * z.imag(); }

// Writes pictures of the Poincare disk as SVG: geodesic segments are circular arcs
// (SVG "A" commands), so the files stay small and exact at any zoom.
class Poincare_svg
{
public:
  explicit Poincare_svg(double size = 800.0) : size_(size), scale_(0.48 * size) {}

  static std::string hsv_colour(double h, double s, double v)
  {
    h = h - std::floor(h);
    const double c = v * s, x = c * (1 - std::abs(std::fmod(h * 6, 2.0) - 1)), m = v - c;
    double r = 0, g = 0, b = 0;
    switch(static_cast<int>(h * 6) % 6) {
      case 0: r = c; g = x; break;
      case 1: r = x; g = c; break;
      case 2: g = c; b = x; break;
      case 3: g = x; b = c; break;
      case 4: r = x; b = c; break;
      default: r = c; b = x; break;
    }
    char buf[8];
    std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", int((r + m) * 255 + 0.5), int((g + m) * 255 + 0.5),
                  int((b + m) * 255 + 0.5));
    return buf;
  }
  // n well separated colours
  static std::string palette(int i, int n, double saturation = 0.85, double value = 0.85)
  {
    // golden-ratio hue steps keep neighbours apart for any n
    (void)n;
    return hsv_colour(0.07 + 0.618033988749895 * i, saturation, value);
  }

  // path data of the geodesic polygon through the points (closed when `closed`)
  std::string geodesic_path(const std::vector<std::complex<double> >& pts, bool closed) const
  {
    std::ostringstream os;
    os.precision(7);
    if(pts.empty())
      return std::string();
    os << "M" << X(pts[0]) << "," << Y(pts[0]);
    const std::size_t n = pts.size();
    for(std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
      os << arc_to(pts[i], pts[(i + 1) % n]);
    if(closed)
      os << "Z";
    return os.str();
  }

  void begin(std::ostream& os, const std::string& title) const
  {
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size_ << "\" height=\"" << size_ + 40
       << "\" viewBox=\"0 0 " << size_ << " " << size_ + 40 << "\">\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
       << "<circle cx=\"" << size_ / 2 << "\" cy=\"" << size_ / 2 << "\" r=\"" << scale_
       << "\" fill=\"#f4f4f4\" stroke=\"#222\" stroke-width=\"1.5\"/>\n"
       << "<text x=\"" << size_ / 2 << "\" y=\"" << size_ + 28 << "\" font-family=\"sans-serif\" font-size=\"18\" "
       << "text-anchor=\"middle\">" << title << "</text>\n";
  }
  void end(std::ostream& os) const { os << "</svg>\n"; }

  void path(std::ostream& os, const std::string& d, const std::string& fill, const std::string& stroke,
            double width, double opacity = 1.0) const
  {
    os << "<path d=\"" << d << "\" fill=\"" << fill << "\" stroke=\"" << stroke << "\" stroke-width=\"" << width
       << "\" stroke-linejoin=\"round\"";
    if(opacity < 1.0)
      os << " opacity=\"" << opacity << "\"";
    os << "/>\n";
  }
  void dot(std::ostream& os, const std::complex<double>& z, double r, const std::string& fill) const
  {
    os << "<circle cx=\"" << X(z) << "\" cy=\"" << Y(z) << "\" r=\"" << r << "\" fill=\"" << fill
       << "\" stroke=\"black\" stroke-width=\"1\"/>\n";
  }
  void label(std::ostream& os, const std::complex<double>& z, const std::string& text, double font = 13) const
  {
    os << "<text x=\"" << X(z) << "\" y=\"" << Y(z) << "\" font-family=\"sans-serif\" font-size=\"" << font
       << "\" text-anchor=\"middle\" dominant-baseline=\"central\">" << text << "</text>\n";
  }

  double X(const std::complex<double>& z) const { return size_ / 2 + scale_ * z.real(); }
  double Y(const std::complex<double>& z) const { return size_ / 2 - scale_ * z.imag(); }

private:
  // SVG arc from a to b along their geodesic (a circle orthogonal to the unit circle,
  // or a diameter). The part of such a circle inside the disk is less than a half circle,
  // so the small-arc flag is always right; the sweep follows the turn a -> midpoint -> b.
  std::string arc_to(const std::complex<double>& a, const std::complex<double>& b) const
  {
    std::ostringstream os;
    os.precision(7);
    const double cross0 = a.real() * b.imag() - a.imag() * b.real();
    const double len = std::hypot(b.real() - a.real(), b.imag() - a.imag());
    if(len < 1e-12 || std::abs(cross0) < 1e-12 * (len + 1e-300)) {
      os << "L" << X(b) << "," << Y(b);
      return os.str();
    }
    // circle orthogonal to the unit circle through a and b: center c with
    // 2 <a, c> = 1 + |a|^2 and 2 <b, c> = 1 + |b|^2
    const double ra = (1 + squared_modulus(a)) / 2, rb = (1 + squared_modulus(b)) / 2;
    const double cx = (ra * b.imag() - rb * a.imag()) / cross0, cy = (a.real() * rb - b.real() * ra) / cross0;
    const double r = std::hypot(a.real() - cx, a.imag() - cy);
    if(r * scale_ > 1e6) { // practically straight
      os << "L" << X(b) << "," << Y(b);
      return os.str();
    }
    // Going from a to b the short way round c: counterclockwise around c in the model when
    // turn > 0. The screen's y axis points down, which mirrors the picture, and SVG's
    // sweep flag 1 means increasing angle in screen coordinates: counterclockwise in the
    // model is then sweep 0 (checked by looking at the right-angled pentagon, whose sides
    // bow towards the origin).
    const double turn = (a.real() - cx) * (b.imag() - cy) - (a.imag() - cy) * (b.real() - cx);
    const int sweep = turn > 0 ? 0 : 1;
    os << "A" << r * scale_ << "," << r * scale_ << " 0 0 " << sweep << " " << X(b) << "," << Y(b);
    return os.str();
  }

  double size_, scale_;
};

// Draws a tile and its images under the group elements up to `depth` (paper, Figure 4).
template <class Tile>
void write_tile_svg(std::ostream& os, const Tile& tile, int depth, const std::string& title)
{
  typedef std::complex<double> C;
  Poincare_svg svg;
  svg.begin(os, title);
  const int n = tile.number_of_corners();
  std::vector<C> corners;
  for(int i = 0; i < n; ++i)
    corners.push_back(C(CGAL::to_double(tile.corner(i).x()), CGAL::to_double(tile.corner(i).y())));
  // colour of a side: one per pair of glued sides
  std::vector<int> side_class(n, -1);
  int classes = 0;
  for(int i = 0; i < n; ++i)
    if(side_class[i] < 0) {
      side_class[i] = classes;
      side_class[tile.paired_side(i)] = classes;
      ++classes;
    }
  auto side_colour = [&](int i, double s, double v) { return Poincare_svg::palette(side_class[i], classes, s, v); };

  const std::vector<typename Tile::Isometry> group = tile.group_elements(depth);
  for(std::size_t e = 1; e < group.size(); ++e) { // faded images
    std::vector<C> img;
    for(const C& c : corners)
      img.push_back(group[e].apply(c));
    svg.path(os, svg.geodesic_path(img, true), "#dde6f0", "none", 0);
    for(int i = 0; i < n; ++i) {
      std::vector<C> side{img[i], img[(i + 1) % n]};
      svg.path(os, svg.geodesic_path(side, false), "none", side_colour(i, 0.35, 0.95), 1.0);
    }
  }
  svg.path(os, svg.geodesic_path(corners, true), "#b9cde4", "none", 0);
  for(int i = 0; i < n; ++i) {
    std::vector<C> side{corners[i], corners[(i + 1) % n]};
    svg.path(os, svg.geodesic_path(side, false), "none", side_colour(i, 0.9, 0.8), 4.0);
  }
  for(int i = 0; i < n; ++i) {
    const int c = tile.corner_cone(i);
    svg.dot(os, corners[i], 7, Poincare_svg::palette(c, tile.number_of_cones(), 0.75, 1.0));
    const double r = std::sqrt(squared_modulus(corners[i]));
    const C out = (r > 1e-9) ? corners[i] * ((r + 0.045) / r) : C(0.0, 0.045);
    svg.label(os, out, std::to_string(c + 1));
  }
  svg.end(os);
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_SVG_H
