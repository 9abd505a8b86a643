// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

// register_distortion: the per-face distortion of a map (HOT::map_distortion(), the map
// report's "distortion") from the source mesh (V, F) and the images of its vertices.

#include "hot_python.h"

#include <CGAL/Hyperbolic_orbifold_Tutte/map_distortion.h>

#include <array>
#include <string>
#include <vector>

namespace hot_python {

namespace {

py::dict summary_dict(const HOT::Distortion_summary& s)
{
  py::dict d;
  d["p50"] = s.p50;
  d["p90"] = s.p90;
  d["p99"] = s.p99;
  d["max"] = s.max;
  d["mean"] = s.mean;
  d["faces"] = s.number_of_faces;
  return d;
}

} // namespace

void register_distortion(py::module_& m)
{
  m.def(
    "map_distortion",
    [](py::handle V_obj, py::handle F_obj, py::handle images_obj) {
      const Double_array V = vertex_array(V_obj);
      const Index_array F = face_array(F_obj);
      const Double_array P = vertex_array(images_obj);
      if(F.ndim() != 2 || F.shape(1) != 3)
        fail(HOT::ERROR_WRONG_PARAMETER, "map_distortion: F must have shape (m, 3)");
      if(P.shape(0) != V.shape(0))
        fail(HOT::ERROR_WRONG_PARAMETER, "map_distortion: images has " + std::to_string(P.shape(0)) + " rows for the " +
                                           std::to_string(V.shape(0)) + " vertices of V");
      HOT::Map_distortion d;
      {
        py::gil_scoped_release release;
        Surface_mesh mesh;
        HOT::Mesh_info info;
        mesh_from_arrays(V.data(), static_cast<std::size_t>(V.shape(0)), F.data(), static_cast<std::size_t>(F.shape(0)), 3, std::nullopt,
                         mesh, info);
        std::vector<Kernel::Point_3> images;
        images.reserve(static_cast<std::size_t>(P.shape(0)));
        for(py::ssize_t i = 0; i < P.shape(0); ++i)
          images.emplace_back(P.data()[3 * i], P.data()[3 * i + 1], P.data()[3 * i + 2]);
        d = HOT::map_distortion(mesh, images);
      }
      const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(d.sigma1.size())};
      py::dict r;
      r["sigma1"] = owning_array(std::move(d.sigma1), shape);
      r["sigma2"] = owning_array(std::move(d.sigma2), shape);
      r["conformal"] = owning_array(std::move(d.conformal), shape);
      r["area"] = owning_array(std::move(d.area), shape);
      r["symmetric_dirichlet"] = owning_array(std::move(d.symmetric_dirichlet), shape);
      r["conformal_summary"] = summary_dict(d.conformal_summary);
      r["area_summary"] = summary_dict(d.area_summary);
      r["symmetric_dirichlet_summary"] = summary_dict(d.symmetric_dirichlet_summary);
      r["symmetric_dirichlet_energy"] = d.symmetric_dirichlet_energy;
      r["degenerate_image_faces"] = d.degenerate_image_faces;
      r["degenerate_source_faces"] = d.degenerate_source_faces;
      r["unmapped_faces"] = d.unmapped_faces;
      r["source_area"] = d.source_area;
      r["image_area"] = d.image_area;
      return r;
    },
    py::arg("V"), py::arg("F"), py::arg("images"),
    "map_distortion(V, F, images) -> dict\n\n"
    "The per-face distortion of the piecewise-linear map sending vertex i of the mesh (V, F) to\n"
    "images[i] (e.g. surface_points() of map()'s result): per face (F's order) the singular values\n"
    "sigma1 >= sigma2 of its differential, the conformal distortion sigma1/sigma2 and the area\n"
    "distortion sigma1 sigma2 / (image area / source area), each an (m,) float array; their\n"
    "percentiles 50, 90, 99, max and mean (conformal_summary, area_summary: the map report's\n"
    "\"distortion\"); the symmetric Dirichlet density s1^2 + s2^2 + 1/s1^2 + 1/s2^2 of the\n"
    "singular values scaled to the total areas (symmetric_dirichlet, its summary, and\n"
    "symmetric_dirichlet_energy, its area-weighted mean: 4 for an isometry up to scale); the counts\n"
    "of degenerate faces (inf where an image face is flat).\n\n"
    "Example:\n"
    "    >>> m = hot.map_meshes(VA, FA, la, VB, FB, lb)\n"
    "    >>> d = hot.map_distortion(VA, FA, hot.surface_points(m[\"faces\"], m[\"bary\"], VB, FB))\n"
    "    >>> d[\"conformal_summary\"][\"p99\"], d[\"symmetric_dirichlet_energy\"]   # 1 and 4 for an isometry");
}

} // namespace hot_python
