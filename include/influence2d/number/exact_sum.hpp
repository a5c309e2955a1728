// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Exact signs of sums of products of doubles, over the whole range of double
/// (subnormals and products beyond double's range included), for decisions on
/// input doubles: ring orientation, and the orientation predicate on three input
/// points when a filter cannot decide it.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "influence2d/assert.hpp"

/// Exact signs of sums of products of doubles (no number type involved).
namespace influence2d::exact_sum {

/// An exact sum of products of doubles, kept as two fixed-point unsigned
/// integers wide enough for any of them, the positive terms' total and the
/// negative terms' (so that no term borrows across the words a sum near 0
/// would span in two's complement): a finite double is m 2^e with an
/// integer m < 2^53 (read from its bits) and e in [-1074, 971], so a product
/// is an integer below 2^106 times 2^(e1 + e2) with e1 + e2 in [-2148,
/// 1942]; each integer counts units of 2^-2252 in 70 words of 64 bits (4480
/// bits: the 4200 a product can reach, and room for 2^100 terms' carries).
/// The sign compares the two from their highest word touched. Precondition:
/// finite inputs (the callers ensure it; NaN or infinity gives a
/// meaningless sum). Each addition costs a few word operations plus its
/// carry; it allocates nothing.
class accumulator {
public:
    /// Adds x exactly (x finite).
    void add(double x) { add_product(x, 1.0); }

    /// Adds a * b exactly (a and b finite), even when the product is beyond
    /// double's range or below its subnormals.
    void add_product(double a, double b) {
        if (a == 0 || b == 0) return;
        const std::uint64_t ma = significand(a), mb = significand(b);
        // The product ma mb < 2^106 as two words, from 32-bit halves.
        const std::uint64_t a_lo = ma & 0xffffffffu, a_hi = ma >> 32, b_lo = mb & 0xffffffffu, b_hi = mb >> 32;
        const std::uint64_t lo = a_lo * b_lo, mid = a_lo * b_hi + a_hi * b_lo, hi = a_hi * b_hi;
        const std::uint64_t low = lo + (mid << 32);
        const std::uint64_t high = hi + (mid >> 32) + (low < lo);
        const int position = exponent(a) + exponent(b) + bias;  // bit of the product's unit
        add_shifted(low, high, position, (a < 0) != (b < 0) ? negative_ : positive_);
    }

    /// The sign of the exact sum: -1, 0 or +1 (0 for no term).
    int sign() const {
        for (int k = top_; k-- > 0;)
            if (positive_[k] != negative_[k]) return positive_[k] > negative_[k] ? 1 : -1;
        return 0;
    }

private:
    static constexpr int bias = 2252;
    static constexpr int count = 70;

    static std::uint64_t bits_of(double x) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        return bits;
    }
    /// The integer m < 2^53 of a finite x = +-m 2^e: its stored fraction,
    /// with the leading bit unless x is subnormal.
    static std::uint64_t significand(double x) {
        const std::uint64_t bits = bits_of(x), fraction = bits & ((std::uint64_t{1} << 52) - 1);
        return (bits >> 52 & 0x7ff) == 0 ? fraction : fraction | std::uint64_t{1} << 52;
    }
    /// The power e of a finite x = +-m 2^e (significand): -1074 for a
    /// subnormal.
    static int exponent(double x) {
        const int field = static_cast<int>(bits_of(x) >> 52 & 0x7ff);
        return field == 0 ? -1074 : field - 1075;
    }

    /// Adds (high 2^64 + low) 2^position to the integer in `words`.
    void add_shifted(std::uint64_t low, std::uint64_t high, int position, std::uint64_t* words) {
        INFLUENCE2D_ASSERT(position >= 0 && position / 64 + 3 <= count,
                           "a product's bits beyond the accumulator's words");
        const int word = position / 64, shift = position % 64;
        // The value shifted spans at most three words.
        const std::uint64_t part[3] = {low << shift, shift ? (high << shift) | (low >> (64 - shift)) : high,
                                       shift ? high >> (64 - shift) : 0};
        unsigned carry = 0;
        int k = word;
        for (; k < count; ++k) {
            const std::uint64_t p = k - word < 3 ? part[k - word] : 0;
            if (k - word >= 3 && carry == 0) break;
            const std::uint64_t w = words[k];
            const std::uint64_t s = w + p;
            const unsigned c1 = s < w;
            const std::uint64_t t = s + carry;
            carry = c1 | (t < s);
            words[k] = t;
        }
        top_ = std::max(top_, k);
    }

    std::uint64_t positive_[count] = {};  ///< the positive terms' total
    std::uint64_t negative_[count] = {};  ///< the negative terms' magnitudes' total
    int top_ = 0;                         ///< one above the highest word either total has touched
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

#if defined(__SIZEOF_INT128__)
/// (The window below needs 128-bit integers and the bit-counting builtins
/// of the compilers that have them.)

/// A finite double as m 2^e: m an odd integer (|m| < 2^53) and e in
/// [-1074, 971], or m = 0 for either zero.
struct dyadic {
    std::int64_t m = 0;  ///< the odd integer, with the double's sign
    int e = 0;           ///< the power of two
};

/// x (finite) as m 2^e, read from its bits: the stored fraction with its
/// leading bit (none for a subnormal), its trailing zero bits moved into e.
inline dyadic dyadic_of(double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    const int field = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
    int e = -1074;
    if (field != 0) {
        m |= std::uint64_t{1} << 52;
        e = field - 1075;
    }
    if (m == 0) return {};
    const int zeros = __builtin_ctzll(m);
    m >>= zeros;
    e += zeros;
    const auto signed_m = static_cast<std::int64_t>(m);
    return {(bits >> 63) != 0 ? -signed_m : signed_m, e};
}

/// The widest span, in bits, of six coordinates that orientation_in_window
/// takes in 128-bit integers: from the least significant bit set among them
/// to the top of the largest, at most 61 bits; each coordinate is then an
/// integer below 2^61 in units of that least bit, each difference below
/// 2^62 (in 64 bits), each product of two below 2^124, and the determinant
/// below 2^125, inside a signed 128-bit integer. Coordinates of one data set
/// (a map in degrees or metres, a grid) nearly always fit.
inline constexpr int orientation_window_bits = 61;

/// The exact sign of the orientation determinant of three points with
/// finite double coordinates, in 128-bit integers, when the six
/// coordinates fit orientation_window_bits (returns whether they did;
/// `sign` is set only then): each coordinate an integer in units of the
/// least bit set among them, the determinant (b - a) x (c - a) in those
/// units squared.
inline bool orientation_in_window(double ax, double ay, double bx, double by, double cx, double cy, int& sign) {
    const double given[6] = {ax, ay, bx, by, cx, cy};
    dyadic d[6];
    int low = 0, high = 0;  // the least bit set, and one above the top bit of the largest
    bool any = false;
    for (int k = 0; k < 6; ++k) {
        d[k] = dyadic_of(given[k]);
        if (d[k].m == 0) continue;
        const auto m = static_cast<std::uint64_t>(d[k].m < 0 ? -d[k].m : d[k].m);
        const int top = d[k].e + 64 - __builtin_clzll(m);  // one above m's top bit, as a power of two
        low = any ? std::min(low, d[k].e) : d[k].e;
        high = any ? std::max(high, top) : top;
        any = true;
    }
    if (!any) {
        sign = 0;
        return true;
    }
    if (high - low > orientation_window_bits) return false;
    std::int64_t v[6];  // each in units of 2^low: |v| < 2^61, so that the product stays in 64 bits
    for (int k = 0; k < 6; ++k) v[k] = d[k].m == 0 ? 0 : d[k].m * (std::int64_t{1} << (d[k].e - low));
    __extension__ typedef __int128 wide;  // (__extension__: no pedantic warning)
    const wide det = static_cast<wide>(v[2] - v[0]) * static_cast<wide>(v[5] - v[1]) -
                     static_cast<wide>(v[3] - v[1]) * static_cast<wide>(v[4] - v[0]);
    sign = det > 0 ? 1 : det < 0 ? -1 : 0;
    return true;
}
#endif

/// The exact sign of the orientation determinant [a b c] of three points
/// with double coordinates by the accumulator, over the whole range: the
/// sum [a b c] = bx cy - bx ay - ax cy - by cx + by ax + ay cx accumulated
/// exactly; coordinates must be finite.
inline int orientation_sign_accumulated(double ax, double ay, double bx, double by, double cx, double cy) {
    accumulator acc;
    acc.add_product(bx, cy);
    acc.add_product(-bx, ay);
    acc.add_product(-ax, cy);
    acc.add_product(-by, cx);
    acc.add_product(by, ax);
    acc.add_product(ay, cx);
    return acc.sign();
}

/// The exact sign of the orientation determinant [a b c] of three points with
/// double coordinates: +1 when c lies left of the directed line a->b, -1
/// right, 0 collinear (also when two of the points coincide); coordinates
/// must be finite. In 128-bit integers when the coordinates fit their
/// window (orientation_in_window, where the compiler has such integers),
/// else by the accumulator (orientation_sign_accumulated).
inline int orientation_sign(double ax, double ay, double bx, double by, double cx, double cy) {
#if defined(__SIZEOF_INT128__)
    int sign = 0;
    if (orientation_in_window(ax, ay, bx, by, cx, cy, sign)) return sign;
#endif
    return orientation_sign_accumulated(ax, ay, bx, by, cx, cy);
}

}  // namespace influence2d::exact_sum
