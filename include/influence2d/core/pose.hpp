// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Rigid poses of the moving polygon (docs/method.md section 1).

#include <cmath>
#include <string>

#include "influence2d/core/invalid_input.hpp"

#include "influence2d/core/point.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

/// A rigid pose: rotation by `theta` radians about the moving polygon's own
/// origin, then translation by (tx, ty). The default is the identity. Every
/// component must be finite: detectors throw invalid_input naming the first
/// one that is not (rotation_pose).
struct pose {
    double tx = 0;     ///< translation along x
    double ty = 0;     ///< translation along y
    double theta = 0;  ///< rotation angle in radians, counter-clockwise
};

/// The pose with its rotation taken as the doubles c = std::cos(theta) and
/// s = std::sin(theta). Every number type poses with these same doubles, so an
/// exact type poses the polygon exactly and all types answer one question.
/// Since c^2 + s^2 is not exactly 1, that question is about B scaled by
/// sqrt(c^2 + s^2), which differs from 1 by less than 1e-15.
struct rotation_pose {
    double c = 1;   ///< std::cos(theta)
    double s = 0;   ///< std::sin(theta)
    double tx = 0;  ///< translation along x
    double ty = 0;  ///< translation along y

    /// Takes the cosine and sine of `p.theta` once, in double (for a
    /// theta of zero, their values without the calls: cos(+-0) is 1 and
    /// sin(+-0) is +-0 exactly, IEEE 754 and C's Annex F). Throws
    /// invalid_input naming the first component of p that is NaN or infinite;
    /// the check is one comparison: x - x is 0 for every finite x and NaN
    /// otherwise, so the sum of the three differences is 0 exactly when all
    /// three are finite.
    explicit rotation_pose(const pose& p) : tx(p.tx), ty(p.ty) {
        check(p);
        turn_to(p.theta);
    }

    /// The pose turned to angle `theta` (finite, not checked), its
    /// translation kept: c and s the constructor's values for theta.
    void turn_to(double theta) {
        if (theta != 0) {
            cosine_and_sine(theta);
        } else {
            c = 1;
            s = theta;
        }
    }

    /// Throws invalid_input as the constructor does for a NaN or infinite
    /// component of p, without taking a cosine or a sine.
    static void check(const pose& p) {
        if (!((p.tx - p.tx) + (p.ty - p.ty) + (p.theta - p.theta) == 0)) refuse(p);
    }

    /// q posed in number type NT: `x' = c*qx - s*qy + tx`,
    /// `y' = s*qx + c*qy + ty`, every operation an NT operation on the input
    /// doubles: exact when NT's ring operations are; in a floating NT each
    /// product and sum rounds.
    template <class NT>
    point<NT> apply(const point<double>& q) const {
        using tr = number_traits<NT>;
        if constexpr (tr::category != number_category::floating) {
            // A translation: each coordinate whose sum is a double is that
            // double, which a filtered NT knows exactly (both coordinates
            // so: an input point, its signs taken in double,
            // orientation_of_doubles); any other, one sum in NT (the
            // products by 1 and 0 are exact, and a filtered NT's bound then
            // holds that sum's rounding alone). A step along one axis thus
            // leaves the other coordinate exact: a point moved along a
            // border parallel to that axis stays on its line.
            if (s == 0 && c == 1) return point<NT>{translated<NT>(q.x, tx), translated<NT>(q.y, ty)};
        }
        if constexpr (has_sum_of_products<NT>::value)
            return point<NT>{tr::sum_of_products(c, q.x, -s, q.y, tx), tr::sum_of_products(s, q.x, c, q.y, ty)};
        const NT cx = tr::from_double(c), sx = tr::from_double(s);
        const NT qx = tr::from_double(q.x), qy = tr::from_double(q.y);
        return point<NT>{cx * qx - sx * qy + tr::from_double(tx), sx * qx + cx * qy + tr::from_double(ty)};
    }

    /// For a pose that is a translation (c = 1, s = 0): whether q posed is a
    /// point of doubles, each sum q + t a double (exact_double_sum), then
    /// that point in `out`; false for a pose that turns, or a sum that
    /// rounds. An exact or filtered type then decides on those doubles
    /// exactly (predicates/exact_doubles.hpp) without making the point.
    bool translates_exactly(const point<double>& q, point<double>& out) const {
        return s == 0 && c == 1 && exact_sum::exact_double_sum(q.x, tx, out.x) &&
               exact_sum::exact_double_sum(q.y, ty, out.y);
    }

    /// A point of the posed frame taken back to the unposed one in double:
    /// the transposed rotation applied to q - t, `x = c*(qx - tx) +
    /// s*(qy - ty)`, `y = c*(qy - ty) - s*(qx - tx)`. The inverse of the
    /// pose up to its rotation doubles' scale factor c^2 + s^2 (within 2^-52
    /// of 1; pose_scale_widening) and the rounding of these operations.
    point<double> unapply_in_double(const point<double>& q) const {
        const double x = q.x - tx, y = q.y - ty;
        return {c * x + s * y, c * y - s * x};
    }

private:
    // c = std::cos(theta) and s = std::sin(theta). With the GNU C library
    // both come from one call of its sincos, which reduces the argument once
    // and then runs the same kernels as its sin and cos: the same doubles
    // (tests/core/pose_test.cpp compares them bit for bit on millions of
    // angles) in about 10 ns, where the two calls take 17 ns. g++ 12 at -O2
    // makes that one call of the two on its own; clang 14 does not.
    // Elsewhere the two calls.
    void cosine_and_sine(double theta) {
#if defined(__GLIBC__) && defined(_GNU_SOURCE)
        ::sincos(theta, &s, &c);
#else
        c = std::cos(theta);
        s = std::sin(theta);
#endif
    }

    // x + t in NT: the double x + t when it is one, else the sum in NT.
    template <class NT>
    static NT translated(double x, double t) {
        using tr = number_traits<NT>;
        double sum;
        if (exact_sum::exact_double_sum(x, t, sum)) return tr::from_double(sum);
        return tr::from_double(x) + tr::from_double(t);
    }

    [[noreturn]] static void refuse(const pose& p) {
        const char* name = !std::isfinite(p.tx) ? "tx" : !std::isfinite(p.ty) ? "ty" : "theta";
        const double value = !std::isfinite(p.tx) ? p.tx : !std::isfinite(p.ty) ? p.ty : p.theta;
        throw invalid_input(std::string("pose: ") + name + " is " +
                            (std::isnan(value) ? "NaN"
                             : value > 0       ? "+infinity"
                                               : "-infinity") +
                            ", not a finite number");
    }
};

}  // namespace influence2d
