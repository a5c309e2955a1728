// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// What a motion query answers and takes: a motion of B between two poses,
/// its first contact, the options.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/influence/bounds.hpp"

namespace influence2d {

/// The first contact of a motion.
template <class NT>
struct contact_result {
    /// Whether the closed regions meet at some time in [0, 1] (for a motion
    /// that turns: come within the tolerance of sweep_options).
    bool contact = false;
    /// The earliest such time: 0 when they meet at the start; exact in an
    /// exact NT for a translation; 0 when there is no contact (but see
    /// step_limit).
    NT time{};
    /// A's feature that B touches first: an edge (B's vertex on it), a
    /// vertex (on B's edge), or, when the regions already meet at the start
    /// without boundary contact, the interior (B's vertex lies inside A).
    /// Input numbering; meaningful only with `contact`.
    feature static_feature{};
    /// B's feature in that contact, as static_feature.
    feature moving_feature{};
    /// For a motion that turns in the angle-linear model: conservative
    /// advancement took sweep_options::max_steps steps without deciding (a
    /// motion that stays within a small multiple of the tolerance for long).
    /// Then `contact` is false, `time` is where it stopped: no contact in
    /// [0, time], none decided after.
    bool step_limit = false;
};

/// How a motion that turns moves between its two poses (docs/sweep.md).
enum class turning_model : std::uint8_t {
    /// The angle linear in time, from.theta + t (to.theta - from.theta);
    /// contact within sweep_options::tolerance, by conservative advancement.
    angle_linear,
    /// The rotation's cosine and sine rational in time: the tangent of half
    /// the turn since the start linear in time (in pieces of at most a
    /// quarter turn, rational_pieces in motion/rational_turn.hpp); contact
    /// exact in an exact number type.
    rational
};

/// Options of first_contact.
struct sweep_options {
    /// For motions that turn: contact is reported at the first step where
    /// the distance between the regions is at most this (absolute, in the
    /// polygons' units; raised to the motion's resolution in double when
    /// smaller, see docs/sweep.md). 1e-9: far below any modelling
    /// tolerance of polygons of size 1 to 10^4, and far above the rounding
    /// of the posing (about 10^-16 times the scene's size) for them.
    double tolerance = 1e-9;
    /// How a motion that turns moves (a translation is the same in both).
    turning_model model = turning_model::angle_linear;
    /// For motions that turn in the angle-linear model: the most steps of
    /// conservative advancement before the query gives up with
    /// contact_result::step_limit (0: no limit). A step costs one separation
    /// query; most motions take tens of steps, a motion that grazes A within a
    /// few times the tolerance may take about its length over the tolerance.
    std::size_t max_steps = 100000;
};

/// The pose of B at time t of the motion from `from` to `to`, as
/// first_contact computes it for a motion that turns: each component
/// from + t (to - from), in double.
inline pose motion_pose(const pose& from, const pose& to, double t) {
    return {from.tx + t * (to.tx - from.tx), from.ty + t * (to.ty - from.ty), from.theta + t * (to.theta - from.theta)};
}

namespace sweep {

/// The scene's size of a motion (for separation_error and the swept
/// boxes' slack): the polygons' largest coordinates and both translations.
inline double motion_scale(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    return coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) + std::fabs(from.ty) + std::fabs(to.tx) +
           std::fabs(to.ty);
}

}  // namespace sweep

}  // namespace influence2d
