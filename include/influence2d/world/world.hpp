// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Many bodies, each a polygon at its own pose, moved step by step: which
/// pairs are in contact after each step (docs/world.md).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/prefetch.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/core/shortest_decimal.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/scene/bounding_disc.hpp"
#include "influence2d/scene/hull_vertices.hpp"
#include "influence2d/scene/inner_disc.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"
#include "influence2d/world/box_tree.hpp"
#include "influence2d/world/narrow_phase.hpp"
#include "influence2d/world/separating_edge.hpp"

namespace influence2d {

/// Two bodies (or two polygons of a layer) by id, `first < second` within
/// one set; ordered by first, then second.
struct body_pair {
    std::uint32_t first = 0;   ///< the smaller id (or the id in the first layer)
    std::uint32_t second = 0;  ///< the larger id (or the id in the second layer)

    /// Lexicographic order.
    friend bool operator<(const body_pair& l, const body_pair& r) {
        return l.first != r.first ? l.first < r.first : l.second < r.second;
    }
    /// Same ids.
    friend bool operator==(const body_pair& l, const body_pair& r) {
        return l.first == r.first && l.second == r.second;
    }
};

/// The buffers sort_body_pairs fills, kept by a caller that sorts again and
/// again (a world, step after step) so that it allocates only when the
/// pairs grow.
struct body_pair_sort_buffers {
    std::vector<body_pair> by_second;  ///< the pairs sorted by second id
    std::vector<std::uint32_t> start;  ///< each id's first place in the counting sort
};

/// Sorts pairs of ids below n in O(n + pairs): a stable counting sort by
/// second id, then by first (a radix sort of two digits); std::sort when
/// the pairs are few (fewer than n / 8: the counts would cost more). The
/// counting sort's buffers are `spare`'s.
inline void sort_body_pairs(std::vector<body_pair>& pairs, std::size_t n, body_pair_sort_buffers& spare) {
    if (pairs.size() * 8 < n) {
        std::sort(pairs.begin(), pairs.end());
        return;
    }
    std::vector<body_pair>& by_second = spare.by_second;
    std::vector<std::uint32_t>& start = spare.start;
    by_second.resize(pairs.size());
    start.resize(n + 1);
    const auto by = [&](const std::vector<body_pair>& in, std::vector<body_pair>& out, auto key) {
        std::fill(start.begin(), start.end(), 0);
        for (const body_pair& p : in) ++start[key(p) + 1];
        for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
        for (const body_pair& p : in) out[start[key(p)]++] = p;
    };
    by(pairs, by_second, [](const body_pair& p) { return p.second; });
    by(by_second, pairs, [](const body_pair& p) { return p.first; });
}

/// sort_body_pairs with buffers of its own.
inline void sort_body_pairs(std::vector<body_pair>& pairs, std::size_t n) {
    body_pair_sort_buffers spare;
    sort_body_pairs(pairs, n, spare);
}

/// A pair whose contact began or ended at a step.
struct contact_event {
    body_pair bodies;     ///< the pair
    bool begins = false;  ///< true: in contact now and not at the last step; false: the reverse
};

/// How a world answers.
struct world_options {
    /// Pairs within this distance count as in contact (0: their closed
    /// regions meet). Finite and >= 0.
    double within = 0;
    /// Keep the witness of each contact (witnesses()).
    bool witness = false;
    /// Keep what showed each contact and try it first at the next step. Off,
    /// every pair with a moved body is tested afresh (same answers).
    bool coherence = true;
    /// Threads of the narrow phase: 1 serial, 0 every hardware thread.
    /// The answers and their order are the serial run's.
    unsigned threads = 1;
};

/// Counters of a world's work since its construction.
struct world_statistics {
    std::size_t steps = 0;         ///< calls of step()
    std::size_t moved = 0;         ///< bodies moved, added or removed, summed over the steps
    std::size_t escaped = 0;       ///< bodies whose box left their enlarged box, summed over the steps
    std::size_t rebuilds = 0;      ///< rebuilds of a box tree
    std::size_t candidates = 0;    ///< pairs whose boxes met and had a moved body
    std::size_t carried = 0;       ///< pairs whose boxes met and neither body moved (answer kept)
    std::size_t witness_hits = 0;  ///< candidates answered by the last step's witness (separated included)
    std::size_t separated = 0;     ///< candidates answered apart by the last step's separating edge
    std::size_t found_apart = 0;   ///< candidates answered apart by a separating edge sought before the one-shot test
    std::size_t nearby_edges = 0;  ///< candidates answered by edges next to the last step's two
    std::size_t exact_pairs = 0;   ///< candidates answered again in the Exact type (a sign NT could not settle)
    std::size_t contacts = 0;      ///< contacts reported, summed over the steps
};

/// Bodies in the plane, each an arbitrary polygon (non-convex, holes,
/// several outer rings) at its own pose, moved step by step; after each
/// step, every pair of bodies within `within` of each other (by default:
/// whose closed regions meet). Fixed bodies are never tested against each
/// other. Bodies of one shape share it (added once with add_shape).
///
/// Each body's region is its polygon posed exactly by its pose (c and s the
/// doubles of rotation_pose): exact when NT is, the answers those of
/// intersects(a, pose_a, b, pose_b) for every pair (query/both_posed.hpp);
/// with Exact not void (certified_world in exact/certified_world.hpp) a
/// pair whose signs NT cannot settle is answered again in Exact.
///
///   step():
///     each body moved since the last step (in parallel blocks when many):
///       its angle's cosine and sine, when the angle changed (move() keeps
///       the angle alone, so that many moves share the threads);
///       its box: its polygon's box posed in double (the box of its four
///       posed corners, from its posed centre and half sides; the posed
///       polygon lies in their parallelogram), cut to the box of its
///       polygon's bounding disc posed (scene/bounding_disc.hpp), grown by
///       the posing margin and within / 2.
///       A box that left the body's enlarged box (the box the trees hold:
///       grown by a sixteenth of its larger side and stretched ahead along
///       the body's last displacement, enlarged_box) escapes: a new
///       enlarged box. Added and removed bodies escape too
///     each tree (fixed bodies, free bodies) with an escaped body: its
///       boxes refitted while the refits since its last rebuild stay below
///       a quarter of its boxes (box_tree::refit, O(log n) each, or, for
///       a 32nd of its boxes or more at once, refit_all: every node made
///       anew, O(n) in sequence); else, and for an added body, rebuilt
///       (linear when the bodies moved little)
///     near pairs (enlarged boxes meet, not both fixed), kept from step to
///       step: when bodies escaped, theirs found again: the free bodies'
///       tree joined with itself and with the fixed bodies' when a quarter
///       of the bodies escaped (box_tree::self_join, join; in parts shared
///       among threads for many bodies), else a query of the trees for each
///       (free bodies; fixed ones too for a free body)
///     candidates <- the near pairs with a moved body whose boxes meet
///       and whose posed bounding discs are not certainly farther apart
///       than `within` (the discs not asked of a contact of the last step)
///       (in parallel blocks for many near pairs). The
///       contacts of the last step whose bodies both stayed keep their
///       answer. In float, double and long double a pair whose coordinates
///       lie far from 1 in scale is answered on its two bodies scaled by a
///       power of two (core/range_scaling.hpp; the same answer), each
///       placed for that pair alone
///     each candidate whose last witness is two edges, or a separating
///       edge (separating_edge.hpp: an edge of one body's convex hull that
///       leaves the other's hull outside), tries it again from a few posed
///       vertices, no body placed
///     the other candidates' bodies placed at their poses (vertices posed
///       in double, and in NT for another type), once each, in buffers
///       kept from step to step (on several threads only for pairs then
///       tested on several)
///     each of them, in parallel blocks when many: bodies_within, the
///       last step's witness tried first (narrow_phase.hpp; a pair whose
///       bodies did not jump seeks two edges that meet, which the next
///       step tests again from four vertices); a pair found apart (with
///       within = 0, neither body having jumped) seeks a separating edge
///       for the next step
///     contacts <- the pairs within `within`, sorted; events: the
///       difference with the last step's contacts
///
/// Cost of a step: O(m + p) for m moved bodies and p near pairs when no
/// body escaped; e escaped bodies among n add O(e log n) refits and
/// queries, or a rebuild of their tree (linear when the bodies moved
/// little) now and then, or O(n + p) joins when a quarter of the bodies
/// escaped; plus the narrow phase: a persisting contact whose witness edges
/// still meet costs four posed vertices and two orientation tests; others
/// the one-shot query's steps. Nothing grows with the number of pairs of
/// bodies.
template <class NT, class Exact = void>
class world {
public:
    using shape_id = std::uint32_t;  ///< a shape, numbered from 0 in order of add_shape
    using body_id = std::uint32_t;   ///< a body, numbered from 0 in order of add_body

    /// An empty world. Throws invalid_input for a distance that is negative,
    /// NaN or infinite.
    explicit world(world_options options = {}) : options_(options) {
        if (!(options.within >= 0) || !std::isfinite(options.within))
            throw invalid_input("world: the distance " + shortest_decimal(options.within) +
                                " is not a finite number >= 0");
    }

    /// Adds a shape that bodies may take; its preparation is shared by them.
    /// Throws invalid_input for an empty polygon, one beyond NT's range, or
    /// one whose hull would take the shapes' hulls past 2^32 corners in all
    /// (each body holds where its hull's corners lie in 32 bits).
    shape_id add_shape(const polygon& p) {
        accepted_polygon<NT>(p, "world's");
        const std::vector<std::uint32_t> hull = hull_vertices(p);
        if (hull.size() > UINT32_MAX - hull_corners_.size())
            throw invalid_input("world: the shapes' hulls would pass 2^32 corners in all");
        const box& local = p.bounds();
        shapes_.push_back(std::make_unique<shape_entry>(
            shape_entry{p,
                        coordinate_scale(p),
                        static_cast<std::uint32_t>(hull_corners_.size()),
                        static_cast<std::uint32_t>(hull.size()),
                        bounding_disc(p),
                        {local.max_x / 2 - local.min_x / 2, local.max_y / 2 - local.min_y / 2},
                        inner_radius(p)}));
        for (std::uint32_t k : hull) hull_corners_.push_back(p.vertex(k));
        return static_cast<shape_id>(shapes_.size() - 1);
    }

    /// Adds a body of shape s at pose q; a `fixed` body is never tested
    /// against another fixed one. Throws invalid_input for an unknown shape
    /// or a pose component that is NaN or infinite.
    body_id add_body(shape_id s, const pose& q, bool fixed = false) {
        if (s >= shapes_.size())
            throw invalid_input("world: no shape " + std::to_string(s) + " (there are " +
                                std::to_string(shapes_.size()) + ")");
        body b;
        b.shape = s;
        b.hull_first = shapes_[s]->hull_first;
        b.hull_count = shapes_[s]->hull_count;
        b.pose = rotation_pose(q);
        b.theta = q.theta;
        b.fixed = fixed;
        bodies_.push_back(std::move(b));
        const body_id id = static_cast<body_id>(bodies_.size() - 1);
        mark_moved(id);
        return id;
    }

    /// Moves body i to pose q (its place at the next step). Throws
    /// invalid_input for an unknown or removed body or a pose component
    /// that is NaN or infinite. The angle's cosine and sine are taken by the
    /// next step (with the moved bodies' boxes, in parallel blocks when
    /// many), and only for an angle that changed.
    void move(body_id i, const pose& q) {
        rotation_pose::check(q);
        body& b = live(i);
        b.pose.tx = q.tx;
        b.pose.ty = q.ty;
        // (The same angle to the bit keeps its cosine and sine.)
        if (std::memcmp(&q.theta, &b.theta, sizeof(double)) != 0) {
            b.theta = q.theta;
            b.turned = true;
        }
        mark_moved(i);
    }

    /// Removes body i: its contacts end at the next step; its id is not
    /// reused. Throws invalid_input for an unknown or removed body.
    void remove(body_id i) {
        body& b = live(i);
        b.alive = false;
        b.placed.reset();
        b.placed_now = false;
        b.all_made = false;
        mark_moved(i);
    }

    /// Brings the world to its bodies' present poses and returns the pairs
    /// in contact, sorted (first < second). See the class comment.
    const std::vector<body_pair>& step() {
        ++stats_.steps;
        stats_.moved += moved_.size();
        place_moved();
        update_near();
        candidates();
        narrow(tested_);
        gather();
        return contacts_;
    }

    /// The pairs in contact after the last step, sorted.
    const std::vector<body_pair>& contacts() const { return contacts_; }
    /// What shows each contact (parallel to contacts()), when
    /// world_options::witness; empty otherwise.
    const std::vector<contact_witness>& witnesses() const { return witnesses_; }
    /// The contacts that began and ended at the last step, sorted by pair.
    const std::vector<contact_event>& events() const { return events_; }
    /// The work done so far.
    const world_statistics& statistics() const { return stats_; }
    /// The number of bodies added (removed ones included).
    std::size_t body_count() const { return bodies_.size(); }
    /// The options the world was made with.
    const world_options& options() const { return options_; }

private:
    struct shape_entry {
        polygon shape;
        double scale;
        std::uint32_t hull_first, hull_count;  // hull_corners_[hull_first, + hull_count): its hull's corners
        disc round;                            // bounding_disc(shape)
        point<double> half;                    // half the sides of shape's box
        double inner;                          // inner_radius(shape): a disc about the box centre in the region
    };
    struct body {
        shape_id shape = 0;
        std::uint32_t hull_first = 0, hull_count = 0;  // its shape's (read by pass 1 without the shape)
        rotation_pose pose{influence2d::pose{}};       // its cosine and sine those of theta once the step made them
        double theta = 0;                              // the angle last given
        bool turned = false;                           // theta changed since its cosine and sine were taken
        bool fixed = false;
        bool alive = true;
        bool moved = false;                          // since the last step
        box bounds;                                  // at the present pose
        box enlarged;                                // held by the trees; holds bounds
        disc round;                                  // its shape's bounding disc posed (posed_disc)
        bool escaped = false;                        // enlarged anew at this step
        bool jumped = false;                         // moved by over a quarter of its size at this step
        double scale = 0;                            // the shape's scale plus |tx| + |ty|
        std::unique_ptr<placed_polygon<NT>> placed;  // posed at the last step that asked
        bool placed_now = false;                     // placed at the present pose
        bool all_made = false;                       // placed, with every vertex in NT made
    };
    // A meeting as a record keeps it, its numbers in 32 bits (a polygon
    // numbers its vertices and edges in 32 bits, core/polygon.hpp): a step
    // copies and reads its records by the ten thousand, at the memory's
    // speed, and a record takes 44 bytes with it instead of 72.
    struct kept_meeting {
        std::uint32_t a_index = 0, b_index = 0;
        meeting::kind how = meeting::kind::none;
        std::uint8_t where = 0;  // the location, for a located vertex

        kept_meeting() = default;
        // (Implicit both ways: a record's meeting reads and is set as one.)
        kept_meeting(const meeting& m)  // NOLINT(google-explicit-constructor)
            : a_index(static_cast<std::uint32_t>(m.a_index)),
              b_index(static_cast<std::uint32_t>(m.b_index)),
              how(m.how),
              where(static_cast<std::uint8_t>(m.where)) {
            INFLUENCE2D_ASSERT(m.a_index <= UINT32_MAX && m.b_index <= UINT32_MAX,
                               "a meeting numbers a vertex or edge beyond 32 bits");
        }
        operator meeting() const {  // NOLINT(google-explicit-constructor)
            meeting m;
            m.how = how;
            m.a_index = a_index;
            m.b_index = b_index;
            m.where = static_cast<location>(where);
            return m;
        }
        explicit operator bool() const { return how != meeting::kind::none; }
    };
    struct record {
        body_pair bodies;
        kept_meeting shown;     // kind none: not within the distance
        separating_edge apart;  // (shown none) a hull edge that kept the bodies apart
        // (shown none) the two edges that last showed the bodies meeting
        // (edge parted_a of the first body's polygon, parted_b of the
        // second's), when `parted`
        std::uint32_t parted_a = 0, parted_b = 0;
        std::int16_t shift = 0;    // the pair answered scaled by 2^shift (range_shift), 0: as it stands
        bool by_witness = false;   // answered by the last step's witness
        bool no_crossing = false;  // shown is a located vertex sought after the edges: none met
        bool sought = false;       // a separating edge was sought at this step before the one-shot test
        bool nearby = false;       // answered by edges next to the last step's two (nearby_edges_meet)
        bool in_exact = false;     // answered again in Exact (bodies_within)
        bool parted = false;

        // Remembers the edges of `was` (when two edges) as those that last
        // showed the bodies meeting: the pair is found apart.
        void part(const meeting& was) {
            if (was.how != meeting::kind::edges || was.a_index > UINT32_MAX || was.b_index > UINT32_MAX) return;
            parted = true;
            parted_a = static_cast<std::uint32_t>(was.a_index);
            parted_b = static_cast<std::uint32_t>(was.b_index);
        }
    };

    body& live(body_id i) {
        if (i >= bodies_.size() || !bodies_[i].alive)
            throw invalid_input("world: no body " + std::to_string(i) +
                                (i < bodies_.size() ? " (it was removed)" : ""));
        return bodies_[i];
    }
    void mark_moved(body_id i) {
        body& b = bodies_[i];
        if (!b.moved) moved_.push_back(i);
        b.moved = true;
    }

    // The box of body b: its polygon's box posed, cut to the box of its
    // posed bounding disc (b.round: as wide as the polygon whatever its
    // turn, where the posed box of a turned polygon is up to sqrt 2 times
    // wider), grown by the posing margin and half the distance (and d's own
    // rounding); a side that is NaN makes it the whole plane. The posed box
    // is the box of its four posed corners, taken from its centre, which is
    // the disc's (bounding_disc centres the disc on the polygon's box),
    // and its half sides: |c| hx + |s| hy across, |s| hx + |c| hy up. Each
    // bound errs from the exact one by the centre's posing (a vertex's) and
    // a few roundings of terms at most the scale: far below the posing
    // margin (placing_slack, 2^-46 times the scale), which the box's two
    // margins hold besides the placings' own errors.
    box box_of(const body& b) const {
        const point<double>& half = shapes_[b.shape]->half;
        const point<double>& centre = b.round.centre;
        const double c = std::fabs(b.pose.c), s = std::fabs(b.pose.s);
        const double across = c * half.x + s * half.y, up = s * half.x + c * half.y;
        box out{centre.x - across, centre.y - up, centre.x + across, centre.y + up};
        const box round = disc_box(b.round);
        if (!round.empty()) {
            out.min_x = std::max(out.min_x, round.min_x);
            out.min_y = std::max(out.min_y, round.min_y);
            out.max_x = std::min(out.max_x, round.max_x);
            out.max_y = std::min(out.max_y, round.max_y);
        }
        out = out.inflated(2 * placing_margin<NT>(b.scale) + options_.within / 2 * (1 + sum_widening));
        if (std::isnan(out.min_x) || std::isnan(out.min_y) || std::isnan(out.max_x) || std::isnan(out.max_y)) {
            const double inf = std::numeric_limits<double>::infinity();
            out = box{-inf, -inf, inf, inf};
        }
        return out;
    }

    // The box the trees hold for a body that did not jump (jumped) and
    // whose box `now` left its enlarged box, after its centre moved by
    // `moved` since the last step: `now` grown by a sixteenth of its larger
    // side (a body that wobbles stays inside) and stretched by eight times
    // `moved` ahead (a body drifting at a steady speed stays inside for
    // several steps); a box that is not finite is kept as it is. (The two
    // factors were chosen on the time study's coherent scenes: 1/8 and 2
    // cost the falling scene 20% more instructions, 1/16 and 16 no fewer.)
    // A body that jumped keeps its box itself: a larger one would only bring
    // more pairs.
    static box enlarged_box(const box& now, const point<double>& moved) {
        constexpr double slack = 0.0625, lead = 8;
        const double side = std::max(now.max_x - now.min_x, now.max_y - now.min_y);
        box out = now.inflated(slack * side);
        if (!std::isfinite(out.min_x) || !std::isfinite(out.max_x) || !std::isfinite(out.min_y) ||
            !std::isfinite(out.max_y))
            return now;
        (moved.x < 0 ? out.min_x : out.max_x) += lead * moved.x;
        (moved.y < 0 ? out.min_y : out.max_y) += lead * moved.y;
        return out;
    }

    // Whether a body whose box is `now` jumped when its centre moved by
    // `moved`: by more than a quarter of its larger side along an axis (NaN
    // too). A body that moves so far in a step gains little from an enlarged
    // box (it would leave it within a step or two) and its pairs little from
    // their last witness.
    static bool jumped(const box& now, const point<double>& moved) {
        const double reach = std::max(now.max_x - now.min_x, now.max_y - now.min_y) / 4;
        return !(std::fabs(moved.x) <= reach && std::fabs(moved.y) <= reach);
    }

    // Step 1: the moved bodies' boxes; those that left their enlarged boxes
    // (and the added and removed bodies) escape, and their trees follow:
    // refitted (box_tree::refit) while the refits since the tree's last
    // rebuild stay below a quarter of its boxes, rebuilt otherwise and for
    // an added body.
    void place_moved() {
        // Each moved body's box, in parallel blocks when many (each body's
        // own fields alone written); the escaped ones then listed in the
        // order of moved_.
        const unsigned threads = moved_.size() < parallel_boxes ? 1u : batch_threads(options_.threads);
        run_in_blocks(moved_.size(), threads, [&](std::size_t first, std::size_t last) {
            for (std::size_t k = first; k < last; ++k) rebox(bodies_[moved_[k]]);
        });
        for (body_id i : moved_)
            if (bodies_[i].escaped) escaped_.push_back(i);
        stats_.escaped += escaped_.size();
        for (const bool fixed : {true, false}) {
            box_tree& tree = fixed ? fixed_tree_ : free_tree_;
            std::size_t& refits = fixed ? fixed_refits_ : free_refits_;
            std::vector<body_id>& refit = spare_refit_;
            refit.clear();
            bool rebuild = false;
            for (body_id i : escaped_)
                if (bodies_[i].fixed == fixed) {
                    rebuild = rebuild || !tree.holds(i);
                    refit.push_back(i);
                }
            if (refit.empty()) continue;
            refits += refit.size();
            if (!rebuild && refits * 4 < tree.size()) {
                const auto enlarged = [&](body_id i) { return bodies_[i].alive ? bodies_[i].enlarged : box{}; };
                if (refit.size() * refit_all_share < tree.size()) {
                    for (body_id i : refit) tree.refit(i, enlarged(i));
                } else {
                    tree.refit_all(refit, enlarged);
                }
                continue;
            }
            std::vector<box>& boxes = spare_boxes_;
            std::vector<std::uint32_t>& ids = spare_ids_;
            boxes.clear();
            ids.clear();
            for (std::size_t i = 0; i < bodies_.size(); ++i)
                if (bodies_[i].alive && bodies_[i].fixed == fixed) {
                    boxes.push_back(bodies_[i].enlarged);
                    ids.push_back(static_cast<std::uint32_t>(i));
                }
            tree.rebuild(boxes, ids);
            ++stats_.rebuilds;
            refits = 0;
        }
    }
    // Body b's pose made (the cosine and sine of an angle that changed), its
    // box at that pose, and whether it escaped (b.escaped): it left its
    // enlarged box, which is made anew, or it was removed.
    void rebox(body& b) const {
        if (!b.alive) {
            b.escaped = true;
            return;
        }
        const point<double> was = b.bounds.centre();
        if (b.turned) {
            b.pose.turn_to(b.theta);  // (theta checked by move())
            b.turned = false;
        }
        b.scale = shapes_[b.shape]->scale + std::fabs(b.pose.tx) + std::fabs(b.pose.ty);
        b.round = posed_disc(shapes_[b.shape]->round, b.pose);
        b.bounds = box_of(b);
        b.placed_now = false;
        b.all_made = false;
        b.jumped = false;
        if (!b.enlarged.contains(b.bounds)) {
            const point<double> now = b.bounds.centre();
            const point<double> moved =
                b.enlarged.empty() ? point<double>{0, 0} : point<double>{now.x - was.x, now.y - was.y};
            b.jumped = jumped(b.bounds, moved);
            b.enlarged = b.jumped ? b.bounds : enlarged_box(b.bounds, moved);
            b.escaped = true;
        }
    }

    // The parts' items, part after part, made the whole of `to` (the
    // parallel passes' results in the serial pass's order), the parts
    // copied by `threads` threads at once, each to its own place; `to` is
    // only resized, so that the items it already holds are not made again.
    template <class T>
    static void gather_in_order(const std::vector<std::vector<T>>& parts, std::vector<T>& to, unsigned threads) {
        std::vector<std::size_t> at(parts.size() + 1, 0);
        for (std::size_t k = 0; k < parts.size(); ++k) at[k + 1] = at[k] + parts[k].size();
        to.resize(at.back());
        run_in_chunks(parts.size(), threads, 1, [&](std::size_t first, std::size_t last) {
            for (std::size_t k = first; k < last; ++k)
                std::copy(parts[k].begin(), parts[k].end(), to.begin() + static_cast<std::ptrdiff_t>(at[k]));
        });
    }

    // Step 2a: the near pairs (enlarged boxes meet), sorted: those of the
    // escaped bodies found again, the others kept.
    void update_near() {
        if (escaped_.empty()) return;
        std::vector<body_pair>& found = spare_pairs_;
        found.clear();
        // Adds the pair of i and j (not the same body), ordered, to `to`.
        const auto adding_to = [](std::vector<body_pair>& to) {
            return [&to](std::uint32_t i, std::uint32_t j) {
                if (i != j) to.push_back({std::min(i, j), std::max(i, j)});
            };
        };
        const auto add = adding_to(found);
        const bool most = escaped_.size() * 4 >= free_tree_.size() + fixed_tree_.size();
        const unsigned threads = bodies_.size() < parallel_join_bodies ? 1u : batch_threads(options_.threads);
        if (most && threads > 1) {
            // The joins cut into parts (box_tree::self_join_parts,
            // join_parts), each part's pairs gathered apart, then in part
            // order: the pairs of the serial joins, sorted below.
            std::vector<box_tree::join_part> parts = free_tree_.self_join_parts(32 * threads);
            const std::size_t own = parts.size();
            for (const box_tree::join_part& p : free_tree_.join_parts(fixed_tree_, 32 * threads)) parts.push_back(p);
            std::vector<std::vector<body_pair>> part_pairs(parts.size());
            run_in_chunks(parts.size(), threads, 1, [&](std::size_t first, std::size_t last) {
                for (std::size_t k = first; k < last; ++k)
                    free_tree_.join_part_pairs(parts[k], k < own ? free_tree_ : fixed_tree_, adding_to(part_pairs[k]));
            });
            gather_in_order(part_pairs, found, threads);
        } else if (most) {
            free_tree_.self_join(add);
            free_tree_.join(fixed_tree_, add);
        } else {
            // (A pair of two escaped bodies is found from both: the sort
            // below keeps one.)
            const auto query = [&](body_id i, auto&& add_to) {
                const body& b = bodies_[i];
                if (!b.alive) return;
                free_tree_.query(b.enlarged, [&](std::uint32_t j) { add_to(i, j); });
                if (!b.fixed) fixed_tree_.query(b.enlarged, [&](std::uint32_t j) { add_to(i, j); });
            };
            const unsigned query_threads =
                escaped_.size() < parallel_escaped_queries ? 1u : batch_threads(options_.threads);
            if (query_threads > 1) {
                // The escaped bodies in blocks, each block's pairs apart (in
                // buffers kept from step to step), then in block order.
                const std::size_t blocks = 4 * std::size_t{query_threads};
                block_found_.resize(blocks);
                run_in_chunks(blocks, query_threads, 1, [&](std::size_t first, std::size_t last) {
                    for (std::size_t k = first; k < last; ++k) {
                        block_found_[k].clear();
                        const auto add_k = adding_to(block_found_[k]);
                        for (std::size_t n = escaped_.size() * k / blocks; n < escaped_.size() * (k + 1) / blocks; ++n)
                            query(escaped_[n], add_k);
                    }
                });
                gather_in_order(block_found_, found, query_threads);
            } else {
                for (body_id i : escaped_) query(i, add);
            }
        }
        sort_body_pairs(found, bodies_.size(), spare_sort_);
        found.erase(std::unique(found.begin(), found.end()), found.end());
        if (!most) {
            // The last near pairs kept where neither body escaped (in place:
            // near_ is replaced below), merged with those found through the
            // sort's buffer.
            near_.erase(std::remove_if(
                            near_.begin(), near_.end(),
                            [&](const body_pair& p) { return bodies_[p.first].escaped || bodies_[p.second].escaped; }),
                        near_.end());
            std::vector<body_pair>& all = spare_sort_.by_second;
            all.clear();
            all.reserve(near_.size() + found.size());
            std::merge(near_.begin(), near_.end(), found.begin(), found.end(), std::back_inserter(all));
            found.swap(all);
        }
        near_.swap(found);  // (the last near pairs' buffer kept for the next step)
        for (body_id i : escaped_) bodies_[i].escaped = false;
        escaped_.clear();
    }

    // Step 2b: the pairs to test (tested_): the near pairs with a moved body
    // whose boxes meet, sorted, each with its last witness; the contacts
    // whose bodies both stayed are carried into kept_. (Every contact of the
    // last step is a near pair: its boxes met, so did its enlarged boxes.)
    // Many near pairs are sought in parallel blocks.
    void candidates() {
        const unsigned threads = near_.size() < parallel_near_pairs ? 1u : batch_threads(options_.threads);
        bool shifted = false;
        if (threads == 1) {
            tested_.clear();
            kept_.clear();
            shifted = candidates_in(0, near_.size(), tested_, kept_);
        } else {
            // Blocks of the near pairs, each block's candidates apart (in
            // buffers kept from step to step), then in block order: the
            // serial pass's.
            const std::size_t blocks = 4 * std::size_t{threads};
            block_tested_.resize(blocks);
            block_kept_.resize(blocks);
            std::vector<char> shifted_in(blocks, 0);
            run_in_chunks(blocks, threads, 1, [&](std::size_t first, std::size_t last) {
                for (std::size_t k = first; k < last; ++k) {
                    block_tested_[k].clear();
                    block_kept_[k].clear();
                    shifted_in[k] = candidates_in(near_.size() * k / blocks, near_.size() * (k + 1) / blocks,
                                                  block_tested_[k], block_kept_[k]);
                }
            });
            gather_in_order(block_tested_, tested_, threads);
            gather_in_order(block_kept_, kept_, threads);
            shifted = std::find(shifted_in.begin(), shifted_in.end(), 1) != shifted_in.end();
        }
        if (shifted)
            for (const record& r : tested_)
                if (r.shift != 0) {
                    scaled_shape(bodies_[r.bodies.first].shape, r.shift);
                    scaled_shape(bodies_[r.bodies.second].shape, r.shift);
                }
        stats_.candidates += tested_.size();
        stats_.carried += kept_.size();
    }

    // Whether the posed bounding discs of bodies a and b lie farther apart
    // than the distance (certainly_farther, each posed centre within its
    // body's placing margin of its exact place): then so do the bodies.
    // Boxes that meet hold such discs when they meet near a corner: about a
    // fifth of them for compact bodies at random places.
    bool discs_apart(const body& a, const body& b) const {
        const double e = std::max(placing_margin<NT>(a.scale), placing_margin<NT>(b.scale));
        // (The sum's two roundings, each below 2^-53 of it, are covered by
        // sum_widening.)
        return certainly_farther(a.round.centre, b.round.centre,
                                 (a.round.radius + b.round.radius + options_.within) * (1 + sum_widening), e);
    }

    // The candidates among near_[first, last) appended to `out`, the carried
    // contacts to `kept`; whether a candidate is to be scaled (its scaled
    // shapes are made afterwards, serially).
    bool candidates_in(std::size_t first, std::size_t last, std::vector<record>& out, std::vector<record>& kept) const {
        bool shifted = false;
        if (first == last) return shifted;
        std::size_t k = static_cast<std::size_t>(
            std::lower_bound(last_.begin(), last_.end(), near_[first],
                             [](const record& r, const body_pair& p) { return r.bodies < p; }) -
            last_.begin());
        for (std::size_t n = first; n < last; ++n) {
            // (The second body of the pair 8 ahead asked for now, without
            // waiting: the near pairs' second bodies lie anywhere in memory,
            // and among 100,000 bodies seldom in the caches.)
            if (n + 8 < last) prefetch(&bodies_[near_[n + 8].second]);
            const body_pair& p = near_[n];
            while (k < last_.size() && last_[k].bodies < p) ++k;
            const bool had = k < last_.size() && last_[k].bodies == p;
            const body &a = bodies_[p.first], &b = bodies_[p.second];
            if (!a.moved && !b.moved) {
                if (had) kept.push_back(last_[k]);
                continue;
            }
            // (A pair in contact at the last step is seldom apart by its
            // discs now, and its witness or its test answers it anyway.)
            if (!boxes_overlap(a.bounds, b.bounds) || (!(had && last_[k].shown) && discs_apart(a, b))) continue;
            record r;
            r.bodies = p;
            r.shift = static_cast<std::int16_t>(pair_shift(a, b));
            shifted = shifted || r.shift != 0;
            if (had && options_.coherence) {
                r.shown = last_[k].shown;
                r.no_crossing = last_[k].no_crossing;
                r.parted = last_[k].parted;
                r.parted_a = last_[k].parted_a;
                r.parted_b = last_[k].parted_b;
                // (A body that jumped has likely crossed the line; a pair
                // answered scaled seeks none.)
                if (!a.jumped && !b.jumped && r.shift == 0) r.apart = last_[k].apart;
            }
            out.push_back(r);
        }
        return shifted;
    }

    // The least work shared among threads. A parallel call costs about
    // 4 us with oneTBB's workers still waiting from the call before and 50
    // us when std::threads are started and joined (query/batch.hpp); the
    // first call after the program did a millisecond of other work finds
    // oneTBB's worker asleep and loses some 20 to 50 us in waking it (a
    // scratch harness, 1,001 calls each way, medians: 20 us of work split
    // in two ran 0.65x as fast as on one thread after such a pause, 100 us
    // 1.13x, 200 us 1.35x). And what one core wrote the other reads slowly:
    // 1,860 pairs a step of the time study's 1,000 bodies of mixed sizes
    // took 229 us of work on one thread and 337 us in all on two (196 us
    // wall), and the serial passes after them lost more than that (the
    // step 0.79x-0.82x as fast on two threads). So a call must bring some
    // hundred microseconds of work, and pairs more: 512 bodies to place
    // (only when their pairs are then tested by several threads: placed on
    // two threads for pairs tested on one, 10,000 falling bodies ran
    // 0.92x as fast, 0.99x placed on one), 8192 edge witnesses to retest
    // (the cheapest test, four vertices posed: tens of nanoseconds) or 4096
    // pairs for bodies_within (a few hundred nanoseconds each; with 1024
    // the mixed sizes above ran 0.79x-0.82x, with 4096 1.00x, the scenes of
    // 1,000 random bodies and 10,000 parcels, random and mixed bodies
    // unchanged or faster). With 128 pairs the time study's 100 bodies of
    // mixed sizes ran 0.64x-0.78x as fast on two threads as on one, 100
    // random bodies 0.71x-0.93x; with 2048 witnesses (and boxes from 4096
    // bodies, below) its 10,000 bodies on the paper's trajectories
    // 0.73x-0.89x (docs/world.md, "All cores").
    static constexpr std::size_t parallel_placings = 512, parallel_witness_tests = 8192, parallel_pair_tests = 4096;
    // Bodies from which the joins of a step where most bodies escaped are
    // shared among threads, and near pairs from which the candidates are
    // sought in parallel blocks: both are a few nanoseconds a body or pair.
    static constexpr std::size_t parallel_join_bodies = 4096, parallel_near_pairs = 16384;
    // Moved bodies from which their boxes are made in parallel blocks (a
    // box is a centre posed and a few products and comparisons, some tens
    // of nanoseconds; the later serial passes then read the boxes the
    // other core wrote). From 4096, the time study's scenes of 10,000
    // bodies ran no faster on two threads than from 16384 and the
    // trajectories' ran slower (docs/world.md, "All cores").
    static constexpr std::size_t parallel_boxes = 16384;
    // Refits at one step from which every node is made anew
    // (box_tree::refit_all) instead of walking from each box to the root
    // (box_tree::refit): a 32nd of the tree's boxes. Scratch harness, boxes
    // on a jittered grid, random ids, medians of 31, alone, one by one
    // against at once: n/32 refits of 1,000 boxes 1.1 against 1.8 us, n/16
    // 2.2 against 1.8; of 10,000 boxes 16.5 against 17.7 us, then 31.7
    // against 18.1; of 100,000 boxes n/64 311 against 190 us, n/4 2.83
    // against 0.34 ms.
    static constexpr std::size_t refit_all_share = 32;
    // Escaped bodies (at a step where most did not escape) from which their
    // queries of the trees are shared among threads: a query is a few
    // hundred nanoseconds (about 250 on the falling scene of 10,000
    // bodies, 2,300 of them escaping a step).
    static constexpr std::size_t parallel_escaped_queries = 1024;

    // Whether body i moved by over a quarter of its size at this step.
    bool jumped_now(body_id i) const { return bodies_[i].moved && bodies_[i].jumped; }

    // Body i's hull corners, pose, scale and posed box centre (a separating
    // edge's test and search).
    hull_view hull_of(body_id i) const {
        const body& b = bodies_[i];
        return {hull_corners_.data() + b.hull_first, b.hull_count, b.pose, b.scale, b.round.centre};
    }

    // Body i's polygon and pose, without its placing (pass 1).
    body_view<NT> posed(body_id i) const {
        const body& b = bodies_[i];
        return {&shapes_[b.shape]->shape, b.pose, b.scale, nullptr};
    }

    body_view<NT> view(body_id i) {
        body& b = bodies_[i];
        return {&shapes_[b.shape]->shape, b.pose, b.scale, b.placed.get()};
    }

    // The shift of a pair of bodies in NT: range_shift of the sum of their
    // scales (which bounds every coordinate either one's placing computes).
    static int pair_shift(const body& a, const body& b) {
        if constexpr (!scaled_into_range_v<NT>) {
            (void)a;
            (void)b;
            return 0;
        } else {
            return range_shift<NT>(a.scale + b.scale);
        }
    }

    // Shape s scaled by 2^k, made once (serially: the candidates' pass) and
    // kept for the pairs that ask for it again.
    const polygon& scaled_shape(shape_id s, int k) {
        std::unique_ptr<polygon>& p = scaled_shapes_[{s, k}];
        if (!p) p = std::make_unique<polygon>(shapes_[s]->shape.scaled_by_power_of_two(k));
        return *p;
    }

    // Body i scaled by 2^k (its shape from scaled_shapes_, its translation
    // and scale), with `placed` as its placing, or none (pass 1).
    body_view<NT> scaled_view(body_id i, int k, placed_polygon<NT>* placed) const {
        const body& b = bodies_[i];
        return {scaled_shapes_.at({b.shape, k}).get(), scaled_by_power_of_two(b.pose, k), std::ldexp(b.scale, k),
                placed};
    }

    // Whether a pair scaled by 2^shift shows its bodies within d (d scaled
    // with it), `last` tried first: both bodies placed at their scaled poses
    // for this pair alone, with run boxes as the world's placings (the same
    // search, the same witness).
    meeting scaled_within(const record& r, const meeting& last, bool* by_witness, witness_preference prefer,
                          bool* in_exact) const {
        const body_view<NT> a = scaled_view(r.bodies.first, r.shift, nullptr),
                            b = scaled_view(r.bodies.second, r.shift, nullptr);
        placed_polygon<NT> pa(*a.shape, a.pose), pb(*b.shape, b.pose);
        pa.make_run_bounds();
        pb.make_run_bounds();
        return bodies_within<NT, Exact>(last, {a.shape, a.pose, a.scale, &pa}, {b.shape, b.pose, b.scale, &pb},
                                        scaled_length(options_.within, r.shift), by_witness, prefer, in_exact);
    }

    // The bodies of the candidates `which` placed at their poses, each
    // once, in parallel blocks when many; a body that stayed keeps its
    // placing. Vertices in double at once; in an NT that placed_polygon
    // keeps (not by_value: an exact type) each made when a test first asks
    // for it, or all of them here when the pairs are then tested by several
    // threads (`shared`), which may not make them concurrently.
    void place_candidates(const std::vector<record>& tested, const std::vector<std::size_t>& which, bool shared) {
        struct placing {
            body_id id;
            bool repose;  // not placed at the present pose yet
        };
        std::vector<placing> asked;
        for (std::size_t k : which) {
            if (tested[k].shift != 0) continue;  // placed scaled, for its pair alone
            for (body_id i : {tested[k].bodies.first, tested[k].bodies.second}) {
                body& b = bodies_[i];
                const bool repose = !b.placed_now, make_all = shared && !b.all_made;
                if (!repose && !make_all) continue;
                b.placed_now = true;
                b.all_made = b.all_made || make_all;
                asked.push_back({i, repose});
            }
        }
        // (Only for pairs then tested by several threads: placings made on
        // the other core and tested here cost more in the tests' reads than
        // their making saved; see parallel_placings.)
        const unsigned threads = !shared || asked.size() < parallel_placings ? 1u : options_.threads;
        run_in_chunks(asked.size(), threads, 64, [&](std::size_t first, std::size_t last) {
            for (std::size_t k = first; k < last; ++k) {
                // (Asked for ahead, without waiting, each read once the read
                // it depends on was asked for: the body 6 places ahead, the
                // placing 3 ahead, the placing's buffers 1 ahead. The bodies
                // come in the candidates' order, anywhere in memory.)
                if (k + 6 < last) {
                    const body& ahead = bodies_[asked[k + 6].id];
                    prefetch(&ahead.pose);
                    prefetch(&ahead.placed);
                }
                if (k + 3 < last) prefetch(bodies_[asked[k + 3].id].placed.get());
                if (k + 1 < last)
                    if (const placed_polygon<NT>* p = bodies_[asked[k + 1].id].placed.get()) p->prefetch_buffers();
                body& b = bodies_[asked[k].id];
                if (asked[k].repose) {
                    if (b.placed)
                        b.placed->repose(b.pose);
                    else
                        b.placed = std::make_unique<placed_polygon<NT>>(shapes_[b.shape]->shape, b.pose);
                    b.placed->make_run_bounds();
                    // (The shape's inner disc about its box centre, posed as
                    // the bounding disc's centre is: b.round.)
                    b.placed->set_inner({b.round.centre, shapes_[b.shape]->inner});
                }
                if constexpr (!placed_polygon<NT>::by_value)
                    if (b.all_made) b.placed->all();
            }
        });
    }

    // Step 3: each candidate's answer, in parallel blocks when there are
    // enough of them to pay for the threads:
    //   pass 1: each pair whose witness is two edges tries them (four
    //           vertices posed, no polygon placed); each pair apart with a
    //           separating edge tries it (its ends and the other hull's
    //           corners posed). When neither body jumped at this step, a
    //           pair new, or whose two edges no longer meet, seeks a
    //           separating edge (seek_separating_edge, from the hulls'
    //           corners posed) when within is 0 and the pair is not
    //           scaled: found, the pair is apart; then a pair whose two
    //           edges no longer meet tries the edges next to them, and a
    //           pair apart at the last step (its separating edge failed,
    //           or it had none) the two edges it parted at and those next
    //           to them (nearby_edges_meet): found, the pair meets by them
    //   the bodies of the pairs left placed (place_candidates)
    //   pass 2: each pair left: bodies_within. A pair whose bodies did not
    //           jump (coherence on) seeks two edges that meet
    //           first (pass 1 can test them again at the next step); a
    //           located vertex found when no edges met (one body in the
    //           other) is tried first; a pair apart that did not seek in
    //           pass 1 seeks a separating edge on the same conditions
    void narrow(std::vector<record>& tested) {
        const bool seeks_separation = options_.coherence && options_.within == 0;
        const unsigned threads = tested.size() < parallel_witness_tests ? 1u : options_.threads;
        run_in_chunks(tested.size(), threads, 256, [&](std::size_t first, std::size_t last) {
            for (std::size_t k = first; k < last; ++k) {
                record& r = tested[k];
                bool edge_failed = false;
                if (r.apart) {
                    r.by_witness = separation_holds<NT>(r.apart, hull_of(r.bodies.first), hull_of(r.bodies.second));
                    if (r.by_witness) continue;
                    r.apart = {};
                    edge_failed = true;
                } else if (r.shown.how == meeting::kind::edges) {
                    r.by_witness = r.shift == 0 ? edge_witness_holds<NT, Exact>(r.shown, posed(r.bodies.first),
                                                                                posed(r.bodies.second), options_.within)
                                                : edge_witness_holds<NT, Exact>(
                                                      r.shown, scaled_view(r.bodies.first, r.shift, nullptr),
                                                      scaled_view(r.bodies.second, r.shift, nullptr),
                                                      scaled_length(options_.within, r.shift));
                    if (r.by_witness) continue;
                } else if (r.shown) {
                    continue;  // (a located vertex: tried in pass 2, on the placings)
                }
                if (jumped_now(r.bodies.first) || jumped_now(r.bodies.second)) continue;
                // (Bodies whose edges parted, or that have just come near,
                // are more often apart than not on the time study's coherent
                // scenes; a separating edge then spares the pair its
                // placings and the one-shot test.)
                if (seeks_separation && r.shift == 0 && !edge_failed) {
                    r.sought = true;
                    r.apart = seek_separating_edge<NT>(hull_of(r.bodies.first), hull_of(r.bodies.second));
                    if (r.apart) {
                        r.part(r.shown);
                        r.shown = {};
                        continue;
                    }
                }
                // (Edges that parted most often leave the bodies meeting
                // by their neighbours; bodies that come back together, by
                // the edges they parted at, or theirs.)
                const bool failed = r.shown.how == meeting::kind::edges;
                if (!failed && !r.parted) continue;
                meeting around;
                around.how = meeting::kind::edges;
                around.a_index = failed ? r.shown.a_index : r.parted_a;
                around.b_index = failed ? r.shown.b_index : r.parted_b;
                const meeting m = r.shift == 0 ? nearby_edges_meet<NT, Exact>(around, !failed, posed(r.bodies.first),
                                                                              posed(r.bodies.second), options_.within)
                                               : nearby_edges_meet<NT, Exact>(
                                                     around, !failed, scaled_view(r.bodies.first, r.shift, nullptr),
                                                     scaled_view(r.bodies.second, r.shift, nullptr),
                                                     scaled_length(options_.within, r.shift));
                if (m) {
                    r.shown = m;
                    r.nearby = true;
                }
            }
        });
        std::vector<std::size_t> left;
        for (std::size_t k = 0; k < tested.size(); ++k)
            if (!tested[k].by_witness && !tested[k].apart && !tested[k].nearby) left.push_back(k);
        const unsigned threads_left = left.size() < parallel_pair_tests ? 1u : batch_threads(options_.threads);
        place_candidates(tested, left, threads_left > 1);
        run_in_chunks(left.size(), threads_left, 16, [&](std::size_t first, std::size_t last) {
            for (std::size_t k = first; k < last; ++k) {
                // (Asked for ahead, without waiting: the placings of the pair
                // 4 places ahead, then their buffers 2 ahead. With the two
                // passes above, a step of 100,000 bodies at random poses
                // costs 1.4x less, of mixed sizes 1.45x less; below 10,000
                // bodies nothing changes beyond the noise.)
                if (k + 4 < last) {
                    const record& ahead = tested[left[k + 4]];
                    prefetch(bodies_[ahead.bodies.first].placed.get());
                    prefetch(bodies_[ahead.bodies.second].placed.get());
                }
                if (k + 2 < last) {
                    const record& ahead = tested[left[k + 2]];
                    for (body_id i : {ahead.bodies.first, ahead.bodies.second})
                        if (const placed_polygon<NT>* p = bodies_[i].placed.get()) p->prefetch_buffers();
                }
                record& r = tested[left[k]];
                const meeting contained = r.no_crossing ? meeting(r.shown) : meeting{};
                const meeting was = r.shown;
                // (A pair of bodies that did not jump will likely be tested
                // again at the next step, where two edges are retested
                // from four vertices and a located vertex needs both bodies
                // placed; a contact of the last step is such a pair.)
                const bool steady = options_.coherence && !jumped_now(r.bodies.first) && !jumped_now(r.bodies.second);
                const witness_preference prefer = steady ? witness_preference::edges : witness_preference::cheapest;
                r.shown = r.shift == 0
                              ? bodies_within<NT, Exact>(contained, view(r.bodies.first), view(r.bodies.second),
                                                         options_.within, &r.by_witness, prefer, &r.in_exact)
                              : scaled_within(r, contained, &r.by_witness, prefer, &r.in_exact);
                if (!r.shown) r.part(was);
                const bool located = r.shown && r.shown.how != meeting::kind::edges;
                r.no_crossing = located && (r.by_witness || prefer == witness_preference::edges);
                // (Bodies that jumped at this step will likely jump again:
                // an edge found for them would seldom serve.)
                if (!r.shown && !r.sought && seeks_separation && r.shift == 0 && !jumped_now(r.bodies.first) &&
                    !jumped_now(r.bodies.second))
                    r.apart = seek_separating_edge<NT>(hull_of(r.bodies.first), hull_of(r.bodies.second));
            }
        });
        for (const record& r : tested) {
            stats_.witness_hits += r.by_witness ? 1 : 0;
            stats_.separated += r.by_witness && r.apart ? 1 : 0;
            stats_.found_apart += !r.by_witness && r.apart && r.sought ? 1 : 0;
            stats_.nearby_edges += r.nearby ? 1 : 0;
            stats_.exact_pairs += r.in_exact ? 1 : 0;
        }
    }

    // Step 4: this step's pairs (carried and tested), its contacts and
    // events; the moved marks cleared.
    void gather() {
        last_.clear();
        std::vector<body_pair> now = std::move(spare_contacts_);  // (its capacity kept from step to step)
        now.clear();
        witnesses_.clear();
        const auto take = [&](const record& r) {
            if (!r.shown) {
                if (r.apart || r.parted) last_.push_back(r);  // apart, its separating edge or parted edges kept
                return;
            }
            last_.push_back(r);
            now.push_back(r.bodies);
            if (options_.witness)
                witnesses_.push_back(witness_of(r.shown, shapes_[bodies_[r.bodies.first].shape]->shape,
                                                shapes_[bodies_[r.bodies.second].shape]->shape));
        };
        // The carried and the tested pairs merged by pair (both sorted).
        std::size_t c = 0, t = 0;
        while (c < kept_.size() || t < tested_.size())
            take(t == tested_.size() || (c < kept_.size() && kept_[c].bodies < tested_[t].bodies) ? kept_[c++]
                                                                                                  : tested_[t++]);
        events_.clear();
        std::size_t i = 0, j = 0;
        while (i < contacts_.size() || j < now.size()) {
            if (j == now.size() || (i < contacts_.size() && contacts_[i] < now[j])) {
                events_.push_back({contacts_[i++], false});
            } else if (i == contacts_.size() || now[j] < contacts_[i]) {
                events_.push_back({now[j++], true});
            } else {
                ++i;
                ++j;
            }
        }
        spare_contacts_ = std::move(contacts_);
        contacts_ = std::move(now);
        stats_.contacts += contacts_.size();
        for (body_id i2 : moved_) bodies_[i2].moved = false;
        moved_.clear();
    }

    world_options options_;
    std::vector<std::unique_ptr<shape_entry>> shapes_;
    // Every shape's hull corners (hull_vertices' order), shape after shape:
    // one array, so that the hulls of shapes added in turn (a layer's
    // parcels, each a shape of its own) lie side by side in memory.
    std::vector<point<double>> hull_corners_;
    std::vector<body> bodies_;
    std::vector<body_id> moved_;
    std::vector<body_id> escaped_;  // at this step
    std::vector<body_pair> near_;   // enlarged boxes meet, not both fixed; sorted
    // Buffers a step fills and empties, kept for their capacity: a world
    // stepped again and again allocates only when it grows.
    std::vector<box> spare_boxes_;                    // a tree's boxes for its rebuild
    std::vector<std::uint32_t> spare_ids_;            // their ids
    std::vector<body_id> spare_refit_;                // the bodies of a tree refitted
    std::vector<body_pair> spare_pairs_;              // the near pairs found at a step
    body_pair_sort_buffers spare_sort_;               // their sort's buffers, and their merge's
    std::size_t fixed_refits_ = 0, free_refits_ = 0;  // since the tree's last rebuild
    box_tree fixed_tree_, free_tree_;
    std::map<std::pair<shape_id, int>, std::unique_ptr<polygon>> scaled_shapes_;  // scaled_shape's copies
    std::vector<record> last_;    // the last step's pairs within the distance, or apart with a separating edge; sorted
    std::vector<record> kept_;    // this step's carried pairs
    std::vector<record> tested_;  // this step's candidates (kept for their capacity)
    // The candidates and carried contacts of each block of near pairs when
    // sought in parallel (candidates(); kept for their capacity).
    std::vector<std::vector<record>> block_tested_, block_kept_;
    // The near pairs found by each block of escaped bodies when their
    // queries are shared (update_near(); kept for their capacity).
    std::vector<std::vector<body_pair>> block_found_;
    std::vector<body_pair> contacts_;
    std::vector<body_pair> spare_contacts_;  // the contacts of the step before last, for their capacity
    std::vector<contact_witness> witnesses_;
    std::vector<contact_event> events_;
    world_statistics stats_;
};

}  // namespace influence2d
