// SPDX-License-Identifier: BSL-1.0
#pragma once
// Adapters for Boost.Geometry: its points, rings, polygons and multi-polygons
// as influence2d input. Header-only; needs Boost (1.74 or later).

#include <type_traits>

#include <boost/geometry/core/access.hpp>
#include <boost/geometry/core/coordinate_dimension.hpp>
#include <boost/geometry/core/coordinate_system.hpp>
#include <boost/geometry/core/coordinate_type.hpp>
#include <boost/geometry/core/cs.hpp>
#include <boost/geometry/core/exterior_ring.hpp>
#include <boost/geometry/core/interior_rings.hpp>
#include <boost/geometry/core/tag.hpp>
#include <boost/geometry/core/tags.hpp>

#include "influence2d/adapters/traits.hpp"

namespace influence2d {

namespace boost_geometry_detail {

template <class G, class Tag>
struct has_bg_tag : std::is_same<typename boost::geometry::traits::tag<std::remove_cv_t<G>>::type, Tag> {};

template <class P>
struct is_bg_plane_point
    : std::bool_constant<
          boost::geometry::dimension<P>::value == 2 &&
          std::is_same_v<typename boost::geometry::coordinate_system<P>::type, boost::geometry::cs::cartesian> &&
          std::is_arithmetic_v<typename boost::geometry::coordinate_type<P>::type>> {};

/// A Boost.Geometry point model this adapter reads: two Cartesian
/// coordinates of an arithmetic type, and not one of the types traits.hpp
/// adapts itself (std::array, which Boost.Geometry can register too).
template <class P>
inline constexpr bool is_bg_point_v =
    std::conjunction_v<has_bg_tag<P, boost::geometry::point_tag>, std::negation<adapters::is_builtin_point<P>>,
                       is_bg_plane_point<P>>;

}  // namespace boost_geometry_detail

/// Any Boost.Geometry point with two Cartesian coordinates of an arithmetic
/// type (model::d2::point_xy<T>, model::point<T, 2, cs::cartesian>, or a type
/// registered with BOOST_GEOMETRY_REGISTER_POINT_2D): x is get<0>, y is
/// get<1>, each converted exactly by coordinate_to_double. Points of other
/// coordinate systems (geographic, spherical) or dimensions are not points
/// here: the library works in the plane.
template <class P>
struct point_traits<P, std::enable_if_t<boost_geometry_detail::is_bg_point_v<P>>> {
    static double x(const P& p) { return coordinate_to_double(boost::geometry::get<0>(p)); }
    static double y(const P& p) { return coordinate_to_double(boost::geometry::get<1>(p)); }
};

/// Adds a Boost.Geometry polygon (any type with Boost.Geometry's polygon tag,
/// such as model::polygon<P, ClockWise, Closed>) to a builder: its exterior
/// ring as an outer ring, then its interior rings as holes, in their order.
/// The model's declared orientation and closure are not relied upon: each
/// ring's orientation is decided from its points, and a last point equal to
/// the first is dropped whether the model says closed or open.
template <class Polygon,
          std::enable_if_t<boost_geometry_detail::has_bg_tag<Polygon, boost::geometry::polygon_tag>::value, int> = 0>
polygon_builder& add_polygon(polygon_builder& builder, const Polygon& poly) {
    builder.add_outer(boost::geometry::exterior_ring(poly));
    return builder.add_holes(boost::geometry::interior_rings(poly));
}

/// The polygon of a Boost.Geometry polygon: ring 0 is its exterior ring,
/// rings 1, 2, ... its interior rings (holes); see add_polygon and
/// polygon_builder (numbering, errors). An empty exterior ring is refused
/// with invalid_input ("ring 0: fewer than three distinct vertices").
template <class Polygon,
          std::enable_if_t<boost_geometry_detail::has_bg_tag<Polygon, boost::geometry::polygon_tag>::value, int> = 0>
polygon make_polygon(const Polygon& poly) {
    polygon_builder builder;
    return add_polygon(builder, poly).build();
}

/// The polygon of a Boost.Geometry multi-polygon (several outer rings): for
/// each part in order, its exterior ring and then its holes, numbered on
/// across the parts as WKT's MULTIPOLYGON is read. Parts may touch at
/// vertices. An empty multi-polygon is refused with invalid_input.
template <class MultiPolygon,
          std::enable_if_t<boost_geometry_detail::has_bg_tag<MultiPolygon, boost::geometry::multi_polygon_tag>::value,
                           int> = 0>
polygon make_polygon(const MultiPolygon& parts) {
    return adapters::build_from_parts(parts);
}

}  // namespace influence2d
