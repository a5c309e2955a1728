// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// A polygon placed in a query's frame for a one-shot question: its vertices
/// in double for the filters, in NT for the decisions (posing_margin in
/// predicates/filters.hpp bounds the distance between the two).

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "influence2d/assert.hpp"
#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/prefetch.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/scene/bounding_disc.hpp"
#include "influence2d/scene/edge_boxes.hpp"

namespace influence2d {

/// A polygon placed in the query's frame: its vertices in double, for the
/// filters, with their box; and in NT, for the decisions, each made on first
/// use. Three placings: the polygon's own vertices, its vertices posed by a
/// rotation_pose, or vertices given in NT. In double the filters' values
/// are the decisions' own (the same operations on the same doubles).
template <class NT>
class placed_polygon {
public:
    /// The polygon where it stands.
    explicit placed_polygon(const polygon& shape) : shape_(shape), how_(how::own), approx_(&shape.vertices()) {
        bounds_ = shape.bounds();
        make_room();
    }

    /// The polygon posed by t: its vertices posed in double at once.
    placed_polygon(const polygon& shape, const rotation_pose& t) : shape_(shape), how_(how::posed), pose_(t) {
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
    placed_polygon(const polygon& shape, const std::vector<point<NT>>& given)
        : shape_(shape), how_(how::given), given_(&given) {
        INFLUENCE2D_ASSERT(given.size() == shape.size(), "the vertices given are not the polygon's");
        if constexpr (std::is_same_v<NT, double>) {
            approx_ = &given;
        } else {
            using tr = number_traits<NT>;
            approx_own_.resize(shape.size());
            for (std::size_t j = 0; j < shape.size(); ++j)
                approx_own_[j] = {tr::to_double(given[j].x), tr::to_double(given[j].y)};
            approx_ = &approx_own_;
        }
        for (const point<double>& v : *approx_) {
            finite_ = finite_ && std::isfinite(v.x) && std::isfinite(v.y);
            bounds_.add(v);
        }
    }

    /// Poses the polygon anew by t, as the posing constructor does, in the
    /// buffers it already holds (a body placed step after step).
    void repose(const rotation_pose& t) {
        INFLUENCE2D_ASSERT(how_ == how::posed, "only a posed polygon is posed anew");
        pose_ = t;
        bounds_ = box{};
        finite_ = true;
        for (std::size_t j = 0; j < shape_.size(); ++j) {
            approx_own_[j] = t.apply<double>(shape_.vertex(j));
            finite_ = finite_ && std::isfinite(approx_own_[j].x) && std::isfinite(approx_own_[j].y);
            bounds_.add(approx_own_[j]);
        }
        runs_.clear();
        rings_.clear();
        inner_ = disc{};
        if constexpr (!std::is_same_v<NT, double>) {
            all_.clear();
            if constexpr (!by_value) made_.assign(shape_.size(), std::nullopt);
        }
    }

    /// Asks the processor to bring what a test first reads (the vertices in
    /// double, the run boxes) into its caches, without waiting for them.
    void prefetch_buffers() const {
        prefetch(approx_->data());
        prefetch(runs_.data());
    }

    placed_polygon(const placed_polygon&) = delete;
    placed_polygon& operator=(const placed_polygon&) = delete;

    /// The polygon's topology.
    const polygon& shape() const { return shape_; }
    /// The vertices in double.
    const std::vector<point<double>>& approx() const { return *approx_; }
    /// The box of approx() (the polygon's own box when it stands where it is).
    const box& bounds() const { return bounds_; }
    /// Whether every double coordinate is finite.
    bool finite() const { return finite_; }
    /// Whether approx() holds exactly the values the decisions take in NT:
    /// in double always (the same doubles), in another NT for the polygon
    /// where it stands (its input doubles). Filters on such a placing need
    /// no margin for it (bodies_within).
    bool exact_in_double() const { return std::is_same_v<NT, double> || how_ == how::own; }
    /// The boxes of the runs of consecutive edges in double (edge_run_boxes),
    /// once make_run_bounds() made them at the present placing; else empty.
    const std::vector<box>& run_bounds() const { return runs_; }
    /// Makes run_bounds(): a pass over the vertices, which pays when the
    /// placing serves several pairs (a pair's edges are then sought where
    /// two runs overlap, overlapping_run_pairs, and a locate passes over
    /// each run off its ray whole).
    void make_run_bounds() { edge_run_boxes(shape_, *approx_, runs_); }
    /// run_bounds() when every coordinate is finite, else none: a run box
    /// leaves NaN out, and serves only where there is none.
    const std::vector<box>& finite_run_bounds() const { return finite_ ? runs_ : no_boxes(); }
    /// The box of each ring in double (box::add: a NaN coordinate left out),
    /// once make_ring_bounds() made them at the present placing, for a
    /// polygon of several rings; else empty.
    const std::vector<box>& ring_bounds() const { return rings_; }
    /// Makes ring_bounds(): a pass over the vertices, which pays when the
    /// placing serves many pairs of a polygon of many rings (layer_pairs):
    /// a vertex off every ring's box is outside the region without a
    /// locate (placed_meet).
    void make_ring_bounds() { ring_boxes(shape_, *approx_, shape_.ring_count() > 1 ? shape_.ring_count() : 0, rings_); }
    /// ring_bounds() when every coordinate is finite, else none (as
    /// finite_run_bounds()).
    const std::vector<box>& finite_ring_bounds() const { return finite_ ? rings_ : no_boxes(); }
    /// A disc in the placed polygon's closed region, its centre posed in
    /// double as a vertex is (within the filters' margin of the exact one),
    /// radius 0 when none is known (placed anew: none).
    const disc& inner() const { return inner_; }
    /// Sets inner() for the present placing: the caller knows the disc to
    /// lie in the region (inner_radius, scene/inner_disc.hpp, posed).
    void set_inner(const disc& d) { inner_ = d; }
    /// Whether p, known to within e on each coordinate, certainly lies in
    /// inner() (certainly_nearer, the radius shrunk by pose_scale_widening
    /// for the pose's scaling, the centre within e too): then in the
    /// region's interior, whatever a locate would pass over.
    bool in_inner(const point<double>& p, double e) const {
        return inner_.radius > 0 && certainly_nearer(p, inner_.centre, inner_.radius * (1 - pose_scale_widening), e);
    }

    /// Whether vertex j in NT is returned by value, made anew on each call
    /// (NT trivially copyable: a double, or a double with its error bound,
    /// whose posing is a few operations on doubles), not as a reference into
    /// the vertices made so far. Such a placed polygon may then be read by
    /// several threads at once without all().
    static constexpr bool by_value = std::is_trivially_copyable_v<NT>;
    /// Vertex j in NT, by value or by reference (by_value). A reference stays
    /// valid until the first call of all() (which gathers the vertices made
    /// so far into one vector).
    std::conditional_t<by_value, point<NT>, const point<NT>&> operator[](std::size_t j) {
        if constexpr (std::is_same_v<NT, double>) {
            return how_ == how::given ? (*given_)[j] : (*approx_)[j];
        } else {
            if (how_ == how::given) return (*given_)[j];
            if (!all_.empty()) return all_[j];
            if constexpr (by_value) {
                // A few operations on doubles: made anew on each call (nothing
                // kept, nothing allocated, and no state for threads to share).
                return make(j);
            } else {
                std::optional<point<NT>>& v = made_[j];
                if (!v) v = make(j);
                return *v;
            }
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
                    all_.push_back(j < made_.size() && made_[j] ? std::move(*made_[j]) : make(j));
                made_.clear();
            }
            return all_;
        }
    }

private:
    // The empty list finite_run_bounds() and finite_ring_bounds() give.
    static const std::vector<box>& no_boxes() {
        static const std::vector<box> none;
        return none;
    }
    enum class how : std::uint8_t { own, posed, given };

    // (A vertex in NT is made on first use: an exact NT allocates for each
    // value, so none is made, not even a default one, before it is asked.
    // Nothing is kept for a by_value NT.)
    void make_room() {
        if constexpr (!std::is_same_v<NT, double> && !by_value) made_.resize(shape_.size());
    }
    point<NT> make(std::size_t j) const {
        const point<double>& v = shape_.vertex(j);
        return how_ == how::own ? to_point<NT>(v) : pose_.apply<NT>(v);
    }

    const polygon& shape_;
    how how_;
    rotation_pose pose_{pose{}};
    const std::vector<point<NT>>* given_ = nullptr;
    const std::vector<point<double>>* approx_ = nullptr;
    std::vector<point<double>> approx_own_;
    box bounds_;
    std::vector<box> runs_;   // run_bounds(), once made
    std::vector<box> rings_;  // ring_bounds(), once made
    disc inner_;              // inner(), radius 0: none
    bool finite_ = true;
    std::vector<std::optional<point<NT>>> made_;  // the vertices made so far, until all()
    std::vector<point<NT>> all_;                  // every vertex, once all() asked
};

}  // namespace influence2d
