// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The double-word number type: a value carried in two doubles with a running
/// bound of its error, about 2^-100 of its magnitude per operation. It is the
/// filter that rounds an exact result to the nearest double
/// (predicates/certain_nearest.hpp) at a few times double's cost: a sign or a
/// rounding its bound cannot settle raises uncertain_sign, and the caller
/// answers in exact rationals instead (certified_separation).

#include <cmath>
#include <limits>

#include "influence2d/number/certified.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/number/unit_roundoff.hpp"

namespace influence2d {

/// The relative bound of one sum or product of double words against the
/// magnitude |hi| of its result. Joldes, Muller and Popescu ("Tight and
/// rigorous error bounds for basic building blocks of double-word
/// arithmetic", ACM TOMS 44(2), 2017) prove at most 3u^2 / (1 - 4u) for the
/// accurate sum (their algorithm 6) and 7u^2 for the product without a fused
/// multiply-add (algorithm 10), u = 2^-53, against the exact result x of the
/// operation on the two words' values; |x| <= (1 + 2u) |hi|, so both stay
/// below 8u^2 |hi| = 2^-103 |hi|. 2^-100 leaves a factor 8 of room. The
/// quotient derives its own bound (operator/).
inline constexpr double word_rounding = 0x1p-100;

/// The relative widening of every bound for its own computation in double (a
/// few roundings of relative 2^-53 each), as certified's.
inline constexpr double word_bound_widening = 0x1p-48;

/// The least magnitude a double word keeps (0 aside). With operands and
/// result of at least 2^-900, Dekker's product is exact (its partial
/// products are at least 2^-104 of the product, above 2^-1004, far from the
/// subnormals), and the few low-word operations of a sum, product or
/// quotient lose at most 2^-1075 each to underflow, well inside the room
/// word_rounding leaves above the algorithms' own bounds ((2^-100 - 2^-103)
/// |hi| > 2^-1001). A result nearer 0 is unknown: every sign of it in doubt.
inline constexpr double word_floor = 0x1p-900;
/// The largest magnitude a double word keeps: Veltkamp's split (a product by
/// 2^27 + 1) and the products of two words stay finite up to it. A larger
/// result (or an infinite or NaN one) is unknown.
inline constexpr double word_ceiling = 0x1p900;

/// A value X known to lie within error() of hi() + lo(), the pair of doubles
/// normalised (hi is lo + hi rounded to nearest). Inputs converted from
/// double are exact (error 0); sums and products of exact doubles are exact
/// (TwoSum, Dekker's product); other operations add word_rounding of their
/// result's magnitude and the propagated errors. Only what a field needs:
/// +, -, *, / and signs. A value whose magnitude leaves [word_floor,
/// word_ceiling] is unknown (an infinite error).
class double_word {
public:
    /// Exactly 0.
    double_word() = default;
    /// x exactly (every int is a double); implicit, for constants as in NT(0).
    double_word(int x) : hi_(x) {}  // NOLINT: integer constants as in NT(0)
    /// x exactly: an input, bound 0. A value outside the kept range is unknown.
    explicit double_word(double x) : hi_(x) {
        if (!kept(x)) forget();
    }

    /// The high word.
    double hi() const { return hi_; }
    /// The low word: |lo| is at most half a unit in the last place of hi.
    double lo() const { return lo_; }
    /// The bound of |X - (hi + lo)|; infinite when nothing is known.
    double error() const { return error_; }
    /// Whether the bound is finite.
    bool known() const { return error_ <= std::numeric_limits<double>::max(); }
    /// Whether the value is the double hi exactly.
    bool exact_double() const { return error_ == 0 && lo_ == 0; }
    /// Whether the value is exactly 0: a product by it is exactly 0 too,
    /// bound 0, whatever the other factor's bound (operator*).
    bool exact_zero() const { return hi_ == 0 && error_ == 0; }

    /// Stores the sign in `s` and returns true when it is certain: |hi| (1 -
    /// 2^-52) > error (|hi + lo| >= |hi| (1 - 2^-53), and the product rounds
    /// down by at most 2^-53 more), or hi = lo = error = 0. Otherwise stores
    /// 0 and returns false.
    bool try_sign(int& s) const {
        if (std::fabs(hi_) * (1 - 2 * unit_roundoff) > error_) {  // false for a NaN bound
            s = hi_ > 0 ? 1 : -1;
            return true;
        }
        s = 0;
        return hi_ == 0 && error_ == 0;
    }
    /// -1, 0 or +1 when certain; otherwise 0 when a doubt_noting object
    /// lives on this thread (which notes it), else throws uncertain_sign.
    int sign() const {
        int s;
        if (try_sign(s)) return s;
        if (doubt_noting::note()) return 0;
        throw uncertain_sign();
    }

    /// The negation: exact.
    friend double_word operator-(const double_word& a) { return {-a.hi_, -a.lo_, a.error_}; }
    /// The sum: exact for two doubles (TwoSum), else the accurate sum of two
    /// words (Joldes, Muller and Popescu's algorithm 6) and word_rounding.
    [[gnu::always_inline]] friend double_word operator+(const double_word& a, const double_word& b) {
        if (!a.known() || !b.known()) return unknown();
        double sh, sl;
        two_sum(a.hi_, b.hi_, sh, sl);
        if (a.lo_ == 0 && b.lo_ == 0) return settled(sh, sl, a.error_ + b.error_, 0);
        double th, tl;
        two_sum(a.lo_, b.lo_, th, tl);
        double vh, vl;
        fast_two_sum(sh, sl + th, vh, vl);
        double zh, zl;
        fast_two_sum(vh, tl + vl, zh, zl);
        return settled(zh, zl, a.error_ + b.error_, word_rounding * std::fabs(zh));
    }
    /// The difference: the sum with -b.
    [[gnu::always_inline]] friend double_word operator-(const double_word& a, const double_word& b) { return a + (-b); }
    /// The product: exact for two doubles (Dekker's product), else the
    /// product of two words (Joldes, Muller and Popescu's algorithm 10) and
    /// word_rounding. The propagated error of A B - a b for |A - a| <= ea,
    /// |B - b| <= eb is at most |a| eb + |b| ea + ea eb <= (|a.hi| + ea) eb
    /// (1 + 2^-52) + |b.hi| ea (1 + 2^-52), |a| <= |a.hi| (1 + 2^-53).
    [[gnu::always_inline]] friend double_word operator*(const double_word& a, const double_word& b) {
        if (!a.known() || !b.known()) return unknown();
        if (a.hi_ == 0 || b.hi_ == 0)  // (by an exact zero: exactly 0, bound 0)
            return settled(0, 0, a.exact_zero() || b.exact_zero() ? 0 : product_error(a, b), 0);
        double ch, cl;
        two_product(a.hi_, b.hi_, ch, cl);
        if (ch == 0) return unknown();  // (underflow)
        const double propagated = product_error(a, b);
        if (a.lo_ == 0 && b.lo_ == 0) return settled(ch, cl, propagated, 0);
        double zh, zl;
        fast_two_sum(ch, cl + (a.hi_ * b.lo_ + a.lo_ * b.hi_), zh, zl);
        return settled(zh, zl, propagated, word_rounding * std::fabs(zh));
    }
    /// The quotient a / b, by its residual: q = a.hi / b.hi rounded, the
    /// residual R = a - b q in words, and the correction R.hi / b.hi rounded;
    /// the result is q plus the correction, exactly (FastTwoSum). Its bound:
    /// with A, B the exact values, A / B - q = (A - q B) / B, where A - q B
    /// lies within eN = |R.lo| + R's error of R.hi (R's error holds A's, the
    /// product word P = b q's, which holds |q| eb and P's rounding, and R's
    /// own rounding) and B within eD = |b.lo| + eb of b.hi;
    /// so |A / B - q - R.hi / b.hi| <= (eN + |R.hi / b.hi| eD) / (|b.hi| - eD)
    /// (for |b.hi| > eD), and the correction's rounding adds 2^-53 of it (and
    /// 2^-1074 when it underflows). |R.hi / b.hi| <= |correction| (1 +
    /// 2^-52); the bound's products may lose `underflow`. Unknown when |b.hi|
    /// is not above 4 eD (a divisor in doubt).
    friend double_word operator/(const double_word& a, const double_word& b) {
        if (!a.known() || !b.known()) return unknown();
        const double e_d = std::fabs(b.lo_) + b.error_;
        if (!(std::fabs(b.hi_) > 4 * e_d)) return unknown();
        const double q = a.hi_ / b.hi_;
        if (!kept(q) || (q == 0 && a.hi_ != 0)) return unknown();
        const double_word r = a - b * double_word(q);
        if (!r.known()) return unknown();
        const double correction = r.hi_ / b.hi_;
        const double e_n = std::fabs(r.lo_) + r.error_;
        const double bound = (e_n + std::fabs(correction) * (1 + 2 * unit_roundoff) * e_d) / (std::fabs(b.hi_) - e_d) +
                             unit_roundoff * std::fabs(correction) + underflow;
        double zh, zl;
        fast_two_sum(q, correction, zh, zl);
        return settled(zh, zl, 0, bound);
    }

    /// a b + c d + t for doubles, in one word, at less cost than those
    /// operations one by one: the products exact (Dekker's, p1 + e1 = a b,
    /// p2 + e2 = c d), their sum and then t by TwoSum (s1 + t1 = p1 + p2,
    /// s2 + t2 = s1 + t), so that the value is s2 + (t2 + t1 + e1 + e2)
    /// exactly; the four low parts are summed in double and joined to s2 by
    /// TwoSum. With M = |p1| + |p2| + |t| and u = 2^-53, the low parts total
    /// at most 3.01 u M, so each of the three rounded sums errs by at most
    /// 3.02 u^2 M: below 9.1 u^2 M < 2^-102.8 M in all, and word_rounding M
    /// (2^-100 M) leaves room for M's own rounding; underflow in the low sums
    /// adds `underflow`. Dekker's products are exact for products in the kept
    /// range (word_floor), whatever the magnitudes of their factors.
    static double_word sum_of_products(double a, double b, double c, double d, double t) {
        double p1, e1, p2, e2;
        two_product(a, b, p1, e1);
        two_product(c, d, p2, e2);
        // (A product that underflows, or leaves the kept range, or a t that
        // does, takes the operations one by one. An input so large that its
        // split overflows makes a low part NaN, and the result unknown.)
        if (!(p1 == 0 ? a == 0 || b == 0 : kept(p1)) || !(p2 == 0 ? c == 0 || d == 0 : kept(p2)) || !kept(t))
            return double_word(a) * double_word(b) + double_word(c) * double_word(d) + double_word(t);
        double s1, t1, s2, t2;
        two_sum(p1, p2, s1, t1);
        two_sum(s1, t, s2, t2);
        const double low = ((e1 + e2) + t1) + t2;
        double zh, zl;
        two_sum(s2, low, zh, zl);
        const double m = std::fabs(p1) + std::fabs(p2) + std::fabs(t);
        const bool exact = e1 == 0 && e2 == 0 && t1 == 0 && t2 == 0;
        return settled(zh, zl, 0, exact ? 0 : word_rounding * m + underflow);
    }

    /// \name Compound assignments
    //@{
    /// `*this = *this op b`, with the bound of that operation.
    double_word& operator+=(const double_word& b) { return *this = *this + b; }
    double_word& operator-=(const double_word& b) { return *this = *this - b; }
    double_word& operator*=(const double_word& b) { return *this = *this * b; }
    double_word& operator/=(const double_word& b) { return *this = *this / b; }
    //@}

private:
    double_word(double hi, double lo, double error) : hi_(hi), lo_(lo), error_(error) {}

    /// What underflow may take from an error bound's products (a few of
    /// 2^-1075 each), as certified's.
    static constexpr double underflow = 0x1p-1072;

    static double_word unknown() { return {0, 0, HUGE_VAL}; }
    /// The propagated error of a product (see operator*), 0 for exact operands.
    static double product_error(const double_word& a, const double_word& b) {
        if (a.error_ == 0 && b.error_ == 0) return 0;
        return ((std::fabs(a.hi_) + a.error_) * b.error_ + std::fabs(b.hi_) * a.error_) * (1 + 2 * unit_roundoff) +
               underflow;
    }
    void forget() {
        hi_ = lo_ = 0;
        error_ = HUGE_VAL;
    }
    /// Whether x is 0 or of a magnitude the type keeps (false for NaN).
    static bool kept(double x) {
        const double m = std::fabs(x);
        return m == 0 || (m >= word_floor && m <= word_ceiling);
    }
    /// The word (hi, lo) with the propagated error and its own rounding, the
    /// sum widened by word_bound_widening; unknown outside the kept range.
    static double_word settled(double hi, double lo, double propagated, double own) {
        if (!kept(hi)) return unknown();
        const double e = propagated + own;
        return {hi, lo, e == 0 ? 0 : e * (1 + word_bound_widening)};
    }
    /// s + e = a + b exactly, s = fl(a + b) (Knuth's TwoSum).
    static void two_sum(double a, double b, double& s, double& e) {
        s = a + b;
        const double bb = s - a;
        e = (a - (s - bb)) + (b - bb);
    }
    /// s + e = a + b exactly for |a| >= |b| or a = 0 (Dekker's FastTwoSum).
    static void fast_two_sum(double a, double b, double& s, double& e) {
        s = a + b;
        e = b - (s - a);
    }
    /// p + e = a b exactly, p = fl(a b), by Veltkamp's split into halves of
    /// 26 bits and Dekker's product (no fused multiply-add needed), for
    /// products within the kept range.
    static void two_product(double a, double b, double& p, double& e) {
        const auto split = [](double x, double& h, double& l) {
            const double g = 134217729.0 * x;  // 2^27 + 1
            h = g - (g - x);
            l = x - h;
        };
        double ah, al, bh, bl;
        split(a, ah, al);
        split(b, bh, bl);
        p = a * b;
        e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    }

    double hi_ = 0, lo_ = 0, error_ = 0;
};

/// The traits of double_word: a filtered type whose undecided signs throw.
template <>
struct number_traits<double_word> {
    static constexpr number_category category = number_category::filtered;  ///< exact signs or none
    static constexpr const char* name = "double_word";                      ///< "double_word"
    /// x exactly, with bound 0.
    static double_word from_double(double x) { return double_word(x); }
    /// a b + c d + t (double_word::sum_of_products).
    static double_word sum_of_products(double a, double b, double c, double d, double t) {
        return double_word::sum_of_products(a, b, c, d, t);
    }
    /// The high word, within |lo| + error of the exact value.
    static double to_double(const double_word& x) { return x.hi(); }
    /// The exact sign; when the bound cannot settle it, as double_word::sign.
    static int sign(const double_word& x) { return x.sign(); }
    /// As for double: the filters widen only for their own rounding.
    static constexpr double filter_slack = 1e-9;
    /// The orientation predicate settles an uncertain sign exactly when its
    /// three points are input doubles (see predicates/orientation.hpp).
    static constexpr bool exact_double_fallback = true;
    /// The sign when certain (see double_word::try_sign).
    static bool try_sign(const double_word& x, int& s) { return x.try_sign(s); }
    /// Whether x is an input double.
    static bool exact(const double_word& x) { return x.exact_double(); }
};

}  // namespace influence2d
