// SPDX-License-Identifier: BSL-1.0
// Must not compile: a detector over a number type that has no
// influence2d::number_traits specialisation. The first error is to be the
// library's static_assert asking for one (tests/compile_fail/compile_fail.cmake).
#include <influence2d/influence2d.hpp>

namespace {

/// A number type with every operation the library uses, but no traits.
struct fixed_point {
    long long raw = 0;
    fixed_point() = default;
    fixed_point(int x) : raw(x) {}  // NOLINT: integer constants as in NT(0)
    friend fixed_point operator+(fixed_point a, fixed_point b) { return fixed_point(a.raw + b.raw, 0); }
    friend fixed_point operator-(fixed_point a, fixed_point b) { return fixed_point(a.raw - b.raw, 0); }
    friend fixed_point operator-(fixed_point a) { return fixed_point(-a.raw, 0); }
    friend fixed_point operator*(fixed_point a, fixed_point b) { return fixed_point(a.raw * b.raw, 0); }
    friend bool operator<(fixed_point a, fixed_point b) { return a.raw < b.raw; }
    friend bool operator>(fixed_point a, fixed_point b) { return a.raw > b.raw; }
    friend bool operator<=(fixed_point a, fixed_point b) { return a.raw <= b.raw; }
    friend bool operator>=(fixed_point a, fixed_point b) { return a.raw >= b.raw; }
    friend bool operator==(fixed_point a, fixed_point b) { return a.raw == b.raw; }
    friend bool operator!=(fixed_point a, fixed_point b) { return a.raw != b.raw; }

private:
    fixed_point(long long r, int) : raw(r) {}
};

}  // namespace

int main() {
    using namespace influence2d;
    const polygon square({ring_input{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, ring_role::outer}});
    detector<fixed_point> d(square, square);
    return d.collide(pose{0, 0, 0}).collides ? 0 : 1;
}
