// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The compile-time features of a detector: a scene pays only for what it uses.

namespace influence2d {

/// The features a `detector<NT, Features>` is built with: bits of
/// `features::...`, or-ed together, given as `feature_set<bits>`. A detector
/// built without a feature runs none of its code and stores none of its state;
/// asking for witnesses or a distance through `detector_options` then throws
/// `std::invalid_argument` at construction, and a polygon of several rings
/// given to a detector without `features::holes` throws `invalid_input`.
namespace features {
/// Nothing optional: the yes/no answer for a pair of one-ring polygons,
/// touching counts, candidates gathered anew every frame.
inline constexpr unsigned none = 0;
/// `detector_options::witness`: the (static edge, moving edge) pairs in contact.
inline constexpr unsigned witness = 1u << 0;
/// `detector_options::distance` > 0: collision within a separation distance.
inline constexpr unsigned distance = 1u << 1;
/// Polygons with more than one ring (holes, several outer rings). Without it
/// the detector takes one-ring polygons only and throws `invalid_input` for
/// others.
inline constexpr unsigned holes = 1u << 2;
/// `detector_options::temporal_coherence`: candidate edges kept between
/// frames while the moving centroid stays near where they were gathered.
/// Without it the option has no effect and candidates are gathered every
/// frame (same answers).
inline constexpr unsigned coherence = 1u << 3;
/// `detector::statistics()`: counters of the work done, for studies.
inline constexpr unsigned statistics = 1u << 4;
/// Every feature (the default).
inline constexpr unsigned all = witness | distance | holes | coherence | statistics;
}  // namespace features

/// A set of features as a type (the detector's second template argument), e.g.
/// `detector<double, feature_set<features::witness | features::coherence>>`.
template <unsigned Bits>
struct feature_set {
    static_assert((Bits & ~features::all) == 0, "feature_set: unknown feature bits");
    /// The feature bits.
    static constexpr unsigned bits = Bits;
    /// Whether the set holds every bit of `f`.
    static constexpr bool has(unsigned f) { return (Bits & f) == f; }
};

/// The smallest detector: yes/no answers for one-ring polygons, nothing kept
/// between frames.
using minimal_features = feature_set<features::none>;
/// Every feature: what `detector<NT>` is.
using all_features = feature_set<features::all>;

}  // namespace influence2d
