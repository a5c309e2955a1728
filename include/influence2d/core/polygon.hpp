// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The polygon model: any number of closed rings of double coordinates.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "influence2d/number/unit_roundoff.hpp"

namespace influence2d {

/// What a ring bounds: the region (outer) or a hole in it.
enum class ring_role : std::uint8_t {
    outer,  ///< an outer boundary; stored counter-clockwise
    hole    ///< a hole; stored clockwise
};

/// One ring as read: its vertices without the closing repetition of the first.
struct ring_input {
    /// The vertices in order, in either orientation. A closing copy of the
    /// first vertex, if given, is dropped (as make_polygon and the WKT reader
    /// drop it), so a ring numbers its edges the same closed or open.
    std::vector<point<double>> vertices;
    ring_role role = ring_role::outer;  ///< decides the stored orientation
};

/// A polygon: outer rings and holes, possibly several outer rings, possibly
/// touching at vertices. Rings are stored with the interior on the left (outer
/// rings counter-clockwise, holes clockwise); the ring orientation is decided
/// exactly. Vertices of all rings are stored in one array, ring after ring; the
/// edge with index i goes from vertex i to vertex next(i). Repeated vertices are
/// kept as zero-length edges so that edge numbers stay those of the input.
///
/// The region is closed: a point is in it when it lies on an edge, or when
/// the rings' winding number around it (outer rings +1, holes -1) is not
/// zero. So nested outer rings add nothing, and a hole outside every outer
/// ring is itself region (winding -1). Accepted as they are: repeated
/// vertices, collinear runs, spikes, self-intersections, rings that touch or
/// cross, rings of zero area (their edges are still boundary).
class polygon {
public:
    /// The most vertices (and edges) a polygon holds: their numbers are kept
    /// in 32 bits, here and in the edge boxes and trees that name them.
    static constexpr std::size_t max_vertices = 0xffffffffu;

    /// An empty placeholder to assign to: no ring, no vertex (size() and
    /// ring_count() are 0). Detectors and the readers' writers need a polygon
    /// built from rings.
    polygon() = default;

    /// Builds the polygon from its rings, in time linear in the vertices.
    /// Throws invalid_input naming ring and vertex for a non-finite coordinate
    /// or a ring with fewer than three distinct vertices, for an empty list,
    /// and for more than max_vertices vertices in all. Each ring is reversed
    /// when the exact sign of its area disagrees with its role; a ring of
    /// zero area keeps the input order.
    explicit polygon(std::vector<ring_input> rings) {
        if (rings.empty()) throw invalid_input("polygon has no ring");
        std::size_t given = 0;  // vertices as given, closing copies included: room enough
        for (const ring_input& ring : rings) given += ring.vertices.size();
        vertices_.reserve(given);
        next_.reserve(given);
        source_edge_.reserve(given);
        ring_begin_.reserve(rings.size() + 1);
        roles_.reserve(rings.size());
        for (std::size_t r = 0; r < rings.size(); ++r) add_ring(r, std::move(rings[r]));
        ring_begin_.push_back(vertices_.size());
        centroid_ = compute_centroid();
        bounds_.add(vertices_.data(), vertices_.data() + vertices_.size());
    }

    /// The number of vertices of all rings, which is also the number of edges.
    std::size_t size() const { return vertices_.size(); }
    /// Every vertex in stored order: ring after ring, each ring oriented as
    /// its role says.
    const std::vector<point<double>>& vertices() const { return vertices_; }
    /// Vertex i in stored order, the start of edge i; requires i < size().
    const point<double>& vertex(std::size_t i) const { return vertices_[i]; }
    /// The index of the end vertex of edge i (the next vertex on its ring; the
    /// ring's first vertex after its last).
    std::size_t next(std::size_t i) const { return next_[i]; }
    /// The index of the start vertex of the edge before edge i on its ring
    /// (the ring's last vertex before its first); requires i < size().
    std::size_t previous(std::size_t i) const {
        if (i > 0 && next_[i - 1] == i) return i - 1;
        // (i begins its ring: the ring's end follows i among the ring starts.)
        return *std::upper_bound(ring_begin_.begin(), ring_begin_.end(), i) - 1;
    }
    /// The number of rings, as given to the constructor.
    std::size_t ring_count() const { return ring_begin_.empty() ? 0 : ring_begin_.size() - 1; }
    /// The index of ring r's first vertex (and edge); requires r < ring_count().
    std::size_t ring_begin(std::size_t r) const { return ring_begin_[r]; }
    /// One past the index of ring r's last vertex (and edge).
    std::size_t ring_end(std::size_t r) const { return ring_begin_[r + 1]; }
    /// The role ring r was given on input.
    ring_role role(std::size_t r) const { return roles_[r]; }
    /// The input's number of edge i: its position in the input order of the
    /// vertices, ring after ring, before any reorientation.
    std::size_t source_edge(std::size_t i) const { return source_edge_[i]; }
    /// The area centroid (the vertex mean for a polygon of zero area), rounded
    /// to double once so that every number type uses the same point.
    /// Computed in long double relative to the first vertex: approximate, and
    /// any point would do for the covering; it is the origin O of the covering (docs/method.md section 2).
    const point<double>& centroid() const { return centroid_; }
    /// The box of all vertices.
    const box& bounds() const { return bounds_; }
    /// Bytes of the heap blocks the polygon holds.
    std::size_t heap_bytes() const {
        return vertices_.capacity() * sizeof(point<double>) +
               (next_.capacity() + source_edge_.capacity()) * sizeof(std::uint32_t) +
               ring_begin_.capacity() * sizeof(std::size_t) + roles_.capacity() * sizeof(ring_role);
    }
    /// The same polygon with every coordinate multiplied by 2^k (std::ldexp):
    /// its rings, their orientation and the edge numbers kept, centroid, box
    /// and area scaled with it. Exact unless a coordinate overflows or falls
    /// among the subnormals (core/range_scaling.hpp brings a floating type's
    /// query into its range with it).
    polygon scaled_by_power_of_two(int k) const {
        polygon p = *this;
        for (point<double>& v : p.vertices_) v = {std::ldexp(v.x, k), std::ldexp(v.y, k)};
        p.centroid_ = {std::ldexp(centroid_.x, k), std::ldexp(centroid_.y, k)};
        p.bounds_.min_x = std::ldexp(bounds_.min_x, k);
        p.bounds_.min_y = std::ldexp(bounds_.min_y, k);
        p.bounds_.max_x = std::ldexp(bounds_.max_x, k);
        p.bounds_.max_y = std::ldexp(bounds_.max_y, k);
        p.area_ = std::ldexp(area_, 2 * k);
        return p;
    }
    /// Signed area in long double, after reorientation (non-negative for a
    /// valid polygon): outer rings add, holes subtract. Rounded, so its sign
    /// is not exact; signed_area_sign() gives a ring's exact sign.
    long double area() const { return area_; }

    /// How many distinct vertices a ring has, counted up to 3 (a ring needs 3).
    /// Vertices compare with double `==`, so +0 equals -0 and each NaN counts
    /// as distinct.
    static std::size_t count_distinct(const std::vector<point<double>>& vs) {
        std::array<point<double>, 3> seen;
        std::size_t count = 0;
        for (const auto& v : vs) {
            bool found = false;
            for (std::size_t k = 0; k < count; ++k) found = found || seen[k] == v;
            if (!found) seen[count++] = v;
            if (count == seen.size()) break;
        }
        return count;
    }

    /// The exact sign of a ring's signed area: +1 counter-clockwise, -1
    /// clockwise, 0 for zero area (collinear vertices, or lobes that cancel, as
    /// in a figure eight). The shoelace sum is evaluated exactly whatever the
    /// magnitude of the coordinates, which must be finite; no vertex gives 0.
    ///
    ///     S  = sum of the 2n products x_k y_k+1 and -y_k x_k+1, in double
    ///     M  = sum of their magnitudes, in double
    ///     if |S| > shoelace_bound(n, M): the sign of S
    ///     else: the sign of the exact fixed-point sum (number/exact_sum.hpp)
    static int signed_area_sign(const std::vector<point<double>>& vs) {
        double sum = 0, magnitude = 0;
        for (std::size_t k = 0; k < vs.size(); ++k) {
            const auto& a = vs[k];
            const auto& b = vs[(k + 1) % vs.size()];
            const double p = a.x * b.y, q = a.y * b.x;
            sum += p;
            sum -= q;
            magnitude += std::fabs(p);
            magnitude += std::fabs(q);
        }
        const double bound = shoelace_bound(vs.size(), magnitude);
        if (sum > bound) return 1;
        if (sum < -bound) return -1;
        return exact_signed_area_sign(vs);
    }

    /// How far the shoelace sum of a ring of n vertices, its 2n products
    /// rounded and added in double (S), may lie from the exact sum, given the
    /// sum of the rounded products' magnitudes as computed (M); infinite when M
    /// overflowed, so that no sign is taken from it. With u = 2^-53:
    ///   - each product is p (1 + d) + e, |d| <= u, |e| <= 2^-1075 (underflow);
    ///   - the 2n - 1 additions add at most g(2n - 1) times the sum of the
    ///     rounded magnitudes, g(m) = m u / (1 - m u) (Higham, Accuracy and
    ///     Stability of Numerical Algorithms, 2nd ed., (4.4)); additions of
    ///     subnormals are exact;
    ///   - so |S - exact| <= g(2n) P + 2n 2^-1074, P the exact sum of the
    ///     products' magnitudes, and P <= (M / (1 - g(2n - 1)) + 2n 2^-1075) /
    ///     (1 - u) by the same two steps backwards.
    /// For n <= 2^40 (2n u <= 2^-12) all the factors together stay below 3 n u
    /// M + 2n 2^-1073; 4 n u leaves room for the rounding of the bound itself
    /// (one product, one sum, each within a factor 1 + u). A contracted
    /// multiply-add rounds once where the model rounds twice: the bound holds.
    static double shoelace_bound(std::size_t n, double magnitude) {
        if (n > (std::size_t{1} << 40)) return HUGE_VAL;
        // (Each of the 2n products' share of the underflow terms above.)
        constexpr double underflow_per_product = 0x1p-1073;
        const double count = static_cast<double>(n);
        return 4 * count * unit_roundoff * magnitude + 2 * count * underflow_per_product;
    }

    /// The exact sign of the shoelace sum, by the fixed-point sum alone.
    static int exact_signed_area_sign(const std::vector<point<double>>& vs) {
        exact_sum::accumulator acc;
        for (std::size_t k = 0; k < vs.size(); ++k) {
            const auto& a = vs[k];
            const auto& b = vs[(k + 1) % vs.size()];
            acc.add_product(a.x, b.y);
            acc.add_product(-a.y, b.x);
        }
        return acc.sign();
    }

private:
    void add_ring(std::size_t r, ring_input ring) {
        auto& vs = ring.vertices;
        if (vs.size() > 1 && vs.front() == vs.back()) vs.pop_back();  // the closing copy
        for (std::size_t k = 0; k < vs.size(); ++k) {
            if (!std::isfinite(vs[k].x) || !std::isfinite(vs[k].y))
                throw invalid_input("ring " + std::to_string(r) + ", vertex " + std::to_string(k) +
                                    ": coordinate is not a finite number");
        }
        if (count_distinct(vs) < 3)
            throw invalid_input("ring " + std::to_string(r) + ": fewer than three distinct vertices");
        const int sign = signed_area_sign(vs);
        const bool want_ccw = ring.role == ring_role::outer;
        const bool reverse = sign != 0 && ((sign > 0) != want_ccw);
        const std::size_t n = vs.size(), base = vertices_.size();
        if (n > max_vertices - base)
            throw invalid_input("ring " + std::to_string(r) + ": the polygon would have more than " +
                                std::to_string(max_vertices) + " vertices");
        ring_begin_.push_back(base);
        roles_.push_back(ring.role);
        for (std::size_t k = 0; k < n; ++k) {
            // Reversed ring: internal edge k runs along input edge n-2-k (mod n).
            vertices_.push_back(reverse ? vs[n - 1 - k] : vs[k]);
            next_.push_back(static_cast<std::uint32_t>(k + 1 < n ? base + k + 1 : base));
            source_edge_.push_back(static_cast<std::uint32_t>(base + (reverse ? (2 * n - 2 - k) % n : k)));
        }
    }

    point<double> compute_centroid() {
        // Relative to the first vertex, so that large offsets do not cost precision.
        const point<double> o = vertices_.front();
        long double a2 = 0, cx = 0, cy = 0, mx = 0, my = 0;
        for (std::size_t i = 0; i < vertices_.size(); ++i) {
            const long double ax = static_cast<long double>(vertices_[i].x) - o.x;
            const long double ay = static_cast<long double>(vertices_[i].y) - o.y;
            const long double bx = static_cast<long double>(vertices_[next_[i]].x) - o.x;
            const long double by = static_cast<long double>(vertices_[next_[i]].y) - o.y;
            const long double cr = ax * by - ay * bx;
            a2 += cr;
            cx += (ax + bx) * cr;
            cy += (ay + by) * cr;
            mx += ax;
            my += ay;
        }
        area_ = a2 / 2;
        const long double n = static_cast<long double>(vertices_.size());
        if (a2 == 0 || !std::isfinite(static_cast<double>(cx / (3 * a2))))
            return point<double>{static_cast<double>(o.x + mx / n), static_cast<double>(o.y + my / n)};
        return point<double>{static_cast<double>(o.x + cx / (3 * a2)), static_cast<double>(o.y + cy / (3 * a2))};
    }

    std::vector<point<double>> vertices_;
    // (Per vertex: 32 bits suffice, max_vertices, and a layer's join reads
    // next_ beside the vertices for every edge it tests.)
    std::vector<std::uint32_t> next_;
    std::vector<std::size_t> ring_begin_;
    std::vector<ring_role> roles_;
    std::vector<std::uint32_t> source_edge_;
    point<double> centroid_;
    box bounds_;
    long double area_ = 0;
};

}  // namespace influence2d
