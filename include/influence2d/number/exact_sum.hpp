// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Exact signs of sums of products of doubles, over the whole range of double
/// (subnormals and products beyond double's range included), for decisions on
/// input doubles: ring orientation, and the orientation predicate on three input
/// points when a filter cannot decide it.

#include <cmath>
#include <cstdint>

#include "influence2d/assert.hpp"

/// Exact signs of sums of products of doubles (no number type involved).
namespace influence2d::exact_sum {

/// An exact sum of products of doubles, kept as one fixed-point two's
/// complement integer wide enough for any of them: a finite double is M 2^E
/// with an integer |M| < 2^53 and E >= -1126, so a product is an integer below
/// 2^106 times 2^(E1 + E2) with E1 + E2 in [-2252, 1942]; the integer counts
/// units of 2^-2252 in 70 words of 64 bits (4480 bits: the 4300 a product can
/// reach, and room for 2^100 terms' carries). Precondition: finite inputs
/// (the callers ensure it; NaN or infinity gives a meaningless sum). Each
/// addition costs a few word operations plus its carry; it allocates nothing.
class accumulator {
public:
    /// Adds x exactly (x finite).
    void add(double x) { add_product(x, 1.0); }

    /// Adds a * b exactly (a and b finite), even when the product is beyond
    /// double's range or below its subnormals.
    void add_product(double a, double b) {
        if (a == 0 || b == 0) return;
        int ea = 0, eb = 0;
        const double fa = std::frexp(a, &ea), fb = std::frexp(b, &eb);
        // |fa|, |fb| in [0.5, 1): the integers |fa| 2^53 and |fb| 2^53 are exact.
        const auto ma = static_cast<std::uint64_t>(std::ldexp(std::fabs(fa), 53));
        const auto mb = static_cast<std::uint64_t>(std::ldexp(std::fabs(fb), 53));
        // The product ma mb < 2^106 as two words, from 32-bit halves.
        const std::uint64_t a_lo = ma & 0xffffffffu, a_hi = ma >> 32, b_lo = mb & 0xffffffffu, b_hi = mb >> 32;
        const std::uint64_t lo = a_lo * b_lo, mid = a_lo * b_hi + a_hi * b_lo, hi = a_hi * b_hi;
        const std::uint64_t low = lo + (mid << 32);
        const std::uint64_t high = hi + (mid >> 32) + (low < lo);
        const int position = (ea - 53) + (eb - 53) + bias;  // bit of the product's unit
        add_shifted(low, high, position, (a < 0) != (b < 0));
    }

    /// The sign of the exact sum: -1, 0 or +1 (0 for no term).
    int sign() const {
        if (words_[count - 1] >> 63) return -1;
        for (const std::uint64_t w : words_)
            if (w != 0) return 1;
        return 0;
    }

private:
    static constexpr int bias = 2252;
    static constexpr int count = 70;

    /// Adds (or subtracts) (high 2^64 + low) 2^position to the integer.
    void add_shifted(std::uint64_t low, std::uint64_t high, int position, bool negative) {
        INFLUENCE2D_ASSERT(position >= 0 && position / 64 + 3 <= count,
                           "a product's bits beyond the accumulator's words");
        const int word = position / 64, shift = position % 64;
        // The value shifted spans at most three words.
        const std::uint64_t part[3] = {low << shift, shift ? (high << shift) | (low >> (64 - shift)) : high,
                                       shift ? high >> (64 - shift) : 0};
        unsigned carry = 0;
        for (int k = word; k < count; ++k) {
            const std::uint64_t p = k - word < 3 ? part[k - word] : 0;
            if (k - word >= 3 && carry == 0) break;
            const std::uint64_t w = words_[k];
            if (!negative) {
                const std::uint64_t s = w + p;
                const unsigned c1 = s < w;
                const std::uint64_t t = s + carry;
                carry = c1 | (t < s);
                words_[k] = t;
            } else {
                const std::uint64_t s = w - p;
                const unsigned b1 = w < p;
                const std::uint64_t t = s - carry;
                carry = b1 | (s < carry);
                words_[k] = t;
            }
        }
    }

    std::uint64_t words_[count] = {};
};

/// Whether a + b is a double (the sum rounds to itself); `sum` gets the
/// rounded fl(a + b) either way. Knuth's TwoSum: with s = fl(a + b) and
/// bb = fl(s - a), the rounding error a + b - s is exactly
/// fl(fl(a - fl(s - bb)) + fl(b - bb)) in round to nearest when s is finite,
/// so the sum is exact when that error is 0. Not exact when s is infinite
/// or NaN.
inline bool exact_double_sum(double a, double b, double& sum) {
    sum = a + b;
    if (!(sum - sum == 0)) return false;
    const double bb = sum - a;
    return (a - (sum - bb)) + (b - bb) == 0;
}

/// The exact sign of the orientation determinant [a b c] of three points with
/// double coordinates: +1 when c lies left of the directed line a->b, -1
/// right, 0 collinear (also when two of the points coincide). The sum
/// [a b c] = bx cy - bx ay - ax cy - by cx + by ax + ay cx is accumulated
/// exactly; coordinates must be finite.
inline int orientation_sign(double ax, double ay, double bx, double by, double cx, double cy) {
    accumulator acc;
    acc.add_product(bx, cy);
    acc.add_product(-bx, ay);
    acc.add_product(-ax, cy);
    acc.add_product(-by, cx);
    acc.add_product(by, ax);
    acc.add_product(ay, cx);
    return acc.sign();
}

}  // namespace influence2d::exact_sum
