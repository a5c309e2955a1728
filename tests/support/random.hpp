// SPDX-License-Identifier: BSL-1.0
#pragma once
// The tests' one random source: a seeded std::mt19937_64 with the draws the
// tests need (53-bit uniform doubles, indices, coin flips). The same seed
// gives the same stream on every platform: no std::*_distribution, whose
// output the standard leaves to the implementation.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>

namespace test_random {

struct rng {
    std::mt19937_64 gen;
    explicit rng(std::uint64_t seed) : gen(seed) {}
    /// Uniform in [0, 1), 53 random bits.
    double unit() { return std::ldexp(static_cast<double>(gen() >> 11), -53); }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform in [-1, 1).
    double signed_unit() { return 2 * unit() - 1; }
    /// Uniform in {0, ..., n - 1} (up to a bias of n / 2^64).
    std::size_t index(std::size_t n) { return static_cast<std::size_t>(gen() % n); }
    /// True with probability p.
    bool chance(double p) { return unit() < p; }
};

}  // namespace test_random
