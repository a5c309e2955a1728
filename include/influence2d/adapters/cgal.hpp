// SPDX-License-Identifier: BSL-1.0
#pragma once
// Adapters for CGAL: Point_2 of any kernel, Polygon_2 and Polygon_with_holes_2
// as influence2d input. Part of the CGAL component (CMake target
// influence2d::cgal; CGAL and, for exact kernels, GMP).

#include <cmath>
#include <string>
#include <type_traits>

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Point_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/number_utils.h>

#include "influence2d/adapters/traits.hpp"
#include "influence2d/core/shortest_decimal.hpp"

namespace influence2d {

namespace cgal_adapter_detail {

/// The exact value behind a CGAL number: the number itself, or for a lazy
/// number (Epeck's field type) its exact value, computed if need be.
template <class FT>
const FT& exact_value(const FT& v) {
    return v;
}
template <class ET>
const ET& exact_value(const CGAL::Lazy_exact_nt<ET>& v) {
    return v.exact();
}

/// The double equal to a kernel coordinate, or invalid_input when there is
/// none. A floating-point field type (Epick's double, float) converts as is,
/// NaN and infinities included (the polygon refuses those). For an exact
/// field type the double from CGAL::to_double is converted back to the exact
/// type and compared: a coordinate such as 1/3 is refused, not rounded.
template <class FT>
double cgal_coordinate_to_double(const FT& v) {
    if constexpr (std::is_floating_point_v<FT>) {
        return coordinate_to_double(v);
    } else {
        const auto& e = exact_value(v);
        using ET = std::decay_t<decltype(e)>;
        const double d = CGAL::to_double(e);
        if (!std::isfinite(d)) throw invalid_input("value is beyond the range of double");
        if (ET(d) != e)
            throw invalid_input("value is not exactly a double (the nearest is about " + shortest_decimal(d) + ")");
        return d;
    }
}

template <class T>
struct is_cgal_polygon_with_holes : std::false_type {};
template <class K, class C>
struct is_cgal_polygon_with_holes<CGAL::Polygon_with_holes_2<K, C>> : std::true_type {};

}  // namespace cgal_adapter_detail

/// CGAL's Point_2 of any kernel (Epick, Epeck, Simple_cartesian<FT>,
/// Cartesian<FT>, ...): x() and y() converted to double exactly. With an
/// exact kernel a coordinate that no double equals (1/3, or a value beyond
/// double's range) throws invalid_input: the detector works on double input
/// and must not silently move a vertex. Lazy coordinates (Epeck) are
/// evaluated exactly for the check.
template <class K>
struct point_traits<CGAL::Point_2<K>> {
    /// The x coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double x(const CGAL::Point_2<K>& p) { return cgal_adapter_detail::cgal_coordinate_to_double(p.x()); }
    /// The y coordinate as a double, checked to be exactly a double (invalid_input otherwise).
    static double y(const CGAL::Point_2<K>& p) { return cgal_adapter_detail::cgal_coordinate_to_double(p.y()); }
};

/// Adds a CGAL Polygon_2 to a builder as a ring of the given role. Its
/// orientation and simplicity are not required: the polygon decides the
/// orientation itself, and a self-intersecting ring is taken as it is
/// (its boundary is every edge).
template <class K, class C>
polygon_builder& add_polygon(polygon_builder& builder, const CGAL::Polygon_2<K, C>& ring,
                             ring_role role = ring_role::outer) {
    return builder.add_ring(ring.container(), role);
}

/// Adds a CGAL Polygon_with_holes_2: its outer boundary as an outer ring,
/// then its holes in order. An unbounded one (no outer boundary: the plane
/// minus its holes) is refused with invalid_input: the library's polygons
/// are bounded.
template <class K, class C>
polygon_builder& add_polygon(polygon_builder& builder, const CGAL::Polygon_with_holes_2<K, C>& poly) {
    if (poly.is_unbounded())
        throw invalid_input("ring " + std::to_string(builder.ring_count()) +
                            ": unbounded polygon with holes (no outer boundary)");
    add_polygon(builder, poly.outer_boundary(), ring_role::outer);
    for (auto h = poly.holes_begin(); h != poly.holes_end(); ++h) add_polygon(builder, *h, ring_role::hole);
    return builder;
}

/// The polygon bounded by a CGAL Polygon_2 (one outer ring, vertex order as
/// stored, either orientation). See polygon_builder (numbering, errors).
template <class K, class C>
polygon make_polygon(const CGAL::Polygon_2<K, C>& ring) {
    polygon_builder builder;
    return add_polygon(builder, ring).build();
}

/// The polygon of a CGAL Polygon_with_holes_2: ring 0 its outer boundary,
/// rings 1, 2, ... its holes. See add_polygon for the unbounded case.
template <class K, class C>
polygon make_polygon(const CGAL::Polygon_with_holes_2<K, C>& poly) {
    polygon_builder builder;
    return add_polygon(builder, poly).build();
}

/// The polygon of several CGAL Polygon_with_holes_2 (a std::vector or any
/// range of them, as CGAL's Boolean operations output): each part's outer
/// boundary, then its holes, numbered on across the parts. Parts may touch.
/// An empty range is refused with invalid_input.
template <class Range,
          std::enable_if_t<cgal_adapter_detail::is_cgal_polygon_with_holes<adapters::element_t<Range>>::value, int> = 0>
polygon make_polygon(const Range& parts) {
    return adapters::build_from_parts(parts);
}

}  // namespace influence2d
