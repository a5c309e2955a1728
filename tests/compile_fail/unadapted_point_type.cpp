// SPDX-License-Identifier: BSL-1.0
// Must not compile: a polygon from a ring of a point type that has no
// influence2d::point_traits specialisation. The first error is to be the
// library's static_assert asking for one (tests/compile_fail/compile_fail.cmake).
#include <vector>

#include <influence2d/adapters/traits.hpp>

namespace {

/// A point type of the caller's own, not adapted.
struct vec2 {
    float u, v;
};

}  // namespace

int main() {
    const std::vector<vec2> ring{{0, 0}, {1, 0}, {0, 1}};
#if defined(INFLUENCE2D_THROUGH_BUILDER)
    const influence2d::polygon p = influence2d::polygon_builder().add_outer(ring).build();
#else
    const influence2d::polygon p = influence2d::make_polygon(ring);
#endif
    return static_cast<int>(p.ring_count());
}
