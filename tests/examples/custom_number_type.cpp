// SPDX-License-Identifier: BSL-1.0
// A number type of your own: any type with +, -, * and comparisons becomes a
// detector number type once influence2d::number_traits is specialised for it.
// Here Boost.Multiprecision's 50-digit binary floating point (header-only),
// compared with double along a trajectory.
#include <cmath>
#include <cstdio>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <influence2d/influence2d.hpp>

using float50 = boost::multiprecision::cpp_bin_float_50;

// What the library needs to know about the type (number/traits.hpp).
template <>
struct influence2d::number_traits<float50> {
    // Operations round (to about 166 bits): answers can differ from the exact
    // ones near contact, like double's, only much closer to it.
    static constexpr number_category category = number_category::floating;
    static constexpr const char* name = "float50";
    static float50 from_double(double x) { return float50(x); }  // exact
    static double to_double(const float50& x) { return x.convert_to<double>(); }
    static int sign(const float50& x) { return x.sign(); }
    // The filters run in double; they are widened by this relative margin so
    // that they never drop what a decision in float50 would keep.
    static constexpr double filter_slack = 1e-12;
};

int main() {
    using namespace influence2d;
    // A star-shaped static polygon and a triangle orbiting it, turning as it goes.
    const polygon star(
        {ring_input{{{4, 0}, {1, 1}, {0, 4}, {-1, 1}, {-4, 0}, {-1, -1}, {0, -4}, {1, -1}}, ring_role::outer}});
    const polygon triangle({ring_input{{{0, 0}, {1.5, 0}, {0, 1.5}}, ring_role::outer}});
    detector_options options;
    options.witness = true;
    detector<float50> wide(star, triangle, options);
    detector<double> plain(star, triangle, options);

    int frames = 0, agree = 0, collisions = 0;
    for (int k = 0; k < 12; ++k) {  // 12 poses on a circle of radius 3
        const double phi = 2 * 3.141592653589793 * k / 12;
        const pose q{3 * std::cos(phi), 3 * std::sin(phi), phi};
        const frame_result a = wide.collide(q), b = plain.collide(q);
        ++frames;
        agree += a.collides == b.collides && a.pairs == b.pairs;
        collisions += a.collides;
        std::printf("frame %2d: float50 %s (%zu pairs), double %s (%zu pairs)\n", k, a.collides ? "collides" : "apart",
                    a.pairs.size(), b.collides ? "collides" : "apart", b.pairs.size());
    }
    // Far from contact the two types answer alike; only a pose within a few
    // double roundings of contact could tell them apart, and none is here.
    std::printf("%s and double agree on %d of %d frames (%d collide)\n", number_traits<float50>::name, agree, frames,
                collisions);
    return agree == frames && collisions > 0 && collisions < frames ? 0 : 1;
}
