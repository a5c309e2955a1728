// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The library in one include: everything but the CGAL number types
/// (influence2d/number/cgal.hpp), quadruple precision
/// (influence2d/number/multiprecision.hpp), the readers and writers
/// (influence2d/io/) and the input audit (influence2d/audit/audit.hpp).

/// \namespace influence2d
/// Collision detection between 2D polygons with triangle coverings and
/// influence areas, templated on the number type NT.

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/version.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/edge_grid.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "influence2d/influence/influence_areas.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/predicates/segments.hpp"
