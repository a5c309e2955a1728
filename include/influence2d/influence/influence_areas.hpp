// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Influence areas (the cones from the covering origin through each edge) and
/// the influence mask of a point (docs/method.md section 4).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "influence2d/assert.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/filters.hpp"

namespace influence2d {

/// Whether P lies in the closed influence area of edge i: beta_i >= 0 and
/// gamma_i >= 0, the cone from the origin through the edge, its two rays
/// included. The area of an edge collinear with the origin (a zero-length
/// edge included) is empty. Two orientation signs: exact when NT is.
template <class NT>
bool in_influence_area(const triangle_covering<NT>& cov, std::size_t i, const point<NT>& p) {
    const int s = cov.sigma(i);
    if (s == 0) return false;
    return orientation(cov.origin(), p, cov.end(i)) * s >= 0 && orientation(cov.origin(), cov.start(i), p) * s >= 0;
}

/// One bit per edge of the static polygon: the influence areas that contain
/// a point. Operations run a 64-bit word at a time.
class influence_mask {
public:
    /// A mask of no edge.
    influence_mask() = default;
    /// A mask of `edges` bits, all clear.
    explicit influence_mask(std::size_t edges) : words_((edges + 63) / 64, 0) {}

    /// Clears every bit.
    void clear() { std::fill(words_.begin(), words_.end(), std::uint64_t{0}); }
    /// Sets bit i; requires i below the size given at construction.
    void set(std::size_t i) {
        INFLUENCE2D_ASSERT(i / 64 < words_.size(), "bit beyond the mask");
        words_[i / 64] |= std::uint64_t{1} << (i % 64);
    }
    /// Whether bit i is set; requires i below the size given at construction.
    bool test(std::size_t i) const {
        INFLUENCE2D_ASSERT(i / 64 < words_.size(), "bit beyond the mask");
        return (words_[i / 64] >> (i % 64)) & 1u;
    }
    /// Whether some bit is set.
    bool any() const {
        for (auto w : words_)
            if (w) return true;
        return false;
    }
    /// Whether some area of `before` is not in this mask: the point left it.
    /// Requires masks of the same size.
    bool left_some_area_of(const influence_mask& before) const {
        INFLUENCE2D_ASSERT(before.words_.size() == words_.size(), "masks of different sizes");
        for (std::size_t k = 0; k < words_.size(); ++k)
            if (before.words_[k] & ~words_[k]) return true;
        return false;
    }
    /// Whether both masks have the same bits (and size).
    bool operator==(const influence_mask& o) const { return words_ == o.words_; }

private:
    std::vector<std::uint64_t> words_;
};

/// Finds the influence areas containing a point without testing every edge:
/// the directions around the origin are cut into equal angular buckets, each
/// listing the cones that overlap it (widened, so the list is conservative);
/// membership is then decided exactly, by barycentric signs, for the cones of
/// the point's bucket only. A point at or very near the origin, where its
/// direction is not known well enough in double, tests every cone. There
/// are 2 to 4 buckets per edge (at least 16, at most 2^20); each cone is
/// listed in the buckets its angle spans, so a query tests one bucket's cones.
template <class NT>
class influence_areas {
public:
    /// An empty index, to be assigned to.
    influence_areas() = default;

    /// Indexes the cones of `cov`, which must outlive the index. Cones whose
    /// direction is not known to half a radian in double (or not finite) are
    /// listed in every bucket; edges collinear with the origin in none.
    explicit influence_areas(const triangle_covering<NT>& cov) : cov_(&cov) {
        constexpr double two_pi = 6.283185307179586;
        const std::size_t n = cov.size();
        INFLUENCE2D_ASSERT(n <= std::numeric_limits<std::uint32_t>::max(), "edge numbers beyond the index's 32 bits");
        buckets_ = 16;
        while (buckets_ < 2 * n && buckets_ < (std::size_t{1} << 20)) buckets_ *= 2;
        const double widen = number_traits<NT>::filter_slack + atan2_widening;
        // Two passes, no list per bucket: each cone's run of buckets (first,
        // count), then the buckets' sizes, their offsets, and the cones put in
        // place (in edge order within a bucket).
        struct run {
            std::uint32_t cone, first, count;
        };
        std::vector<run> runs;
        runs.reserve(n);
        offsets_.assign(buckets_ + 1, 0);
        const point<double> o = to_double_point(cov.origin());
        const long buckets = static_cast<long>(buckets_);
        for (std::size_t i = 0; i < n; ++i) {
            const int s = cov.sigma(i);
            if (s == 0) {
                degenerate_.push_back(static_cast<std::uint32_t>(i));
                continue;
            }
            const point<double> a = to_double_point(cov.start(i)), b = to_double_point(cov.end(i));
            // The cone turns counter-clockwise from `from` to `to`, by less than pi.
            const point<double>& from = s > 0 ? a : b;
            const point<double>& to = s > 0 ? b : a;
            // The directions from o are rounded: widen by their possible error.
            const double spread = widen + direction_error(from, o) + direction_error(to, o);
            double lo = std::atan2(from.y - o.y, from.x - o.x) - spread;
            double hi = std::atan2(to.y - o.y, to.x - o.x) + spread;
            if (hi < lo) hi += two_pi;
            // A direction not known to half a radian (or not finite: coordinates
            // whose differences overflow) puts the cone in every bucket.
            if (!(spread < 0.5) || !std::isfinite(lo)) {
                lo = -3.141592653589793;
                hi = lo + two_pi;
            }
            const double k = static_cast<double>(buckets_) / two_pi;
            const long first = static_cast<long>(std::floor((lo + 3.141592653589793) * k));
            const long last = static_cast<long>(std::floor((hi + 3.141592653589793) * k));
            const long count = std::min(last - first + 1, buckets);
            const long wrapped = ((first % buckets) + buckets) % buckets;
            runs.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(wrapped),
                            static_cast<std::uint32_t>(std::max(count, 0L))});
            for (long c = 0; c < count; ++c) ++offsets_[static_cast<std::size_t>((wrapped + c) % buckets) + 1];
            all_.push_back(static_cast<std::uint32_t>(i));
        }
        for (std::size_t b = 0; b < buckets_; ++b) offsets_[b + 1] += offsets_[b];
        cones_.resize(offsets_.back());
        std::vector<std::uint32_t> next(offsets_.begin(), offsets_.end() - 1);
        for (const run& r : runs)
            for (std::uint32_t c = 0; c < r.count; ++c) cones_[next[(r.first + c) % buckets_]++] = r.cone;
        origin_scale_ = std::fabs(o.x) + std::fabs(o.y);
    }

    /// Bytes of the heap blocks held (capacities).
    std::size_t heap_bytes() const {
        return (offsets_.capacity() + cones_.capacity() + all_.capacity() + degenerate_.capacity()) *
               sizeof(std::uint32_t);
    }

    /// Calls visit(i) for every edge i whose influence area contains P, in
    /// no particular order. Membership is exact when NT is; the bucket only
    /// narrows which cones are tested.
    template <class Visit>
    void for_each_containing(const point<NT>& p, Visit&& visit) const {
        using tr = number_traits<NT>;
        const double dx = tr::to_double(p.x - cov_->origin().x);
        const double dy = tr::to_double(p.y - cov_->origin().y);
        const double scale = origin_scale_ + std::fabs(tr::to_double(p.x)) + std::fabs(tr::to_double(p.y));
        const bool direction_known =
            std::fabs(dx) + std::fabs(dy) > direction_trust_factor * tr::filter_slack * scale &&
            std::isfinite(dx + dy + scale);
        const std::uint32_t* first = all_.data();
        const std::uint32_t* last = all_.data() + all_.size();
        if (direction_known) {
            constexpr double two_pi = 6.283185307179586;
            const double f =
                std::floor((std::atan2(dy, dx) + 3.141592653589793) * static_cast<double>(buckets_) / two_pi);
            const std::size_t b = static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(buckets_ - 1)));
            first = cones_.data() + offsets_[b];
            last = cones_.data() + offsets_[b + 1];
        }
        for (const std::uint32_t* it = first; it != last; ++it)
            if (in_influence_area(*cov_, *it, p)) visit(static_cast<std::size_t>(*it));
    }

    /// Feito's inclusion test restricted to the triangles that can contain P:
    /// a triangle lies in its edge's cone, so only the cones containing P add
    /// to the sum (see feito_locate), and the edges collinear with the
    /// origin, whose cones are empty, are checked for P on them. The origin
    /// itself, in every cone, takes the full sum from a vertex. The same
    /// answer as locate() on the covering (closed region: boundary on an
    /// edge), at the cost of the cones near P's direction.
    location locate(const point<NT>& p) const {
        const auto& cov = *cov_;
        if (same_point(p, cov.origin())) return influence2d::locate(cov, p);
        for (std::uint32_t i : degenerate_)
            if (on_segment(p, cov.start(i), cov.end(i))) return location::boundary;
        long long doubled = 0;
        bool boundary = false;
        for_each_containing(p, [&](std::size_t i) {
            const barycentric_signs b = cov.signs(i, p);
            if (b.alpha < 0) return;
            if (b.alpha == 0) boundary = true;  // on the line, inside the cone: on the edge
            doubled += (b.beta == 0 || b.gamma == 0) ? cov.sigma(i) : 2 * cov.sigma(i);
        });
        if (boundary) return location::boundary;
        return doubled != 0 ? location::inside : location::outside;
    }

    /// The influence mask of P: one bit per edge, set for the areas containing
    /// P. `out` must have one bit per edge of the covering; it is cleared first.
    void mask(const point<NT>& p, influence_mask& out) const {
        out.clear();
        for_each_containing(p, [&](std::size_t i) { out.set(i); });
    }

private:
    /// A bound of the angular error of the direction o->q computed in double.
    static double direction_error(const point<double>& q, const point<double>& o) {
        const double len = std::fabs(q.x - o.x) + std::fabs(q.y - o.y);
        const double mag = std::fabs(q.x) + std::fabs(q.y) + std::fabs(o.x) + std::fabs(o.y);
        return len > 0 ? 8 * std::numeric_limits<double>::epsilon() * mag / len : 1.0;
    }

    const triangle_covering<NT>* cov_ = nullptr;
    std::size_t buckets_ = 0;
    std::vector<std::uint32_t> offsets_;
    std::vector<std::uint32_t> cones_;
    std::vector<std::uint32_t> all_;
    std::vector<std::uint32_t> degenerate_;
    double origin_scale_ = 0;
};

}  // namespace influence2d
