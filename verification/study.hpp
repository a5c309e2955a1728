// SPDX-License-Identifier: BSL-1.0
#pragma once
// The precision study: the method's decisions (verification/decisions.hpp)
// evaluated in each number type, compared with the exact reference and timed.
//
// For each family of cases, each number type and each decision kind the study
// counts the questions asked, the answers that differ from the exact
// reference, and the time the type took to answer them (std::chrono::
// steady_clock over each run of questions; building the scene is not timed).
//
//   for each case (A, B, d, query points, poses of B):
//       build the reference and one evaluator per number type      (not timed)
//       for each chunk of questions:
//           the reference answers every decision kind of the chunk
//           for each number type, for each decision kind:
//               time its answers to the chunk; compare each with the reference
//
// The queries beyond yes or no (the separation, the first contact along a
// translation; verification/query_study.hpp) are asked of every type too, on
// the same scenes: their errors against the exact answers, and their time.
//
//   for each case, after its decisions:
//       for each query, for each chunk of its questions (poses, translations):
//           the exact answers                                          (not timed)
//           for each number type: time its answers; compare each with the exact one
//
// The image-space baseline (verification/raster.hpp), the paper's own
// comparison, answers the `collides` questions of the scenes with d = 0 at
// each resolution of a ladder, beside the number types: its misses and
// invented contacts against the exact answers, and its time.
//
// Number types come from one type list (study_modes): each is run once, by the
// same code. A disagreement of a type that claims the exact answer (its
// category is not floating) is a bug of the library: it is kept as a
// reproducible case, a JSON file (see data/regressions/README.md) that
// replay_regression answers again.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "influence2d/io/wkt.hpp"
#include "influence2d/number/multiprecision.hpp"
#include "verification/decisions.hpp"
#include "verification/families.hpp"
#include "verification/query_study.hpp"
#include "verification/raster.hpp"
#include "verification/seeded_draws.hpp"
#include "verification/stiff_cases.hpp"

namespace influence2d::verification {

/// A number type of the study: answers in NT, and in Fallback where NT raises
/// uncertain_sign (Fallback == NT: no fallback).
template <class NT, class Fallback = NT>
struct number_mode {
    using number = NT;
    using fallback = Fallback;
    using evaluator_type = evaluator<NT, Fallback>;
    /// How the type answers the queries: a filtered type (one with a
    /// fallback) through certified_separation and certified_first_contact.
    using route_type = query_route<NT, !std::is_same_v<NT, Fallback>>;
    static std::string name() { return number_type_name<NT>(); }
    /// Whether the type claims the exact answer: its category is not floating.
    static constexpr bool claims_exact = is_exact_v<NT>;
};

template <class... Modes>
struct mode_list {};

/// Every number type of the study, each once.
using study_modes = mode_list<number_mode<float>, number_mode<double>, number_mode<long double>, number_mode<quad>,
#ifdef INFLUENCE2D_HAS_FLOAT128
                              number_mode<float128>,
#endif
                              number_mode<certified, exact_rational>, number_mode<interval, exact_rational>,
                              number_mode<exact_rational>>;

template <class... Modes>
std::vector<std::string> mode_names(mode_list<Modes...>) {
    return {Modes::name()...};
}

/// The names of the case families: the paper's five, the stiff families,
/// then the offset and scale sweeps.
inline std::vector<std::string> study_family_names() {
    std::vector<std::string> names;
    for (family f : all_families) names.push_back(family_name(f));
    for (stiff_family f : all_stiff_families()) names.push_back(stiff_family_name(f));
    names.push_back("offset_sweep");
    names.push_back("scale_sweep");
    return names;
}

/// The families a run takes unless told: all but `large`, whose static
/// polygon of over 100,000 vertices makes every all-edges decision (alpha
/// selection, candidates, pairs, brute force) cost seconds per frame in the
/// slow types; it runs when named.
inline std::vector<std::string> default_study_families() {
    std::vector<std::string> names = study_family_names();
    names.erase(std::remove(names.begin(), names.end(), stiff_family_name(stiff_family::large)), names.end());
    return names;
}

/// The image-space baseline's resolutions unless told: powers of two from 16
/// to 4096 pixels along the longer side of A's box.
inline std::vector<std::size_t> default_raster_resolutions() {
    std::vector<std::size_t> r;
    for (std::size_t p = 16; p <= 4096; p *= 2) r.push_back(p);
    return r;
}

/// One scene of the study and its questions.
struct study_case {
    std::string family;    ///< the row of study.csv
    std::string sweep;     ///< "offset" or "scale" for a sweep's case, else empty
    double magnitude = 0;  ///< the sweep's magnitude
    std::string scene;     ///< names A, B and d, for the examples
    polygon a, b;
    double distance = 0;
    std::vector<point<double>> points;  ///< for the point decisions
    std::vector<pose> poses;            ///< for the pose decisions
};

/// The 64-bit FNV-1a hash of a text: stable across platforms.
inline std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 1469598103934665603ULL;
    for (unsigned char ch : text) h = (h ^ ch) * 1099511628211ULL;
    return h;
}

namespace study_detail {

struct random_source {
    std::mt19937_64 gen;
    explicit random_source(std::uint64_t seed) : gen(seed) {}
    double unit() { return std::ldexp(static_cast<double>(gen() >> 11), -53); }
    std::size_t index(std::size_t n) { return static_cast<std::size_t>(gen() % n); }
};

/// A point of A's boundary (a vertex or an edge's midpoint) and the unit
/// outward normal there (the interior is on the left of the stored edges).
inline std::pair<point<double>, point<double>> boundary_point(const polygon& a, random_source& r) {
    const std::size_t i = r.index(a.size());
    const point<double> v0 = a.vertex(i), v1 = a.vertex(a.next(i));
    point<double> at = v0, n{v1.y - v0.y, -(v1.x - v0.x)};
    if (r.index(2) == 0) {
        std::size_t prev = i;
        while (a.next(prev) != i) prev = a.next(prev);
        const point<double> u = a.vertex(prev);
        n = {n.x + (v0.y - u.y), n.y - (v0.x - u.x)};
    } else {
        at = {(v0.x + v1.x) / 2, (v0.y + v1.y) / 2};
    }
    const double len = std::hypot(n.x, n.y);
    if (len > 0) n = {n.x / len, n.y / len};
    return {at, n};
}

/// The vertex of B, turned by (c, s), furthest against the direction n.
inline point<double> extreme_against(const polygon& b, double c, double s, const point<double>& n) {
    point<double> best{};
    double best_dot = HUGE_VAL;
    for (const auto& q : b.vertices()) {
        const point<double> t{c * q.x - s * q.y, s * q.x + c * q.y};
        const double dot = t.x * n.x + t.y * n.y;
        if (dot < best_dot) {
            best_dot = dot;
            best = t;
        }
    }
    return best;
}

}  // namespace study_detail

/// Poses of B about A, near contact, in turn (as tests/detect/random_frames_test.cpp):
///   - random: B's centroid in a random direction from A's, at a distance in
///     the outer 40% of R_A + r_B + 4 (one in four anywhere within it), turned
///     at random;
///   - contact: theta = 0 and t = a - q, a a vertex or edge midpoint of A, q
///     the vertex of B furthest against A's outward normal n at a (exact on the
///     families' 2^-20 grid), then the same pose pushed 2^-20 along n;
///   - turned contact: a random theta and t = a - R q rounded (touching up to
///     rounding), pushed along n by 0 or +-2^-k times the coordinates' size,
///     k in 20..56.
/// With d > 0 every contact is pushed d further along n: the cliff of the
/// distance test.
inline std::vector<pose> contact_poses(const polygon& a, const polygon& b, double distance, std::size_t count,
                                       std::uint64_t seed) {
    using namespace study_detail;
    random_source r(seed);
    const point<double> ca = a.centroid(), cb = b.centroid();
    const double reach = bounding_radius(a, ca) + bounding_radius(b, cb) + 4;
    const double size = coordinate_scale(a) + reach;
    std::vector<pose> poses;
    poses.reserve(count);
    while (poses.size() < count) {
        const std::size_t k = poses.size();
        if (k % 8 < 2) {
            const double dist = reach * (k % 16 == 0 ? r.unit() : 0.6 + 0.4 * r.unit());
            const double phi = 2 * pi * r.unit(), theta = 2 * pi * r.unit() - pi;
            const double c = std::cos(theta), s = std::sin(theta);
            poses.push_back({ca.x + dist * std::cos(phi) - (c * cb.x - s * cb.y),
                             ca.y + dist * std::sin(phi) - (s * cb.x + c * cb.y), theta});
            continue;
        }
        const auto [at, n] = boundary_point(a, r);
        if (k % 8 < 4) {
            const point<double> q = extreme_against(b, 1, 0, n);
            const pose touch{at.x - q.x + distance * n.x, at.y - q.y + distance * n.y, 0};
            const double hair = std::ldexp(1.0, -20);
            poses.push_back(k % 8 == 2 ? touch : pose{touch.tx + hair * n.x, touch.ty + hair * n.y, 0});
            continue;
        }
        const double theta = 2 * pi * r.unit() - pi;
        const point<double> q = extreme_against(b, std::cos(theta), std::sin(theta), n);
        const std::size_t push = r.index(3);
        const double h = push == 0 ? 0 : std::ldexp(push == 1 ? size : -size, -20 - static_cast<int>(r.index(37)));
        poses.push_back({at.x - q.x + (distance + h) * n.x, at.y - q.y + (distance + h) * n.y, theta});
    }
    return poses;
}

/// The cases of one family (a name from study_family_names()): `cases` scenes
/// of `frames` poses and as many query points each (cone_query_points).
///   - paper families: A of the family, B of the next ones in turn, sizes 8 to
///     64 for A and 8 to 32 for B in turn, shapes from `seed`; d = 0.5 for
///     every third case, else 0; poses from contact_poses;
///   - stiff families: make_stiff_scenes (d = 0);
///   - offset_sweep, scale_sweep: `cases` scenes at each of offset_magnitudes()
///     or scale_magnitudes() (make_offset_scenes, make_scaled_scenes).
inline std::vector<study_case> make_study_cases(const std::string& name, std::size_t cases, std::size_t frames,
                                                std::uint64_t seed) {
    std::vector<study_case> out;
    const auto add_stiff = [&](std::vector<stiff_scene> scenes, const std::string& sweep) {
        for (stiff_scene& s : scenes) {
            study_case k;
            k.family = name;
            k.sweep = sweep;
            k.magnitude = s.magnitude;
            k.scene = s.name;
            k.a = std::move(s.a);
            k.b = std::move(s.b);
            k.poses = std::move(s.poses);
            k.points = cone_query_points(k.a, k.poses.size(), seed ^ fnv1a(s.name));
            out.push_back(std::move(k));
        }
    };
    if (name == "offset_sweep" || name == "scale_sweep") {
        const bool offset = name == "offset_sweep";
        for (double m : offset ? offset_magnitudes() : scale_magnitudes())
            add_stiff(offset ? make_offset_scenes(m, cases, seed, frames) : make_scaled_scenes(m, cases, seed, frames),
                      offset ? "offset" : "scale");
        return out;
    }
    for (stiff_family f : all_stiff_families())
        if (stiff_family_name(f) == name) {
            add_stiff(make_stiff_scenes(f, cases, seed, frames), "");
            return out;
        }
    static constexpr std::size_t a_sizes[] = {8, 16, 32, 64};
    static constexpr std::size_t b_sizes[] = {8, 16, 32};
    for (std::size_t fi = 0; fi < std::size(all_families); ++fi) {
        const family f = all_families[fi];
        if (family_name(f) != name) continue;
        for (std::size_t c = 0; c < cases; ++c) {
            const family g = all_families[(fi + 1 + c) % std::size(all_families)];
            const std::size_t na = a_sizes[c % 4], nb = b_sizes[(c / 4 + fi) % 3];
            const std::uint64_t s = seed + 1000003 * (fi + 1) + 7919 * c;
            study_case k;
            k.family = name;
            k.a = make_family_polygon(f, na, s);
            k.b = make_family_polygon(g, nb, s + 1);
            k.distance = c % 3 == 2 ? 0.5 : 0;
            k.scene = family_name(f) + "_" + std::to_string(na) + " / " + family_name(g) + "_" + std::to_string(nb) +
                      ", d = " + (k.distance > 0 ? "0.5" : "0");
            k.poses = contact_poses(k.a, k.b, k.distance, frames, s + 2);
            k.points = cone_query_points(k.a, frames, s + 3);
            out.push_back(std::move(k));
        }
        return out;
    }
    throw std::invalid_argument("unknown case family: " + name);
}

/// Answers to a run of questions, stored flat: answer k is
/// values[ends[k-1] .. ends[k]).
struct answer_batch {
    answer values;
    std::vector<std::size_t> ends;

    void clear() {
        values.clear();
        ends.clear();
    }
    void close() { ends.push_back(values.size()); }
    std::size_t begin_of(std::size_t k) const { return k == 0 ? 0 : ends[k - 1]; }
    answer get(std::size_t k) const {
        return answer(values.begin() + static_cast<std::ptrdiff_t>(begin_of(k)),
                      values.begin() + static_cast<std::ptrdiff_t>(ends[k]));
    }
    bool same(std::size_t k, const answer_batch& o) const {
        return ends[k] - begin_of(k) == o.ends[k] - o.begin_of(k) &&
               std::equal(values.begin() + static_cast<std::ptrdiff_t>(begin_of(k)),
                          values.begin() + static_cast<std::ptrdiff_t>(ends[k]),
                          o.values.begin() + static_cast<std::ptrdiff_t>(o.begin_of(k)));
    }
};

/// An answer as text: [1, 2, 3], cut after `limit` values.
inline std::string answer_text(const answer& a, std::size_t limit = 24) {
    std::string s = "[";
    for (std::size_t i = 0; i < a.size() && i < limit; ++i) s += (i ? ", " : "") + std::to_string(a[i]);
    if (a.size() > limit) s += ", ... (" + std::to_string(a.size()) + " values)";
    return s + "]";
}

/// A double as %.17g: it reads back to the same double.
inline std::string exact_text(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

/// A pose as text: (tx, ty, theta).
inline std::string pose_text(const pose& p) {
    return "(" + exact_text(p.tx) + ", " + exact_text(p.ty) + ", " + exact_text(p.theta) + ")";
}

/// The question of a decision as text.
inline std::string question_text(decision_kind k, const query& q) {
    if (asks_point(k)) return "point (" + exact_text(q.at.x) + ", " + exact_text(q.at.y) + ")";
    return "pose " + pose_text(q.placement);
}

/// The question of a query as text: a pose (the separation; motion.from), a
/// translation or a turn (in the query's model).
inline std::string question_text(query_kind k, const translation& motion) {
    if (k == query_kind::separation) return "pose " + pose_text(motion.from);
    const std::string span = "from " + pose_text(motion.from) + " to " + pose_text(motion.to);
    if (k == query_kind::first_contact) return "translation " + span;
    return std::string(k == query_kind::turning_rational ? "rational" : "angle-linear") + " turn " + span;
}

// --- Reproducible cases ---------------------------------------------------

/// A pose as JSON: {"tx": ..., "ty": ..., "theta": ...}, each %.17g.
inline std::string pose_json(const pose& p) {
    return "{\"tx\": " + exact_text(p.tx) + ", \"ty\": " + exact_text(p.ty) + ", \"theta\": " + exact_text(p.theta) +
           "}";
}

/// The first lines of a reproducible case: what was asked (`key`: decision
/// or query), of which type, on which polygons.
inline std::string regression_head(const std::string& key, const std::string& asked, const std::string& number_type,
                                   const polygon& a, const polygon& b) {
    return "{\n  \"" + key + "\": \"" + asked + "\",\n  \"number_type\": \"" + number_type + "\",\n  \"static\": \"" +
           to_wkt(a) + "\",\n  \"moving\": \"" + to_wkt(b) + "\",\n";
}

/// The JSON text of a reproducible case (format: data/regressions/README.md).
inline std::string regression_json(const polygon& a, const polygon& b, double distance, decision_kind k, const query& q,
                                   const std::string& number_type, const answer& expected, const answer& got) {
    const auto list = [](const answer& v) {
        std::string s = "[";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
        return s + "]";
    };
    std::string s = regression_head("decision", decision_name(k), number_type, a, b);
    s += "  \"distance\": " + exact_text(distance) + ",\n";
    if (asks_point(k))
        s += "  \"point\": {\"x\": " + exact_text(q.at.x) + ", \"y\": " + exact_text(q.at.y) + "},\n";
    else
        s += "  \"pose\": " + pose_json(q.placement) + ",\n";
    s += "  \"expected\": " + list(expected) + ",\n";
    s += "  \"got\": " + list(got) + "\n}\n";
    return s;
}

/// The JSON text of a reproducible case of a query: its pose (the
/// separation) or translation, the exact answer and the type's, as text.
inline std::string query_regression_json(const polygon& a, const polygon& b, query_kind k, const translation& motion,
                                         const std::string& number_type, const std::string& expected,
                                         const std::string& got) {
    std::string s = regression_head("query", query_name(k), number_type, a, b);
    if (k == query_kind::separation)
        s += "  \"pose\": " + pose_json(motion.from) + ",\n";
    else
        s += "  \"from\": " + pose_json(motion.from) + ",\n  \"to\": " + pose_json(motion.to) + ",\n";
    s += "  \"expected\": " + nlohmann::json(expected).dump() + ",\n";
    s += "  \"got\": " + nlohmann::json(got).dump() + "\n}\n";
    return s;
}

/// A reproducible case read back: of a decision, or of a query (`asked`).
struct regression_case {
    decision_kind decision{};
    std::optional<query_kind> asked;  ///< the query, for a query's case
    std::string number_type;
    polygon a, b;
    double distance = 0;
    query question;
    answer expected;
    translation motion;         ///< a query's question: its pose (motion.from) or translation
    std::string expected_text;  ///< a query's exact answer as text
};

inline pose parse_pose(const nlohmann::json& j) {
    return {j.at("tx").get<double>(), j.at("ty").get<double>(), j.at("theta").get<double>()};
}

/// A query's reproducible case (its "query" key read as `kind`).
inline regression_case parse_query_regression(const nlohmann::json& j, query_kind kind, const std::string& source) {
    regression_case r;
    r.asked = kind;
    r.number_type = j.at("number_type").get<std::string>();
    r.a = read_wkt(j.at("static").get<std::string>(), source + ": static");
    r.b = read_wkt(j.at("moving").get<std::string>(), source + ": moving");
    if (kind == query_kind::separation)
        r.motion = {parse_pose(j.at("pose")), parse_pose(j.at("pose"))};
    else
        r.motion = {parse_pose(j.at("from")), parse_pose(j.at("to"))};
    r.expected_text = j.at("expected").get<std::string>();
    return r;
}

inline regression_case parse_regression(const std::string& text, const std::string& source) {
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        if (j.contains("query")) {
            const auto kind = query_from_name(j.at("query").get<std::string>());
            if (!kind) throw std::runtime_error("unknown query " + j.at("query").get<std::string>());
            return parse_query_regression(j, *kind, source);
        }
        regression_case r;
        const auto kind = decision_from_name(j.at("decision").get<std::string>());
        if (!kind) throw std::runtime_error("unknown decision " + j.at("decision").get<std::string>());
        r.decision = *kind;
        r.number_type = j.at("number_type").get<std::string>();
        r.a = read_wkt(j.at("static").get<std::string>(), source + ": static");
        r.b = read_wkt(j.at("moving").get<std::string>(), source + ": moving");
        r.distance = j.at("distance").get<double>();
        if (asks_point(r.decision))
            r.question.at = {j.at("point").at("x").get<double>(), j.at("point").at("y").get<double>()};
        else
            r.question.placement = parse_pose(j.at("pose"));
        r.expected = j.at("expected").get<answer>();
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(source + ": " + e.what());
    }
}

/// The outcome of answering a reproducible case again.
struct replay_outcome {
    bool reference_agrees = true;          ///< the reference still gives `expected`
    std::vector<std::string> disagreeing;  ///< exact-claiming types whose answer differs
};

/// Answers the case again with the reference and with every number type of
/// `Modes` that claims the exact answer.
template <class... Modes>
replay_outcome replay_regression(const regression_case& r, mode_list<Modes...>) {
    replay_outcome out;
    if (r.asked) {
        out.reference_agrees = exact_answer_text(r.a, r.b, *r.asked, r.motion) == r.expected_text;
        const auto check = [&](auto mode) {
            using M = decltype(mode);
            if constexpr (M::claims_exact)
                if (fresh_answer<typename M::route_type>(r.a, r.b, *r.asked, r.motion).first.differs())
                    out.disagreeing.push_back(M::name());
        };
        (check(Modes{}), ...);
        return out;
    }
    out.reference_agrees = reference_decisions(r.a, r.b, r.distance).decide(r.decision, r.question) == r.expected;
    const auto check = [&](auto mode) {
        using M = decltype(mode);
        if constexpr (M::claims_exact) {
            typename M::evaluator_type ev(r.a, r.b, r.distance);
            if (ev.decide(r.decision, r.question) != r.expected) out.disagreeing.push_back(M::name());
        }
    };
    (check(Modes{}), ...);
    return out;
}

inline replay_outcome replay_regression(const regression_case& r) { return replay_regression(r, study_modes{}); }

// --- The study ------------------------------------------------------------

/// Where a run is: scene `scene` of `scenes` of family `family` of `families`
/// (counted from 0; family == families at the end).
struct study_progress {
    std::size_t family = 0, families = 0, scene = 0, scenes = 0;
    std::string name;
};

struct study_options {
    std::vector<std::string> families = default_study_families();
    std::vector<std::string> types;        ///< empty: every type of the list
    std::vector<decision_kind> decisions;  ///< empty: every decision kind
    std::size_t cases = 2;                 ///< scenes per family (per magnitude for a sweep)
    /// The scenes of each family run: those numbered [first_scene,
    /// end_scene) in make_study_cases' order (the others are made, not run).
    /// A scene starts with fresh evaluators, so a family's scenes can run
    /// apart and their counts be summed.
    std::size_t first_scene = 0;
    std::size_t end_scene = std::numeric_limits<std::size_t>::max();
    std::size_t frames = 100;  ///< poses and query points per scene
    std::uint64_t seed = 20040202;
    std::size_t examples = 3;  ///< disagreements kept per type and decision (or query)
    /// The queries asked (separation, first contact); empty: none.
    std::vector<query_kind> queries{std::begin(all_query_kinds), std::end(all_query_kinds)};
    std::size_t query_frames = 128;  ///< questions per scene for each query (at most `frames`)
    /// The image-space baseline (verification/raster.hpp) at each of these
    /// resolutions, asked the `collides` questions of every scene with d = 0
    /// (it has no distance test); empty: not asked.
    std::vector<std::size_t> raster_resolutions = default_raster_resolutions();
    std::string regressions_dir;  ///< where reproducible cases go; empty: not written
    std::function<void(const study_progress&)> progress;
};

struct decision_tally {
    std::size_t cases = 0, disagreements = 0;
    double nanoseconds = 0;
    double rate() const { return cases ? static_cast<double>(disagreements) / static_cast<double>(cases) : 0; }
    double ns_per_query() const { return cases ? nanoseconds / static_cast<double>(cases) : 0; }
};

/// The image-space baseline's answers to the `collides` questions at one
/// resolution: contacts it missed, contacts it invented, and its time.
struct raster_tally {
    std::size_t questions = 0, missed = 0, invented = 0;
    double nanoseconds = 0;
    std::size_t wrong() const { return missed + invented; }
    double rate() const { return questions ? static_cast<double>(wrong()) / static_cast<double>(questions) : 0; }
    double ns_per_question() const { return questions ? nanoseconds / static_cast<double>(questions) : 0; }
    void merge(const raster_tally& o) {
        questions += o.questions;
        missed += o.missed;
        invented += o.invented;
        nanoseconds += o.nanoseconds;
    }
};

/// One line of raster.csv.
struct raster_row {
    std::size_t resolution = 0;
    std::string family;
    raster_tally tally;
};

/// One line of study.csv.
struct study_row {
    std::string number_type, family, decision;
    decision_tally tally;
};

/// The answers of one type to one query: how many differ from the exact
/// ones, and how, the error of each measured value, and the time.
struct query_tally {
    std::size_t questions = 0;
    std::size_t differing = 0;        ///< answers differing in any way below
    std::size_t meeting_differs = 0;  ///< meet (separation) or contact (first contact) or not
    std::size_t features_differ = 0;  ///< the closest (first) features
    std::size_t values_differ = 0;    ///< not the value a type claiming exactness claims
    std::vector<double> errors;       ///< relative distance errors, absolute time errors
    double nanoseconds = 0;

    void add(const query_outcome& o) {
        ++questions;
        differing += o.differs() ? 1 : 0;
        meeting_differs += o.meeting_differs ? 1 : 0;
        features_differ += o.features_differ ? 1 : 0;
        values_differ += o.value_differs ? 1 : 0;
        if (o.error) errors.push_back(*o.error);
    }
    void merge(const query_tally& o) {
        questions += o.questions;
        differing += o.differing;
        meeting_differs += o.meeting_differs;
        features_differ += o.features_differ;
        values_differ += o.values_differ;
        errors.insert(errors.end(), o.errors.begin(), o.errors.end());
        nanoseconds += o.nanoseconds;
    }
    std::optional<double> largest_error() const {
        if (errors.empty()) return std::nullopt;
        return *std::max_element(errors.begin(), errors.end());
    }
    /// The lower median.
    std::optional<double> median_error() const {
        if (errors.empty()) return std::nullopt;
        std::vector<double> e = errors;
        const auto mid = e.begin() + static_cast<std::ptrdiff_t>((e.size() - 1) / 2);
        std::nth_element(e.begin(), mid, e.end());
        return *mid;
    }
    double ns_per_question() const { return questions ? nanoseconds / static_cast<double>(questions) : 0; }
};

/// One line of queries.csv.
struct query_row {
    std::string number_type, family, query;
    query_tally tally;
};

/// One line of stability.csv: every decision of a sweep's magnitude pooled.
struct stability_row {
    std::string number_type, sweep;
    double magnitude = 0;
    decision_tally tally;
};

struct study_example {
    std::string number_type, family, decision, scene, question, got, expected;
};

struct type_summary {
    std::string number_type;
    bool claims_exact = false;
    bool has_fallback = false;
    std::size_t questions = 0;
    std::size_t fallbacks = 0;             ///< questions answered by the fallback type
    std::size_t setup_fallbacks = 0;       ///< scenes that could not be set up in the type itself
    std::size_t refused_scenes = 0;        ///< scenes beyond the type's range (float): not asked
    std::size_t refused_query_scenes = 0;  ///< the same for the queries
};

struct study_result {
    std::vector<std::string> families, types;
    std::vector<study_row> rows;
    std::vector<query_row> query_rows;
    std::vector<stability_row> stability;
    std::vector<raster_row> raster_rows;
    std::vector<study_example> examples;
    std::vector<type_summary> summaries;
    std::vector<std::string> regressions;  ///< files written
    std::size_t cases = 0;
    double seconds = 0;
};

template <class... Modes>
class study_runner {
public:
    explicit study_runner(study_options o) : o_(std::move(o)) {
        const std::vector<std::string> all = mode_names(mode_list<Modes...>{});
        if (o_.types.empty()) o_.types = all;
        for (const std::string& t : o_.types)
            if (std::find(all.begin(), all.end(), t) == all.end())
                throw std::invalid_argument("unknown number type: " + t);
        selected_ = {std::find(o_.types.begin(), o_.types.end(), Modes::name()) != o_.types.end()...};
        for (std::size_t d = 0; d < kinds; ++d)
            if (o_.decisions.empty() ||
                std::find(o_.decisions.begin(), o_.decisions.end(), all_decision_kinds[d]) != o_.decisions.end())
                asked_.push_back(d);
        summaries_ = {
            type_summary{Modes::name(), Modes::claims_exact, Modes::evaluator_type::has_fallback, 0, 0, 0, 0, 0}...};
    }

    study_result run() {
        const auto start = std::chrono::steady_clock::now();
        std::size_t scenes = 0;
        const std::size_t families = o_.families.size();
        for (std::size_t f = 0; f < families; ++f) {
            // One family at a time: a long run keeps only its poses in memory.
            const std::size_t frames =
                o_.families[f] == stiff_family_name(stiff_family::large) && !only_per_frame_decisions()
                    ? std::min(o_.frames, large_frames)
                    : o_.frames;
            const std::vector<study_case> cases = make_study_cases(o_.families[f], o_.cases, frames, o_.seed);
            const std::size_t end = std::min(o_.end_scene, cases.size());
            for (std::size_t k = std::min(o_.first_scene, end); k < end; ++k) {
                if (o_.progress) o_.progress({f, families, k, cases.size(), o_.families[f]});
                run_case(cases[k], std::index_sequence_for<Modes...>{});
                run_queries(cases[k], std::index_sequence_for<Modes...>{});
                ++scenes;
            }
        }
        if (o_.progress) o_.progress({families, families, 0, 0, ""});
        study_result r = collect();
        r.cases = scenes;
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return r;
    }

private:
    static constexpr std::size_t kinds = std::size(all_decision_kinds);
    /// Poses per scene of `large` when a decision over all its edges is asked
    /// (alpha selection, candidates, pairs, brute force): each costs seconds
    /// per frame in the slow types.
    static constexpr std::size_t large_frames = 16;

    bool only_per_frame_decisions() const {
        return std::all_of(asked_.begin(), asked_.end(), [](std::size_t d) {
            const decision_kind k = all_decision_kinds[d];
            return k == decision_kind::cone_membership || k == decision_kind::mask || k == decision_kind::containment ||
                   k == decision_kind::collides;
        });
    }
    static constexpr std::size_t chunk = 128;

    template <std::size_t... I>
    void run_case(const study_case& c, std::index_sequence<I...>) {
        reference_decisions ref(c.a, c.b, c.distance);
        std::tuple<std::optional<typename Modes::evaluator_type>...> evaluators;
        ((selected_[I] ? set_up(I, std::get<I>(evaluators), c) : void()), ...);
        std::vector<answer_batch> expected(kinds);
        answer_batch got;
        std::vector<query> questions;
        std::vector<raster_test> rasters;
        if (c.distance == 0 && asks(decision_kind::collides))
            for (std::size_t resolution : o_.raster_resolutions) rasters.emplace_back(c.a, c.b, resolution);
        const std::size_t n = std::min(c.points.size(), c.poses.size());
        for (std::size_t first = 0; first < n; first += chunk) {
            questions.clear();
            for (std::size_t k = first; k < std::min(n, first + chunk); ++k)
                questions.push_back({c.points[k], c.poses[k]});
            for (std::size_t d : asked_) {
                expected[d].clear();
                for (const query& q : questions) {
                    ref.decide(all_decision_kinds[d], q, expected[d].values);
                    expected[d].close();
                }
            }
            (run_mode<Modes>(I, std::get<I>(evaluators), c, questions, expected, got), ...);
            for (std::size_t k = 0; k < rasters.size(); ++k)
                run_raster(o_.raster_resolutions[k], rasters[k], c, questions,
                           expected[index_of(decision_kind::collides)]);
        }
        ((std::get<I>(evaluators) ? add_fallbacks(I, *std::get<I>(evaluators)) : void()), ...);
    }

    template <class Mode, class Evaluator>
    void run_mode(std::size_t m, std::optional<Evaluator>& ev, const study_case& c, const std::vector<query>& questions,
                  const std::vector<answer_batch>& expected, answer_batch& got) {
        if (!ev) return;
        for (std::size_t d : asked_) {
            const decision_kind kind = all_decision_kinds[d];
            got.clear();
            const auto t0 = std::chrono::steady_clock::now();
            for (const query& q : questions) {
                ev->decide(kind, q, got.values);
                got.close();
            }
            const auto t1 = std::chrono::steady_clock::now();
            decision_tally& t = tallies_[{m, c.family, d}];
            decision_tally* s = c.sweep.empty() ? nullptr : &stability_[{m, c.sweep, c.magnitude}];
            t.nanoseconds += std::chrono::duration<double, std::nano>(t1 - t0).count();
            t.cases += questions.size();
            if (s) s->cases += questions.size();
            summaries_[m].questions += questions.size();
            for (std::size_t k = 0; k < questions.size(); ++k) {
                if (got.same(k, expected[d])) continue;
                ++t.disagreements;
                if (s) ++s->disagreements;
                if (examples_[{m, d}]++ < o_.examples)
                    example_list_.push_back({Mode::name(), c.family, decision_name(kind), c.scene,
                                             question_text(kind, questions[k]), answer_text(got.get(k)),
                                             answer_text(expected[d].get(k))});
                if (Mode::claims_exact && !o_.regressions_dir.empty()) write_regression<Mode>(c, kind, questions[k]);
            }
        }
    }

    bool asks(decision_kind k) const { return std::find(asked_.begin(), asked_.end(), index_of(k)) != asked_.end(); }
    static std::size_t index_of(decision_kind k) {
        return static_cast<std::size_t>(std::find(std::begin(all_decision_kinds), std::end(all_decision_kinds), k) -
                                        std::begin(all_decision_kinds));
    }

    /// The image-space baseline's answers to a chunk of `collides` questions,
    /// timed, each compared with the exact answer.
    void run_raster(std::size_t resolution, raster_test& raster, const study_case& c,
                    const std::vector<query>& questions, const answer_batch& expected) {
        std::vector<char> got(questions.size());
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t k = 0; k < questions.size(); ++k) got[k] = raster.collide(questions[k].placement) ? 1 : 0;
        const auto t1 = std::chrono::steady_clock::now();
        raster_tally& t = raster_tallies_[{resolution, c.family}];
        t.nanoseconds += std::chrono::duration<double, std::nano>(t1 - t0).count();
        t.questions += questions.size();
        for (std::size_t k = 0; k < questions.size(); ++k) {
            const bool want = expected.get(k) == answer{1};
            t.missed += want && !got[k] ? 1 : 0;
            t.invented += !want && got[k] ? 1 : 0;
        }
    }

    static constexpr std::size_t query_chunk = 16;

    /// The queries of one scene, each on its first query_frames poses (and as
    /// many translations between them): per chunk of questions, the exact
    /// answers (not timed), then every type's, timed and compared.
    template <std::size_t... I>
    void run_queries(const study_case& c, std::index_sequence<I...>) {
        if (o_.queries.empty()) return;
        const std::size_t n = std::min(c.poses.size(), query_questions(c));
        const std::vector<translation> translations = study_translations(c.a, c.b, c.poses, n);
        const std::vector<translation> turns = study_turns(c.a, c.b, c.poses, n);
        query_reference exact(c.a, c.b);
        std::tuple<std::optional<typename Modes::route_type>...> routes;
        ((selected_[I] ? set_up_route(I, std::get<I>(routes), c) : void()), ...);
        std::vector<translation> questions;
        for (query_kind k : o_.queries)
            for (std::size_t first = 0; first < n; first += query_chunk) {
                const std::size_t last = std::min(n, first + query_chunk);
                if (k == query_kind::separation) {
                    questions.clear();
                    std::vector<separation_result<exact_rational>> expected;
                    for (std::size_t i = first; i < last; ++i) {
                        questions.push_back({c.poses[i], c.poses[i]});
                        expected.push_back(exact.separation(c.poses[i]));
                    }
                    (ask<Modes>(I, std::get<I>(routes), c, k, questions, expected), ...);
                } else {
                    const std::vector<translation>& motions = asks_turn(k) ? turns : translations;
                    questions.assign(motions.begin() + static_cast<std::ptrdiff_t>(first),
                                     motions.begin() + static_cast<std::ptrdiff_t>(last));
                    std::vector<contact_result<exact_rational>> expected;
                    for (const translation& m : questions) expected.push_back(exact.first_contact(m, k));
                    (ask<Modes>(I, std::get<I>(routes), c, k, questions, expected), ...);
                }
            }
    }

    /// Questions per scene for each query: query_frames, at most
    /// large_frames on `large`.
    std::size_t query_questions(const study_case& c) const {
        return c.family == stiff_family_name(stiff_family::large) ? std::min(o_.query_frames, large_frames)
                                                                  : o_.query_frames;
    }

    /// One type's answers to a chunk of one query's questions (a separation's
    /// pose is motion.from), timed, each compared with the exact answer.
    template <class Mode, class Route, class Exact>
    void ask(std::size_t m, std::optional<Route>& route, const study_case& c, query_kind k,
             const std::vector<translation>& questions, const std::vector<Exact>& expected) {
        if (!route) return;
        const auto answer_of = [&](const translation& q) {
            if constexpr (std::is_same_v<Exact, separation_result<exact_rational>>)
                return route->separation(q.from);
            else
                return route->first_contact(q, k);
        };
        std::vector<decltype(answer_of(questions.front()))> got;
        got.reserve(questions.size());
        const auto t0 = std::chrono::steady_clock::now();
        for (const translation& q : questions) got.push_back(answer_of(q));
        const auto t1 = std::chrono::steady_clock::now();
        query_tally& t = query_tallies_[{m, c.family, k}];
        t.nanoseconds += std::chrono::duration<double, std::nano>(t1 - t0).count();
        for (std::size_t i = 0; i < questions.size(); ++i) {
            const query_outcome o = compare_answer(got[i], expected[i], Route::claim);
            t.add(o);
            if (!o.differs()) continue;
            if (examples_[{m, kinds + static_cast<std::size_t>(k)}]++ < o_.examples)
                example_list_.push_back({Mode::name(), c.family, query_name(k), c.scene, question_text(k, questions[i]),
                                         answer_text(got[i]), answer_text(expected[i])});
            if (Mode::claims_exact && !o_.regressions_dir.empty()) write_query_regression<Mode>(c, k, questions[i]);
        }
    }

    /// Builds a type's route for the scene's queries; a type that refuses the
    /// scene (coordinates beyond float's range) is not asked.
    template <class Route>
    void set_up_route(std::size_t m, std::optional<Route>& route, const study_case& c) {
        try {
            route.emplace(c.a, c.b);
        } catch (const invalid_input&) {
            route.reset();
            ++summaries_[m].refused_query_scenes;
        }
    }

    /// Builds a type's evaluator for the scene; a type that refuses the scene
    /// (coordinates beyond float's range) is not asked its questions.
    template <class Evaluator>
    void set_up(std::size_t m, std::optional<Evaluator>& ev, const study_case& c) {
        try {
            ev.emplace(c.a, c.b, c.distance);
        } catch (const invalid_input&) {
            ev.reset();
            ++summaries_[m].refused_scenes;
        }
    }

    template <class Evaluator>
    void add_fallbacks(std::size_t m, const Evaluator& ev) {
        summaries_[m].fallbacks += ev.fallbacks();
        summaries_[m].setup_fallbacks += ev.setup_fell_back() ? 1 : 0;
    }

    /// Writes the disagreement as a reproducible case on A and B as read back
    /// from their WKT (whose edge numbers are the stored ones), with the
    /// expected and the obtained answers of that single question.
    template <class Mode>
    void write_regression(const study_case& c, decision_kind kind, const query& q) {
        const polygon a = read_wkt(to_wkt(c.a)), b = read_wkt(to_wkt(c.b));
        const answer expected = reference_decisions(a, b, c.distance).decide(kind, q);
        const answer got = typename Mode::evaluator_type(a, b, c.distance).decide(kind, q);
        keep_regression(decision_name(kind), Mode::name(),
                        regression_json(a, b, c.distance, kind, q, Mode::name(), expected, got));
    }

    /// The same for a query's question, answered alone by fresh objects.
    template <class Mode>
    void write_query_regression(const study_case& c, query_kind k, const translation& motion) {
        const polygon a = read_wkt(to_wkt(c.a)), b = read_wkt(to_wkt(c.b));
        const std::string got = fresh_answer<typename Mode::route_type>(a, b, k, motion).second;
        keep_regression(query_name(k), Mode::name(),
                        query_regression_json(a, b, k, motion, Mode::name(), exact_answer_text(a, b, k, motion), got));
    }

    /// Writes a reproducible case to regressions_dir as
    /// <asked>-<number type>-<hash of the text>.json.
    void keep_regression(const std::string& asked, const std::string& number_type, const std::string& text) {
        char name[32];  // the same case gets the same name
        std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(fnv1a(text)));
        const std::filesystem::path dir(o_.regressions_dir);
        std::filesystem::create_directories(dir);
        const std::filesystem::path path = dir / (asked + "-" + number_type + "-" + name + ".json");
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out) throw std::runtime_error(path.string() + ": cannot write");
        if (std::find(regressions_.begin(), regressions_.end(), path.string()) == regressions_.end())
            regressions_.push_back(path.string());
    }

    study_result collect() const {
        study_result r;
        r.families = o_.families;
        const std::vector<std::string> names = mode_names(mode_list<Modes...>{});
        for (std::size_t m = 0; m < names.size(); ++m) {
            if (!selected_[m]) continue;
            r.types.push_back(names[m]);
            r.summaries.push_back(summaries_[m]);
            for (const std::string& f : o_.families)
                for (std::size_t d = 0; d < kinds; ++d) {
                    const auto it = tallies_.find({m, f, d});
                    if (it != tallies_.end())
                        r.rows.push_back({names[m], f, decision_name(all_decision_kinds[d]), it->second});
                }
            for (const std::string& f : o_.families)
                for (query_kind k : all_query_kinds) {
                    const auto it = query_tallies_.find({m, f, k});
                    if (it != query_tallies_.end()) r.query_rows.push_back({names[m], f, query_name(k), it->second});
                }
            for (const auto& [key, t] : stability_)
                if (std::get<0>(key) == m) r.stability.push_back({names[m], std::get<1>(key), std::get<2>(key), t});
        }
        for (std::size_t resolution : o_.raster_resolutions)
            for (const std::string& f : o_.families) {
                const auto it = raster_tallies_.find({resolution, f});
                if (it != raster_tallies_.end()) r.raster_rows.push_back({resolution, f, it->second});
            }
        r.examples = example_list_;
        r.regressions = regressions_;
        return r;
    }

    study_options o_;
    std::vector<bool> selected_;
    std::vector<std::size_t> asked_;  ///< indices into all_decision_kinds
    std::vector<type_summary> summaries_;
    std::map<std::tuple<std::size_t, std::string, std::size_t>, decision_tally> tallies_;
    std::map<std::tuple<std::size_t, std::string, query_kind>, query_tally> query_tallies_;
    std::map<std::tuple<std::size_t, std::string, double>, decision_tally> stability_;
    std::map<std::pair<std::size_t, std::string>, raster_tally> raster_tallies_;
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> examples_;
    std::vector<study_example> example_list_;
    std::vector<std::string> regressions_;
};

/// Runs the study over the number types of `Modes`.
template <class... Modes>
study_result run_study(const study_options& o, mode_list<Modes...>) {
    return study_runner<Modes...>(o).run();
}

inline study_result run_study(const study_options& o) { return run_study(o, study_modes{}); }

}  // namespace influence2d::verification
