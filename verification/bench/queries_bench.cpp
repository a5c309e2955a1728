// SPDX-License-Identifier: BSL-1.0
// (d) The queries beyond yes or no, against the peers that offer them, on the
// same inputs:
//   separation/<method>/<cell>   the distance between the closed regions at
//       random poses near contact (the time study's random workload: B's
//       centroid uniform in the annulus 0.4 to 1.1 times R_A + R_B, any
//       angle); influence2d's separation_query<double> and
//       certified_separation_query (one object over the poses: double, certified),
//       the one-shot separation<double> and certified_separation (both edge
//       trees built per call: double_once, certified_once), GEOS's
//       GEOSDistance_r (A built once, B built posed for each query) and
//       GEOSPreparedDistance_r (A prepared once);
//   first_contact/<method>/<cell>   the first contact along a motion from
//       one random pose to another random pose of the annulus: translations
//       (the angle kept) for influence2d's first_contact<double> and
//       certified_first_contact; on convex 8-gons also Box2D's
//       b2TimeOfImpact (conservative advancement in float, reporting a time
//       where the shapes are within its target separation, a few
//       thousandths, not the contact itself) on the same translations and
//       on motions that turn, with influence2d's first_contact<double> on
//       those too;
//   exit_distance/<method>/<cell>   how far B, at a random pose of the
//       annulus, must move along the direction of that pose's translation
//       motion (above) to leave A: influence2d's exit_distance<double> and
//       certified_exit_distance.
//   tiling/<query>/<method>   North Carolina's counties (data/real/
//       nc_counties.wkt, a tiling whose neighbours share their border
//       vertices exactly), every pair of neighbours (polygons sharing a
//       vertex): separation, B pushed off A along the line from A's centroid
//       to B's by the first of 1e-5, 2e-5, 4e-5, ... degrees that leaves
//       them apart, the one-shot separation<double> and certified_separation;
//       first_contact, B pushed off by 1e-3 degrees and translated back past
//       its place and aside by 0.3 times the push, to either side,
//       first_contact<double> and certified_first_contact;
//       first_contact_straight, the same translated straight back (every
//       shared vertex passes through its twin at once); exit_distance,
//       B pushed into A by 1e-3 degrees and leaving along the push or aside
//       by 0.3 times it, to either side, exit_distance<double> and
//       certified_exit_distance. A shared border moved by a translation
//       stays parallel to itself: exact ties.
// One iteration is one query; the queries cycle through 1,024 poses or
// motions (tiling: through its pairs' poses or motions). Counters:
// max_relative_difference (separation: the largest
// |d - d_GEOS| / max(d_GEOS, 1e-300) over the poses, checked once before
// timing), exact_share (certified separation: the share of poses answered
// in exact rationals), contacts (first contact: the share of motions with
// contact), overlapping (exit distance: the share of poses where the
// regions meet), by_filter (certified exit distance: the share answered by
// the search in certified, without the exact search).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_exit_distance.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/exit_distance.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "verification/peers.hpp"

#if INFLUENCE2D_HAVE_BOX2D
#include <box2d/b2_time_of_impact.h>
#endif

namespace influence2d::bench {
namespace {

struct cell {
    std::string type;
    int static_size, moving_size;
    std::string name() const { return type + "_" + std::to_string(static_size) + "x" + std::to_string(moving_size); }
    const polygon& a() const { return family(type + "_" + std::to_string(static_size)); }
    const polygon& b() const { return family(type + "_" + std::to_string(moving_size)); }
};

const std::vector<cell>& cells() {
    static const std::vector<cell> all = {{"convex", 8, 8},   {"contour", 64, 64},   {"contour", 1024, 8},
                                          {"hole", 1024, 64}, {"starred", 256, 256}, {"irregular", 1024, 1024}};
    return all;
}

constexpr std::size_t query_count = 1024;
constexpr std::uint64_t query_seed = 20040202;

/// The random poses of a cell (the time study's annulus).
std::vector<pose> poses_of(const cell& c, std::uint64_t seed = query_seed) {
    const polygon &a = c.a(), &b = c.b();
    const double r = bounding_radius(a, a.centroid()) + bounding_radius(b, b.centroid());
    return random_poses(a, b, query_count, 0.4 * r, 1.1 * r, seed);
}

/// Motions from one random pose to another; `turning` keeps both angles,
/// else the angle of the start.
std::vector<std::pair<pose, pose>> motions_of(const cell& c, bool turning) {
    const std::vector<pose> from = poses_of(c), to = poses_of(c, query_seed + 1);
    std::vector<std::pair<pose, pose>> m;
    for (std::size_t k = 0; k < from.size(); ++k)
        m.push_back({from[k], turning ? to[k] : pose{to[k].tx, to[k].ty, from[k].theta}});
    return m;
}

void separation_double(benchmark::State& state, const cell& c) {
    const std::vector<pose> poses = poses_of(c);
    separation_query<double> query(c.a(), c.b());
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(query(poses[k]).squared_distance);
        k = (k + 1) % poses.size();
    }
}

void separation_certified(benchmark::State& state, const cell& c) {
    const std::vector<pose> poses = poses_of(c);
    certified_separation_query query(c.a(), c.b());
    std::size_t k = 0, exact = 0, asked = 0;
    for (auto _ : state) {
        const certified_separation_result r = query(poses[k]);
        exact += r.exact_pairs != 0;
        ++asked;
        benchmark::DoNotOptimize(r.distance);
        k = (k + 1) % poses.size();
    }
    state.counters["exact_share"] = static_cast<double>(exact) / static_cast<double>(std::max<std::size_t>(asked, 1));
}

void separation_double_once(benchmark::State& state, const cell& c) {
    const std::vector<pose> poses = poses_of(c);
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(separation<double>(c.a(), c.b(), poses[k]).squared_distance);
        k = (k + 1) % poses.size();
    }
}

void separation_certified_once(benchmark::State& state, const cell& c) {
    const std::vector<pose> poses = poses_of(c);
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(certified_separation(c.a(), c.b(), poses[k]).distance);
        k = (k + 1) % poses.size();
    }
}

void first_contact_double(benchmark::State& state, const cell& c, bool turning,
                          turning_model model = turning_model::angle_linear) {
    const auto motions = motions_of(c, turning);
    const sweep_options options{sweep_options{}.tolerance, model};
    std::size_t k = 0, contacts = 0, asked = 0;
    for (auto _ : state) {
        const auto r = first_contact<double>(c.a(), c.b(), motions[k].first, motions[k].second, options);
        contacts += r.contact;
        ++asked;
        benchmark::DoNotOptimize(r.time);
        k = (k + 1) % motions.size();
    }
    state.counters["contacts"] = static_cast<double>(contacts) / static_cast<double>(std::max<std::size_t>(asked, 1));
}

void first_contact_certified(benchmark::State& state, const cell& c, bool turning = false,
                             turning_model model = turning_model::angle_linear) {
    const auto motions = motions_of(c, turning);
    const sweep_options options{sweep_options{}.tolerance, model};
    std::size_t k = 0, contacts = 0, asked = 0;
    for (auto _ : state) {
        const auto r = certified_first_contact(c.a(), c.b(), motions[k].first, motions[k].second, options);
        contacts += r.contact;
        ++asked;
        benchmark::DoNotOptimize(r.time);
        k = (k + 1) % motions.size();
    }
    state.counters["contacts"] = static_cast<double>(contacts) / static_cast<double>(std::max<std::size_t>(asked, 1));
}

/// The exit distance at the poses of a cell along the directions of its
/// translations, in double or certified.
void exit_distances(benchmark::State& state, const cell& c, bool certified) {
    const std::vector<pose> poses = poses_of(c);
    const auto motions = motions_of(c, false);
    std::size_t k = 0, overlapping = 0, by_filter = 0, asked = 0;
    for (auto _ : state) {
        const double dx = motions[k].second.tx - motions[k].first.tx, dy = motions[k].second.ty - motions[k].first.ty;
        bool filtered = false;
        const double s = certified ? certified_exit_distance(c.a(), c.b(), poses[k], dx, dy, &filtered)
                                   : exit_distance<double>(c.a(), c.b(), poses[k], dx, dy);
        overlapping += s > 0;
        by_filter += filtered;
        ++asked;
        benchmark::DoNotOptimize(s);
        k = (k + 1) % poses.size();
    }
    const double n = static_cast<double>(std::max<std::size_t>(asked, 1));
    state.counters["overlapping"] = static_cast<double>(overlapping) / n;
    if (certified) state.counters["by_filter"] = static_cast<double>(by_filter) / n;
}

/// The tiling: North Carolina's counties and their pairs of neighbours
/// (polygons sharing a vertex), each pair's translation off the shared
/// border (a unit vector along the line between the centroids).
struct tiling {
    std::vector<polygon> counties;
    struct neighbours {
        std::size_t a, b;
        point<double> out;  ///< from A's centroid towards B's, of length 1
    };
    std::vector<neighbours> pairs;

    tiling() {
        const std::string path = std::string(INFLUENCE2D_DATA_DIR) + "/real/nc_counties.wkt";
        std::ifstream in(path);
        for (std::string line; std::getline(in, line);)
            if (!line.empty()) counties.push_back(read_wkt(line, path));
        std::vector<std::vector<std::pair<double, double>>> vertices(counties.size());
        for (std::size_t i = 0; i < counties.size(); ++i) {
            for (const point<double>& v : counties[i].vertices()) vertices[i].push_back({v.x, v.y});
            std::sort(vertices[i].begin(), vertices[i].end());
        }
        for (std::size_t i = 0; i < counties.size(); ++i)
            for (std::size_t j = i + 1; j < counties.size(); ++j) {
                std::vector<std::pair<double, double>> common;
                std::set_intersection(vertices[i].begin(), vertices[i].end(), vertices[j].begin(), vertices[j].end(),
                                      std::back_inserter(common));
                if (common.empty()) continue;
                const point<double> ca = counties[i].centroid(), cb = counties[j].centroid();
                const double length = std::hypot(cb.x - ca.x, cb.y - ca.y);
                pairs.push_back({i, j, {(cb.x - ca.x) / length, (cb.y - ca.y) / length}});
            }
    }
    static const tiling& get() {
        static const tiling t;
        return t;
    }
};

/// The tiling's separation queries: each pair of neighbours with B pushed
/// off A by the first of 1e-5 2^k degrees that leaves them apart.
std::vector<std::pair<std::size_t, pose>> tiling_apart() {
    const tiling& t = tiling::get();
    std::vector<std::pair<std::size_t, pose>> out;
    for (std::size_t k = 0; k < t.pairs.size(); ++k) {
        const auto& n = t.pairs[k];
        for (double push = 1e-5; push < 8; push *= 2) {
            const pose q{n.out.x * push, n.out.y * push, 0};
            if (separation<exact_rational>(t.counties[n.a], t.counties[n.b], q).meet()) continue;
            out.push_back({k, q});
            break;
        }
    }
    return out;
}

void tiling_separation(benchmark::State& state, bool certified) {
    const tiling& t = tiling::get();
    const std::vector<std::pair<std::size_t, pose>> queries = tiling_apart();
    std::size_t k = 0, exact = 0, asked = 0;
    for (auto _ : state) {
        const auto& [i, q] = queries[k];
        const polygon &a = t.counties[t.pairs[i].a], &b = t.counties[t.pairs[i].b];
        if (certified) {
            const certified_separation_result r = certified_separation(a, b, q);
            exact += r.exact_pairs != 0;
            benchmark::DoNotOptimize(r.distance);
        } else {
            benchmark::DoNotOptimize(separation<double>(a, b, q).squared_distance);
        }
        ++asked;
        k = (k + 1) % queries.size();
    }
    if (certified)
        state.counters["exact_share"] =
            static_cast<double>(exact) / static_cast<double>(std::max<std::size_t>(asked, 1));
}

void tiling_first_contact(benchmark::State& state, bool certified, bool straight) {
    const tiling& t = tiling::get();
    std::vector<std::tuple<std::size_t, pose, pose>> motions;
    const double push = 1e-3;
    for (std::size_t k = 0; k < t.pairs.size(); ++k)
        for (const double aside : straight ? std::vector<double>{0.0} : std::vector<double>{0.3, -0.3}) {
            const point<double> o{t.pairs[k].out.x * push, t.pairs[k].out.y * push};
            motions.emplace_back(k, pose{o.x, o.y, 0}, pose{-o.x - aside * o.y, -o.y + aside * o.x, 0});
        }
    std::size_t k = 0;
    for (auto _ : state) {
        const auto& [i, from, to] = motions[k];
        const polygon &a = t.counties[t.pairs[i].a], &b = t.counties[t.pairs[i].b];
        benchmark::DoNotOptimize(certified ? certified_first_contact(a, b, from, to).time
                                           : first_contact<double>(a, b, from, to).time);
        k = (k + 1) % motions.size();
    }
}

void tiling_exit_distance(benchmark::State& state, bool certified) {
    const tiling& t = tiling::get();
    std::vector<std::tuple<std::size_t, pose, point<double>>> queries;
    const double push = 1e-3;
    for (std::size_t k = 0; k < t.pairs.size(); ++k)
        for (const double aside : {0.0, 0.3, -0.3}) {
            const point<double> o{t.pairs[k].out.x * push, t.pairs[k].out.y * push};
            queries.emplace_back(k, pose{-o.x, -o.y, 0}, point<double>{o.x - aside * o.y, o.y + aside * o.x});
        }
    std::size_t k = 0, by_filter = 0, asked = 0;
    for (auto _ : state) {
        const auto& [i, q, d] = queries[k];
        const polygon &a = t.counties[t.pairs[i].a], &b = t.counties[t.pairs[i].b];
        if (certified) {
            bool filtered = false;
            benchmark::DoNotOptimize(certified_exit_distance(a, b, q, d.x, d.y, &filtered));
            by_filter += filtered ? 1 : 0;
        } else {
            benchmark::DoNotOptimize(exit_distance<double>(a, b, q, d.x, d.y));
        }
        ++asked;
        k = (k + 1) % queries.size();
    }
    if (certified)
        state.counters["by_filter"] =
            static_cast<double>(by_filter) / static_cast<double>(std::max<std::size_t>(asked, 1));
}

#if INFLUENCE2D_HAVE_GEOS
/// GEOS's distance, A built (and prepared) once, B built posed per query.
class geos_distance {
public:
    explicit geos_distance(const cell& c) : b_rings_(verification::peer_rings(c.b())) {
        a_ = g_.make(verification::peer_rings(c.a()), rotation_pose(pose{}));
        prepared_ = GEOSPrepare_r(g_.ctx, a_);
    }
    geos_distance(const geos_distance&) = delete;
    geos_distance& operator=(const geos_distance&) = delete;
    ~geos_distance() {
        GEOSPreparedGeom_destroy_r(g_.ctx, prepared_);
        GEOSGeom_destroy_r(g_.ctx, a_);
    }
    double operator()(const pose& p, bool prepared) {
        GEOSGeometry* b = g_.make(b_rings_, rotation_pose(p));
        double d = -1;
        const int ok = prepared ? GEOSPreparedDistance_r(g_.ctx, prepared_, b, &d) : GEOSDistance_r(g_.ctx, a_, b, &d);
        GEOSGeom_destroy_r(g_.ctx, b);
        if (!ok) throw std::runtime_error("geos: distance failed: " + g_.error);
        return d;
    }

private:
    verification::geos_builder g_;
    std::vector<std::vector<point<double>>> b_rings_;
    GEOSGeometry* a_ = nullptr;
    const GEOSPreparedGeometry* prepared_ = nullptr;
};

void separation_geos(benchmark::State& state, const cell& c, bool prepared) {
    const std::vector<pose> poses = poses_of(c);
    geos_distance geos(c);
    separation_query<double> ours(c.a(), c.b());
    double worst = 0;
    for (const pose& p : poses) {
        const double g = geos(p, prepared), d = distance_of<double>(ours(p).squared_distance);
        worst = std::max(worst, std::fabs(d - g) / std::max(g, 1e-300));
    }
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(geos(poses[k], prepared));
        k = (k + 1) % poses.size();
    }
    state.counters["max_relative_difference"] = worst;
}
#endif

#if INFLUENCE2D_HAVE_BOX2D
void first_contact_box2d(benchmark::State& state, const cell& c, bool turning) {
    const b2PolygonShape a = verification::box2d_peer::shape(verification::box2d_peer::vertices(c.a()));
    const b2PolygonShape b = verification::box2d_peer::shape(verification::box2d_peer::vertices(c.b()));
    b2TOIInput in;
    in.proxyA.Set(&a, 0);
    in.proxyB.Set(&b, 0);
    in.sweepA.localCenter.SetZero();
    in.sweepA.c0.SetZero();
    in.sweepA.c.SetZero();
    in.sweepA.a0 = in.sweepA.a = 0;
    in.sweepA.alpha0 = 0;
    in.sweepB.localCenter.SetZero();
    in.sweepB.alpha0 = 0;
    in.tMax = 1;
    const auto motions = motions_of(c, turning);
    std::size_t k = 0, contacts = 0, asked = 0;
    for (auto _ : state) {
        const pose &p0 = motions[k].first, &p1 = motions[k].second;
        in.sweepB.c0.Set(static_cast<float>(p0.tx), static_cast<float>(p0.ty));
        in.sweepB.c.Set(static_cast<float>(p1.tx), static_cast<float>(p1.ty));
        in.sweepB.a0 = static_cast<float>(p0.theta);
        in.sweepB.a = static_cast<float>(p1.theta);
        b2TOIOutput out;
        b2TimeOfImpact(&out, &in);
        contacts += out.state == b2TOIOutput::e_touching || out.state == b2TOIOutput::e_overlapped;
        ++asked;
        benchmark::DoNotOptimize(out.t);
        k = (k + 1) % motions.size();
    }
    state.counters["contacts"] = static_cast<double>(contacts) / static_cast<double>(std::max<std::size_t>(asked, 1));
}
#endif

}  // namespace

void register_query_benchmarks() {
    for (const cell& c : cells()) {
        benchmark::RegisterBenchmark(("separation/double/" + c.name()).c_str(), separation_double, c);
        benchmark::RegisterBenchmark(("separation/certified/" + c.name()).c_str(), separation_certified, c);
        benchmark::RegisterBenchmark(("separation/double_once/" + c.name()).c_str(), separation_double_once, c);
        benchmark::RegisterBenchmark(("separation/certified_once/" + c.name()).c_str(), separation_certified_once, c);
#if INFLUENCE2D_HAVE_GEOS
        benchmark::RegisterBenchmark(("separation/geos/" + c.name()).c_str(), separation_geos, c, false);
        benchmark::RegisterBenchmark(("separation/geos_prepared/" + c.name()).c_str(), separation_geos, c, true);
#endif
        benchmark::RegisterBenchmark(("first_contact/double/" + c.name()).c_str(), first_contact_double, c, false,
                                     turning_model::angle_linear);
        benchmark::RegisterBenchmark(("first_contact/certified/" + c.name()).c_str(), first_contact_certified, c, false,
                                     turning_model::angle_linear);
        benchmark::RegisterBenchmark(("exit_distance/double/" + c.name()).c_str(), exit_distances, c, false);
        benchmark::RegisterBenchmark(("exit_distance/certified/" + c.name()).c_str(), exit_distances, c, true);
    }
    // Motions that turn: the angle-linear model's advancement and the
    // rational model's exact roots.
    for (const cell& c : {cell{"convex", 8, 8}, cell{"contour", 64, 64}}) {
        benchmark::RegisterBenchmark(("first_contact_turning/double/" + c.name()).c_str(), first_contact_double, c,
                                     true, turning_model::angle_linear);
        benchmark::RegisterBenchmark(("first_contact_turning/certified/" + c.name()).c_str(), first_contact_certified,
                                     c, true, turning_model::angle_linear);
        benchmark::RegisterBenchmark(("first_contact_turning/rational_double/" + c.name()).c_str(),
                                     first_contact_double, c, true, turning_model::rational);
        benchmark::RegisterBenchmark(("first_contact_turning/rational_certified/" + c.name()).c_str(),
                                     first_contact_certified, c, true, turning_model::rational);
    }
    for (const bool certified : {false, true}) {
        const std::string method = certified ? "certified" : "double";
        benchmark::RegisterBenchmark(("tiling/separation/" + method).c_str(), tiling_separation, certified);
        benchmark::RegisterBenchmark(("tiling/first_contact/" + method).c_str(), tiling_first_contact, certified,
                                     false);
        benchmark::RegisterBenchmark(("tiling/first_contact_straight/" + method).c_str(), tiling_first_contact,
                                     certified, true);
        benchmark::RegisterBenchmark(("tiling/exit_distance/" + method).c_str(), tiling_exit_distance, certified);
    }
    const cell small{"convex", 8, 8};
#if INFLUENCE2D_HAVE_BOX2D
    benchmark::RegisterBenchmark(("first_contact/box2d/" + small.name()).c_str(), first_contact_box2d, small, false);
    benchmark::RegisterBenchmark(("first_contact_turning/box2d/" + small.name()).c_str(), first_contact_box2d, small,
                                 true);
#endif
}

}  // namespace influence2d::bench
