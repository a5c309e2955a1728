// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The sound detector: the paper's method with the defects of its literal
/// form removed (docs/method.md section 7).

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "influence2d/assert.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/detect/containment.hpp"
#include "influence2d/detect/convex_pair.hpp"
#include "influence2d/detect/features.hpp"
#include "influence2d/detect/pairs.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/influence/edge_grid.hpp"
#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/influence/located_through_tree.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/scene/bounding_disc.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/inner_disc.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"
#include "influence2d/scene/reaching_vertices.hpp"

namespace influence2d {

/// Counters of the work a detector did, for studies of its filters.
struct detector_statistics {
    std::size_t frames = 0;              ///< frames asked (calls of collide)
    std::size_t circle_rejections = 0;   ///< frames answered by the bounding circles
    std::size_t candidate_rebuilds = 0;  ///< frames that gathered candidates anew
    std::size_t candidate_edges = 0;     ///< static edges inside their extended area
    std::size_t disc_rejections = 0;     ///< frames whose moving edges all keep off A's circle
    std::size_t segment_tests = 0;       ///< segment-pair decisions (in NT; after the double filters but in double)
    std::size_t containment_tests = 0;   ///< frames that ran the inclusion tests
    std::size_t tree_frames = 0;         ///< frames whose pairs came from A's edge tree
    std::size_t jump_frames = 0;         ///< frames with no coherence to use (both edge trees, or every pair)
    std::size_t convex_frames = 0;       ///< frames answered by the separating-edge test of two convex polygons
    std::size_t disc_frames = 0;         ///< frames of two convex polygons answered by their inner discs overlapping
    std::size_t last_pair_frames = 0;    ///< frames answered by an edge pair that met last (last_pair_meets)
    std::size_t interior_frames = 0;     ///< jumps answered by a vertex deep in the other region (vertices_deep_inside)
    std::size_t containment_rings_excluded = 0;  ///< rings containment found outside the other polygon by its cells
    std::size_t containment_tree_locates = 0;    ///< rings containment located through the other polygon's edge tree
};

namespace detector_detail {

/// A member of type T that exists only when `On`; empty otherwise, so that a
/// class deriving from it stores nothing for it (empty base). Tag tells
/// several of them apart.
template <class T, bool On, int Tag>
struct feature_state {
    T value{};
};
template <class T, int Tag>
struct feature_state<T, false, Tag> {};

/// The edge pairs that met which a frame of small steps may try
/// (detector::last_pair_meets): the one that met last, then up to seven
/// that met before it and no longer met when last tried. Poses that wander
/// within a small range (shuffled poses along a shared border, a body that
/// jitters) cross at a few pairs in turn, each most often again within a
/// few frames; a pair test costs a hundred instructions or so, a search
/// of the candidates or the trees thousands. Measured on the real pairs of
/// docs/bench/real_profile.md (callgrind, the loop of
/// scripts/profile/real_frames.cpp over 200 poses of each order, double),
/// against the last pair alone: NC's Northampton x Halifax 5,075 -> 1,475
/// instructions a frame on its shuffled poses (4 pairs in all: 2,312; 16:
/// 1,475, as 8), Jones x Craven 3,786 -> 1,539, Chile x Argentina 3,006 ->
/// 1,364, Russia x Kazakhstan 2,810 -> 998, Canada x United States 3,653 ->
/// 1,847; their walks 0.59x to 0.95x; the frames apart and the boroughs'
/// unchanged. The time study's families (75 cells: convex, starred,
/// irregular, contour and hole; circular, linear and random; the first
/// 9,000 frames of each): 0.983x to 1.018x, 1.001x in the geometric mean.
inline constexpr std::size_t recent_met_pairs = 8;

/// What temporal coherence keeps between frames: where the cached candidates
/// were gathered, and the location of that point when there were none.
struct coherence_state {
    double skin = 0;  ///< how far the centroid may move before gathering anew
    point<double> center;
    bool valid = false;
    bool center_inside = false;
    point<double> last;  ///< the previous frame's posed centroid
    bool has_last = false;
    bool last_step_small = false;  ///< whether the previous frame moved less than the skin
    std::uint32_t separating = 0;  ///< the edge that last separated two convex polygons (convex_regions_meet)
    std::uint32_t met_a = 0;       ///< A's edge of the pair that last met (test_pair)
    std::uint32_t met_b = 0;       ///< B's edge of that pair
    bool has_met = false;          ///< whether a pair has met since the detector was made
    /// Pairs that met before and no longer met when last tried
    /// (detector::last_pair_meets), the latest first, each once:
    /// `earlier_count` of them.
    std::array<std::pair<std::uint32_t, std::uint32_t>, recent_met_pairs> earlier{};
    std::size_t earlier_count = 0;

    /// Keeps (e, j) as the latest of the earlier pairs: moved to the front
    /// when kept already, else in front of the others, the oldest dropped
    /// when all places are taken.
    void keep_earlier(std::uint32_t e, std::uint32_t j) {
        const std::pair<std::uint32_t, std::uint32_t> pair(e, j);
        std::size_t k = 0;
        while (k < earlier_count && earlier[k] != pair) ++k;
        if (k == earlier_count && earlier_count < earlier.size()) ++earlier_count;
        if (k == earlier.size()) --k;
        for (; k > 0; --k) earlier[k] = earlier[k - 1];
        earlier[0] = pair;
    }

    /// Whether p lies within the skin of `from` (a filter in double; a
    /// distance that is not a number counts as within).
    [[gnu::always_inline]] bool within_skin(const point<double>& from, const point<double>& p) const {
        return !(filter_length(p.x - from.x, p.y - from.y) > skin);
    }
};

/// The separation distance in NT and its square.
template <class NT>
struct distance_state {
    NT distance, distance2;
};

}  // namespace detector_detail

/// Collision detection between a static polygon A and a moving polygon B, one
/// pose of B per frame. Exact when NT is (number_traits<NT>::category is not
/// floating); in floating types it answers as the brute-force reference in the
/// same type does, up to the rounding of its own decisions.
///
/// Per frame, in collide()'s order (n = r_B + d, p = B's posed centroid, O_A
/// and R_A A's centroid and bounding radius). Everything before the pair
/// tests is a filter: evaluated in double, widened by a margin that covers
/// rounding, so that it can keep too much but never drop anything.
///
///   p <- B's centroid posed in double; margin <- the rounding of the frame
///   |p - O_A| > R_A + n (the bounding circles apart):          disjoint
///   A and B small and convex (convex_pair_pays), d == 0, no witnesses
///   asked: their inner discs certainly overlap:                they meet
///       an edge of one with every vertex of the other strictly outside
///       its line, the last frame's first (convex_regions_meet): disjoint
///       else                                                    they meet
///   with witnesses, A and B small and convex, their inner discs certainly
///   overlap: the pairs of a jump (below), no containment: none
///   means that one holds the other                          they meet
///   (else the pairs are sought as for any polygons: the edge pairs are
///   the answer, and their search shows the meeting too)
///   no witnesses asked, p within the skin of the last frame's, and the edge
///   pair that met last (features::coherence) meets again by the pair tests,
///   or, while they pay, one of the recent_met_pairs that met before it
///   (last_pair_meets):                                          they meet
///   p jumped (a random pose, a first frame far from the last, or no
///   features::coherence: coherent_step), or B has more chunks than the
///   candidates' bound allows with any candidate (candidates_can_pay):
///       A and B convex, their inner discs certainly overlap
///           (inner_discs_overlap):                              they meet
///           (with witnesses: the pairs below, no containment)
///       few edge pairs (every_pair_pays): B posed in double; B's edges
///           whose boxes meet A's box, against A's edges whose boxes meet
///           B's: every pair whose boxes meet gets the pair tests; then containment
///       else A's and B's edge trees traversed together, B's circles posed:
///           below a leaf of B each of its edges, posed in double, finds the
///           static edges near it; each pair gets the pair tests; then containment
///   candidates <- the static edges within n + skin of p, from the edge grid,
///       kept while p stays within `skin` of where they were gathered
///       (temporal coherence; sound because the skin is part of the radius)
///   if the test pays (B has no more chunks of chunk_edges (8) edges than
///   candidates) and no moving edge, posed in double under its chunk's
///   circle, comes within R_A + d of O_A: no boundary pair   (clear_of_a)
///   B of fewer than a quarter as many edges as candidates (tree_pays):
///       each moving edge, posed in double, finds the static edges near it
///       through A's edge tree; each pair gets the pair tests; then containment
///   the last frame's candidates (or the cache) times B's chunks above
///   candidate_chunk_limit (candidates_pay fails): the edge trees traversed
///   together, as for a jump
///   else keep the candidates whose extended area of length n contains p (and,
///   B posed in double first when it has no more edges than candidates,
///   whose box meets B's):
///       none: no edge of A within n of p, so B lies wholly inside or outside
///           A: collides iff p is in A (or containment, with B's box used)
///       else each candidate against the moving edges whose box meets its own
///           (grown by d and the margin; chunks whose posed circle misses it
///           skipped whole): the pair tests; then containment
///
///   pair tests: for d == 0 the signs of alpha of the moving edge's ends
///       (the paper's detailed test) and the same with the roles swapped, as
///       filters in double; then the exact segment test (d == 0) or the exact
///       distance test (d > 0), on the two edges' vertices posed in NT
///   containment (no pair met): the regions meet iff one contains a ring of
///       the other; a ring's vertex outside the other polygon's bounding
///       circle or box (in double, widened) is outside it without a locate;
///       so is one with a vertex deep outside the other's cells, when built;
///       a ring whose vertex the other polygon's edge tree, when built,
///       locates in double for certain takes that answer
///       (certain_location_through_tree); in an exact or filtered NT, A's
///       vertices are located in B by crossings settled in double first
///       (one_contains_other)
///
/// Features (features.hpp) are chosen at compile time; `detector<NT>` has them
/// all. Without `witness` and `distance` the frame stops at the first meeting
/// pair and the segment test is the only pair test; without `coherence` every
/// frame is a jump; without `holes` the ring bookkeeping
/// is gone (one ring each); without `statistics` nothing is counted.
template <class NT, class Features = all_features>
class detector
    : detector_detail::feature_state<detector_statistics, Features::has(features::statistics), 0>,
      detector_detail::feature_state<detector_detail::coherence_state, Features::has(features::coherence), 1>,
      detector_detail::feature_state<pair_collector, Features::has(features::witness), 2>,
      detector_detail::feature_state<detector_detail::distance_state<NT>, Features::has(features::distance), 3> {
    static constexpr bool with_statistics = Features::has(features::statistics);
    static constexpr bool with_coherence = Features::has(features::coherence);
    static constexpr bool with_witness = Features::has(features::witness);
    static constexpr bool with_distance = Features::has(features::distance);
    static constexpr bool with_holes = Features::has(features::holes);
    using statistics_state = detector_detail::feature_state<detector_statistics, with_statistics, 0>;
    using coherence_state = detector_detail::feature_state<detector_detail::coherence_state, with_coherence, 1>;
    using witness_state = detector_detail::feature_state<pair_collector, with_witness, 2>;
    using distance_state = detector_detail::feature_state<detector_detail::distance_state<NT>, with_distance, 3>;

public:
    /// The feature set the detector was built with.
    using feature_set_type = Features;

    /// Precomputes A's covering and influence areas; the edge grid (for B's
    /// reach) and the edge trees are built by the first frame that needs them.
    /// Throws std::invalid_argument when `options` asks for witnesses or a
    /// distance > 0 the detector was built without (or d < 0 or not finite),
    /// invalid_input for an empty polygon, one beyond NT's range, or one of
    /// several rings without features::holes. collide throws invalid_input
    /// for a pose with a NaN or infinite component. In float, double or
    /// long double, polygons whose largest coordinate lies outside NT's safe window
    /// are prepared scaled by a power of two 2^k, and each frame's
    /// translation and the distance d with them (core/range_scaling.hpp):
    /// the same answers, without overflow or underflow.
    detector(const polygon& static_polygon, const polygon& moving_polygon, detector_options options = {})
        : detector(range_shift<NT>(checked(static_polygon, "static"), checked(moving_polygon, "moving")),
                   static_polygon, moving_polygon, options) {}

    /// A detector on prepared polygons (prepare_static, prepare_moving),
    /// which many detectors may share, in any number of threads: one A for
    /// many B, one B for many A. Building it costs the per-frame arrays
    /// (linear in B's vertices); A's and B's structures are the shared ones.
    /// Throws as the constructor from polygons.
    detector(std::shared_ptr<const static_scene<NT>> static_polygon,
             std::shared_ptr<const moving_scene<NT>> moving_polygon, detector_options options = {})
        : a_(checked(std::move(static_polygon), "static")),
          b_(checked(std::move(moving_polygon), "moving")),
          options_(options),
          given_distance_(options.distance) {
        using tr = number_traits<NT>;
        if (!(options_.distance >= 0) || !std::isfinite(options_.distance))
            throw std::invalid_argument("detector: the distance must be finite and >= 0");
        if (!with_witness && options_.witness)
            throw std::invalid_argument("detector: built without features::witness, options.witness must be false");
        if (!with_distance && options_.distance != 0)
            throw std::invalid_argument("detector: built without features::distance, options.distance must be 0");
        reach_ = moving_reach(b_.radius(), distance());
        if constexpr (with_coherence) coherence_state::value.skin = options_.temporal_coherence ? 0.25 * reach_ : 0.0;
        margin_ = placing_margin<NT>(a_->scale + a_->radius + reach_ + skin() + b_.scene().scale);
        const polygon& as = a_->shape;
        ring_boxes(as, as.vertices(), with_holes ? as.ring_count() : 1, a_ring_boxes_);
        if (every_pair_pays())
            for (std::size_t e = 0; e < as.size(); ++e)
                a_edge_boxes_.push_back(edge_box_of(as, as.vertices(), e, {0, 0}, {0, 0}));
        make_chunks();
        convex_route_ = distance() == 0 && a_->convex && b_.scene().convex && convex_pair_pays(as.size(), b_.size());
        inner_discs_ = a_->convex && b_.scene().convex;
        if (inner_discs_) {
            a_inner_ = a_->inner();
            b_inner_ = b_.scene().inner();
        }
        if constexpr (with_distance) {
            distance_state::value.distance = tr::from_double(options_.distance);
            distance_state::value.distance2 = distance_state::value.distance * distance_state::value.distance;
        }
    }

    /// Whether the closed regions of A and of B posed by q are at distance
    /// <= d (they meet, for d = 0); with witnesses, every edge pair within d.
    /// Throws invalid_input for a pose with a NaN or infinite component.
    ///
    ///   q's translation scaled by 2^k when the polygons were (the constructor)
    ///   f <- the frame: B's centroid p posed in double, the rounding margin
    ///   if A's and B's bounding circles are apart:            disjoint
    ///   if A and B are small and convex, d == 0, and no witnesses asked:
    ///       if their inner discs certainly overlap:           they meet
    ///       if an edge of one separates them:                 disjoint
    ///       else                                              they meet
    ///   if A and B are small and convex, witnesses asked, and their inner
    ///   discs certainly overlap: the pairs below, no containment
    ///   if p jumped (no coherence to use):
    ///       if A and B are convex and their inner discs certainly
    ///       overlap:                       they meet (with witnesses: the
    ///                                      pairs below, no containment)
    ///       pairs from A's and B's edge trees
    ///       traversed together (every pair's boxes, for two small polygons),
    ///       then containment
    ///   refresh the cached candidates if p left their skin
    ///   if circle_test_pays() and B's edges keep off A's circle:
    ///       no boundary pair:                                  containment of A in B
    ///   if tree_pays():   pairs from each moving edge's query of A's edge tree
    ///   if not candidates_pay(): pairs from the edge trees traversed together
    ///   else:             pairs from the candidates in p's extended areas
    ///   (both end in containment when no pair meets)
    frame_result collide(const pose& q) {
        if (shift_ != 0) return collide_at(scaled_by_power_of_two(q, shift_));
        return collide_at(q);
    }

    /// collide(q) for a loop over many frames: whether the closed regions
    /// are within d, the witnesses (when asked for) written into `pairs`,
    /// which is cleared first and keeps its capacity from call to call, so
    /// that frames allocate nothing once it holds a frame's pairs. The same
    /// answer and pairs as collide(q).
    bool collide(const pose& q, std::vector<edge_pair>& pairs) {
        pairs.clear();
        // (out_ is set for this call only, an exception included.)
        struct writing {
            std::vector<edge_pair>*& at;
            ~writing() { at = nullptr; }
        };
        out_ = &pairs;
        const writing reset{out_};
        return collide(q).collides;
    }

    /// Builds now what frames otherwise build on first use: A's cone index
    /// and edge tree, B's edge tree, both polygons' deep cells and reaching
    /// vertices when the pair
    /// can search the trees (not two small convex polygons, nor a pair of
    /// few edge pairs, every_pair_pays; all shared with every detector on
    /// the same prepared polygons) and the detector's edge grid. Frames after it cost
    /// the same from the first one on, as a real-time loop wants; answers are
    /// unchanged. Costs about what the first frames would have paid.
    void build_structures() {
        (void)a_->areas();
        (void)a_tree();
        (void)b_tree();
        if (!convex_route_ && !every_pair_pays()) {
            (void)a_->interior();
            (void)b_.scene().interior();
            (void)a_->reaching();
            (void)b_.scene().reaching();
        }
        if (!grid_built_) build_grid();
    }

    /// Counters of the work done so far (only with features::statistics).
    const detector_statistics& statistics() const {
        static_assert(with_statistics, "detector built without features::statistics");
        return statistics_state::value;
    }
    /// The options the detector was built with.
    detector_options options() const {
        detector_options o = options_;
        o.distance = given_distance_;
        return o;
    }

    /// Bytes the detector holds beyond the prepared polygons it shares (A's
    /// covering, influence areas and edge tree, B's shape and edge tree: the
    /// same for every feature set, see static_scene and moving_scene): its own
    /// size and the capacities of its arrays.
    std::size_t state_bytes() const {
        const std::size_t grid =
            grid_built_ ? (grid_.cell_count() + 1 + grid_.entry_count()) * sizeof(std::uint32_t) : 0;
        std::size_t bytes = sizeof(*this) + grid + chunks_.capacity() * sizeof(chunk) +
                            chunk_centers_.capacity() * sizeof(point<double>) + b_edge_boxes_.capacity() * sizeof(box) +
                            chunk_boxes_frame_.capacity() * sizeof(std::uint64_t) +
                            (cache_.capacity() + candidates_.capacity()) * sizeof(std::uint32_t) + b_.heap_bytes() +
                            a_ring_boxes_.capacity() * sizeof(box) + a_edge_boxes_.capacity() * sizeof(edge_box);
        if constexpr (with_witness) bytes += witness_state::value.heap_bytes();
        return bytes;
    }

private:
    /// The constructor from polygons, with the power of two 2^shift by which
    /// they (and each frame's translation, and d) are scaled.
    detector(int shift, const polygon& static_polygon, const polygon& moving_polygon, detector_options options)
        : detector(prepare_static<NT>(static_polygon, shift), prepare_moving<NT>(moving_polygon, shift),
                   scaled_distance(options, shift)) {
        shift_ = shift;
        given_distance_ = options.distance;
    }

    /// The options with d scaled by 2^shift (scaled_length).
    static detector_options scaled_distance(detector_options o, int shift) {
        o.distance = scaled_length(o.distance, shift);
        return o;
    }

    /// collide() on a pose in the prepared polygons' units.
    frame_result collide_at(const pose& q) {
        tally(&detector_statistics::frames);
        const frame f = begin_frame(q);
        if (circles_apart(f)) {
            tally(&detector_statistics::circle_rejections);
            return {};
        }
        if (convex_route_ && !witnessing()) {
            if (inner_discs_overlap(f)) return {true, {}};
            tally(&detector_statistics::convex_frames);
            return {convex_meet(f), {}};
        }
        if (convex_route_ && inner_discs_overlap(f)) return convex_pairs(f);
        if (last_pair_meets(f)) {
            tally(&detector_statistics::last_pair_frames);
            return {true, {}};
        }
        if (!candidates_can_pay() || !coherent_step(f)) {
            if (!convex_route_ && inner_discs_overlap(f))
                return witnessing() ? convex_pairs(f) : frame_result{true, {}};
            return every_pair_pays() ? every_pair(f) : pairs_through_trees(f);
        }
        refresh_candidates(f);
        if (circle_test_pays() &&
            edges_clear_of(f.t, a_->shape.centroid(), a_->radius + distance() + 2 * f.margin, f.margin))
            return clear_of_a(f);
        if (tree_pays()) return pairs_through_tree(f);
        if (!candidates_pay()) return every_pair_pays() ? every_pair(f) : pairs_through_trees(f);
        return pairs_through_candidates(f);
    }

    /// One frame's pose and the filters' rounding: B's centroid posed in
    /// double (p), the margin of the frame's double values, and B's reach
    /// widened by it (n).
    struct frame {
        rotation_pose t;
        point<double> p;
        double margin = 0, n = 0;
    };

    /// Poses B's centroid for the frame. Rounding of the posed coordinates is
    /// relative to the magnitudes of the terms that make them: B's own
    /// coordinates and A's (in margin_), the translation, and the result;
    /// placing_margin of their sum (the posings' own rounding for a type
    /// that places as finely as double, posing_margin for float). Every
    /// filter below takes the margin as the distance on each coordinate
    /// between a point in double and the same point in NT and bounds its
    /// own rounding separately (certain_side, farther_widening, the trees'
    /// and grid's grows), or rounds a few times by at most u times the
    /// scale, which placing_slack covers.
    frame begin_frame(const pose& q) {
        frame f{rotation_pose(q), {}, 0, 0};
        b_.place(f.t);
        f.p = b_.approximate_centroid();
        f.margin =
            margin_ + placing_margin<NT>(std::fabs(f.p.x) + std::fabs(f.p.y) + std::fabs(q.tx) + std::fabs(q.ty));
        f.n = reach_ + f.margin;
        return f;
    }

    /// The first filter: whether the bounding circles are certainly apart (a filter in
    /// double, widened by the margin).
    bool circles_apart(const frame& f) const {
        const point<double>& o = a_->shape.centroid();
        return filter_length(f.p.x - o.x, f.p.y - o.y) > a_->radius + f.n + f.margin;
    }

    /// Gathering: the candidates gathered within n + skin, reused while p moves
    /// less than the skin.
    void refresh_candidates(const frame& f) {
        if constexpr (with_coherence) {
            const detector_detail::coherence_state& c = coherence_state::value;
            if (c.valid && c.within_skin(c.center, f.p)) return;
        }
        gather(f.p, f.margin);
    }

    /// Whether this frame can use coherence: the cached candidates are still
    /// valid (p within their skin), or p moved less than the skin in each of
    /// the last two frames, so that candidates gathered now are likely to
    /// serve the next frames (a trajectory's steps; two, so that a random
    /// pose landing near the last one by chance does not gather). A jump (a random pose, a first frame far
    /// from the last, or a detector without features::coherence) takes the
    /// edge trees instead: gathering would cost about as much as the frame
    /// and serve no other.
    bool coherent_step(const frame& f) {
        if constexpr (with_coherence) {
            detector_detail::coherence_state& c = coherence_state::value;
            if (!options_.temporal_coherence) return false;
            const bool in_skin = c.valid && c.within_skin(c.center, f.p);
            const bool small_step = c.has_last && c.within_skin(c.last, f.p);
            const bool moving_steadily = small_step && c.last_step_small;
            c.last = f.p;
            c.has_last = true;
            c.last_step_small = small_step;
            return in_skin || moving_steadily;
        }
        return false;
    }

    /// Whether the edge pair that met last (kept by test_pair with
    /// features::coherence), or one of the pairs that met before it
    /// (recent_met_pairs, while recent_pairs_odds_ finds them worth
    /// asking), still meets, by the pair tests: asked first
    /// when no witness is (a frame then needs one meeting pair, not all)
    /// and p moved at most the skin since the last frame. Along a
    /// trajectory two overlapping polygons most often keep crossing at the
    /// same two edges for many frames; one pair test then answers the frame
    /// where the search would descend the trees or scan the candidates
    /// first. A pair that no longer meets costs one test, and the frame
    /// goes on as before; one that meets counts as the small step it was
    /// for the next frame's coherent_step.
    [[gnu::always_inline]] bool last_pair_meets(const frame& f) {
        if constexpr (with_coherence) {
            const detector_detail::coherence_state& c = coherence_state::value;
            if (!options_.temporal_coherence || !c.has_met || witnessing() || !c.has_last ||
                !c.within_skin(c.last, f.p))
                return false;
            return pairs_that_met_meet(f);
        } else {
            (void)f;
            return false;
        }
    }

    /// last_pair_meets past its conditions: the pair tests.
    bool pairs_that_met_meet(const frame& f) {
        if constexpr (with_coherence) {
            detector_detail::coherence_state& c = coherence_state::value;
            // The latest; failing, it joins the earlier pairs, which are
            // tried next when the frame before was a small step too (poses
            // wandering within a small range, not a random pose landing
            // near the last one by chance) and while they pay
            // (recent_pairs_odds_). (A pair that meets becomes the latest
            // in test_pair, which writes nothing else.)
            const auto meets = [&](std::uint32_t e, std::uint32_t j) {
                return test_pair(e, j, b_.approximate_now(j), b_.approximate_now(next_b(j)), f.margin);
            };
            if (!meets(c.met_a, c.met_b)) {
                c.keep_earlier(c.met_a, c.met_b);
                if (c.earlier_count == 1 || !c.last_step_small || !recent_pairs_odds_.worth_asking()) return false;
                std::size_t k = 1;
                while (k < c.earlier_count && !meets(c.earlier[k].first, c.earlier[k].second)) ++k;
                recent_pairs_odds_.record(k < c.earlier_count);
                if (k == c.earlier_count) return false;
            }
            c.last = f.p;
            c.last_step_small = true;
            return true;
        } else {
            (void)f;
            return false;
        }
    }

    /// Whether vertices_deep_inside may be asked: both polygons' deep cells
    /// were built (by another detector sharing them, or build_structures),
    /// or this detector has searched the trees (n_A + n_B) /
    /// interior_build_edges times already, and builds them now.
    bool interiors_pay() {
        if (a_->interior_if_built() && b_.scene().interior_if_built()) return true;
        return ++searches_without_interiors_ > (a_->shape.size() + b_.size()) / interior_build_edges;
    }

    /// Whether a few vertices alone show that the regions meet (see
    /// deep_probes for which): B's vertices posed in double (within the
    /// frame margin of their values in NT) looked up in A's deep cells
    /// (interior_cells::holds), then A's vertices placed in B's frame by the
    /// inverse pose in double, looked up in B's (within twice the margin,
    /// plus B's scale times pose_scale_widening for the pose's scale
    /// factor). A vertex of one polygon in the other's closed region is a
    /// point of both regions: the frame collides, at any separation
    /// distance. Asked by the trees' search without witnesses (a witness is
    /// an edge pair), while probe_odds finds it worth asking: two polygons
    /// that overlap by much of their area (random poses near contact, poses
    /// that jump about a shared border) most often have such a vertex,
    /// found by a look-up each, where the descent of both trees visits
    /// dozens of node pairs before the first crossing.
    bool vertices_deep_inside(const frame& f) {
        const interior_cells& in_a = a_->interior();
        const point<double>& o = a_->shape.centroid();
        if (!in_a.empty()) {
            // A's centroid seen from B's, in B's frame.
            const point<double> w = f.t.unapply_in_double(o);
            const point<double>& c = b_.scene().centroid;
            const auto posed_deep = [&](std::uint32_t j) { return in_a.holds(b_.approximate_now(j), f.margin); };
            if (deep_b_.found(posed_deep, b_.scene().reaching().toward(w.x - c.x, w.y - c.y))) return true;
        }
        const interior_cells& in_b = b_.scene().interior();
        if (in_b.empty()) return false;
        const double margin = placed_in_b_margin(f.margin);
        const polygon& as = a_->shape;
        const auto placed_deep = [&](std::uint32_t e) {
            return in_b.holds(f.t.unapply_in_double(as.vertex(e)), margin);
        };
        return deep_a_.found(placed_deep, a_->reaching().toward(f.p.x - o.x, f.p.y - o.y));
    }

    /// The margin of a vertex of A placed in B's frame by the inverse pose
    /// in double (rotation_pose::unapply_in_double) and looked up in B's
    /// cells: twice the frame margin, plus B's scale times
    /// pose_scale_widening for the pose's scale factor.
    double placed_in_b_margin(double frame_margin) const {
        return 2 * frame_margin + b_.scene().scale * pose_scale_widening;
    }

    /// Whether two convex polygons are small enough for the separating-edge
    /// test: it tests at most na + nb edges, each against up to the other's
    /// vertices (na nb orientations when they meet in the worst order), where
    /// the other routes start with a centroid, a cached or a tree search.
    static bool convex_pair_pays(std::size_t na, std::size_t nb) { return na * nb <= convex_pair_limit; }

    /// B's inner disc posed for the frame: its centre in double, within the
    /// frame margin of the exact one, its radius shrunk by 1.5 margin (see
    /// b_inner_).
    disc posed_b_inner(const frame& f) const {
        return {f.t.template apply<double>(b_inner_.centre), std::max(b_inner_.radius - 1.5 * f.margin, 0.0)};
    }

    /// Whether A and B, both convex, certainly meet by their inner discs
    /// (A's as prepared, B's posed_b_inner): the discs overlap
    /// (discs_certainly_overlap), each in its polygon's region: on random
    /// poses of convex polygons near contact 60% to 80% of the poses are
    /// answered so, before any vertex of B is posed; other polygons do not
    /// ask (inner_discs_). A frame that gathers witnesses still seeks its
    /// pairs (the discs do not tell which edges meet), but needs no
    /// containment test when it finds none (convex_pairs).
    bool inner_discs_overlap(const frame& f) {
        if (!inner_discs_) return false;
        const disc b = posed_b_inner(f);
        if (!discs_certainly_overlap(a_inner_.centre, a_inner_.radius, b.centre, b.radius, f.margin)) return false;
        tally(&detector_statistics::disc_frames);
        return true;
    }

    /// Whether convex A and B meet, their inner discs not certainly
    /// overlapping (inner_discs_overlap, asked first): the separating-edge
    /// test (convex_regions_meet): A's vertices exact as
    /// given, B's posed in double within the frame margin and in NT when a
    /// sign needs them. The separating edge is kept for the next frame with
    /// features::coherence. The spread of the vertices'
    /// doubles: a vertex of A lies within R_A of O_A, one of B within r_B
    /// (B's radius) of its exact centroid, whose double p is within the
    /// margin of it and within |p - O_A| of O_A; so two vertices lie within
    /// R_A + r_B + |p - O_A| + 4 margin in the Euclidean norm (each double
    /// within margin sqrt 2 of its point), within
    /// sqrt 2 (< 1.5) times that in the L1 norm (the 6% between sqrt 2 and
    /// 1.5 is far above the computation's few roundings of 2^-53 each).
    bool convex_meet(const frame& f) {
        b_.place_approximate();
        const polygon& as = a_->shape;
        const auto& cov = a_->covering;
        const auto a = make_convex_view(
            as.size(), as.vertices().data(), [&](std::size_t i) -> const point<NT>& { return cov.start(i); }, 0.0,
            a_inner_);
        const auto b = make_convex_view(
            b_.size(), &b_.approximate(0), [&](std::size_t j) -> const point<NT>& { return b_.vertex(j); }, f.margin,
            posed_b_inner(f));
        const point<double>& o = a_->shape.centroid();
        const double spread = 1.5 * (a_->radius + b_.radius() + filter_length(f.p.x - o.x, f.p.y - o.y) + 4 * f.margin);
        if constexpr (with_coherence) return convex_regions_meet<NT>(a, b, spread, coherence_state::value.separating);
        std::uint32_t none = 0;
        return convex_regions_meet<NT>(a, b, spread, none);
    }

    /// The witnesses of two convex polygons known to meet (their inner discs
    /// overlap, inner_discs_overlap): every edge pair that meets, by the
    /// pair search of a jump; none means that one polygon holds the other,
    /// so no containment test is asked.
    frame_result convex_pairs(const frame& f) {
        return every_pair_pays() ? every_pair(f, true) : pairs_through_trees(f, true);
    }

    /// For a jump, testing the boxes of every edge pair costs less than
    /// descending both trees when there are few pairs (every_pair_limit,
    /// every_pair_limit_b_near).
    bool every_pair_pays() const {
        const std::size_t pairs = a_->shape.size() * b_.size();
        return pairs <= every_pair_limit || (pairs <= every_pair_limit_b_near && b_.size() <= 2 * a_->shape.size());
    }

    /// The strategies' size heuristics. The circle test of B's edges against
    /// A's circle pays when B has no more chunks than cached candidates (+1):
    /// it then costs about what one pass over the candidates would.
    bool circle_test_pays() const { return chunks_.size() <= cache_.size() + 1; }
    /// A's edge tree pays when B's edges times tree_cost are fewer than the
    /// cached candidates: a tree query costs about tree_cost box tests.
    bool tree_pays() const { return b_.shape().size() * tree_cost < cache_.size(); }
    /// B is posed in double before the candidates are filtered when it has no
    /// more edges than there are cached candidates: its box then prunes them.
    bool pose_b_first() const { return b_.shape().size() <= cache_.size(); }
    /// The candidates pay while the last frame's count of them (the cache's
    /// size after a gather) times B's chunks is at most candidate_chunk_limit:
    /// each candidate is tested against every chunk's circle, so that a B of
    /// many chunks near many edges of A (two large polygons along a shared
    /// border) would pay for the whole boundary within reach at every frame,
    /// where the trees traversed together pay for the edges that meet.
    bool candidates_pay() const { return candidate_estimate_ * chunks_.size() <= candidate_chunk_limit; }
    /// Whether candidates_pay can hold for any frame that finds one: not when
    /// B's chunks alone exceed its bound (a B of more than
    /// candidate_chunk_limit * chunk_edges edges). Such a B takes the trees
    /// at once: gathering the candidates and testing B's chunks against A's
    /// circle first would cost more than the trees' frame they lead to.
    bool candidates_can_pay() const { return chunks_.size() <= candidate_chunk_limit; }

    /// When B's edges keep off A's bounding circle: no boundary pair.
    /// B's vertices lie outside A's circle, so outside A; A lies wholly in
    /// B or wholly outside it, and can lie in B only if its first vertex
    /// lies within B's circle.
    frame_result clear_of_a(const frame& f) {
        tally(&detector_statistics::disc_rejections);
        tally(&detector_statistics::containment_tests);
        const point<double>& a0 = a_->shape.vertex(0);
        if (filter_length(a0.x - f.p.x, a0.y - f.p.y) > b_.radius() + 2 * f.margin) return {};
        place_approximate(f.t);
        return {contains(f.n, f.margin, false), {}};
    }

    /// The pair search without candidates, for a frame with no coherence to use:
    /// first a vertex of either polygon deep in the other's region
    /// (vertices_deep_inside, while probe_odds finds it worth asking); then
    /// A's edge tree (in A's frame) and B's (in B's frame, its circles posed
    /// by the frame's pose) traversed together (edge_tree::query_pairs):
    /// below a leaf of B each of its edges, posed in double only then, finds
    /// the static edges near it (or, for a B of more edges than A, the other
    /// way round in B's frame: A's circles and edges placed there by the
    /// inverse pose), and each such pair gets the pair tests,
    /// stopping at the first meeting pair without witnesses; then containment
    /// with B's box taken from its posed bounding circle.
    frame_result pairs_through_trees(const frame& f, bool meet_known = false) {
        tally(&detector_statistics::jump_frames);
        if (!witnessing() && interiors_pay() && interior_odds_.worth_asking()) {
            const bool deep = vertices_deep_inside(f);
            interior_odds_.record(deep);
            if (deep) {
                tally(&detector_statistics::interior_frames);
                return {true, {}};
            }
        }
        if constexpr (with_witness)
            if (options_.witness) witness_state::value.clear();
        // The posed circles hold B's posed edges up to the pose's scale
        // factor (pose_scale_widening) and the rounding of the posed centre
        // (the frame margin).
        const double circle_grow = distance() + 2 * f.margin + b_.radius() * pose_scale_widening;
        const auto test = [&](std::uint32_t e, std::uint32_t j) {
            tally(&detector_statistics::candidate_edges);
            return test_pair(e, j, b_.approximate_now(j), b_.approximate_now(next_b(j)), f.margin) && !witnessing();
        };
        const double grow = distance() + f.margin, line_grow = distance() + 2 * f.margin;
        const edge_tree::turn_of turn{std::fabs(f.t.c), std::fabs(f.t.s)};
        bool met;
        if (b_.size() <= a_->shape.size()) {
            // B's circles posed into A's frame; B's edges query A's subtrees.
            const auto place = [&](const point<double>& q) { return f.t.template apply<double>(q); };
            const auto ends = [&](std::uint32_t j) {
                return std::pair<point<double>, point<double>>(b_.approximate_now(j), b_.approximate_now(next_b(j)));
            };
            met = a_tree().query_pairs(b_tree(), place, turn, circle_grow, grow, line_grow, ends, test);
        } else {
            // The larger B in its own frame: A's circles and edges placed
            // there by the inverse pose, evaluated in double (rounding of the
            // order of the frame margin's, and the pose's scale factor,
            // below pose_scale_widening: both inside the grows); A's edges
            // query B's subtrees.
            const rotation_pose t = f.t;
            const auto place = [t](const point<double>& q) { return t.unapply_in_double(q); };
            const polygon& as = a_->shape;
            const auto ends = [&](std::uint32_t e) {
                return std::pair<point<double>, point<double>>(place(as.vertex(e)), place(as.vertex(as.next(e))));
            };
            const double a_circle_grow = distance() + 2 * f.margin + a_->radius * pose_scale_widening;
            met = b_tree().query_pairs(a_tree(), place, turn, a_circle_grow, grow, line_grow, ends,
                                       [&](std::uint32_t j, std::uint32_t e) { return test(e, j); });
        }
        if (met) return {true, {}};
        if constexpr (with_witness) {
            const pair_collector& pairs = witness_state::value;
            if (!pairs.empty()) return {true, numbered(pairs)};
        }
        if (meet_known) return {true, {}};
        tally(&detector_statistics::containment_tests);
        // B's box as the traversal saw it: the box of its posed root circle,
        // cut to its root box turned about the posed centre (far narrower
        // for a long B turned little: a ring of A outside it is outside B
        // without a look-up).
        const point<double> c = f.t.template apply<double>(b_tree().root_center());
        const double r = b_tree().root_radius() * (1 + pose_scale_widening) + 2 * f.margin;
        const box turned = b_tree().placed_box([&](const point<double>& q) { return f.t.template apply<double>(q); },
                                               turn, b_tree().root_radius() * pose_scale_widening + 2 * f.margin);
        box bb;
        bb.add({std::max(c.x - r, turned.min_x), std::max(c.y - r, turned.min_y)});
        bb.add({std::min(c.x + r, turned.max_x), std::min(c.y + r, turned.max_y)});
        const bool finite =
            std::isfinite(bb.min_x) && std::isfinite(bb.min_y) && std::isfinite(bb.max_x) && std::isfinite(bb.max_y);
        return {contains_within(bb, finite, f.n, f.margin, true, [&](std::size_t j) { return b_.approximate_now(j); }),
                {}};
    }

    /// The pair search for a jump of two small polygons: B posed in double,
    /// every pair whose boxes (grown by d and the margin) meet gets the pair
    /// tests, stopping at the first meeting pair without witnesses; then
    /// containment. An edge of B whose box misses A's, or an edge of A whose
    /// box misses B's, meets no edge of the other: the pairs' boxes are
    /// tested only between the edges left (every_pair_pays: B has at most
    /// every_pair_limit edges, A at least three).
    frame_result every_pair(const frame& f, bool meet_known = false) {
        tally(&detector_statistics::jump_frames);
        place_approximate(f.t);
        if constexpr (with_witness)
            if (options_.witness) witness_state::value.clear();
        const polygon& as = a_->shape;
        const double grow = distance() + f.margin;
        INFLUENCE2D_ASSERT(b_.size() <= every_pair_limit, "every_pair: more edges of B than its array holds");
        // (B's boxes grown, A's kept from the constructor: the same
        // comparisons as A's grown against B's.)
        std::array<edge_box, every_pair_limit> near_a;  // B's grown edge boxes that meet A's box
        std::size_t near = 0;
        box bb;  // B's box (each vertex starts an edge)
        for (std::size_t j = 0; j < b_.size(); ++j) {
            const point<double>&u = b_.approximate(j), &v = b_.approximate(next_b(j));
            const edge_box ej{std::min(u.x, v.x) - grow, std::max(u.x, v.x) + grow, std::min(u.y, v.y) - grow,
                              std::max(u.y, v.y) + grow, static_cast<std::uint32_t>(j)};
            bb.add(u);
            near_a[near] = ej;
            near += boxes_meet(ej, as.bounds()) ? 1 : 0;
        }
        bb = bb.inflated(grow);
        for (std::uint32_t e = 0; near > 0 && e < as.size(); ++e) {
            const edge_box& ea = a_edge_boxes_[e];
            if (!meets_box(ea, bb)) continue;
            // (The boxes met listed first, without a branch per box: at
            // random poses each would be mispredicted about as often as
            // not.)
            std::array<std::uint32_t, every_pair_limit> met;
            std::size_t hits = 0;
            for (std::size_t k = 0; k < near; ++k) {
                met[hits] = near_a[k].edge;
                hits += boxes_meet(near_a[k], ea) ? 1 : 0;
            }
            for (std::size_t h = 0; h < hits; ++h) {
                tally(&detector_statistics::candidate_edges);
                const std::size_t j = met[h];
                if (test_pair(e, j, b_.approximate(j), b_.approximate(next_b(j)), f.margin) && !witnessing())
                    return {true, {}};
            }
        }
        return finish(f.n, f.margin, meet_known);
    }

    /// The pair search through A's edge tree: each moving edge, posed in double,
    /// finds the static edges near it, and each such pair gets the pair
    /// tests; then containment.
    frame_result pairs_through_tree(const frame& f) {
        tally(&detector_statistics::tree_frames);
        place_approximate(f.t);
        if constexpr (with_witness)
            if (options_.witness) witness_state::value.clear();
        const polygon& bs = b_.shape();
        for (std::size_t j = 0; j < bs.size(); ++j) {
            const point<double>&u = b_.approximate(j), &v = b_.approximate(next_b(j));
            const bool met =
                a_tree().query(u, v, distance() + f.margin, distance() + 2 * f.margin, [&](std::uint32_t e) {
                    tally(&detector_statistics::candidate_edges);
                    return test_pair(e, j, u, v, f.margin) && !witnessing();
                });
            if (met) return {true, {}};
        }
        return finish(f.n, f.margin);
    }

    /// The pair search and containment through the cached candidates: keep
    /// those whose extended area of length n contains p (and, with B posed first, whose box meets
    /// B's); none decides at once (containment, or p's location when B's box was
    /// not used: the disk of radius n about p then holds no edge of A, so B
    /// lies wholly inside or outside A); else each candidate against the
    /// moving edges near it (the pair tests), then containment.
    frame_result pairs_through_candidates(const frame& f) {
        const bool posed = pose_b_first();
        if (posed) place_approximate(f.t);
        candidates_.clear();
        const polygon& as = a_->shape;
        const polygon& bs = b_.shape();
        box bb;  // with B posed in double: B's box grown by d and the margin
        if (posed) {
            for (std::size_t j = 0; j < bs.size(); ++j) bb.add(b_.approximate(j));
            bb = bb.inflated(distance() + f.margin);
        }
        if (!bb.empty()) {
            // Only edges whose box meets B's can meet B.
            for (std::uint32_t e : cache_) {
                const point<double>&u = as.vertex(e), &v = as.vertex(as.next(e));
                if (std::max(u.x, v.x) >= bb.min_x && std::min(u.x, v.x) <= bb.max_x &&
                    std::max(u.y, v.y) >= bb.min_y && std::min(u.y, v.y) <= bb.max_y &&
                    may_be_in_extended_area(options_.shape, f.p, u, v, f.n + f.margin))
                    candidates_.push_back(e);
            }
            tally(&detector_statistics::candidate_edges, candidates_.size());
            candidate_estimate_ = candidates_.size();
            if (candidates_.empty()) {  // no boundary pair: containment
                tally(&detector_statistics::containment_tests);
                return {contains(f.n, f.margin), {}};
            }
        } else {
            for (std::uint32_t e : cache_)
                if (may_be_in_extended_area(options_.shape, f.p, as.vertex(e), as.vertex(as.next(e)), f.n + f.margin))
                    candidates_.push_back(e);
            tally(&detector_statistics::candidate_edges, candidates_.size());
            candidate_estimate_ = candidates_.size();
            if (candidates_.empty()) return p_located(f);
        }
        if (!posed) place_approximate(f.t);
        if constexpr (with_witness)
            if (options_.witness) witness_state::value.clear();
        ++boxes_frame_;  // B's edges' boxes made anew, chunk by chunk, as test_edge reaches them
        for (std::uint32_t e : candidates_)
            if (test_edge(e, f.margin) && !witnessing()) return {true, {}};
        return finish(f.n, f.margin);
    }

    /// No edge of A within n of p: B lies wholly inside or outside A, as p
    /// does (cached with the candidates when there were none to gather).
    frame_result p_located(const frame& f) {
        tally(&detector_statistics::containment_tests);
        if constexpr (with_coherence)
            if (cache_.empty()) return {coherence_state::value.center_inside, {}};
        // p outside A's bounding circle (widened) is outside A.
        const point<double>& o = a_->shape.centroid();
        if (filter_length(f.p.x - o.x, f.p.y - o.y) > a_->radius + 2 * f.margin) return {};
        return {a_->areas().locate(b_.centroid()) == location::inside, {}};
    }

    /// The polygon, refused when empty, beyond NT's range (accepted_polygon)
    /// or, built without holes, with several rings.
    static const polygon& checked(const polygon& p, const char* which) {
        accepted_polygon<NT>(p, which);
        if (!with_holes && p.ring_count() != 1)
            throw invalid_input(std::string("detector built without features::holes: the ") + which + " polygon has " +
                                std::to_string(p.ring_count()) + " rings");
        return p;
    }
    /// A prepared polygon, checked as above (and refused when null).
    template <class Scene>
    static std::shared_ptr<const Scene> checked(std::shared_ptr<const Scene> s, const char* which) {
        if (!s) throw invalid_input(std::string("detector: no prepared ") + which + " polygon (a null pointer)");
        checked(s->shape, which);
        return s;
    }
    /// The separation distance (0 without features::distance).
    double distance() const {
        if constexpr (with_distance) return options_.distance;
        return 0;
    }
    /// The skin of the candidate cache (0 without features::coherence).
    double skin() const {
        if constexpr (with_coherence) return coherence_state::value.skin;
        return 0;
    }
    bool witnessing() const {
        if constexpr (with_witness) return options_.witness;
        return false;
    }
    template <class Counter>
    void tally(Counter counter, std::size_t k = 1) {
        if constexpr (with_statistics) statistics_state::value.*counter += k;
    }
    /// The end vertex of B's edge j.
    std::size_t next_b(std::size_t j) const {
        if constexpr (with_holes) return b_.shape().next(j);
        return j + 1 == b_.size() ? 0 : j + 1;
    }

    /// Poses B's vertices and its chunks' centres by t in double.
    void place_approximate(const rotation_pose& t) {
        b_.place_approximate();
        for (std::size_t c = 0; c < chunks_.size(); ++c) chunk_centers_[c] = t.apply<double>(chunks_[c].center);
    }

    /// The edge grid over A for B's reach and the skin (built once).
    void build_grid() {
        grid_ = edge_grid(a_->shape, reach_ + skin(), margin_);
        grid_built_ = true;
    }

    /// Gathers the edges within reach + skin of p into the cache. When there
    /// are none, the disk of that radius about p holds no boundary of A, so
    /// every point within the skin of p is located as p is: that is cached too.
    /// Without features::coherence every frame gathers anew.
    void gather(const point<double>& pd, double frame_margin) {
        tally(&detector_statistics::candidate_rebuilds);
        cache_.clear();
        const double keep = reach_ + skin() + frame_margin + margin_;
        const polygon& s = a_->shape;
        if (!grid_built_) build_grid();
        for (std::uint32_t e : grid_.query(pd))
            if (may_be_within(pd, s.vertex(e), s.vertex(s.next(e)), keep)) cache_.push_back(e);
        candidate_estimate_ = cache_.size();
        if constexpr (with_coherence) {
            detector_detail::coherence_state& c = coherence_state::value;
            c.center = pd;
            c.valid = false;
            if (cache_.empty()) c.center_inside = a_->areas().locate(b_.centroid()) == location::inside;
            c.valid = options_.temporal_coherence;
        }
        INFLUENCE2D_ASSERT(cache_.size() <= s.size(), "more cached candidates than static edges");
    }

    /// The frame's pairs in A's and B's input numbering: written into the
    /// caller's vector during collide(q, pairs) (none returned), else
    /// returned.
    std::vector<edge_pair> numbered(const pair_collector& pairs) const {
        if (out_ == nullptr) return pairs.in_input_numbering(a_->shape, b_.shape());
        pairs.in_input_numbering(a_->shape, b_.shape(), *out_);
        return {};
    }

    /// The end of a frame whose pairs were all tested: the pairs found, if
    /// any (with witnesses), else containment (or the meeting already known,
    /// `meet_known`: one polygon holds the other).
    frame_result finish(double n, double frame_margin, bool meet_known = false) {
        frame_result r;
        if constexpr (with_witness) {
            const pair_collector& pairs = witness_state::value;
            if (!pairs.empty()) {
                r.collides = true;
                r.pairs = numbered(pairs);
                return r;
            }
        }
        if (meet_known) return {true, {}};
        tally(&detector_statistics::containment_tests);
        r.collides = contains(n, frame_margin);
        return r;
    }

    /// Containment, B's vertices posed in double: whether one region holds a ring
    /// of the other (B's rings only if `b_may_be_inside_a`). Each shortcut
    /// holds per ring, so that every part of a multipolygon is accounted for:
    ///   a ring of A can lie in B only if that ring's box lies in B's box (the
    ///   box of the double approximations, grown by the rounding margin; a
    ///   value that is not finite leaves the question open);
    ///   a ring of B can lie in A only if its first vertex lies within A's
    ///   bounding circle (widened; NaN leaves it open);
    ///   and either only if none of its ring_probes vertices lies deep
    ///   outside the other polygon (ring_certainly_outside).
    bool contains(double n, double frame_margin, bool b_may_be_inside_a = true) {
        box bb;
        bool finite = true;
        for (std::size_t j = 0; j < b_.shape().size() && finite; ++j) {
            const point<double>& v = b_.approximate(j);
            finite = std::isfinite(v.x) && std::isfinite(v.y);
            bb.add(v);
        }
        return contains_within(bb.inflated(frame_margin), finite, n, frame_margin, b_may_be_inside_a,
                               [&](std::size_t j) { return b_.approximate(j); });
    }

    /// Containment given B's box (a box that holds posed B, with its rounding;
    /// `finite` false when it cannot be trusted) and B's vertices posed in
    /// double by `approximate(j)`.
    template <class Approximate>
    bool contains_within(const box& b_box, bool finite, double n, double frame_margin, bool b_may_be_inside_a,
                         Approximate&& approximate) {
        const interior_cells* in_a = nullptr;
        const interior_cells* in_b = nullptr;
        if (containment_cells_pay()) {
            in_a = &a_->interior();
            in_b = &b_.scene().interior();
        }
        const polygon& as = a_->shape;
        const rotation_pose& t = b_.placement();
        // A's vertices placed in B's frame by the inverse pose in double,
        // within placed_in_b_margin, and for a vertex far from B (beyond its
        // box) within unapply_widening of its distance from the pose's
        // origin.
        const double placed_margin = placed_in_b_margin(frame_margin);
        const auto placed_in_b = [&](std::size_t e) {
            const point<double>& v = as.vertex(e);
            const double reach = std::fabs(v.x - t.tx) + std::fabs(v.y - t.ty);
            return std::pair<point<double>, double>(t.unapply_in_double(v), placed_margin + unapply_widening * reach);
        };
        const polygon& bs = b_.shape();
        const auto a_ring_fate = [&](std::size_t r) {
            if (finite && !b_box.contains(a_ring_boxes_[r])) return ring_fate::outside;
            return ring_fate_in(in_b, b_.scene().tree_if_built(), bs, as, r, placed_in_b);
        };
        const point<double>& o = as.centroid();
        const double a_reach = a_->radius + 2 * frame_margin;
        const auto b_ring_fate = [&](std::size_t r) {
            if (!b_may_be_inside_a) return ring_fate::outside;
            const point<double> v = approximate(bs.ring_begin(r));
            if (filter_length(v.x - o.x, v.y - o.y) > a_reach) return ring_fate::outside;  // NaN: may be
            // (In a type that is not exact, A's cone index locates B's
            // vertex in a few cones, cheaper than a descent of A's tree.)
            const edge_tree* tree =
                number_traits<NT>::category == number_category::exact ? a_->tree_if_built() : nullptr;
            return ring_fate_in(in_a, tree, as, bs, r, [&](std::size_t j) {
                return std::pair<point<double>, double>(approximate(j), frame_margin);
            });
        };
        return one_contains_other<NT, with_holes>(*a_, b_, std::optional<double>(n), a_ring_fate, b_ring_fate,
                                                  std::optional<double>(frame_margin));
    }

    /// What is known of ring r of `shape`, past the box and circle filters,
    /// in the other polygon (`other`, in its own frame), its vertex j placed
    /// in the other's frame within a margin by `placed(j)` (a pair of the
    /// point in double and the margin):
    ///   the other's cells built (`cells`) and ring_certainly_outside finds
    ///   the ring outside them (its vertices placed, then looked up):
    ///   outside, tallied
    ///   the other's edge tree built (`tree`): the ring's first vertex,
    ///   placed, located through it in double
    ///   (certain_location_through_tree): inside or outside when that
    ///   settles it, tallied
    ///   else unknown, to be located by one_contains_other; without the
    ///   cells that locate is counted as a scan of the other polygon for
    ///   containment_cells_pay
    /// The tree's answer is valid for the ring whichever vertex: with no
    /// boundary pair the ring lies wholly in one face of the other's rings.
    template <class Placed>
    ring_fate ring_fate_in(const interior_cells* cells, const edge_tree* tree, const polygon& other,
                           const polygon& shape, std::size_t r, Placed&& placed) {
        const auto outside = [&](std::size_t j) {
            const auto [q, margin] = placed(j);
            return cells->excludes(q, margin);
        };
        if (cells && ring_certainly_outside(shape, r, outside)) {
            tally(&detector_statistics::containment_rings_excluded);
            return ring_fate::outside;
        }
        if (tree) {
            const auto [q, margin] = placed(shape.ring_begin(r));
            if (const std::optional<location> where = certain_location_through_tree(other, *tree, q, margin)) {
                tally(&detector_statistics::containment_tree_locates);
                return *where == location::inside ? ring_fate::inside : ring_fate::outside;
            }
        }
        if (!cells) containment_scanned_ += other.size();
        return ring_fate::unknown;
    }

    /// Whether ring r of `shape` certainly lies outside the other polygon:
    /// one of ring_probes of its vertices, spread along it, lies deep outside
    /// it (`outside(j)`, the other's cells). containment's premise (no edge
    /// of one meets an edge of the other) puts the whole ring in one face of
    /// the other's rings, so that one vertex outside puts it all outside,
    /// whichever vertex it is: a vertex on a shared border is not deep, one
    /// across the ring from it may be.
    template <class Outside>
    static bool ring_certainly_outside(const polygon& shape, std::size_t r, Outside&& outside) {
        const std::size_t first = shape.ring_begin(r), count = shape.ring_end(r) - first;
        const std::size_t probes = std::min(count, ring_probes);
        for (std::size_t k = 0; k < probes; ++k)
            if (outside(first + k * count / probes)) return true;
        return false;
    }

    /// Whether containment may ask the cells: both were built, or the rings
    /// this detector's containment tests located without them would have
    /// scanned more than cells_build_scans edges per edge of A and B, and it
    /// builds them now (as interiors_pay for the searches).
    bool containment_cells_pay() {
        if (a_->interior_if_built() && b_.scene().interior_if_built()) return true;
        return containment_scanned_ > cells_build_scans * (a_->shape.size() + b_.size());
    }

    /// Whether every moving edge, posed by t in double, is farther than
    /// `reach` from c (a distance that is not finite counts as near). B's
    /// edges come in chunks of up to chunk_edges (8) with a bounding circle in B's own frame
    /// (valid under any rigid motion): a chunk whose posed circle keeps clear
    /// of the disc is not looked into.
    bool edges_clear_of(const rotation_pose& t, const point<double>& c, double reach, double frame_margin) const {
        const polygon& bs = b_.shape();
        for (const chunk& k : chunks_) {
            const point<double> q = t.apply<double>(k.center);
            if (filter_length(q.x - c.x, q.y - c.y) > reach + k.radius + frame_margin) continue;
            point<double> u = t.apply<double>(bs.vertex(k.first));
            for (std::size_t j = k.first; j < k.last; ++j) {
                const point<double> v = t.apply<double>(bs.vertex(next_b(j)));
                if (may_be_within(c, u, v, reach)) return false;
                u = v;
            }
        }
        return true;
    }

    /// B's edges in chunks of up to chunk_edges (8) consecutive edges of a ring, each with
    /// the centre of its vertices' box and an upper bound of their distance
    /// from it.
    void make_chunks() {
        const polygon& bs = b_.shape();
        for (std::size_t r = 0; r < (with_holes ? bs.ring_count() : 1); ++r)
            for (std::size_t first = bs.ring_begin(r); first < bs.ring_end(r); first += chunk_edges) {
                chunk k;
                k.first = first;
                k.last = std::min(first + chunk_edges, bs.ring_end(r));
                box around;
                around.add(bs.vertices().data() + k.first, bs.vertices().data() + k.last);
                around.add(bs.vertex(bs.next(k.last - 1)));
                k.center = {around.min_x / 2 + around.max_x / 2, around.min_y / 2 + around.max_y / 2};
                long double r2 = 0;
                for (std::size_t j = k.first; j <= k.last; ++j) {
                    const point<double>& v = bs.vertex(j < k.last ? j : bs.next(k.last - 1));
                    const long double dx = static_cast<long double>(v.x) - k.center.x;
                    const long double dy = static_cast<long double>(v.y) - k.center.y;
                    r2 = std::max(r2, dx * dx + dy * dy);
                }
                k.radius = upper_sqrt(r2);
                chunks_.push_back(k);
            }
        chunk_centers_.resize(chunks_.size());
        b_edge_boxes_.resize(b_.size());
        chunk_boxes_frame_.assign(chunks_.size(), 0);
    }

    /// Tests static edge e against the moving edges whose boxes (from the
    /// double approximations of their posed ends, grown by the rounding
    /// margin and the distance) meet the static edge's; records the pairs
    /// found. A chunk of B whose posed circle misses that box is skipped
    /// whole (B's chunks: a subdivision in B's own frame, valid under any
    /// rigid motion).
    bool test_edge(std::uint32_t e, double frame_margin) {
        const polygon& as = a_->shape;
        box eb;
        eb.add(as.vertex(e));
        eb.add(as.vertex(as.next(e)));
        eb = eb.inflated(frame_margin + distance());
        bool found = false;
        for (std::size_t c = 0; c < chunks_.size(); ++c) {
            // The chunk's posed vertices, and so its edges, lie within its
            // radius of its posed centre, up to the rounding of both.
            const point<double>& q = chunk_centers_[c];
            const double r = chunks_[c].radius + 2 * frame_margin;
            if (q.x < eb.min_x - r || q.x > eb.max_x + r || q.y < eb.min_y - r || q.y > eb.max_y + r) continue;
            if (chunk_boxes_frame_[c] != boxes_frame_) {
                // This frame's boxes of the chunk's edges, for every candidate after this one.
                chunk_boxes_frame_[c] = boxes_frame_;
                for (std::size_t j = chunks_[c].first; j < chunks_[c].last; ++j) {
                    const point<double>&u = b_.approximate(j), &v = b_.approximate(next_b(j));
                    b_edge_boxes_[j] = {std::min(u.x, v.x), std::min(u.y, v.y), std::max(u.x, v.x), std::max(u.y, v.y)};
                }
            }
            for (std::size_t j = chunks_[c].first; j < chunks_[c].last; ++j) {
                const box& be = b_edge_boxes_[j];
                if (be.max_x < eb.min_x || be.min_x > eb.max_x || be.max_y < eb.min_y || be.min_y > eb.max_y) continue;
                if (!test_pair(e, j, b_.approximate(j), b_.approximate(next_b(j)), frame_margin)) continue;
                if (!witnessing()) return true;
                found = true;
            }
        }
        return found;
    }

    /// The exact decision for static edge e and moving edge j (recorded when
    /// they meet, with witnesses). For d == 0, in a type other than double,
    /// two filters in double come first, each the paper's detailed test with
    /// the roles of the edges swapped: both ends of one edge strictly on the
    /// same side of the other's line (alpha of the same non-zero sign), so
    /// the edges cannot meet; then edges that certainly cross in double
    /// (segments_certainly_cross) meet, at any d. Only then are the vertices
    /// posed in NT: the signs of alpha (orientation against the static edge's
    /// line, alpha up to the constant sigma_e) and the segment test (d == 0),
    /// or the exact distance test (d > 0).
    /// u and v are the moving edge's ends posed in double.
    bool test_pair(std::uint32_t e, std::size_t j, const point<double>& u, const point<double>& v,
                   double frame_margin) {
        const polygon& as = a_->shape;
        INFLUENCE2D_ASSERT(e < as.size() && j < b_.size(), "an edge pair beyond the polygons' edges");
        const std::size_t k = next_b(j);
        const point<double>&p = as.vertex(e), &q = as.vertex(as.next(e));
        // (In double the filter's values are the decision's own, A's ends as
        // given and B's posed alike: it could only repeat the decision's
        // signs.)
        if constexpr (!std::is_same_v<NT, double>)
            if (distance() == 0 && !segments_may_meet(p, q, u, v, frame_margin)) return false;
        tally(&detector_statistics::segment_tests);
        const auto& cov = a_->covering;
        const point<NT>& a = cov.start(e);
        const point<NT>& b = cov.end(e);
        // B's ends in NT: in double, u and v themselves (posed alike).
        const auto moving = [&](std::size_t i, const point<double>& posed) -> const point<NT>& {
            if constexpr (std::is_same_v<NT, double>) {
                (void)i;
                return posed;
            } else {
                (void)posed;
                return b_.vertex(i);
            }
        };
        const auto decide = [&] {
            // (Two edges that cross clearly, A's ends exact and B's posed in
            // double within the frame margin, cross in NT too, and so come
            // within any d: no vertex posed in NT. In double the doubles are
            // the decision's own: no second filter.)
            if constexpr (!std::is_same_v<NT, double>)
                if (segments_certainly_cross(p, q, u, v, frame_margin)) return true;
            const point<NT>&c = moving(j, u), &d = moving(k, v);
            if constexpr (with_distance)
                if (options_.distance > 0) return segments_within(a, b, c, d, distance_state::value.distance2);
            return segments_intersect(orientation(a, b, c), orientation(a, b, d), a, b, c, d);
        };
        const bool meet = decide();
        if constexpr (with_witness)
            if (meet && options_.witness) witness_state::value.add(e, j);
        if constexpr (with_coherence)
            if (meet) {
                detector_detail::coherence_state& c = coherence_state::value;
                c.met_a = e;
                c.met_b = static_cast<std::uint32_t>(j);
                c.has_met = true;
            }
        return meet;
    }

    std::shared_ptr<const static_scene<NT>> a_;
    posed_polygon<NT> b_;
    detector_options options_;   ///< d in the prepared polygons' units
    double given_distance_ = 0;  ///< d as given
    int shift_ = 0;              ///< the polygons and poses scaled by 2^shift_
    double reach_ = 0, margin_ = 0;
    std::vector<box> a_ring_boxes_;  ///< the box of each ring of A
    /// The caller's vector for the witnesses during collide(q, pairs); else none.
    std::vector<edge_pair>* out_ = nullptr;
    /// The box of each edge of A, when the pair may take the every-pair
    /// search (every_pair_pays); else empty.
    std::vector<edge_box> a_edge_boxes_;
    /// B's edges per chunk: a chunk's circle test replaces this many edge
    /// tests when it misses, and costs one more when it does not; 8 keeps the
    /// circles tight on the families' polygons while dividing the edge tests
    /// of a far chunk by 8.
    static constexpr std::size_t chunk_edges = 8;
    struct chunk {
        point<double> center;
        double radius = 0;
        std::size_t first = 0, last = 0;  ///< B's edges [first, last) of one ring
    };
    std::vector<chunk> chunks_;
    std::vector<point<double>> chunk_centers_;  ///< posed by place_approximate
    /// B's posed edges' boxes, made by test_edge for the chunks it reaches:
    /// chunk c's are this frame's when chunk_boxes_frame_[c] is
    /// boxes_frame_ (counted by pairs_through_candidates from 1).
    std::vector<box> b_edge_boxes_;
    std::vector<std::uint64_t> chunk_boxes_frame_;
    std::uint64_t boxes_frame_ = 0;
    /// A's edge tree (shared; built by the first frame that asks for it).
    const edge_tree& a_tree() const { return a_->tree(); }
    /// B's edge tree in B's own frame (shared; built by the first frame that asks).
    const edge_tree& b_tree() const { return b_.scene().tree(); }

    edge_grid grid_;  ///< built by the first gather
    bool grid_built_ = false;
    /// A frame takes the tree when B's edges times this are fewer than the
    /// cached static edges: a tree query costs about that many box tests.
    static constexpr std::size_t tree_cost = 4;
    /// A jump tests every edge pair's boxes when A's edges times B's are at
    /// most this many: a box test costs a few comparisons, a tree descent a
    /// posed circle and a box distance per node pair plus a segment query
    /// per moving edge.
    static constexpr std::size_t every_pair_limit = 64;
    /// The same limit when B has at most twice A's edges. Measured on the
    /// time study's random poses (the detector alone on a cell's 20,000
    /// poses, 9 passes; each cell's two builds run in turn five to seven
    /// times; the least pass of each, which this machine's slow spells do
    /// not reach: a cell on the same route in both builds came out at 0.99
    /// to 1.02): every pair took 0.66 to 0.93 times the trees' time at
    /// 8 x 16, 16 x 16 and 32 x 8 (starred, irregular, contour, hole), 0.94
    /// to 1.18 at 8 x 32, and 0.76 to 1.29 at 512 and 1,024 pairs.
    /// (Instructions count otherwise: callgrind gives every pair up to 62%
    /// more at 256 pairs; the trees' descent costs more in branches and
    /// memory than in instructions.)
    static constexpr std::size_t every_pair_limit_b_near = 256;
    /// A detector searches the trees (n_A + n_B) / interior_build_edges times
    /// before it builds the deep cells (interiors_pay): building them costs
    /// 0.2 to 1.5 us per edge on the time study's 1,024-gons and a search of
    /// two such polygons 1.2 to 9 us, so the searches before cost a third
    /// of the build or more, and a detector asked a few frames never builds
    /// them.
    static constexpr std::size_t interior_build_edges = 16;
    std::size_t searches_without_interiors_ = 0;
    /// Containment builds the cells once its rings located without them
    /// (each counted as a scan of the other polygon's edges, an upper bound
    /// on its work) reach cells_build_scans edges per edge of A and B
    /// (containment_cells_pay). Measured (double, alone): building both
    /// polygons' cells costs 0.4 to 3.2 us per edge on the time study's
    /// families of 8 to 1,024 edges, 0.12 us on two boroughs (the cells
    /// capped); Feito's scan 5 to 37 ns per edge. The scans before the
    /// build then cost between a tenth and a few times the build, and a
    /// pair whose rings lie apart in each other's boxes (the islands of a
    /// multipolygon just apart from its neighbour: dozens of scans of tens
    /// of thousands of edges a frame) builds them within a few frames.
    static constexpr std::size_t cells_build_scans = 64;
    std::size_t containment_scanned_ = 0;
    /// The vertices of a ring containment looks up in the other polygon's
    /// cells before it locates the ring (ring_certainly_outside): a look-up
    /// costs a few ns, a locate a scan of the other polygon (or a cone
    /// look-up in A), and a ring along a shared border most often has a
    /// vertex across from it that is deep outside.
    static constexpr std::size_t ring_probes = 8;
    /// Which vertices of one polygon vertices_deep_inside looks up in the
    /// other's deep cells: the one found there last, then those reaching
    /// farthest toward the other polygon's centroid (reaching_vertices::
    /// toward: three, along the nearest of eight directions and its two
    /// neighbours). The one found is kept for the next frame, where poses
    /// that jump about one region (a range of poses along a shared border)
    /// most often find it again. On the time study's random poses these
    /// four look-ups answered as many frames as the last one and sixteen
    /// spread along the rings had, at a fifth of the failed look-ups' cost.
    struct deep_probes {
        std::uint32_t last = 0;
        template <class Deep>
        bool found(Deep&& deep, const std::array<std::uint32_t, reaching_vertices::probes>& reaching) {
            if (deep(last)) return true;
            for (std::uint32_t j : reaching)
                if (j != last && deep(j)) {
                    last = j;
                    return true;
                }
            return false;
        }
    };
    deep_probes deep_b_, deep_a_;
    /// Whether the look-ups of vertices_deep_inside are worth their cost in
    /// this detector's frames: a score that a frame they answer raises by
    /// hit_gain and one they cannot answer lowers by 1, within
    /// [-score_limit, hit_gain]. While it is above -score_limit they are
    /// asked at every search; below, at every trial_period-th one only (a
    /// trial that can raise it again). They pay when they answer more than
    /// one search in hit_gain + 1: failed look-ups cost a tenth of a tree
    /// descent or less, one that answers saves the descent.
    struct probe_odds {
        static constexpr int hit_gain = 8, score_limit = 8;
        static constexpr unsigned trial_period = 16;
        int score = 0;
        unsigned skipped = 0;
        bool worth_asking() { return score > -score_limit || ++skipped % trial_period == 0; }
        void record(bool answered) {
            score = answered ? std::min(score + hit_gain, hit_gain) : std::max(score - 1, -score_limit);
        }
    };
    probe_odds interior_odds_;
    /// The same odds for the pairs that met before the last one
    /// (last_pair_meets): they answer frames whose poses wander about a
    /// border, and seldom a trajectory that has left its contact or random
    /// poses that land near the last one by chance, where each of them
    /// would cost a pair test at every frame.
    probe_odds recent_pairs_odds_;
    bool convex_route_ = false;  ///< A and B convex and small, d == 0
    /// A and B both convex: their inner discs lie deep enough in them to
    /// answer many frames (inner_discs_overlap). Measured on the time study's
    /// random poses (any static polygon against a 64-gon of its family, the
    /// discs about the boxes' centres): the discs overlap on 60% to 80% of
    /// the poses of convex pairs, 3% to 6% of starred and irregular ones
    /// (0.2% for two irregular 64-gons), and never for the contour and hole
    /// families, whose box centres lie outside them.
    bool inner_discs_ = false;
    /// With inner_discs_: A's and B's inner discs, each in its own frame
    /// (scene/inner_disc.hpp; radius 0: none), which show the polygons
    /// meeting when they overlap (convex_meet) and settle the
    /// separating-edge test's edges that the other polygon reaches across
    /// with one side test each (separating_edge_of). B's posed in NT is
    /// the rigid image only in an exact NT: in a floating NT each posed
    /// vertex lies within the frame margin of it on each coordinate, so each
    /// edge's line within margin sqrt 2 < 1.5 margin, and the posed convex
    /// region holds the disc shrunk by that much (convex_meet shrinks it).
    disc a_inner_, b_inner_;
    /// candidates_pay's bound on candidates times B's chunks. Measured on the
    /// paper's trajectories over the families (8 to 1,024 edges each, double):
    /// at 256 no cell got more than 5% slower than through the candidates
    /// alone, and the linear trajectories of pairs of 256 edges and more ran
    /// 1.1x to 14x faster; at 128, pairs of a 1,024-gon and an 8-gon got 15%
    /// slower.
    static constexpr std::size_t candidate_chunk_limit = 256;

    /// The static edges within reach (+ skin) of where they were gathered:
    /// kept between frames with features::coherence, else anew each frame.
    std::vector<std::uint32_t> cache_;
    std::vector<std::uint32_t> candidates_;
    /// The candidates the next frame through them expects (candidates_pay):
    /// the last such frame's count, or the cache's size after a gather.
    std::size_t candidate_estimate_ = 0;
};

}  // namespace influence2d
