// SPDX-License-Identifier: BSL-1.0
#pragma once
// Adapters: polygons built from the caller's own point and ring types.
//
// A point type becomes usable by specialising point_traits; a ring is then any
// range of such points (anything a range-based for loop accepts), and
// make_polygon or polygon_builder turns rings into an influence2d::polygon.
// Ready specialisations: influence2d::point<T>, std::array<T, 2> and
// std::pair<T, T> for arithmetic T (this header); Boost.Geometry points
// (adapters/boost_geometry.hpp); CGAL's Point_2 (adapters/cgal.hpp).
//
// The detector works on double input. A coordinate that has no exactly equal
// double is refused with invalid_input rather than rounded: rounding would
// silently move a vertex and change the geometry that is tested.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"

namespace influence2d {

/// How the adapters read a point of type P. The primary template is left
/// undefined (so that is_point_v can ask about any type); a ring of a point
/// type without a specialisation stops make_polygon and polygon_builder with
/// a static_assert saying to specialise point_traits. A type is a point once a
/// specialisation provides
///
///     static double x(const P&);   // the x coordinate as a double
///     static double y(const P&);   // the y coordinate as a double
///
/// Both must return the coordinate exactly. A coordinate that has no equal
/// double should make them throw invalid_input with a message saying why (the
/// adapters add the ring and vertex); coordinate_to_double does this for the
/// arithmetic types. NaN and infinities may be returned: the polygon refuses
/// them, naming ring and vertex. The second parameter is for specialisations
/// that match a family of types through std::enable_if_t.
template <class P, class Enable = void>
struct point_traits;

/// The double equal to the arithmetic value v, or invalid_input when there is
/// none: float and double always convert; long double converts when its value
/// is a double (NaN and infinities pass through, for the polygon to refuse);
/// integers convert when their magnitude is at most 2^53. Larger integers are
/// refused even when the particular value is a double (2^60 is): above 2^53
/// not every integer is one, and whether a ring is accepted should not depend
/// on which of its integers happen to be.
template <class T>
double coordinate_to_double(T v) {
    static_assert(std::is_arithmetic_v<T>, "coordinate_to_double takes an arithmetic type");
    if constexpr (std::is_integral_v<T>) {
        if constexpr (std::numeric_limits<T>::digits > 53) {
            constexpr T limit = T(1) << 53;
            bool beyond = v > limit;
            if constexpr (std::is_signed_v<T>) beyond = beyond || v < -limit;
            if (beyond) {
                std::string text = "integer";
                if constexpr (std::numeric_limits<T>::digits <= 64) text += " " + std::to_string(v);
                throw invalid_input(text + " is beyond 2^53 in magnitude, where not every integer is a double");
            }
        }
        return static_cast<double>(v);
    } else {
        const double d = static_cast<double>(v);
        if (std::isfinite(v) && static_cast<T>(d) != v) {
            std::array<char, 64> text{};
            std::snprintf(text.data(), text.size(), "%.21Lg", static_cast<long double>(v));
            throw invalid_input(std::string("value ") + text.data() + " is not exactly a double");
        }
        return d;
    }
}

/// The parts the adapter headers (adapters/boost_geometry.hpp,
/// adapters/cgal.hpp) share with this one: range and ring checks, the
/// polygon of a range of parts.
namespace adapters {

/// The types this header adapts itself; the Boost.Geometry adapter leaves
/// them alone even where Boost.Geometry registers them as points too.
template <class P>
struct is_builtin_point : std::false_type {};
template <class T>
struct is_builtin_point<point<T>> : std::is_arithmetic<T> {};
template <class T>
struct is_builtin_point<std::array<T, 2>> : std::is_arithmetic<T> {};
template <class T>
struct is_builtin_point<std::pair<T, T>> : std::is_arithmetic<T> {};

template <class P, class = void>
struct has_point_traits : std::false_type {};
template <class P>
struct has_point_traits<P, std::void_t<decltype(static_cast<double>(point_traits<P>::x(std::declval<const P&>()))),
                                       decltype(static_cast<double>(point_traits<P>::y(std::declval<const P&>())))>>
    : std::true_type {};

/// begin and end as a range-based for loop finds them: members, or free
/// functions through argument-dependent lookup, or std's for arrays.
/// begin and end as a range-for finds them (std:: or by argument-dependent
/// lookup).
namespace range_lookup {
using std::begin;
using std::end;
/// The iterator type begin() gives for a const R.
template <class R>
using begin_t = decltype(begin(std::declval<const R&>()));
/// The sentinel type end() gives for a const R.
template <class R>
using end_t = decltype(end(std::declval<const R&>()));
}  // namespace range_lookup

/// The element type of a range R.
template <class R>
using element_t = std::decay_t<decltype(*std::declval<range_lookup::begin_t<R>>())>;

template <class R, class = void>
struct is_range : std::false_type {};
template <class R>
struct is_range<R, std::void_t<element_t<R>, range_lookup::end_t<R>>> : std::true_type {};

template <class R, class = void>
struct is_ring : std::false_type {};
template <class R>
struct is_ring<R, std::void_t<element_t<R>, range_lookup::end_t<R>>> : has_point_traits<element_t<R>> {};

template <class R, class = void>
struct is_ring_range : std::false_type {};
template <class R>
struct is_ring_range<R, std::void_t<element_t<R>, range_lookup::end_t<R>>> : is_ring<element_t<R>> {};

/// Instantiated first by every function that reads a ring, so that a ring of
/// a point type without point_traits stops the compilation with this message
/// rather than with a missing member deep inside the adapters.
template <class Ring>
struct ring_check {
    static_assert(is_range<Ring>::value, "a ring is a range of points (a type with begin and end)");
    static_assert(!is_range<Ring>::value || is_ring<Ring>::value,
                  "the ring's point type has no point traits: specialise influence2d::point_traits for it "
                  "(see influence2d/adapters/traits.hpp)");
    static constexpr bool value = true;  ///< true once the checks pass
};

/// As ring_check, for a range of rings (the holes).
template <class Rings>
struct ring_range_check {
    static_assert(is_range<Rings>::value, "the holes are a range of rings (a type with begin and end)");
    static constexpr bool value = ring_check<element_t<Rings>>::value;  ///< true once the checks pass
};

/// "ring R, vertex V", for messages.
inline std::string vertex_place(std::size_t ring, std::size_t vertex) {
    return "ring " + std::to_string(ring) + ", vertex " + std::to_string(vertex);
}

}  // namespace adapters

/// True when P has point_traits (a usable specialisation).
template <class P>
inline constexpr bool is_point_v = adapters::has_point_traits<P>::value;
/// True when R is a range (begin/end) of points.
template <class R>
inline constexpr bool is_ring_v = adapters::is_ring<R>::value;
/// True when R is a range of rings.
template <class R>
inline constexpr bool is_ring_range_v = adapters::is_ring_range<R>::value;

/// influence2d's own point, for any arithmetic coordinate type.
template <class T>
struct point_traits<point<T>, std::enable_if_t<std::is_arithmetic_v<T>>> {
    /// The x coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double x(const point<T>& p) { return coordinate_to_double(p.x); }
    /// The y coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double y(const point<T>& p) { return coordinate_to_double(p.y); }
};

/// std::array<T, 2>: element 0 is x, element 1 is y.
template <class T>
struct point_traits<std::array<T, 2>, std::enable_if_t<std::is_arithmetic_v<T>>> {
    /// The x coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double x(const std::array<T, 2>& p) { return coordinate_to_double(p[0]); }
    /// The y coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double y(const std::array<T, 2>& p) { return coordinate_to_double(p[1]); }
};

/// std::pair<T, T>: first is x, second is y.
template <class T>
struct point_traits<std::pair<T, T>, std::enable_if_t<std::is_arithmetic_v<T>>> {
    /// The x coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double x(const std::pair<T, T>& p) { return coordinate_to_double(p.first); }
    /// The y coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double y(const std::pair<T, T>& p) { return coordinate_to_double(p.second); }
};

/// Collects rings, each from any range of points, and builds the polygon.
/// Rings are numbered 0, 1, ... in the order they are added and vertices
/// 0, 1, ... within a ring in range order; edge k of a ring goes from its
/// vertex k to vertex k + 1 (the last back to vertex 0), and the polygon's
/// source_edge numbers and the detector's witness pairs follow this order.
///
/// A ring may come closed or open: a last point equal to the first (after
/// conversion to double) is taken as the closing repetition and dropped; any
/// other repeated point stays, as a zero-length edge. Orientation is free:
/// the polygon reorients outer rings counter-clockwise and holes clockwise,
/// deciding the orientation exactly. Several outer rings are allowed, as are
/// rings touching at vertices. A hole is not tied to an outer ring: the
/// region is influence2d::polygon's, the points on a ring and those around
/// which the winding numbers of the rings (outer +1, hole -1) do not sum to 0.
///
/// Errors are invalid_input, never undefined behaviour: from add_ring, a
/// coordinate that is not exactly a double ("ring r, vertex k: x: ...", the
/// builder left as it was before the call); from
/// build, a NaN or infinite coordinate (ring and vertex), a ring with fewer
/// than three distinct points (ring), or no ring at all.
class polygon_builder {
public:
    /// Adds a ring of the given role; returns *this for chaining.
    template <class Ring>
    polygon_builder& add_ring(const Ring& ring, ring_role role) {
        static_assert(adapters::ring_check<Ring>::value);
        using P = adapters::element_t<Ring>;
        ring_input in;
        in.role = role;
        const std::size_t r = rings_.size();
        std::size_t k = 0;
        for (const auto& p : ring) {
            in.vertices.push_back({read(r, k, "x", [&] { return point_traits<P>::x(p); }),
                                   read(r, k, "y", [&] { return point_traits<P>::y(p); })});
            ++k;
        }
        rings_.push_back(std::move(in));
        return *this;
    }
    /// Adds an outer boundary.
    template <class Ring>
    polygon_builder& add_outer(const Ring& ring) {
        return add_ring(ring, ring_role::outer);
    }
    /// Adds a hole.
    template <class Ring>
    polygon_builder& add_hole(const Ring& ring) {
        return add_ring(ring, ring_role::hole);
    }
    /// Adds every ring of a range of rings as a hole.
    template <class Rings>
    polygon_builder& add_holes(const Rings& rings) {
        static_assert(adapters::ring_range_check<Rings>::value);
        for (const auto& ring : rings) add_hole(ring);
        return *this;
    }

    /// How many rings have been added.
    std::size_t ring_count() const { return rings_.size(); }
    /// The rings as added so far, closing repetitions included (the polygon
    /// drops them, and only them).
    const std::vector<ring_input>& rings() const { return rings_; }

    /// The polygon of the rings added (see the class comment for errors).
    polygon build() const { return polygon(rings_); }

private:
    template <class Read>
    static double read(std::size_t ring, std::size_t vertex, const char* axis, Read&& get) {
        try {
            return static_cast<double>(get());
        } catch (const invalid_input& e) {
            throw invalid_input(adapters::vertex_place(ring, vertex) + ": " + axis + ": " + e.what());
        }
    }

    std::vector<ring_input> rings_;
};

namespace adapters {

/// The polygon of a range of parts (polygons with holes of some library),
/// each added in order by the add_polygon overload for its type (declared by
/// the adapter headers in namespace influence2d, found by argument-dependent
/// lookup through polygon_builder).
template <class Parts>
polygon build_from_parts(const Parts& parts) {
    polygon_builder builder;
    for (const auto& part : parts) add_polygon(builder, part);
    return builder.build();
}

/// Whether add_polygon takes a T (a polygon type of some library, adapted by
/// the headers that declare add_polygon for it).
template <class T, class = void>
struct is_part : std::false_type {};
template <class T>
struct is_part<T, std::void_t<decltype(add_polygon(std::declval<polygon_builder&>(), std::declval<const T&>()))>>
    : std::true_type {};

/// What make_polygon takes as a ring: a range of points, or a range of
/// elements that are neither ranges nor polygons of an adapted library (then
/// most likely points without point_traits, which ring_check reports).
template <class R, class = void>
struct is_ring_candidate : is_ring<R> {};
template <class R>
struct is_ring_candidate<R, std::enable_if_t<is_range<R>::value && !is_ring<R>::value>>
    : std::bool_constant<!is_range<element_t<R>>::value && !is_part<element_t<R>>::value> {};

}  // namespace adapters

/// The polygon bounded by one ring (a range of points, closed or open, either
/// orientation; see polygon_builder for numbering and errors).
template <class Ring, std::enable_if_t<adapters::is_ring_candidate<Ring>::value, int> = 0>
polygon make_polygon(const Ring& outer) {
    static_assert(adapters::ring_check<Ring>::value);
    return polygon_builder().add_outer(outer).build();
}

/// The polygon bounded by `outer` (ring 0) with the rings of `holes` as holes
/// (rings 1, 2, ... in range order). Holes are meant to lie inside the outer
/// ring; nothing checks it. See polygon_builder for numbering and errors.
template <class Ring, class Holes,
          std::enable_if_t<adapters::is_ring_candidate<Ring>::value && adapters::is_range<Holes>::value, int> = 0>
polygon make_polygon(const Ring& outer, const Holes& holes) {
    static_assert(adapters::ring_check<Ring>::value && adapters::ring_range_check<Holes>::value);
    return polygon_builder().add_outer(outer).add_holes(holes).build();
}

}  // namespace influence2d
