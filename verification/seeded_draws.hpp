// SPDX-License-Identifier: BSL-1.0
#pragma once
// The seeded draws of the scene generators (verification/families.hpp,
// verification/stiff_cases.hpp): the same numbers on every platform for the
// same seed, never through a library distribution, whose algorithm is
// implementation-defined.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace influence2d::verification {

/// Pi, as the generators draw angles with it.
inline constexpr double pi = 3.14159265358979323846;

/// The splitmix64 finaliser: decorrelates nearby seeds.
inline std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/// Uniform doubles in [0, 1) from the top 53 bits (never a library distribution,
/// whose algorithm is implementation-defined).
class uniform_source {
public:
    explicit uniform_source(std::uint64_t seed) : engine_(seed) {}
    double next() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double between(double lo, double hi) { return lo + (hi - lo) * next(); }

private:
    std::mt19937_64 engine_;
};

/// `count` increasing angles from `start` covering `span`: the gaps are
/// span * w_k / sum(w) with weights w_k uniform in [1 - spread, 1 + spread].
/// With `closed` the gaps go once around (count gaps, last back to the first
/// angle); otherwise count - 1 gaps run from `start` to `start + span`.
inline std::vector<double> jittered_angles(uniform_source& u, std::size_t count, double start, double span,
                                           double spread, bool closed) {
    const std::size_t gaps = closed ? count : count - 1;
    std::vector<double> w(gaps);
    double total = 0;
    for (double& x : w) {
        x = u.between(1 - spread, 1 + spread);
        total += x;
    }
    std::vector<double> angles(count);
    double sum = 0;
    for (std::size_t k = 0; k < count; ++k) {
        angles[k] = start + span * (sum / total);
        if (k < gaps) sum += w[k];
    }
    return angles;
}

/// Smooth random wobble in [-1, 1]: the mean of three sinusoids of low
/// frequency with random phases.
class wobble {
public:
    explicit wobble(uniform_source& u) {
        for (double& p : phase_) p = u.between(0, 2 * pi);
    }
    double operator()(double angle) const {
        return (std::sin(angle + phase_[0]) + std::sin(2 * angle + phase_[1]) + std::sin(3 * angle + phase_[2])) / 3;
    }

private:
    double phase_[3] = {};
};

}  // namespace influence2d::verification
