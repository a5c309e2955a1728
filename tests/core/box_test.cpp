// SPDX-License-Identifier: BSL-1.0
// The box of a range of points (box::add over [first, last), taken on four
// interleaved boxes) against the box that adding each point in turn makes,
// on random ranges of every length up to 40 with NaN, infinite, signed-zero
// and repeated coordinates mixed in; and box_membership against
// box::contains.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "influence2d/core/box.hpp"

using namespace influence2d;

namespace {

// Whether two doubles compare the same (NaN equal to NaN; +0 and -0 equal,
// as every use of a box compares them).
bool same_bound(double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; }

bool same_box(const box& l, const box& r) {
    return same_bound(l.min_x, r.min_x) && same_bound(l.min_y, r.min_y) && same_bound(l.max_x, r.max_x) &&
           same_bound(l.max_y, r.max_y);
}

}  // namespace

TEST_CASE("box: the box of a range of points is the box of its points added one by one", "[box]") {
    std::mt19937_64 rng(20261201);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const double specials[] = {nan, inf, -inf, 0.0, -0.0, 1e300, -1e-300, 0x1p-1074};
    std::uniform_real_distribution<double> coordinate(-100, 100);
    std::uniform_int_distribution<int> pick(0, 15);
    std::size_t differing = 0, cases = 0;
    for (std::size_t length = 0; length <= 40; ++length)
        for (int trial = 0; trial < 50; ++trial) {
            std::vector<point<double>> v(length);
            for (point<double>& p : v) {
                const int kx = pick(rng), ky = pick(rng);
                p.x = kx < 8 ? specials[kx] : coordinate(rng);
                p.y = ky < 8 ? specials[ky] : coordinate(rng);
            }
            // From an empty box, and from a box that already holds a point.
            for (const bool start_empty : {true, false}) {
                box one_by_one, at_once;
                if (!start_empty) {
                    one_by_one.add({0.5, -0.5});
                    at_once.add({0.5, -0.5});
                }
                for (const point<double>& p : v) one_by_one.add(p);
                at_once.add(v.data(), v.data() + v.size());
                ++cases;
                if (!same_box(one_by_one, at_once)) ++differing;
            }
        }
    CHECK(cases == 41 * 50 * 2);
    CHECK(differing == 0);
}

TEST_CASE("box: a range whose every coordinate is NaN leaves the box as it was", "[box]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<point<double>> v(9, point<double>{nan, nan});
    box b;
    b.add(v.data(), v.data() + v.size());
    CHECK(b.empty());
    b.add({1, 2});
    b.add(v.data(), v.data() + v.size());
    CHECK((b.min_x == 1 && b.max_x == 1 && b.min_y == 2 && b.max_y == 2));
}

TEST_CASE("box: box_membership answers as box::contains", "[box]") {
    // Boxes and points drawn from a few values, so that sides are hit
    // exactly; NaN, infinite and signed-zero coordinates and bounds mixed in,
    // empty and inverted boxes too.
    std::mt19937_64 rng(20261207);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const double values[] = {nan, inf, -inf, 0.0, -0.0, -1, 1, 2, 0x1p-1074, 1e300, 1.5, std::nextafter(1.0, 2.0)};
    std::uniform_int_distribution<std::size_t> pick(0, std::size(values) - 1);
    std::size_t inside = 0, outside = 0, differing = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const box b{values[pick(rng)], values[pick(rng)], values[pick(rng)], values[pick(rng)]};
        const box_membership m(b);
        for (int k = 0; k < 8; ++k) {
            const point<double> p{values[pick(rng)], values[pick(rng)]};
            const bool want = b.contains(p);
            (want ? inside : outside) += 1;
            differing += m.contains(p) != want;
        }
    }
    CHECK(differing == 0);
    // Not vacuous: both answers often.
    CHECK(inside > 2000);
    CHECK(outside > 10000);
}
