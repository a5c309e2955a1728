// SPDX-License-Identifier: BSL-1.0
// The table of number types (number_types.hpp) and what each entry points at:
// the detector over the poses, the separation at every pose, the first
// contact of every motion and, for the exact types, whether both polygons
// posed in the world meet, instantiated here once for every type.

#include "number_types.hpp"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_both_posed.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/exact/interval_detector.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/motion/motion.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/multiprecision.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/query/both_posed.hpp"

namespace influence2d::cli {

namespace {

/// Times the frames: with one thread, the loop of one detector built before
/// the clock starts; with more, the whole batch (each thread builds its
/// detector from `make`, on shared prepared polygons where the detector
/// takes them). `done(detector)` sees each detector after its frames.
template <class Make, class Done>
frames_run time_frames(const detector_job& job, Make&& make, Done&& done) {
    frames_run r;
    if (job.threads <= 1) {
        auto det = make();
        r.frames.resize(job.poses.size());
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < job.poses.size(); ++i) r.frames[i] = det.collide(job.poses[i]);
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        done(det);
        return r;
    }
    const auto start = std::chrono::steady_clock::now();
    r.frames = collide_batch(job.poses, make, job.threads, done);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

/// A plain number type: every algorithm's detector in NT; the sound one on
/// A and B prepared once for every thread. In float, double and long double,
/// a scene far from 1 in scale (its polygons and every pose's translation)
/// runs scaled by a power of two into the type's range, d with it
/// (core/range_scaling.hpp): the same answers, without overflow or underflow.
template <class NT>
frames_run run_in(const detector_job& job) {
    if (const int k = batch_range_shift<NT>(job.a, job.b, job.poses.data(), job.poses.size())) {
        const polygon a = job.a.scaled_by_power_of_two(k), b = job.b.scaled_by_power_of_two(k);
        std::vector<pose> poses;
        poses.reserve(job.poses.size());
        for (const pose& p : job.poses) poses.push_back(scaled_by_power_of_two(p, k));
        detector_job scaled{a, b, poses, job.options, job.algorithm, job.threads};
        scaled.options.distance = scaled_length(job.options.distance, k);
        return run_in<NT>(scaled);
    }
    const auto nothing = [](const auto&) {};
    if (job.algorithm == "paper")
        return time_frames(
            job, [&] { return paper_detector<NT>(job.a, job.b, job.options); }, nothing);
    if (job.algorithm == "brute-force")
        return time_frames(
            job, [&] { return brute_force_detector<NT>(job.a, job.b, job.options); }, nothing);
    const auto a = prepare_static<NT>(job.a);
    const auto b = prepare_moving<NT>(job.b);
    return time_frames(
        job, [&] { return detector<NT>(a, b, job.options); }, nothing);
}

/// A filtered type: Wrapper<Detector> runs Detector in a fast type and answers
/// a frame again in exact rationals when a sign is not certain
/// (certified_detector, interval_detector). Not for the paper's algorithm
/// (number_type::exact_fallback says why).
template <template <template <class...> class> class Wrapper>
frames_run run_filtered(const detector_job& job) {
    std::atomic<std::size_t> exact_frames{0};
    const auto count = [&](const auto& det) { exact_frames += det.exact_frames(); };
    frames_run r = job.algorithm == "brute-force"
                       ? time_frames(
                             job, [&] { return Wrapper<brute_force_detector>(job.a, job.b, job.options); }, count)
                       : time_frames(
                             job, [&] { return Wrapper<detector>(job.a, job.b, job.options); }, count);
    r.exact_frames = exact_frames.load();
    return r;
}

/// A motion's row from its first contact (the time already a double).
template <class NT>
contact_row row_of(const contact_result<NT>& r, double time) {
    return {r.contact, r.contact || r.step_limit ? time : 0.0, r.static_feature, r.moving_feature, r.step_limit};
}

/// A time of NT as the nearest double (exactly rounded for an exact NT).
template <class NT>
double time_as_double(const NT& t) {
    return nearest_double(time_fraction<NT>{t, NT(1)});
}

/// The separation at every pose, in NT, one query object over the poses.
template <class NT>
std::vector<separation_row> separations_in(const polygon& a, const polygon& b, const std::vector<pose>& poses) {
    separation_query<NT> query(a, b);
    std::vector<separation_row> rows;
    rows.reserve(poses.size());
    for (const pose& p : poses) {
        const separation_result<NT> r = query(p);
        rows.push_back({distance_of<NT>(r.squared_distance), r.static_feature, r.moving_feature});
    }
    return rows;
}

/// The separation at every pose, certified: exact features, the distance
/// within one unit in the last place; one query object over the poses.
std::vector<separation_row> certified_separations(const polygon& a, const polygon& b, const std::vector<pose>& poses) {
    certified_separation_query query(a, b);
    std::vector<separation_row> rows;
    rows.reserve(poses.size());
    for (const pose& p : poses) {
        const certified_separation_result r = query(p);
        rows.push_back({r.distance, r.static_feature, r.moving_feature});
    }
    return rows;
}

/// The first contact of each motion from poses[k] to poses[k + 1], in NT.
template <class NT>
std::vector<contact_row> contacts_in(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                                     const sweep_options& options) {
    std::vector<contact_row> rows;
    for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
        const contact_result<NT> r = first_contact<NT>(a, b, poses[k], poses[k + 1], options);
        rows.push_back(row_of(r, time_as_double(r.time)));
    }
    return rows;
}

/// The first contact of each motion, certified.
std::vector<contact_row> certified_contacts(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                                            const sweep_options& options) {
    std::vector<contact_row> rows;
    for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
        const contact_result<double> r = certified_first_contact(a, b, poses[k], poses[k + 1], options);
        rows.push_back(row_of(r, r.time));
    }
    return rows;
}

/// Whether A posed by pose_a and B posed by pose_b meet, both posed exactly
/// in exact rationals (no rounded relative pose).
bool exact_meets_both(const polygon& a, const pose& pose_a, const polygon& b, const pose& pose_b) {
    return intersects<exact_rational>(a, pose_a, b, pose_b);
}

/// The same answer through the certified type, exact rationals for a pose in doubt.
bool certified_meets_both(const polygon& a, const pose& pose_a, const polygon& b, const pose& pose_b) {
    return certified_intersects(a, pose_a, b, pose_b);
}

}  // namespace

const number_type number_types[number_type_count] = {
    // clang-format off
    {"float", "IEEE single precision, refusing coordinates beyond float's range", false, false, &run_in<float>,
     &separations_in<float>, &contacts_in<float>, nullptr},
    {"double", "IEEE double precision", false, false, &run_in<double>,
     &separations_in<double>, &contacts_in<double>, nullptr},
    {"long-double", "the platform's long double (64-bit significand on x86)", false, false, &run_in<long double>,
     &separations_in<long double>, &contacts_in<long double>, nullptr},
    {"quad", "113-bit software floating point (Boost cpp_bin_float_quad)", false, false, &run_in<quad>,
     &separations_in<quad>, &contacts_in<quad>, nullptr},
    {"exact", "CGAL's exact rationals, slower", true, false, &run_in<exact_rational>,
     &separations_in<exact_rational>, &contacts_in<exact_rational>, &exact_meets_both},
    {"certified", "double with a running error bound, a frame whose signs it cannot certify answered again in exact rationals (counted as 'exact fallbacks')", true, true, &run_filtered<certified_detector>,
     &certified_separations, &certified_contacts, &certified_meets_both},
    {"interval", "the same with CGAL's interval arithmetic (separation and sweep: as certified)", true, true, &run_filtered<interval_detector>,
     &certified_separations, &certified_contacts, &certified_meets_both},
    // clang-format on
};

}  // namespace influence2d::cli
