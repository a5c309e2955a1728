// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// One query without a detector: whether A and B posed by q meet, at the cost
/// of reading both polygons once (docs/method.md, "One-shot queries").

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/scene/prepared.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/segments.hpp"

namespace influence2d {

namespace one_shot_detail {

/// An edge's box in double (posed, for B) with its edge number.
struct edge_box {
    double min_x, max_x, min_y, max_y;
    std::uint32_t edge;
};

/// The edges of a polygon whose vertices (in double) are `v` and whose box
/// meets `window`, each with its box grown by `grow`. With shifts, each box
/// is that of the edge translated by every point between `from` and `to`
/// (the union of its boxes shifted by both).
inline void edges_meeting(const polygon& shape, const std::vector<point<double>>& v, const box& window, double grow,
                          std::vector<edge_box>& out, point<double> from = {0, 0}, point<double> to = {0, 0}) {
    out.clear();
    out.reserve(shape.size());
    const double low_x = std::min(from.x, to.x) - grow, high_x = std::max(from.x, to.x) + grow;
    const double low_y = std::min(from.y, to.y) - grow, high_y = std::max(from.y, to.y) + grow;
    for (std::size_t e = 0; e < shape.size(); ++e) {
        const point<double>&a = v[e], &b = v[shape.next(e)];
        const edge_box k{std::min(a.x, b.x) + low_x, std::max(a.x, b.x) + high_x, std::min(a.y, b.y) + low_y,
                         std::max(a.y, b.y) + high_y, static_cast<std::uint32_t>(e)};
        // (A NaN coordinate fails every comparison: such an edge is kept.)
        if (!(k.max_x < window.min_x || k.min_x > window.max_x || k.max_y < window.min_y || k.min_y > window.max_y))
            out.push_back(k);
    }
}

/// Calls meet(i, j) for each pair of A's edge boxes and B's edge boxes that
/// overlap (sort and sweep along x), until meet returns true; returns whether
/// it did. Both lists are sorted in place by min_x.
template <class Meet>
bool overlapping_pairs(std::vector<edge_box>& as, std::vector<edge_box>& bs, Meet&& meet) {
    const auto by_min_x = [](const edge_box& l, const edge_box& r) { return l.min_x < r.min_x; };
    std::sort(as.begin(), as.end(), by_min_x);
    std::sort(bs.begin(), bs.end(), by_min_x);
    const auto overlap_y = [](const edge_box& l, const edge_box& r) {
        return !(l.max_y < r.min_y || r.max_y < l.min_y);
    };
    std::size_t i = 0, j = 0;
    while (i < as.size() && j < bs.size()) {
        if (as[i].min_x <= bs[j].min_x) {
            // A's box i starts first: it meets B's boxes starting before it ends.
            for (std::size_t k = j; k < bs.size() && bs[k].min_x <= as[i].max_x; ++k)
                if (overlap_y(as[i], bs[k]) && meet(as[i].edge, bs[k].edge)) return true;
            ++i;
        } else {
            for (std::size_t k = i; k < as.size() && as[k].min_x <= bs[j].max_x; ++k)
                if (overlap_y(as[k], bs[j]) && meet(as[k].edge, bs[j].edge)) return true;
            ++j;
        }
    }
    return false;
}

/// A polygon placed in the query's frame: its vertices in double, for the
/// filters, with their box; and in NT, for the decisions, each made on first
/// use. Three placings: the polygon's own vertices, its vertices posed by a
/// rotation_pose, or vertices given in NT. In double the filters' values
/// are the decisions' own (the same operations on the same doubles).
template <class NT>
class placed {
public:
    /// The polygon where it stands.
    explicit placed(const polygon& shape) : shape_(shape), how_(how::own), approx_(&shape.vertices()) {
        bounds_ = shape.bounds();
        make_room();
    }

    /// The polygon posed by t: its vertices posed in double at once.
    placed(const polygon& shape, const rotation_pose& t) : shape_(shape), how_(how::posed), pose_(t) {
        approx_own_.resize(shape.size());
        for (std::size_t j = 0; j < shape.size(); ++j) {
            approx_own_[j] = t.apply<double>(shape.vertex(j));
            finite_ = finite_ && std::isfinite(approx_own_[j].x) && std::isfinite(approx_own_[j].y);
            bounds_.add(approx_own_[j]);
        }
        approx_ = &approx_own_;
        make_room();
    }

    /// The polygon's vertices given in NT (shape's topology); their doubles
    /// are number_traits<NT>::to_double of them.
    placed(const polygon& shape, const std::vector<point<NT>>& given)
        : shape_(shape), how_(how::given), given_(&given) {
        INFLUENCE2D_ASSERT(given.size() == shape.size(), "the vertices given are not the polygon's");
        if constexpr (std::is_same_v<NT, double>) {
            approx_ = &given;
        } else {
            using tr = number_traits<NT>;
            approx_own_.resize(shape.size());
            for (std::size_t j = 0; j < shape.size(); ++j) approx_own_[j] = {tr::to_double(given[j].x), tr::to_double(given[j].y)};
            approx_ = &approx_own_;
        }
        for (const point<double>& v : *approx_) {
            finite_ = finite_ && std::isfinite(v.x) && std::isfinite(v.y);
            bounds_.add(v);
        }
    }

    placed(const placed&) = delete;
    placed& operator=(const placed&) = delete;

    /// The polygon's topology.
    const polygon& shape() const { return shape_; }
    /// The vertices in double.
    const std::vector<point<double>>& approx() const { return *approx_; }
    /// The box of approx() (the polygon's own box when it stands where it is).
    const box& bounds() const { return bounds_; }
    /// Whether every double coordinate is finite.
    bool finite() const { return finite_; }

    /// Vertex j in NT. The reference stays valid until the first call of
    /// all() (which gathers the vertices made so far into one vector).
    const point<NT>& operator[](std::size_t j) {
        if constexpr (std::is_same_v<NT, double>) {
            return how_ == how::given ? (*given_)[j] : (*approx_)[j];
        } else {
            if (how_ == how::given) return (*given_)[j];
            if (!all_.empty()) return all_[j];
            std::optional<point<NT>>& v = made_[j];
            if (!v) v = make(j);
            return *v;
        }
    }

    /// Every vertex in NT.
    const std::vector<point<NT>>& all() {
        if constexpr (std::is_same_v<NT, double>) {
            return how_ == how::given ? *given_ : *approx_;
        } else {
            if (how_ == how::given) return *given_;
            if (all_.empty()) {
                all_.reserve(shape_.size());
                for (std::size_t j = 0; j < shape_.size(); ++j)
                    all_.push_back(made_[j] ? std::move(*made_[j]) : make(j));
                made_.clear();
            }
            return all_;
        }
    }

    /// The origin of the covering that locates points in this polygon: its
    /// centroid placed like its vertices (for given vertices, the centre of
    /// their box in double, or their first vertex when that box is beyond
    /// double's range; any point gives the same winding numbers).
    point<NT> origin() const {
        using tr = number_traits<NT>;
        switch (how_) {
        case how::own:
            return {tr::from_double(shape_.centroid().x), tr::from_double(shape_.centroid().y)};
        case how::posed:
            return pose_.apply<NT>(shape_.centroid());
        default: {
            const double x = bounds_.min_x / 2 + bounds_.max_x / 2, y = bounds_.min_y / 2 + bounds_.max_y / 2;
            if (std::isfinite(x) && std::isfinite(y)) return {tr::from_double(x), tr::from_double(y)};
            return (*given_)[0];  // beyond double's range: a vertex serves too
        }
        }
    }

private:
    enum class how : std::uint8_t { own, posed, given };

    // (A vertex in NT is made on first use: an exact NT allocates for each
    // value, so none is made, not even a default one, before it is asked.)
    void make_room() {
        if constexpr (!std::is_same_v<NT, double>) made_.resize(shape_.size());
    }
    point<NT> make(std::size_t j) const {
        using tr = number_traits<NT>;
        const point<double>& v = shape_.vertex(j);
        return how_ == how::own ? point<NT>{tr::from_double(v.x), tr::from_double(v.y)} : pose_.apply<NT>(v);
    }

    const polygon& shape_;
    how how_;
    rotation_pose pose_{pose{}};
    const std::vector<point<NT>>* given_ = nullptr;
    const std::vector<point<double>>* approx_ = nullptr;
    std::vector<point<double>> approx_own_;
    box bounds_;
    bool finite_ = true;
    std::vector<std::optional<point<NT>>> made_;  // the vertices made so far, until all()
    std::vector<point<NT>> all_;                  // every vertex, once all() asked
};

/// What showed that two placed polygons meet.
struct meeting {
    /// Which test answered.
    enum class kind : std::uint8_t {
        none,         ///< they do not meet
        a_vertex_in_b,  ///< A's vertex `a_index` lies in B (`where`: inside or on the boundary)
        b_vertex_in_a,  ///< B's vertex `b_index` lies in A
        edges         ///< A's edge `a_index` meets B's edge `b_index`
    } how = kind::none;
    std::size_t a_index = 0;  ///< A's vertex or edge (stored numbering)
    std::size_t b_index = 0;  ///< B's vertex or edge (stored numbering)
    location where = location::outside;  ///< for a located vertex

    /// Whether the regions meet.
    explicit operator bool() const { return how != kind::none; }
};

/// Whether the closed regions of the two placed polygons meet, and what
/// showed it; `e` bounds the distance between each coordinate in double
/// and in NT (the filters' margin). The steps of intersects below, after
/// the posing.
template <class NT>
meeting placed_meet(placed<NT>& a, placed<NT>& b, double e) {
    const box& ab = a.bounds();
    box b_window = b.bounds().inflated(e), a_window = ab.inflated(e);
    // A coordinate beyond double's range (or NaN from inf - inf) leaves the
    // place open: no box shortcut, every edge a candidate.
    if (!a.finite() || !b.finite()) {
        const double inf = std::numeric_limits<double>::infinity();
        b_window = box{-inf, -inf, inf, inf};
        a_window = b_window;
    }
    if (b_window.max_x < ab.min_x || b_window.min_x > ab.max_x || b_window.max_y < ab.min_y ||
        b_window.min_y > ab.max_y)
        return {};

    // Containment first: one vertex of every ring located in the other
    // polygon (containment.hpp says why that decides the case of no
    // boundary pair). A vertex in the other's closed region is a meeting
    // point whatever the boundaries do, and most poses that meet are
    // answered here in linear time, before any sorting. A vertex outside the
    // other polygon's box (widened) is outside it without a locate.
    const auto outside = [](const point<double>& v, const box& w) {
        return v.x < w.min_x || v.x > w.max_x || v.y < w.min_y || v.y > w.max_y;  // NaN: may be inside
    };
    const polygon &as = a.shape(), &bs = b.shape();
    std::optional<point<NT>> a_origin, b_origin;  // once a ring asks
    for (std::size_t r = 0; r < bs.ring_count(); ++r) {
        const std::size_t j = bs.ring_begin(r);
        if (outside(b.approx()[j], a_window)) continue;
        if (!a_origin) a_origin = a.origin();
        const location l = locate(as, a.all(), *a_origin, b[j]);
        if (l != location::outside) return {meeting::kind::b_vertex_in_a, 0, j, l};
    }
    for (std::size_t r = 0; r < as.ring_count(); ++r) {
        const std::size_t i = as.ring_begin(r);
        if (outside(a.approx()[i], b_window)) continue;
        if (!b_origin) b_origin = b.origin();
        const location l = locate(bs, b.all(), *b_origin, a[i]);
        if (l != location::outside) return {meeting::kind::a_vertex_in_b, i, 0, l};
    }

    // No ring inside the other polygon: the regions meet iff the boundaries
    // do. Candidate edges: those whose box meets the other polygon's box.
    std::vector<edge_box> a_edges, b_edges;
    edges_meeting(as, a.approx(), b_window, e, a_edges);
    edges_meeting(bs, b.approx(), a_window, e, b_edges);
    meeting found;
    overlapping_pairs(a_edges, b_edges, [&](std::uint32_t i, std::uint32_t j) {
        const std::size_t i2 = as.next(i), j2 = bs.next(j);
        if (!segments_may_meet(a.approx()[i], a.approx()[i2], b.approx()[j], b.approx()[j2], e)) return false;
        if (!segments_intersect(a[i], a[i2], b[j], b[j2])) return false;
        found = {meeting::kind::edges, i, j, location::boundary};
        return true;
    });
    return found;
}

/// The margin of the filters of two polygons posed in double: each
/// coordinate c x - s y + t is a few rounded operations on terms bounded by
/// the polygon's scale and |t|, so its error is below filter_slack times
/// their sum (filter_slack >= 1e-9, far above double's few ulps); `scale`
/// is that sum for both polygons.
template <class NT>
double posing_margin(double scale) {
    return number_traits<NT>::filter_slack * 4 * scale + std::numeric_limits<double>::min();
}

}  // namespace one_shot_detail

/// Whether the closed regions of A and of B posed by q meet (touching
/// counts; B inside a hole of A does not meet A): the question a detector
/// answers for one frame with distance 0, without building one. Exact when NT
/// is; a filtered NT may throw uncertain_sign (certified_intersects in
/// exact/certified_detector.hpp answers exactly through it). Throws invalid_input
/// for an empty polygon, one beyond NT's range, or a pose with a NaN or
/// infinite component.
///
///   pose B's vertices in double; e <- their rounding margin
///   if the boxes of A and of posed B (grown by e) are apart:   disjoint
///   for one vertex of every ring of each polygon, within the other's box:
///       located in the other polygon (exact), not outside:     meet
///   A's edges whose box meets B's box, B's edges whose box meets A's box
///   for each pair of those whose boxes overlap (sort and sweep along x):
///       filter in double: the paper's detailed test both ways (segments_may_meet)
///       exact segment test in NT on the posed vertices:       meet
///   disjoint
///
/// Time O((n + m) log(n + m) + k) for n and m edges and k overlapping boxes
/// (linear for most poses that meet: a located vertex answers them);
/// no structure outlives the call. For many poses of one pair a detector is
/// faster (it keeps A's precomputation and the last frame's candidates).
template <class NT>
bool intersects(const polygon& a, const polygon& b, const pose& q) {
    using namespace one_shot_detail;
    accepted_polygon<NT>(a, "static");
    accepted_polygon<NT>(b, "moving");
    const rotation_pose t(q);
    placed<NT> pa(a), pb(b, t);
    const double e = posing_margin<NT>(coordinate_scale(b) + coordinate_scale(a) + std::fabs(q.tx) + std::fabs(q.ty));
    return static_cast<bool>(placed_meet(pa, pb, e));
}

}  // namespace influence2d
