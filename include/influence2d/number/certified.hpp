// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The certified number type: a double with a running bound of its error.
/// A sign it cannot decide raises uncertain_sign; certified_detector (in
/// exact/certified_detector.hpp) then answers the frame in an exact type.
/// The same detector code, generic in NT, runs on it unchanged.

#include <cmath>
#include <limits>
#include <stdexcept>

#include "influence2d/number/traits.hpp"
#include "influence2d/number/unit_roundoff.hpp"

namespace influence2d {

/// Thrown when a certified value is too close to zero, relative to its error
/// bound, for its sign to be known; or when a bound overflowed.
class uncertain_sign : public std::runtime_error {
public:
    /// The exception, with a fixed message.
    uncertain_sign() : std::runtime_error("sign not certain in double precision") {}
};

/// While an object of this class lives on a thread, a sign of `certified`
/// (or of a double word, number/double_word.hpp) that its bound cannot settle
/// is noted (noted() turns true) and taken as 0, where it would raise
/// uncertain_sign. Raising costs the unwinder's walk
/// of the frames up to the handler, about 3 us (a one-shot query of two
/// rectangles takes 70 ns in double), and polygons that touch exactly, moved
/// by sums no double holds, put a doubt in most of their queries. Only for a
/// computation that ends whatever signs it is given (no loop waits on a
/// sign, no order is sorted by them, nothing is indexed or asserted on what
/// exact signs alone guarantee), keeps no state past its answer, and whose
/// answer is discarded when noted(): the signs after the first doubt need not
/// be the exact ones. Scopes nest: the innermost notes.
class doubt_noting {
public:
    doubt_noting() : outer_(active_) { active_ = this; }
    ~doubt_noting() { active_ = outer_; }
    doubt_noting(const doubt_noting&) = delete;
    doubt_noting& operator=(const doubt_noting&) = delete;

    /// Whether a sign was in doubt since this object was made.
    bool noted() const { return noted_; }

    /// Notes a doubt in the innermost live object of this thread; false
    /// when there is none (the doubt is then raised).
    static bool note() {
        if (active_ == nullptr) return false;
        active_->noted_ = true;
        return true;
    }

private:
    friend class doubt_raising;
    doubt_noting* outer_;
    bool noted_ = false;
    static inline thread_local doubt_noting* active_ = nullptr;
};

/// While an object of this class lives on a thread, a sign in doubt raises
/// uncertain_sign again, even within a doubt_noting's scope: for a
/// computation that catches the doubt itself and builds what outlives the
/// scope (inner_radius, kept by a prepared polygon; certified_separation's
/// preparation in double words), which a noted 0 would leave wrong, and for
/// fallback<>::run's fast computation, whose answer would otherwise be kept.
/// A filter that catches a doubt only to choose its route (a sign
/// "unknown") needs none: within a doubt_noting the doubt is noted all the
/// same, and the answer dropped. A doubt_noting made inside it notes again.
/// Scopes nest.
class doubt_raising {
public:
    doubt_raising() : outer_(doubt_noting::active_) { doubt_noting::active_ = nullptr; }
    ~doubt_raising() { doubt_noting::active_ = outer_; }
    doubt_raising(const doubt_raising&) = delete;
    doubt_raising& operator=(const doubt_raising&) = delete;

private:
    doubt_noting* outer_;
};

/// A value v with a bound e such that |exact - v| <= e, where `exact` is the
/// result of the same ring operations on the exact inputs. Inputs converted
/// from double are exact (e = 0). Each operation adds the rounding error of
/// its result (at most u |v| for u = 2^-53, plus 2^-1022 for underflow)
/// and the propagated errors; the bound is computed in rounded arithmetic and
/// then widened by (1 + 2^-48), more than the rounding of its few operations.
/// A NaN or infinite value or bound leaves every sign uncertain. Signs that
/// are given are exact; only ring operations are provided (no division).
///
/// Why each bound holds (round to nearest; x the exact result of the
/// operation on the values a.v, b.v, v = fl(x)):
///  - a +- b: exact - v = (exact_a - a.v) +- (exact_b - b.v) + (x - v), and
///    |x - v| <= u |v| (half an ulp of v's binade). u |v| is computed exactly
///    (a power-of-two scaling) unless it is subnormal; then it is rounded to a
///    multiple of 2^-1074, while x - v, a difference of multiples of 2^-1074,
///    is such a multiple no larger than u |v|, so it is still covered. With
///    both inputs exact the bound is u |v| itself, no widening needed (this is
///    the common case of differences of input coordinates); otherwise
///    a.e + b.e + u |v| is computed with two roundings and widened.
///  - a * b: exact_a exact_b - v = a.v db + b.v da + da db + (x - v), with
///    |da| <= a.e, |db| <= b.e, so the error is at most
///    (|a.v| + a.e) b.e + |b.v| a.e + u |v| + [underflow], the first term
///    being |a.v| b.e + a.e b.e in one product. The underflow allowance covers
///    the product v and the three products of the bound losing 2^-1075 each.
///    A factor that is exactly 0 (exact_zero) makes the product exactly 0:
///    bound 0 (a NaN or infinite other factor gives a NaN value, uncertain
///    whatever its bound).
///    The bound's computation rounds at most five times along any of its
///    terms (relative 2^-53 each), well inside the widening by 2^-48.
class certified {
public:
    /// Exactly 0.
    certified() = default;
    /// x exactly (every int is a double); implicit, for constants as in NT(0).
    certified(int x) : v_(x) {}  // NOLINT: integer constants as in NT(0)
    /// x exactly: an input, bound 0. A non-finite x leaves every sign uncertain.
    explicit certified(double x) : v_(x) {}
    /// The value v with the bound e; the caller vouches that |exact - v| <= e.
    certified(double v, double e) : v_(v), e_(e) {}

    /// The computed value v: the rounded result of the same operations in double.
    double value() const { return v_; }
    /// The bound e of |exact - v|.
    double error() const { return e_; }

    /// Whether the value is known exactly (an input double, or an operation
    /// whose bound is still 0).
    bool exact() const { return e_ == 0; }
    /// Whether the value is exactly 0: a product by it is exactly 0 too
    /// (operator*), bound 0, whatever the other factor's bound (a NaN
    /// factor aside: its product stays NaN, every sign uncertain).
    bool exact_zero() const { return v_ == 0 && e_ == 0; }

    /// Stores the sign in `s` and returns true when it is certain (|v| > e,
    /// or v == e == 0); otherwise stores 0 and returns false.
    bool try_sign(int& s) const {
        if (std::fabs(v_) > e_) {  // false for NaN values or bounds
            s = v_ > 0 ? 1 : -1;
            return true;
        }
        s = 0;
        return v_ == 0 && e_ == 0;
    }

    /// -1, 0 or +1, when certain; otherwise 0 when a doubt_noting object
    /// lives on this thread (which notes it), else throws uncertain_sign.
    int sign() const {
        int s;
        if (try_sign(s)) return s;
        if (doubt_noting::note()) return 0;
        throw uncertain_sign();
    }

    /// The sum, with its bound (see the class comment).
    friend certified operator+(const certified& a, const certified& b) { return sum(a.v_ + b.v_, a.e_ + b.e_); }
    /// The difference, with its bound (see the class comment).
    friend certified operator-(const certified& a, const certified& b) { return sum(a.v_ - b.v_, a.e_ + b.e_); }
    /// The negation: exact, the bound unchanged.
    friend certified operator-(const certified& a) { return {-a.v_, a.e_}; }
    /// The product, with its bound (see the class comment).
    friend certified operator*(const certified& a, const certified& b) {
        const double v = a.v_ * b.v_;
        const double e = (std::fabs(a.v_) + a.e_) * b.e_ + std::fabs(b.v_) * a.e_ + u * std::fabs(v) + eta;
        // (v = 0 first: the test of the factors only where it can hold.)
        if (v == 0 && (a.exact_zero() || b.exact_zero())) return {};
        return {v, widen(e)};
    }
    /// \name Compound assignments
    //@{
    /// `*this = *this op b`, with the bound of that operation.
    certified& operator+=(const certified& b) { return *this = *this + b; }
    certified& operator-=(const certified& b) { return *this = *this - b; }
    certified& operator*=(const certified& b) { return *this = *this * b; }
    //@}

    /// \name Comparisons
    //@{
    /// By the sign of a - b; throws uncertain_sign when that sign is not
    /// certain (equal values with non-zero bounds included).
    friend bool operator<(const certified& a, const certified& b) { return (a - b).sign() < 0; }
    friend bool operator>(const certified& a, const certified& b) { return (a - b).sign() > 0; }
    friend bool operator<=(const certified& a, const certified& b) { return (a - b).sign() <= 0; }
    friend bool operator>=(const certified& a, const certified& b) { return (a - b).sign() >= 0; }
    friend bool operator==(const certified& a, const certified& b) { return (a - b).sign() == 0; }
    friend bool operator!=(const certified& a, const certified& b) { return (a - b).sign() != 0; }
    //@}

private:
    static constexpr double u = unit_roundoff;
    // Underflow: the product and the three error terms can each lose
    // 2^-1075, 2^-1073 in all. The allowance is the least normal double,
    // 2^-1022, which holds that and keeps the bound of every product normal
    // or 0 (a sum of exact values keeps u |v|, subnormal only for |v| below
    // 2^-969). With 2^-1072, a product of tiny values carried a subnormal
    // bound, and the operations on it took an orientation from 6 to 46 ns
    // (x86, where arithmetic on subnormals is microcoded). Only values
    // within 2^-1022 of zero lose a sign that 2^-1073 would have left
    // certain. A product by an exact zero (a difference of equal
    // coordinates, as axis-parallel edges and shared vertices give) needs
    // no allowance: it is exactly 0, and a determinant of points on one
    // axis-parallel line is then certainly 0.
    static constexpr double eta = 0x1p-1022;
    // Only the bound's own rounding (relative 2^-53 per operation on it, at
    // most five of them along a term) needs covering; 2^-48 leaves room, and
    // the widening's own rounding cannot take it below e (it rounds e (1 +
    // 2^-48) >= e to nearest, and e is a double).
    static constexpr double bound_widening = 0x1p-48;
    static double widen(double e) { return e * (1 + bound_widening); }
    /// The result v of a sum or difference whose inputs' bounds add up to
    /// `propagated` (see the class comment).
    static certified sum(double v, double propagated) {
        const double r = u * std::fabs(v);
        return {v, propagated == 0 ? r : widen(propagated + r)};
    }

    double v_ = 0;
    double e_ = 0;
};

/// The traits of certified: a filtered type whose undecided signs throw.
template <>
struct number_traits<certified> {
    static constexpr number_category category = number_category::filtered;  ///< exact signs or none
    static constexpr const char* name = "certified";                        ///< "certified"
    /// x exactly, with bound 0.
    static certified from_double(double x) { return certified(x); }
    /// The computed value, within error() of the exact one.
    static double to_double(const certified& x) { return x.value(); }
    /// The exact sign; throws uncertain_sign when the bound cannot settle it.
    static int sign(const certified& x) { return x.sign(); }
    /// As for double: the filters widen only for their own rounding.
    static constexpr double filter_slack = 1e-9;
    /// The orientation predicate may settle an uncertain sign exactly when its
    /// three points are input doubles (see predicates/orientation.hpp).
    static constexpr bool exact_double_fallback = true;
    /// The sign when certain (see certified::try_sign).
    static bool try_sign(const certified& x, int& s) { return x.try_sign(s); }
    /// Whether x is known exactly (an input double).
    static bool exact(const certified& x) { return x.exact(); }
};

}  // namespace influence2d
