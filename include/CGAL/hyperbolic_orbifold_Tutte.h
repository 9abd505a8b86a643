// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_H

/// \file hyperbolic_orbifold_Tutte.h
/// Includes every public header of the package. Include your mesh type's header
/// (e.g. `<CGAL/Surface_mesh.h>`) before this one, as for `CGAL::Seam_mesh`.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/weight_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/interpolation_model.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_isometry_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Chart_point.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_type.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_tile.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/parameters.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_layout.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_statistics.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/genus.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_checks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Mesh_preparation.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/prepare_mesh_for_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_graph.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Hyperbolic_orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/read_cones.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/hyperbolic_orbifold_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/fixed_boundary_hyperbolic_Tutte_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/certify_hyperbolic_orbifold_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Corner_embedding_certificate.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/certify_corner_embedding.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/select_landmarks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Embedding_locator.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/surface_maps.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_reliability.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/map_distortion.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/refine_orbifold_map.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/match_extremities.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/Orbifold_collection.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_H
