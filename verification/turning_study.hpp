// SPDX-License-Identifier: BSL-1.0
#pragma once
// The time study of motions that turn (influence2d-bench, section "Turning
// motions"; turning.csv): per cell, B moves from a random pose near contact
// (its centroid in the annulus 0.7 to 1.2 times R_A + R_B about A's, any
// angle) by a random step of up to 0.3 times R_A + R_B, turning by up to half
// a turn either way (turning_motions): about half the motions meet A. Every
// method answers the first contact of the same motions, each compared with the
// exact answer of its own model:
//
//   method                  model         how
//   rational_certified      rational      certified_first_contact: the exact
//                                         answer of the rational model (its
//                                         reference)
//   rational_double         rational      first_contact<double>
//   angle_linear_certified  angle-linear  certified_first_contact: conservative
//                                         advancement decided on exact
//                                         distances, contact within 1e-9 (the
//                                         angle-linear reference)
//   angle_linear_double     angle-linear  first_contact<double>
//   box2d_toi               angle-linear  Box2D's b2TimeOfImpact in float, B's
//                                         sweep about its own origin (the
//                                         angle-linear motion), shapes without
//                                         skin; convex polygons of at most 8
//                                         vertices only. It reports "touching"
//                                         within its target separation (about
//                                         0.005 units), not at the contact
//   geos_sampled_S          angle-linear  GEOSPreparedIntersects_r (A prepared
//                                         once) at the S + 1 times k / S of the
//                                         motion, k = 0, 1, ..., stopping at the
//                                         first that meets: the user's way
//                                         without continuous detection
//
// Per method: contacts, misses (the reference has a contact, the method
// none), inventions (the reverse), Box2D's failures (e_failed, counted apart
// and as no contact), and the largest |t - T| where both report a contact.
// Timing: rounds, every method over all motions in turn in each round, at
// least 3 rounds (an odd number) until `seconds` have passed; the median
// round of each method counts.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "verification/families.hpp"
#include "verification/peers.hpp"
#include "verification/report_text.hpp"
#include "verification/seeded_draws.hpp"

#if INFLUENCE2D_HAVE_BOX2D
#include <box2d/b2_time_of_impact.h>
#endif

namespace influence2d::verification {

/// One cell of the turning study: a family and the two sizes.
struct turning_cell {
    std::string type;
    std::size_t static_size = 0, moving_size = 0;
};

struct turning_study_options {
    std::vector<turning_cell> cells = {{"convex", 8, 8}, {"contour", 64, 64}, {"starred", 256, 256}};
    std::size_t motions = 256;                             ///< motions per cell
    std::vector<std::size_t> samples = {16, 32, 64, 256};  ///< the sampling methods' S
    double seconds = 0.5;                                  ///< seconds of timed rounds per cell
    double random_inner = 0.7, random_outer = 1.2;         ///< the start's annulus, in units of R_A + R_B
    double step = 0.3;                                     ///< the longest move, in units of R_A + R_B
    std::uint64_t seed = default_family_seed;              ///< of the family polygons and the motions
};

/// One method's answer to one motion.
struct turning_answer {
    bool contact = false;
    double time = 0;      ///< meaningful with contact
    bool failed = false;  ///< Box2D's e_failed (no contact reported)
};

/// One method on one cell.
struct turning_row {
    turning_cell cell;
    std::string method;
    std::string model;  ///< "rational" or "angle-linear"
    std::size_t motions = 0, contacts = 0, misses = 0, inventions = 0, failed = 0;
    std::size_t rounds = 0;
    double largest_time_error = 0;  ///< over the motions where both report a contact
    double seconds = 0;             ///< the median round, over all motions
    bool reference = false;         ///< this method's answers are its model's reference
    std::vector<turning_answer> answers;
    double us_per_motion() const { return motions ? 1e6 * seconds / static_cast<double>(motions) : 0; }
};

namespace turning_study_detail {

using clock = std::chrono::steady_clock;

/// A method of the study: its name, its model, and its answer to a motion
/// (a closure over what it built for the cell, outside the timing).
struct method {
    std::string name, model;
    bool reference = false;
    std::function<turning_answer(const pose&, const pose&)> answer;
};

inline turning_answer from_contact(const contact_result<double>& r) { return {r.contact, r.time, false}; }

/// The library's four routes.
inline std::vector<method> own_methods(const polygon& a, const polygon& b) {
    std::vector<method> out;
    for (const turning_model model : {turning_model::rational, turning_model::angle_linear}) {
        const bool rational = model == turning_model::rational;
        const sweep_options o{sweep_options{}.tolerance, model};
        const std::string prefix = rational ? "rational_" : "angle_linear_",
                          name = rational ? "rational" : "angle-linear";
        out.push_back({prefix + "certified", name, true, [&a, &b, o](const pose& p, const pose& q) {
                           return from_contact(certified_first_contact(a, b, p, q, o));
                       }});
        out.push_back({prefix + "double", name, false, [&a, &b, o](const pose& p, const pose& q) {
                           return from_contact(first_contact<double>(a, b, p, q, o));
                       }});
    }
    return out;
}

#if INFLUENCE2D_HAVE_BOX2D
/// Box2D's time of impact on shapes built once: B's sweep about its origin,
/// A at rest.
inline method box2d_method(const polygon& a, const polygon& b) {
    auto input = std::make_shared<b2TOIInput>();
    auto shapes = std::make_shared<std::pair<b2PolygonShape, b2PolygonShape>>(
        box2d_peer::shape(box2d_peer::vertices(a)), box2d_peer::shape(box2d_peer::vertices(b)));
    input->proxyA.Set(&shapes->first, 0);
    input->proxyB.Set(&shapes->second, 0);
    input->sweepA.localCenter.SetZero();
    input->sweepA.c0.SetZero();
    input->sweepA.c.SetZero();
    input->sweepA.a0 = input->sweepA.a = 0;
    input->sweepA.alpha0 = 0;
    input->sweepB.localCenter.SetZero();
    input->sweepB.alpha0 = 0;
    input->tMax = 1;
    return {"box2d_toi", "angle-linear", false, [input, shapes](const pose& p, const pose& q) {
                input->sweepB.c0.Set(static_cast<float>(p.tx), static_cast<float>(p.ty));
                input->sweepB.c.Set(static_cast<float>(q.tx), static_cast<float>(q.ty));
                input->sweepB.a0 = static_cast<float>(p.theta);
                input->sweepB.a = static_cast<float>(q.theta);
                b2TOIOutput out;
                b2TimeOfImpact(&out, input.get());
                turning_answer r;
                r.failed = out.state == b2TOIOutput::e_failed;
                r.contact = out.state == b2TOIOutput::e_touching || out.state == b2TOIOutput::e_overlapped;
                r.time = out.state == b2TOIOutput::e_overlapped ? 0.0 : static_cast<double>(out.t);
                return r;
            }};
}
#endif

#if INFLUENCE2D_HAVE_GEOS
/// Sampling with GEOS prepared: the first of the times k / S at which B,
/// posed as the angle-linear motion poses it (motion_pose), meets A.
inline method geos_sampled_method(const polygon& a, const polygon& b, std::size_t samples) {
    auto peer = std::make_shared<geos_peer>(a, b);
    return {"geos_sampled_" + std::to_string(samples), "angle-linear", false,
            [peer, samples](const pose& p, const pose& q) {
                for (std::size_t k = 0; k <= samples; ++k) {
                    const double t = static_cast<double>(k) / static_cast<double>(samples);
                    if (peer->collide(motion_pose(p, q, t))) return turning_answer{true, t, false};
                }
                return turning_answer{};
            }};
}
#endif

}  // namespace turning_study_detail

/// The motions of a cell: from the random poses of the annulus (seeded as
/// the time study's) by a step of uniform direction and length up to
/// `step` (R_A + R_B), turning by a uniform angle in [-pi, pi].
inline std::vector<std::pair<pose, pose>> turning_motions(const turning_study_options& o, const polygon& a,
                                                          const polygon& b) {
    const double r = bounding_radius(a, a.centroid()) + bounding_radius(b, b.centroid());
    const std::vector<pose> from = random_poses(a, b, o.motions, o.random_inner * r, o.random_outer * r, o.seed);
    uniform_source u(mix(o.seed + 1));
    std::vector<std::pair<pose, pose>> out;
    for (const pose& p : from) {
        const double direction = u.between(0, 2 * pi), length = u.between(0, o.step * r), turn = u.between(-pi, pi);
        out.push_back({p, {p.tx + length * std::cos(direction), p.ty + length * std::sin(direction), p.theta + turn}});
    }
    return out;
}

/// Runs the study: one row per method and cell, in the order of the cells
/// and then of the methods (the library's, Box2D's where it applies, the
/// sampling ones).
inline std::vector<turning_row> run_turning_study(const turning_study_options& o) {
    using namespace turning_study_detail;
    std::vector<turning_row> rows;
    for (const turning_cell& c : o.cells) {
        const family f = family_of(c.type);
        const polygon a = make_family_polygon(f, c.static_size, o.seed);
        const polygon b = make_family_polygon(f, c.moving_size, o.seed);
        const std::vector<std::pair<pose, pose>> motions = turning_motions(o, a, b);
        std::vector<method> methods = own_methods(a, b);
#if INFLUENCE2D_HAVE_BOX2D
        if (box2d_peer::applies(a, b)) methods.push_back(box2d_method(a, b));
#endif
#if INFLUENCE2D_HAVE_GEOS
        for (std::size_t s : o.samples) methods.push_back(geos_sampled_method(a, b, s));
#endif
        // Rounds: every method over all motions in turn.
        std::vector<std::vector<double>> round_seconds(methods.size());
        std::vector<std::vector<turning_answer>> answers(methods.size());
        const auto start = clock::now();
        for (std::size_t round = 0;; ++round) {
            for (std::size_t m = 0; m < methods.size(); ++m) {
                std::vector<turning_answer> got;
                got.reserve(motions.size());
                const auto t0 = clock::now();
                for (const auto& [p, q] : motions) got.push_back(methods[m].answer(p, q));
                round_seconds[m].push_back(std::chrono::duration<double>(clock::now() - t0).count());
                if (round == 0) answers[m] = std::move(got);
            }
            const double spent = std::chrono::duration<double>(clock::now() - start).count();
            if (round + 1 >= 3 && (round + 1) % 2 == 1 && spent >= o.seconds) break;
        }
        // The references: the certified method of each model.
        std::map<std::string, const std::vector<turning_answer>*> reference;
        for (std::size_t m = 0; m < methods.size(); ++m)
            if (methods[m].reference) reference[methods[m].model] = &answers[m];
        for (std::size_t m = 0; m < methods.size(); ++m) {
            turning_row row;
            row.cell = c;
            row.method = methods[m].name;
            row.model = methods[m].model;
            row.reference = methods[m].reference;
            row.motions = motions.size();
            row.rounds = round_seconds[m].size();
            row.seconds = median_of(round_seconds[m]);
            const std::vector<turning_answer>& want = *reference.at(methods[m].model);
            for (std::size_t k = 0; k < motions.size(); ++k) {
                const turning_answer& got = answers[m][k];
                row.contacts += got.contact;
                row.failed += got.failed;
                row.misses += want[k].contact && !got.contact;
                row.inventions += !want[k].contact && got.contact;
                if (want[k].contact && got.contact)
                    row.largest_time_error = std::max(row.largest_time_error, std::fabs(got.time - want[k].time));
            }
            row.answers = answers[m];  // a copy: the references are read by later rows
            rows.push_back(std::move(row));
        }
    }
    return rows;
}

}  // namespace influence2d::verification
