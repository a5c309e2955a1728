// SPDX-License-Identifier: BSL-1.0
// Changes of a scene that must not change its answer, in exact arithmetic,
// on the catalogue and on random multipolygon scenes:
//   - roles swapped at theta = 0: collide(A, B, (tx, ty, 0)) equals
//     collide(B, A, (-tx, -ty, 0)), witness pairs swapped;
//   - each ring starting at another vertex;
//   - each ring given in the opposite orientation;
//   - the rings in another order (parts and holes shuffled);
//   - both polygons translated by the same dyadic offset (A's vertices and
//     B's pose; frames where a sum would round are skipped);
//   - the polygon written as WKT (a MULTIPOLYGON when it has several outer
//     rings) and read back;
//   - a multipolygon split into its parts: A meets B iff some part does, and
//     the witness pairs are the union of the parts' pairs.
// The witness pairs are compared in the original numbering: every rewrite
// carries, for each edge, the input number it had.

#include <catch2/catch.hpp>

#include "support/catalogue.hpp"
#include "support/effort.hpp"
#include "support/random_scenes.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;

/// Rings with, for each edge, the number it has in the original input.
struct numbered_rings {
    std::vector<ring_input> rings;
    std::vector<std::vector<std::size_t>> labels;  ///< labels[r][k]: edge k of ring r

    /// The polygon, and the original number of each of its input edges.
    polygon build() const { return polygon(rings); }
    std::vector<std::size_t> original() const {
        std::vector<std::size_t> out;
        for (const auto& l : labels) out.insert(out.end(), l.begin(), l.end());
        return out;
    }
};

/// P's rings as stored, each edge labelled with its input number.
numbered_rings rings_of(const polygon& p) {
    numbered_rings out;
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
        ring_input ring{{}, p.role(r)};
        std::vector<std::size_t> labels;
        for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i) {
            ring.vertices.push_back(p.vertex(i));
            labels.push_back(p.source_edge(i));
        }
        out.rings.push_back(std::move(ring));
        out.labels.push_back(std::move(labels));
    }
    return out;
}

/// Every ring starting at a random vertex; never between two copies of a
/// repeated vertex, where the last vertex would equal the first and be read
/// as the ring's closing copy.
numbered_rings rotated_starts(numbered_rings in, rng& g) {
    for (std::size_t r = 0; r < in.rings.size(); ++r) {
        auto& v = in.rings[r].vertices;
        auto& l = in.labels[r];
        std::size_t s = g.index(v.size());
        while (v[s] == v[(s + v.size() - 1) % v.size()]) s = (s + 1) % v.size();
        std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(s), v.end());
        std::rotate(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(s), l.end());
    }
    return in;
}

/// Every ring in the opposite orientation: new vertex k is old vertex
/// n-1-k, so new edge k runs along old edge n-2-k (mod n).
numbered_rings reversed(numbered_rings in) {
    for (std::size_t r = 0; r < in.rings.size(); ++r) {
        auto& v = in.rings[r].vertices;
        const std::vector<std::size_t> old = in.labels[r];
        const std::size_t n = v.size();
        std::reverse(v.begin(), v.end());
        for (std::size_t k = 0; k < n; ++k) in.labels[r][k] = old[(2 * n - 2 - k) % n];
    }
    return in;
}

/// The rings in a random order.
numbered_rings shuffled(const numbered_rings& in, rng& g) {
    std::vector<std::size_t> order(in.rings.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), g.gen);
    numbered_rings out;
    for (std::size_t r : order) {
        out.rings.push_back(in.rings[r]);
        out.labels.push_back(in.labels[r]);
    }
    return out;
}

/// Every vertex moved by o; empty when a sum would round.
std::optional<numbered_rings> translated(numbered_rings in, point<double> o) {
    for (auto& ring : in.rings)
        for (auto& v : ring.vertices) {
            const point<double> w{v.x + o.x, v.y + o.y};
            if (w.x - o.x != v.x || w.y - o.y != v.y || w.x - v.x != o.x || w.y - v.y != o.y) return std::nullopt;
            v = w;
        }
    return in;
}

/// Whether a + b is exact in double.
bool exact_sum(double a, double b) {
    const double s = a + b;
    return s - a == b && s - b == a;
}

/// The pairs of r with each edge renamed by the label maps, sorted; `swap`
/// exchanges the roles first (for the role-swapped scene).
std::vector<edge_pair> renamed(const frame_result& r, const std::vector<std::size_t>& a_labels,
                               const std::vector<std::size_t>& b_labels, bool swap = false) {
    std::vector<edge_pair> out;
    for (const edge_pair& p : r.pairs) {
        const std::size_t s = swap ? p.moving_edge : p.static_edge, m = swap ? p.static_edge : p.moving_edge;
        out.push_back({a_labels.at(s), b_labels.at(m)});
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string describe_pairs(const std::vector<edge_pair>& pairs) {
    std::ostringstream s;
    for (const edge_pair& p : pairs) s << '[' << p.static_edge << ',' << p.moving_edge << ']';
    return s.str();
}

detector_options with_witness() {
    detector_options o;
    o.witness = true;
    return o;
}

using exact_detector = detector<exact_rational>;

/// The identity labels of a polygon's input numbering.
std::vector<std::size_t> identity(const polygon& p) {
    std::vector<std::size_t> out(p.size());
    std::iota(out.begin(), out.end(), 0);
    return out;
}

/// Runs every rewrite of (A, B) on the frames against the answers of the
/// scene as given. `parts`, when not empty, are A's parts as polygons with
/// the input numbers of their edges in A. Returns how many comparisons ran.
std::size_t check_metamorphic(const std::string& label, const polygon& A, const polygon& B,
                              const std::vector<pose>& frames, std::uint64_t seed,
                              const std::vector<std::pair<polygon, std::vector<std::size_t>>>& parts = {}) {
    rng g(seed);
    std::size_t comparisons = 0;
    exact_detector base(A, B, with_witness());
    std::vector<frame_result> expected;
    for (const pose& p : frames) expected.push_back(base.collide(p));

    // One rewrite of both polygons at a time, through one detector each (so
    // its caches carry from frame to frame).
    const auto check_rewrite = [&](const std::string& what, const numbered_rings& a, const numbered_rings& b) {
        exact_detector d(a.build(), b.build(), with_witness());
        const auto al = a.original(), bl = b.original();
        for (std::size_t f = 0; f < frames.size(); ++f) {
            INFO(label << ", " << what << ", frame " << f);
            const frame_result got = d.collide(frames[f]);
            CHECK(got.collides == expected[f].collides);
            CHECK(describe_pairs(renamed(got, al, bl)) == describe_pairs(expected[f].pairs));
            ++comparisons;
        }
    };
    const numbered_rings a = rings_of(A), b = rings_of(B);
    check_rewrite("starts rotated", rotated_starts(a, g), rotated_starts(b, g));
    check_rewrite("rings reversed", reversed(a), reversed(b));
    check_rewrite("rings shuffled", shuffled(a, g), shuffled(b, g));
    {
        // WKT needs an outer ring first; the round trip keeps stored order.
        const polygon a2 = read_wkt(to_wkt(A)), b2 = read_wkt(to_wkt(B));
        std::vector<std::size_t> al(A.size()), bl(B.size());
        for (std::size_t i = 0; i < A.size(); ++i) al[i] = A.source_edge(i);
        for (std::size_t i = 0; i < B.size(); ++i) bl[i] = B.source_edge(i);
        exact_detector d(a2, b2, with_witness());
        for (std::size_t f = 0; f < frames.size(); ++f) {
            INFO(label << ", WKT round trip, frame " << f);
            const frame_result got = d.collide(frames[f]);
            CHECK(got.collides == expected[f].collides);
            CHECK(describe_pairs(renamed(got, al, bl)) == describe_pairs(expected[f].pairs));
            ++comparisons;
        }
    }
    {
        // The same dyadic offset for A's vertices and B's translation.
        const point<double> o{0x1p-3 * static_cast<double>(1 + g.index(64)),
                              -0x1p-5 * static_cast<double>(g.index(4096))};
        const auto a_moved = translated(a, o);
        if (a_moved) {
            exact_detector d(a_moved->build(), B, with_witness());
            const auto al = a_moved->original();
            const auto bl = identity(B);
            for (std::size_t f = 0; f < frames.size(); ++f) {
                const pose& p = frames[f];
                if (!exact_sum(p.tx, o.x) || !exact_sum(p.ty, o.y)) continue;
                INFO(label << ", both translated by (" << o.x << ", " << o.y << "), frame " << f);
                const frame_result got = d.collide(pose{p.tx + o.x, p.ty + o.y, p.theta});
                CHECK(got.collides == expected[f].collides);
                CHECK(describe_pairs(renamed(got, al, bl)) == describe_pairs(expected[f].pairs));
                ++comparisons;
            }
        }
    }
    {
        // Roles swapped, for translations.
        exact_detector d(B, A, with_witness());
        const auto al = identity(A), bl = identity(B);
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const pose& p = frames[f];
            if (p.theta != 0) continue;
            INFO(label << ", roles swapped, frame " << f);
            const frame_result got = d.collide(pose{-p.tx, -p.ty, 0});
            CHECK(got.collides == expected[f].collides);
            CHECK(describe_pairs(renamed(got, al, bl, true)) == describe_pairs(expected[f].pairs));
            ++comparisons;
        }
    }
    if (!parts.empty()) {
        std::vector<exact_detector> split;
        for (const auto& part : parts) split.emplace_back(part.first, B, with_witness());
        const auto bl = identity(B);
        for (std::size_t f = 0; f < frames.size(); ++f) {
            INFO(label << ", split into " << parts.size() << " parts, frame " << f);
            bool any = false;
            std::vector<edge_pair> pairs;
            for (std::size_t k = 0; k < parts.size(); ++k) {
                const frame_result r = split[k].collide(frames[f]);
                any = any || r.collides;
                const auto named = renamed(r, parts[k].second, bl);
                pairs.insert(pairs.end(), named.begin(), named.end());
            }
            std::sort(pairs.begin(), pairs.end());
            CHECK(any == expected[f].collides);
            CHECK(describe_pairs(pairs) == describe_pairs(expected[f].pairs));
            ++comparisons;
        }
    }
    return comparisons;
}

}  // namespace

TEST_CASE("metamorphic: the catalogue's answers survive rewrites of its scenes", "[metamorphic][catalogue]") {
    std::size_t comparisons = 0;
    std::uint64_t seed = 0xca7a1005ULL;
    for (const auto& c : test_catalogue::cases()) {
        std::vector<pose> frames;
        for (const auto& f : c.frames)
            if (f.distance == 0) frames.push_back(f.where);
        comparisons += check_metamorphic(c.name, c.fixed, c.moving, frames, ++seed);
    }
    CHECK(comparisons > 300);
}

TEST_CASE("metamorphic: random multipolygon scenes survive rewrites", "[metamorphic][multipolygon]") {
    const int scenes = test_effort::scaled(24);
    std::size_t comparisons = 0;
    for (int k = 0; k < scenes; ++k) {
        rng g(0x3e7a0000ULL + static_cast<std::uint64_t>(k));
        const test_scenes::multi a = k % 2 ? test_scenes::random_swallower(g) : test_scenes::random_multi(g, 30);
        const test_scenes::multi b = k % 2 ? test_scenes::random_multi(g, 20, 10) : test_scenes::random_swallower(g);
        const polygon A = a.to_polygon(), B = b.to_polygon();
        // A's parts as polygons, each edge numbered as in A.
        std::vector<std::pair<polygon, std::vector<std::size_t>>> parts;
        std::size_t offset = 0;
        for (const auto& part : a.parts) {
            test_scenes::multi one;
            one.parts.push_back(part);
            const polygon p = one.to_polygon();
            std::vector<std::size_t> labels(p.size());
            std::iota(labels.begin(), labels.end(), offset);
            offset += p.size();
            parts.emplace_back(p, labels);
        }
        std::vector<pose> frames;
        for (int f = 0; f < 12; ++f) {
            const auto& pa = a.parts[g.index(a.parts.size())];
            const auto& pb = b.parts[g.index(b.parts.size())];
            const double reach = pa.radius * g.uniform(0, 1.5);
            const double angle = g.uniform(0, 6.283185307179586);
            const double theta = g.chance(0.6) ? 0 : g.uniform(-3.2, 3.2);
            frames.push_back(test_scenes::aimed(
                pb.center, {pa.center.x + reach * std::cos(angle), pa.center.y + reach * std::sin(angle)}, theta));
        }
        comparisons += check_metamorphic("random scene " + std::to_string(k), A, B, frames,
                                         0x77770000ULL + static_cast<std::uint64_t>(k), parts);
    }
    CHECK(comparisons > static_cast<std::size_t>(scenes) * 60);
}
