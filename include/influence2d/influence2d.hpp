// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The library in one include, layer by layer (docs/architecture.md):
/// everything but the CGAL number types (influence2d/number/cgal.hpp) and the
/// exact entry points built on them (influence2d/exact/), quadruple precision
/// (influence2d/number/multiprecision.hpp), the readers and writers
/// (influence2d/io/) and the input audit (influence2d/audit/audit.hpp).

/// \namespace influence2d
/// Collision detection between 2D polygons with triangle coverings and
/// influence areas, templated on the number type NT.

#include "influence2d/core/box.hpp"
#include "influence2d/core/feature.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/containment.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/features.hpp"
#include "influence2d/detect/pairs.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/edge_grid.hpp"
#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/influence/influence_areas.hpp"
#include "influence2d/motion/exit_distance.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/motion/motion.hpp"
#include "influence2d/motion/rational_turn.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/motion/translation_events.hpp"
#include "influence2d/motion/turning.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/number/unit_roundoff.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/predicates/polynomial_roots.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/predicates/shared_vertex.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/query/both_posed.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"
#include "influence2d/version.hpp"
#include "influence2d/world/box_sweep.hpp"
#include "influence2d/world/box_tree.hpp"
#include "influence2d/world/layer_pairs.hpp"
#include "influence2d/world/narrow_phase.hpp"
#include "influence2d/world/projections_apart.hpp"
#include "influence2d/world/world.hpp"
