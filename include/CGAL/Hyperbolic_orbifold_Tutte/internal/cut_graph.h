// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CUT_GRAPH_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CUT_GRAPH_H

// transitional: for the tools until they use the public names.
// The cut and the landmark tour are public now, in
// <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h> and
// <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h> (which holds the alias
// internal::compute_tsp_landmark_order); surface_maps.h still includes this file.
// Remove it once it includes those.

#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/cut_through_landmarks.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/landmark_tour.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_INTERNAL_CUT_GRAPH_H
