// SPDX-License-Identifier: BSL-1.0
#pragma once
// Random arithmetic for the tests of the filtered number types (certified,
// double_word): doubles of many magnitudes, and random expression trees
// whose every node a tally checks against the exact rationals of the same
// operations.

#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

#include "support/random.hpp"

namespace test_chains {

/// Binary exponents of the magnitudes drawn: about 1e-300, 1e-150, 1e-20, 1,
/// 1e20, 1e150, 1e300.
inline constexpr int scales[] = {-997, -498, -66, 0, 66, 498, 997};

/// A random double near 2^scale (within 2^+-6), or, now and then, a zero, a
/// small integer, a subnormal or a double with few significant bits.
inline double random_double(test_random::rng& r, int scale) {
    const double sgn = r.index(2) == 0 ? 1.0 : -1.0;
    switch (r.index(16)) {
    case 0: return 0.0;
    case 1: return sgn * static_cast<double>(1 + r.index(16));
    case 2: return sgn * std::ldexp(static_cast<double>(1 + r.index(std::size_t{1} << 20)), -1074);
    case 3: return sgn * std::ldexp(static_cast<double>(r.gen() >> 12), -1074);  // up to 2^52 ulps
    case 4: return sgn * std::ldexp(static_cast<double>(1 + r.index(1024)), scale - 5);
    default: return sgn * std::ldexp(1 + r.unit(), scale + static_cast<int>(r.index(13)) - 6);
    }
}

/// Random expression trees of depth <= 6 over Tracked values (a value in the
/// type under test beside its exact rational, made from a double by `leaf`),
/// every node given to tally.check. The operations are +, - and *, and / too
/// when Divides. A node's operands are new subtrees or, one time in three, a
/// value built before in the same chain (so that x - y, with y sharing most
/// of x, cancels).
template <class Tracked, class Tally, bool Divides = false>
class chain_builder {
public:
    using leaf_of = Tracked (*)(double);
    chain_builder(test_random::rng& r, Tally& t, leaf_of leaf) : r_(r), t_(t), leaf_(leaf) {}

    void run(int depth) {
        pool_.clear();
        base_ = scales[r_.index(std::size(scales))];
        build(depth);
    }

private:
    Tracked build(int depth) {
        if (depth == 0 || r_.index(5) == 0) return operand();
        const Tracked a = build(depth - 1);
        const Tracked b = (!pool_.empty() && r_.index(3) == 0) ? pool_[r_.index(pool_.size())] : build(depth - 1);
        Tracked v;
        switch (r_.index(Divides ? 4 : 3)) {
        case 0: v = a + b; break;
        case 1: v = a - b; break;
        case 2: v = a * b; break;
        default:
            if constexpr (Divides) v = a / b;
            break;
        }
        if (r_.index(2) == 0) v = v - (r_.index(2) == 0 ? a : b);  // cancel one operand again
        t_.check(v);
        pool_.push_back(v);
        return v;
    }

    Tracked operand() {
        // Mostly the chain's own magnitude; a quarter of the leaves elsewhere.
        const int scale = r_.index(4) == 0 ? scales[r_.index(std::size(scales))] : base_;
        Tracked v = leaf_(random_double(r_, scale));
        t_.check(v);
        return v;
    }

    test_random::rng& r_;
    Tally& t_;
    leaf_of leaf_;
    std::vector<Tracked> pool_;
    int base_ = 0;
};

}  // namespace test_chains
