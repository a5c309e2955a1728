// SPDX-License-Identifier: BSL-1.0
#pragma once
// The time study (docs/method.md section 8): the paper's grid of cells, each method
// on the same poses, every answer counted against the exact reference.
//
// Workloads (time_cell::trajectory; the --trajectories option):
//   circular  the paper's orbit (90,000 poses, gap 9: never colliding)
//   linear    the paper's approach (9,000 poses, ending in collision)
//   random    independent poses near contact: influence2d::random_poses, B's
//             centroid uniform in area in the annulus 0.4 (R_A + R_B) ..
//             1.1 (R_A + R_B) about A's centroid (R: bounding radii about the
//             centroids; about 40..110 for the families), angle uniform;
//             20,000 poses, seeded
//   one-shot  the random poses again, each a query of its own: nothing built
//             for the pair is kept from one pose to the next
// The first three ask a method built once for the pair (its frame form), the
// last asks its one-shot form (method_table below).
//
//   for each polygon type, workload, static size n, moving size m (a cell):
//       A = family polygon (type, n), B = family polygon (type, m)
//       reference = certified_detector<detector> on every pose, in order
//                   (exact answers: checked against CGAL's exact kernel by the
//                   long run); untimed
//       preparation: each method built for A and B in turns, at least 3 times
//                    (an odd number) until `preparation_seconds`; the median
//                    build counts (the detector's constructor with
//                    build_structures(), GEOS's prepared
//                    geometry, ...; a one-shot form keeps only its input;
//                    GEOS builds the index of a prepared geometry on its first
//                    query, so that part of its preparation falls in the
//                    first pose, not here)
//       for each method:
//           built once (not timed); then timed over its poses:
//             - repeated methods (influence2d's double, certified and paper
//               detectors; its one-shot double, certified and detector per
//               query) run in passes on fresh objects; the pass is repeated
//               (at least `repeated_passes`, an odd number, and until
//               `repeat_seconds` of passes) and the median pass counts, so
//               that a cell of a few milliseconds is not at the mercy of one
//               interruption; the methods take turns pass by pass, so that a
//               slower spell of the machine falls on all of them alike and
//               their ratios hold. A frame form's pass is every pose in order
//               (temporal coherence is its to use; random poses give it
//               none); a one-shot pass is every k-th pose, k chosen so that a
//               pass takes about a third of `budget` (k = 1 when all poses
//               fit);
//             - the other methods (exact mode, all-pairs test, the peers),
//               which are slow on large cells, run every k-th pose, k chosen
//               from a probe of 8 evenly spaced poses so that a pass takes
//               about a third of `budget` (k = 1 when all poses fit), in 3
//               passes on fresh objects taking turns with the repeated
//               methods' first three, and the median pass counts: a peer's
//               time is taken in the same spells of the machine as the
//               library's, never in one pass of its own;
//           answers compared with the reference on those poses.
//
// A row gives poses run, seconds, ns per pose, collisions, disagreements and
// the preparation. The peak heap use of each method is measured on one cell
// (the largest of the first workload).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/exact/certified_intersects.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/query/intersects.hpp"
#include "verification/families.hpp"
#include "verification/heap_meter.hpp"
#include "verification/peers.hpp"
#include "verification/raster.hpp"
#include "verification/report_text.hpp"

namespace influence2d::verification {

/// Whether GEOS and Box2D were found when this was built.
#if INFLUENCE2D_HAVE_GEOS
inline constexpr bool have_geos = true;
#else
inline constexpr bool have_geos = false;
#endif
#if INFLUENCE2D_HAVE_BOX2D
inline constexpr bool have_box2d = true;  ///< see have_geos
#else
inline constexpr bool have_box2d = false;  ///< see have_geos
#endif

/// The workloads, in their default order.
inline const std::vector<std::string>& known_trajectories() {
    static const std::vector<std::string> all = {"circular", "linear", "random", "one-shot"};
    return all;
}

/// Whether a workload asks each method's one-shot form (else its frame form).
inline bool is_one_shot(const std::string& trajectory) { return trajectory == "one-shot"; }

// ---------------------------------------------------------------------------
// The forms of influence2d's methods that the detectors are not already.

/// No form of the method for this kind of workload.
struct no_form {};

/// An influence2d detector D built with every structure its frames use
/// (D::build_structures()), so that its preparation is counted as such and
/// not in its first frames, as a real-time loop would build it. The peers'
/// indexes built by a first query are kept out of the timed frames alike
/// (stride_for asks the probe poses untimed first).
template <class D>
class fully_built : public D {
public:
    fully_built(const polygon& a, const polygon& b, detector_options o = {}) : D(a, b, o) { D::build_structures(); }
};

/// A detector<double> asked for the witnesses of each frame (every edge pair
/// that meets), fully built, each frame's pairs written into one vector kept
/// from frame to frame (collide(q, pairs), as a loop over many frames would
/// ask them): what contact features cost, beside a peer's contact manifold
/// written into the caller's struct.
class witness_detector : public fully_built<detector<double>> {
public:
    witness_detector(const polygon& a, const polygon& b) : fully_built<detector<double>>(a, b, with_witness()) {}
    bool collide(const pose& q) { return detector<double>::collide(q, pairs_); }

private:
    static detector_options with_witness() {
        detector_options o;
        o.witness = true;
        return o;
    }
    std::vector<edge_pair> pairs_;
};

/// influence2d's one-shot query in NT: intersects<NT>(A, B, pose).
template <class NT>
class one_shot_query {
public:
    one_shot_query(const polygon& a, const polygon& b) : a_(&a), b_(&b) {}
    bool collide(const pose& p) const { return intersects<NT>(*a_, *b_, p); }

private:
    const polygon *a_, *b_;
};

/// influence2d's certified one-shot query: certified_intersects(A, B, pose).
class certified_one_shot_query {
public:
    certified_one_shot_query(const polygon& a, const polygon& b) : a_(&a), b_(&b) {}
    bool collide(const pose& p) const { return certified_intersects(*a_, *b_, p); }

private:
    const polygon *a_, *b_;
};

/// A detector<double> built for one query and asked once: what the one-shot
/// query saves.
class detector_per_query {
public:
    detector_per_query(const polygon& a, const polygon& b) : a_(&a), b_(&b) {}
    bool collide(const pose& p) const { return detector<double>(*a_, *b_).collide(p).collides; }

private:
    const polygon *a_, *b_;
};

// ---------------------------------------------------------------------------
// The registry: one entry per method.

/// What the time study knows of a method.
struct method_info {
    const char* name;
    bool own;           ///< influence2d's (else a peer)
    bool available;     ///< its library was found when this was built
    const char* needs;  ///< the macro telling whether it was ("" for none)
    bool repeated;      ///< timed over every pose, passes repeated to repeat_seconds (else strided, 3 passes)
    bool (*applies)(const polygon&, const polygon&);  ///< whether it can take the cell's pair
    const char* frames;                               ///< its frame form, for help and reports ("" if none)
    const char* one_shot;                             ///< its one-shot form ("" if none)
    bool approximate = false;                         ///< answers only approximately by design (never the fastest peer)
};

/// A method: its description and the types of its two forms (no_form where it
/// has none); each form is built from (A, B) and answers collide(pose).
template <class Frames, class OneShot>
struct method_entry {
    using frames_form = Frames;
    using one_shot_form = OneShot;
    method_info info;
};

inline bool any_pair(const polygon&, const polygon&) { return true; }

/// Every method of the time study, influence2d's first. Adding a method is
/// adding an entry here.
inline const auto& method_table() {
    static const auto table = std::make_tuple(
        method_entry<fully_built<detector<double>>, one_shot_query<double>>{
            {"double", true, true, "", true, any_pair, "detector<double>", "intersects<double>"}},
        method_entry<fully_built<certified_detector<detector>>, certified_one_shot_query>{
            {"certified", true, true, "", true, any_pair, "certified_detector<detector> (the reference)",
             "certified_intersects"}},
        method_entry<fully_built<detector<exact_rational>>, one_shot_query<exact_rational>>{
            {"exact", true, true, "", false, any_pair, "detector<exact_rational>", "intersects<exact_rational>"}},
        method_entry<witness_detector, no_form>{
            {"double-witness", true, true, "", true, any_pair,
             "detector<double> with witnesses (every meeting edge pair, into a vector kept across frames)", ""}},
        method_entry<no_form, detector_per_query>{
            {"double-detector", true, true, "", true, any_pair, "", "detector<double> built, then one collide"}},
        method_entry<paper_detector<double>, no_form>{
            {"paper", true, true, "", true, any_pair, "paper_detector<double> (the paper's algorithm as written)", ""}},
        method_entry<brute_force_detector<double>, no_form>{
            {"brute_force", true, true, "", false, any_pair,
             "brute_force_detector<double> (every edge pair, then containment)", ""}},
        method_entry<boost_geometry_peer, boost_geometry_one_shot>{
            {"boost_geometry", false, true, "", false, boost_geometry_peer::applies,
             "Boost.Geometry intersects, B's rings refilled", "Boost.Geometry intersects, posed B built"}},
        method_entry<geos_peer, geos_one_shot>{{"geos", false, have_geos, "INFLUENCE2D_HAVE_GEOS", false,
                                                geos_peer::applies, "GEOS, A prepared, GEOSPreparedIntersects",
                                                "GEOS, both built, GEOSIntersects"}},
        method_entry<cgal_peer, cgal_peer>{{"cgal", false, true, "", false, cgal_peer::applies,
                                            "CGAL Boolean-set do_intersect, exact kernel",
                                            "the same (B posed fresh every query)"}},
        method_entry<box2d_peer, box2d_one_shot>{
            {"box2d", false, have_box2d, "INFLUENCE2D_HAVE_BOX2D", false, box2d_peer::applies,
             "Box2D b2TestOverlap (convex, at most 8 vertices)", "Box2D, both shapes built, b2TestOverlap"}},
        method_entry<box2d_manifold_peer, box2d_manifold_one_shot>{
            {"box2d-manifold", false, have_box2d, "INFLUENCE2D_HAVE_BOX2D", false, box2d_manifold_peer::applies,
             "Box2D b2CollidePolygons, a point in the manifold (convex, at most 8 vertices)",
             "Box2D, both shapes built, b2CollidePolygons"}},
        method_entry<raster_peer<64>, no_form>{{"raster-64", false, true, "", false, any_pair,
                                                "image space: both rasterised, 64 pixels along A's box", "", true}},
        method_entry<raster_peer<256>, no_form>{{"raster-256", false, true, "", false, any_pair,
                                                 "image space: both rasterised, 256 pixels along A's box", "", true}},
        method_entry<raster_peer<1024>, no_form>{{"raster-1024", false, true, "", false, any_pair,
                                                  "image space: both rasterised, 1024 pixels along A's box", "",
                                                  true}});
    return table;
}

/// The descriptions of every method, in the table's order.
inline const std::vector<method_info>& method_infos() {
    static const std::vector<method_info> all =
        std::apply([](const auto&... e) { return std::vector<method_info>{e.info...}; }, method_table());
    return all;
}

/// Every method the time study knows, ours first, available or not.
inline const std::vector<std::string>& known_methods() {
    static const std::vector<std::string> all = [] {
        std::vector<std::string> out;
        for (const method_info& m : method_infos()) out.push_back(m.name);
        return out;
    }();
    return all;
}

/// The description of method m; throws invalid_argument naming the known
/// methods if there is none.
inline const method_info& method_of(const std::string& m) {
    for (const method_info& i : method_infos())
        if (m == i.name) return i;
    std::string known;
    for (const std::string& k : known_methods()) known += (known.empty() ? "" : ", ") + k;
    throw std::invalid_argument("unknown method '" + m + "' (known: " + known + ")");
}

/// Whether the peer library of a method was found when this was built (GEOS
/// and Box2D are optional; every other method is always there).
inline bool method_available(const std::string& m) { return method_of(m).available; }

/// Whether a method is one of influence2d's (else a peer).
inline bool is_own_method(const std::string& m) { return method_of(m).own; }

/// Whether a method has a form for the workload.
inline bool runs_on(const std::string& m, const std::string& trajectory) {
    const method_info& i = method_of(m);
    return *(is_one_shot(trajectory) ? i.one_shot : i.frames) != '\0';
}

/// The methods of the time study, ours first: those this build has.
inline const std::vector<std::string>& time_study_methods() {
    static const std::vector<std::string> available = [] {
        std::vector<std::string> out;
        for (const method_info& m : method_infos())
            if (m.available) out.push_back(m.name);
        return out;
    }();
    return available;
}

/// The peers this build lacks (their libraries were not found), for reports.
inline std::vector<std::string> missing_methods() {
    std::vector<std::string> out;
    for (const method_info& m : method_infos())
        if (!m.available) out.push_back(m.name);
    return out;
}

/// Checks a list of method names: each known and available; throws
/// invalid_argument naming the first that is not.
inline void check_methods(const std::vector<std::string>& methods) {
    for (const std::string& m : methods)
        if (!method_of(m).available)
            throw std::invalid_argument("method '" + m + "': its library was not found when this was built (" +
                                        method_of(m).needs + ")");
}

/// The reference: this method's frame form on every pose, in order (a
/// workload that asks frame forms).
inline const std::string reference_method = "certified", reference_workload = "random";

struct time_cell {
    std::string type;        ///< family name: convex, starred, irregular, contour, hole
    std::string trajectory;  ///< the workload: circular, linear, random or one-shot
    std::size_t static_size = 0, moving_size = 0;
};

struct time_row {
    time_cell cell;
    std::string method;
    std::size_t trajectory_frames = 0;  ///< poses of the workload
    std::size_t frames = 0;             ///< poses run (every stride-th)
    std::size_t stride = 1;
    std::size_t passes = 1;  ///< timed passes over the poses (the median counts)
    double seconds = 0;      ///< for the poses run (the median pass), set-up excluded
    std::size_t collisions = 0;
    std::size_t disagreements = 0;       ///< with the reference, on the poses run
    bool reference = false;              ///< this method's answers are the reference
    double preparation_seconds = 0;      ///< building the method for A and B (the median build)
    std::size_t preparation_builds = 0;  ///< builds timed
    double ns_per_frame() const { return frames ? 1e9 * seconds / static_cast<double>(frames) : 0; }
};

struct memory_row {
    time_cell cell;
    std::string method;
    std::size_t frames = 0;
    std::size_t peak_bytes = 0;  ///< heap, from building the method to its last frame
};

struct time_study_progress {
    std::size_t cell = 0, cells = 0;  ///< cell == cells at the end
    time_cell at;
};

struct time_study_options {
    std::vector<std::string> types = {"convex", "starred", "irregular", "contour", "hole"};
    std::vector<std::string> trajectories = known_trajectories();
    std::vector<std::size_t> sizes = {8, 16, 32, 64, 128, 256, 512, 1024};
    std::vector<std::string> methods = time_study_methods();
    std::size_t circular_frames = 90000, linear_frames = 9000;
    std::size_t random_frames = 20000;  ///< poses of the random and one-shot workloads
    double gap = 9;
    double random_inner = 0.4, random_outer = 1.1;  ///< the annulus, in units of R_A + R_B
    double budget = 0.25;                           ///< seconds per strided method and cell
    double repeat_seconds = 0.05;                   ///< seconds of repeated passes per repeated method and cell
    std::size_t repeated_passes = 5;                ///< passes of a repeated method at least (odd)
    double preparation_seconds = 0.005;             ///< seconds of repeated builds per method and cell
    std::size_t memory_frames = 1000;               ///< frames of the memory pass (evenly spaced)
    std::uint64_t seed = default_family_seed;       ///< of the family polygons and the random poses
    std::function<void(const time_study_progress&)> progress;
};

/// What influence2d's double detector did on a cell of a frame workload
/// (untimed, a detector of its own over every pose): the counters that say
/// where a frame's time goes.
struct work_row {
    time_cell cell;
    std::size_t frames = 0;
    detector_statistics statistics;
};

struct time_study_result {
    std::vector<time_row> rows;
    std::vector<memory_row> memory;
    std::vector<work_row> work;  ///< per cell of a frame workload that runs double
    double seconds = 0;
};

namespace time_study_detail {

using clock = std::chrono::steady_clock;

template <class T>
struct form_tag {
    using type = T;
};

/// Calls g(form_tag<Form>{}) with the type of method m's form for the
/// workload; throws invalid_argument if m is unknown, unavailable or has no
/// such form.
template <class G>
void with_form(const std::string& m, const std::string& trajectory, G&& g) {
    const method_info& info = method_of(m);
    check_methods({m});
    if (!runs_on(m, trajectory))
        throw std::invalid_argument("method '" + m + "' does not run on the " + trajectory + " workload");
    const bool one_shot = is_one_shot(trajectory);
    std::apply(
        [&](const auto&... e) {
            const auto one = [&](const auto& entry) {
                if (std::string(entry.info.name) != info.name) return;
                using entry_type = std::decay_t<decltype(entry)>;
                if (one_shot) {
                    if constexpr (!std::is_same_v<typename entry_type::one_shot_form, no_form>)
                        g(form_tag<typename entry_type::one_shot_form>{});
                } else {
                    if constexpr (!std::is_same_v<typename entry_type::frames_form, no_form>)
                        g(form_tag<typename entry_type::frames_form>{});
                }
            };
            (one(e), ...);
        },
        method_table());
}

}  // namespace time_study_detail

/// Calls f(d) with method m's form for the workload built for A and B.
template <class F>
void with_method(const std::string& m, const std::string& trajectory, const polygon& a, const polygon& b, F&& f) {
    time_study_detail::with_form(m, trajectory, [&](auto tag) {
        typename decltype(tag)::type d(a, b);
        f(d);
    });
}

/// Seconds to build method m's form for A and B (destruction not counted).
inline double build_seconds(const std::string& m, const std::string& trajectory, const polygon& a, const polygon& b) {
    double seconds = 0;
    time_study_detail::with_form(m, trajectory, [&](auto tag) {
        std::optional<typename decltype(tag)::type> d;
        const auto t0 = time_study_detail::clock::now();
        d.emplace(a, b);
        seconds = std::chrono::duration<double>(time_study_detail::clock::now() - t0).count();
    });
    return seconds;
}

/// Whether the form d (a method built for a pair) answers that the pair
/// meets at pose p: a frame form's frame_result, a one-shot form's bool.
template <class D>
bool form_collides(D& d, const pose& p) {
    if constexpr (std::is_same_v<decltype(d.collide(p)), bool>)
        return d.collide(p);
    else
        return d.collide(p).collides;
}

/// Runs d on poses[0], poses[stride], ...; answers into `answers` (one per
/// frame run); returns the seconds taken.
template <class D>
double run_frames(D& d, const std::vector<pose>& poses, std::size_t stride, std::vector<char>& answers) {
    answers.clear();
    answers.reserve(poses.size() / stride + 1);
    const auto t0 = time_study_detail::clock::now();
    for (std::size_t k = 0; k < poses.size(); k += stride) answers.push_back(form_collides(d, poses[k]) ? 1 : 0);
    return std::chrono::duration<double>(time_study_detail::clock::now() - t0).count();
}

namespace time_study_detail {

/// The stride that keeps a run of d within `budget` seconds, from 8 evenly
/// spaced frames, asked once untimed (first calls pay for cold caches and
/// first allocations) and then timed (1 when the whole trajectory fits).
template <class D>
std::size_t stride_for(D& d, const std::vector<pose>& poses, double budget) {
    const std::size_t probe = std::min<std::size_t>(8, poses.size());
    if (probe == 0) return 1;
    for (std::size_t k = 0; k < probe; ++k) (void)form_collides(d, poses[k * poses.size() / probe]);
    const auto t0 = clock::now();
    for (std::size_t k = 0; k < probe; ++k) (void)form_collides(d, poses[k * poses.size() / probe]);
    const double per_frame = std::chrono::duration<double>(clock::now() - t0).count() / static_cast<double>(probe);
    const double whole = per_frame * static_cast<double>(poses.size());
    if (whole <= budget) return 1;
    return static_cast<std::size_t>(std::ceil(whole / budget));
}

/// Whether rounds of turns go on: until every method has at least 3 samples
/// (an odd number) and `seconds` of them, or 101.
inline bool more_rounds(std::size_t round, const std::map<std::string, std::vector<double>>& samples, double seconds) {
    if (round < 3 || round % 2 == 0) return true;
    if (round >= 101) return false;
    for (const auto& [m, s] : samples)
        if (std::accumulate(s.begin(), s.end(), 0.0) < seconds) return true;
    return false;
}

}  // namespace time_study_detail

/// The cells of a run, in the order they are run.
inline std::vector<time_cell> time_study_cells(const time_study_options& o) {
    std::vector<time_cell> cells;
    for (const std::string& t : o.types)
        for (const std::string& j : o.trajectories)
            for (std::size_t n : o.sizes)
                for (std::size_t m : o.sizes) cells.push_back({t, j, n, m});
    return cells;
}

/// The annulus of the random poses about A's centroid: inner..outer times
/// R_A + R_B, R the bounding radii about the centroids.
inline std::pair<double, double> random_annulus(const time_study_options& o, const polygon& a, const polygon& b) {
    const double r = bounding_radius(a, a.centroid()) + bounding_radius(b, b.centroid());
    return {o.random_inner * r, o.random_outer * r};
}

/// The poses of a cell: its trajectory, or the random stream (random and
/// one-shot: the same poses).
inline std::vector<pose> time_study_poses(const time_study_options& o, const time_cell& c, const polygon& a,
                                          const polygon& b) {
    if (c.trajectory == "circular") return circular_trajectory(a, b, o.circular_frames, o.gap);
    if (c.trajectory == "linear") return linear_trajectory(a, b, o.linear_frames, o.gap);
    if (c.trajectory == "random" || c.trajectory == "one-shot") {
        const auto [inner, outer] = random_annulus(o, a, b);
        return random_poses(a, b, o.random_frames, inner, outer, o.seed);
    }
    throw std::invalid_argument("unknown trajectory: " + c.trajectory);
}

namespace time_study_detail {

/// The timed passes of a repeated method on a cell.
struct timed_passes {
    std::vector<char> answers;  ///< of the first pass
    std::size_t stride = 1;
    std::size_t passes = 0;
    double median = 0;  ///< seconds of the median pass
};

/// Times `methods` on a cell: passes on fresh objects, the methods taking
/// turns pass by pass. Every method takes the first 3 rounds; a repeated
/// method goes on, two rounds at a time, until it has `repeated_passes` and
/// they sum to `repeat_seconds` (or 101 rounds), so that each ends with an
/// odd number of passes (a median of 3 passes of a few tens of milliseconds
/// can fall on two slow spells of the machine). A repeated method's
/// frame-form pass is every pose in order; a one-shot pass, and every pass of
/// the others, every k-th pose, k from a probe (on an object of its own: a
/// detector with temporal coherence starts its timed passes fresh) so that a
/// pass takes about budget / 3.
inline std::map<std::string, timed_passes> time_passes(const time_study_options& o, const std::string& trajectory,
                                                       const std::vector<std::string>& methods, const polygon& a,
                                                       const polygon& b, const std::vector<pose>& poses) {
    std::map<std::string, timed_passes> out;
    std::map<std::string, std::vector<double>> seconds;
    std::map<std::string, bool> taking_turns;
    for (const std::string& m : methods) {
        seconds[m];
        taking_turns[m] = true;
        if (is_one_shot(trajectory) || !method_of(m).repeated)
            with_method(m, trajectory, a, b,
                        [&](auto& probe) { out[m].stride = stride_for(probe, poses, o.budget / 3); });
    }
    std::vector<char> repeated;
    for (std::size_t round = 0; round < 101; ++round) {
        if (round >= 3 && round % 2 == 1)
            for (const std::string& m : methods)
                taking_turns[m] = taking_turns[m] && method_of(m).repeated &&
                                  (seconds[m].size() < o.repeated_passes ||
                                   std::accumulate(seconds[m].begin(), seconds[m].end(), 0.0) < o.repeat_seconds);
        bool any = false;
        for (const std::string& m : methods) {
            if (!taking_turns[m]) continue;
            any = true;
            with_method(m, trajectory, a, b, [&](auto& fresh) {
                seconds[m].push_back(run_frames(fresh, poses, out[m].stride, round == 0 ? out[m].answers : repeated));
            });
        }
        if (!any) break;
    }
    for (const std::string& m : methods) {
        out[m].passes = seconds[m].size();
        out[m].median = median_of(seconds[m]);
    }
    return out;
}

/// The preparation of each of `methods` on a cell: builds for A and B, the
/// methods taking turns, until each has at least 3 (an odd number) and
/// `preparation_seconds` of them, or 101; the median build and the count.
inline std::map<std::string, std::pair<double, std::size_t>> time_preparation(const time_study_options& o,
                                                                              const std::string& trajectory,
                                                                              const std::vector<std::string>& methods,
                                                                              const polygon& a, const polygon& b) {
    std::map<std::string, std::vector<double>> seconds;
    for (const std::string& m : methods) seconds[m];
    for (std::size_t round = 0; !methods.empty() && more_rounds(round, seconds, o.preparation_seconds); ++round)
        for (const std::string& m : methods) seconds[m].push_back(build_seconds(m, trajectory, a, b));
    std::map<std::string, std::pair<double, std::size_t>> out;
    for (auto& [m, s] : seconds) out[m] = {median_of(s), s.size()};
    return out;
}

}  // namespace time_study_detail

/// The methods among o.methods that run on a cell's pair and workload.
inline std::vector<std::string> cell_methods(const time_study_options& o, const std::string& trajectory,
                                             const polygon& a, const polygon& b) {
    std::vector<std::string> out;
    for (const std::string& m : o.methods)
        if (runs_on(m, trajectory) && method_of(m).applies(a, b)) out.push_back(m);
    return out;
}

/// Runs the study.
inline time_study_result run_time_study(const time_study_options& o) {
    using namespace time_study_detail;
    check_methods(o.methods);
    for (const std::string& j : o.trajectories)
        if (std::find(known_trajectories().begin(), known_trajectories().end(), j) == known_trajectories().end())
            throw std::invalid_argument("unknown trajectory: " + j);
    const auto start = clock::now();
    const std::vector<time_cell> cells = time_study_cells(o);
    time_study_result r;
    std::vector<char> reference, answers;
    for (std::size_t ci = 0; ci < cells.size(); ++ci) {
        const time_cell& c = cells[ci];
        if (o.progress) o.progress({ci, cells.size(), c});
        const family f = family_of(c.type);
        const polygon a = make_family_polygon(f, c.static_size, o.seed);
        const polygon b = make_family_polygon(f, c.moving_size, o.seed);
        const std::vector<pose> poses = time_study_poses(o, c, a, b);
        const std::vector<std::string> methods = cell_methods(o, c.trajectory, a, b);

        // The reference: the certified detector on every pose, in order (not
        // timed: the certified method's row is a run of its own, like every
        // other method's, after this pass has brought the poses into cache).
        with_method(reference_method, reference_workload, a, b,
                    [&](auto& d) { (void)run_frames(d, poses, 1, reference); });
        if (!is_one_shot(c.trajectory) && std::find(methods.begin(), methods.end(), "double") != methods.end()) {
            detector<double> d(a, b);
            for (const pose& p : poses) (void)d.collide(p);
            r.work.push_back({c, poses.size(), d.statistics()});
        }
        const auto preparation = time_preparation(o, c.trajectory, methods, a, b);
        const std::map<std::string, timed_passes> timed = time_passes(o, c.trajectory, methods, a, b, poses);
        for (const std::string& m : methods) {
            time_row row;
            row.cell = c;
            row.method = m;
            row.trajectory_frames = poses.size();
            row.reference = m == reference_method && !is_one_shot(c.trajectory);
            row.preparation_seconds = preparation.at(m).first;
            row.preparation_builds = preparation.at(m).second;
            const timed_passes& t = timed.at(m);
            answers = t.answers;
            row.stride = t.stride;
            row.passes = t.passes;
            row.seconds = t.median;
            row.frames = answers.size();
            for (std::size_t k = 0; k < answers.size(); ++k) {
                row.collisions += answers[k] ? 1 : 0;
                row.disagreements += answers[k] != reference[k * row.stride] ? 1 : 0;
            }
            r.rows.push_back(row);
        }
    }

    // Peak heap per method on the largest cell: first type and workload,
    // largest sizes, memory_frames evenly spaced poses.
    if (heap_meter::available() && !cells.empty() && o.memory_frames > 0) {
        const std::size_t n = *std::max_element(o.sizes.begin(), o.sizes.end());
        const time_cell c{o.types.front(), o.trajectories.front(), n, n};
        const family f = family_of(c.type);
        const polygon a = make_family_polygon(f, c.static_size, o.seed);
        const polygon b = make_family_polygon(f, c.moving_size, o.seed);
        const std::vector<pose> poses = time_study_poses(o, c, a, b);
        const std::size_t stride = std::max<std::size_t>(1, poses.size() / o.memory_frames);
        for (const std::string& m : cell_methods(o, c.trajectory, a, b)) {
            memory_row row{c, m, 0, 0};
            heap_meter::start();
            with_method(m, c.trajectory, a, b, [&](auto& d) { (void)run_frames(d, poses, stride, answers); });
            row.peak_bytes = heap_meter::stop();
            row.frames = answers.size();
            r.memory.push_back(row);
        }
    }
    if (o.progress) o.progress({cells.size(), cells.size(), {}});
    r.seconds = std::chrono::duration<double>(clock::now() - start).count();
    return r;
}

}  // namespace influence2d::verification
