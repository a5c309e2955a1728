// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Audit of a polygon's input: every degeneracy the library meets, each with
/// where it is and what the library does with it.
///
///     audit_report r = audit_rings(rings);   // rings as read (closing points included)
///     r.accepted: whether polygon(...) accepts the rings; r.findings: what is there.
///
/// The rings are those of the input (WKT: read_wkt_rings), before any check, so
/// that what the reader refuses is reported as well as what it accepts.

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// What an audit finding is about. unclosed_ring, non_finite and
/// too_few_vertices make the input refused, as does an empty exterior ring
/// followed by holes; the library keeps the others as they are
/// (reversed_orientation: reversed; an empty ring: ignored).
enum class finding_kind {
    empty_ring,            ///< a ring without points (WKT `EMPTY` or `()`)
    unclosed_ring,         ///< the last point differs from the first (or the ring has one point)
    non_finite,            ///< a coordinate is NaN or infinite
    too_few_vertices,      ///< a ring with fewer than three distinct vertices
    repeated_vertex,       ///< a vertex equals the next: a zero-length edge
    near_repeated_vertex,  ///< an edge shorter than the tolerance (audit_options)
    collinear_run,         ///< a vertex on the line between its neighbours, going on straight
    spike,                 ///< the ring turns back at a vertex: a spike of zero width
    self_intersection,     ///< two edges of one ring, not adjacent, meet (touching counts)
    rings_meet,            ///< edges of two rings meet (touching counts)
    reversed_orientation,  ///< a clockwise outer ring or a counter-clockwise hole
    /// A hole that no outer ring winds around (the other rings' winding
    /// number there is 0): inside it the winding number is -1, so its inside
    /// belongs to the region (see polygon). A hole inside another hole is one.
    hole_outside_shell,
    /// A ring that meets no other lying where the other rings already wind
    /// (an outer ring inside an outer ring, a hole inside nested shells or a
    /// stray hole): the finding says which winding numbers it separates and
    /// whether its inside is region.
    nested_ring,
    non_manifold_vertex,    ///< one point is a vertex at two places that are not consecutive
    zero_area,              ///< a ring whose exact signed area is 0
    near_zero_area,         ///< a ring whose area is below the tolerance (audit_options)
    centroid_on_edge_line,  ///< the centroid lies on an edge's line: flat triangle, empty cone
    inexact_in_float,       ///< a coordinate that float cannot represent: float mode rounds it
    beyond_float,           ///< a coordinate beyond float's range
    beyond_double_products  ///< a coordinate above 2^500 or below 2^-500 in magnitude (not 0)
};

/// The number of enumerators of finding_kind: their values run from 0 to
/// finding_kind_count - 1.
inline constexpr std::size_t finding_kind_count = static_cast<std::size_t>(finding_kind::beyond_double_products) + 1;

/// The enumerator's name as text ("unknown" for a value outside the enum);
/// a string literal, never freed.
inline const char* finding_name(finding_kind k) {
    switch (k) {
    case finding_kind::empty_ring: return "empty_ring";
    case finding_kind::unclosed_ring: return "unclosed_ring";
    case finding_kind::non_finite: return "non_finite";
    case finding_kind::too_few_vertices: return "too_few_vertices";
    case finding_kind::repeated_vertex: return "repeated_vertex";
    case finding_kind::near_repeated_vertex: return "near_repeated_vertex";
    case finding_kind::collinear_run: return "collinear_run";
    case finding_kind::spike: return "spike";
    case finding_kind::self_intersection: return "self_intersection";
    case finding_kind::rings_meet: return "rings_meet";
    case finding_kind::reversed_orientation: return "reversed_orientation";
    case finding_kind::hole_outside_shell: return "hole_outside_shell";
    case finding_kind::nested_ring: return "nested_ring";
    case finding_kind::non_manifold_vertex: return "non_manifold_vertex";
    case finding_kind::zero_area: return "zero_area";
    case finding_kind::near_zero_area: return "near_zero_area";
    case finding_kind::centroid_on_edge_line: return "centroid_on_edge_line";
    case finding_kind::inexact_in_float: return "inexact_in_float";
    case finding_kind::beyond_float: return "beyond_float";
    case finding_kind::beyond_double_products: return "beyond_double_products";
    }
    return "unknown";
}

/// One finding: what, where (ring and vertex or edge, in input numbering:
/// edge k runs from vertex k to vertex k+1 of its ring), and what the library
/// does with it.
struct finding {
    /// A finding of kind k at ring 0, everything else empty.
    explicit finding(finding_kind k) : kind(k) {}
    finding_kind kind;                        ///< what it is
    std::size_t ring = 0;                     ///< the ring, numbered in input order from 0
    std::optional<std::size_t> vertex;        ///< or the edge, for edge findings; none for ring findings
    std::optional<std::size_t> other_ring;    ///< for findings between two places
    std::optional<std::size_t> other_vertex;  ///< the other place's vertex or edge
    point<double> at{};                       ///< a point of the finding
    std::string what;                         ///< one line
    std::string effect;                       ///< what the library does
    bool rejects = false;                     ///< the library refuses the input for it
};

/// What audit_rings found, and whether the library accepts the rings.
struct audit_report {
    std::vector<finding> findings;  ///< at most audit_options::max_per_kind of each kind
    std::size_t total = 0;          ///< findings of every kind, listed or not
    /// The findings of each kind, listed or not, at the kind's value
    /// (`counts[static_cast<std::size_t>(k)]`); they sum to `total`.
    std::array<std::size_t, finding_kind_count> counts{};
    bool accepted = true;   ///< polygon(...) accepts the rings
    std::string rejection;  ///< its message when it does not
    /// The number of rings.
    std::size_t rings = 0, vertices = 0;  ///< the number of vertices of all rings, closing points not counted
};

/// The tolerances and limits of audit_rings.
struct audit_options {
    /// Points closer than this times the polygon's extent (the longer side of
    /// the box of all its vertices) are near-repeated; a ring whose area is
    /// below this times the square of its box's diagonal has near-zero area.
    double relative_tolerance = 0x1p-40;
    /// At most this many findings of one kind are listed (audit_report::total
    /// counts them all).
    std::size_t max_per_kind = 50;
};

namespace audit_detail {

/// The polygon's extent: the longer side of the box of its finite vertices
/// (0 without any).
inline double extent_of(const std::vector<std::vector<point<double>>>& rings) {
    box b;
    for (const auto& r : rings)
        for (const auto& p : r)
            if (std::isfinite(p.x) && std::isfinite(p.y)) b.add(p);
    return b.empty() ? 0 : std::max(b.max_x - b.min_x, b.max_y - b.min_y);
}

/// Whether every vertex of the ring lies on one line (exact).
inline bool all_collinear(const std::vector<point<double>>& ring) {
    std::size_t other = 1;
    while (other < ring.size() && ring[other] == ring[0]) ++other;
    for (std::size_t i = other + 1; i < ring.size(); ++i)
        if (exact_orientation(ring[0], ring[other], ring[i]) != 0) return false;
    return true;
}

/// Whether edge j follows edge i on the ring with only zero-length edges
/// between them (so that they share the end of i).
inline bool adjacent(const std::vector<point<double>>& ring, std::size_t i, std::size_t j) {
    const std::size_t n = ring.size();
    for (std::size_t k = (i + 1) % n; k != i; k = (k + 1) % n) {
        if (k == j) return true;
        if (!(ring[k] == ring[(k + 1) % n])) return false;
    }
    return false;
}

struct edge_ref {
    std::size_t ring, index;
    point<double> a, b;
    double min_x, max_x;
};

/// Every pair of edges that meet, except zero-length edges and edges adjacent
/// on a ring, which share their vertex by construction: consecutive edges, or
/// edges with only zero-length edges between them (a repeated vertex); a
/// sweep over x.
template <class Visit>
void meeting_edges(const std::vector<std::vector<point<double>>>& rings, Visit visit) {
    std::vector<edge_ref> edges;
    for (std::size_t r = 0; r < rings.size(); ++r)
        for (std::size_t i = 0, n = rings[r].size(); i < n; ++i) {
            const point<double>& a = rings[r][i];
            const point<double>& b = rings[r][(i + 1) % n];
            if (a == b) continue;
            edges.push_back({r, i, a, b, std::min(a.x, b.x), std::max(a.x, b.x)});
        }
    std::sort(edges.begin(), edges.end(), [](const edge_ref& p, const edge_ref& q) { return p.min_x < q.min_x; });
    std::vector<const edge_ref*> active;
    for (const edge_ref& e : edges) {
        active.erase(
            std::remove_if(active.begin(), active.end(), [&](const edge_ref* f) { return f->max_x < e.min_x; }),
            active.end());
        for (const edge_ref* f : active) {
            if (f->ring == e.ring &&
                (adjacent(rings[e.ring], f->index, e.index) || adjacent(rings[e.ring], e.index, f->index)))
                continue;
            if (std::max(f->a.y, f->b.y) < std::min(e.a.y, e.b.y) || std::max(e.a.y, e.b.y) < std::min(f->a.y, f->b.y))
                continue;
            if (segments_meet_exactly(f->a, f->b, e.a, e.b)) {
                const bool first = std::tie(f->ring, f->index) < std::tie(e.ring, e.index);
                visit(first ? *f : e, first ? e : *f);
            }
        }
        active.push_back(&e);
    }
}

inline std::string coordinates(const point<double>& p) {
    return "(" + shortest_decimal(p.x) + " " + shortest_decimal(p.y) + ")";
}

/// The report being written: adds findings, counting each kind and listing at
/// most audit_options::max_per_kind of it; a finding that rejects the input
/// makes it refused (the first one's text is the rejection).
class collector {
public:
    explicit collector(const audit_options& o) : options(o) {}

    /// Adds f to the report.
    void add(finding f) {
        if (f.rejects && report.accepted) refuse(f.what);
        ++report.total;
        if (report.counts[static_cast<std::size_t>(f.kind)]++ < options.max_per_kind)
            report.findings.push_back(std::move(f));
    }
    /// Marks the input refused with this message.
    void refuse(std::string message) {
        report.accepted = false;
        report.rejection = std::move(message);
    }
    /// Adds a finding about a whole ring, shown at p.
    void add_at_ring(finding_kind k, std::size_t ring, point<double> p, std::string what, std::string effect,
                     bool rejects = false) {
        add(make(k, ring, std::nullopt, p, std::move(what), std::move(effect), rejects));
    }
    /// Adds a finding about vertex (or edge) v of a ring, shown at p.
    void add_at_vertex(finding_kind k, std::size_t ring, std::size_t v, point<double> p, std::string what,
                       std::string effect, bool rejects = false) {
        add(make(k, ring, v, p, std::move(what), std::move(effect), rejects));
    }

    audit_report report;           ///< what has been found so far
    const audit_options& options;  ///< the tolerances and limits

private:
    static finding make(finding_kind k, std::size_t ring, std::optional<std::size_t> v, point<double> p,
                        std::string what, std::string effect, bool rejects) {
        finding f{k};
        f.ring = ring;
        f.vertex = v;
        f.at = p;
        f.what = std::move(what);
        f.effect = std::move(effect);
        f.rejects = rejects;
        return f;
    }
};

/// The rings as the library takes them (closing point dropped), and which of
/// them are usable: finite, closed, with three distinct vertices.
struct ring_set {
    std::vector<std::vector<point<double>>> rings;  ///< one per input ring, empty for an empty one
    std::vector<bool> usable;                       ///< whether the later checks look at the ring
};

/// Which usable rings have an edge meeting another ring's, or another edge of their own.
struct meetings {
    std::vector<bool> other;   ///< an edge meets an edge of another ring
    std::vector<bool> itself;  ///< two edges of the ring, not adjacent, meet
};

/// Reads the rings and reports what refuses them: empty, non-finite, unclosed, too few vertices.
inline ring_set read_rings(collector& c, const std::vector<wkt_ring>& input) {
    ring_set set;
    c.report.rings = input.size();
    for (std::size_t k = 0; k < input.size(); ++k) {
        const auto& pts = input[k].points;
        bool ok = true;
        if (pts.empty()) {
            // GEOS and JTS read an empty ring as no ring; an empty exterior
            // followed by its holes leaves holes without a part.
            if (empty_exterior_with_holes(input, k))
                c.add_at_ring(finding_kind::empty_ring, k, {}, "empty exterior ring with holes", "refused", true);
            else
                c.add_at_ring(finding_kind::empty_ring, k, {}, "empty ring",
                              "ignored, as GEOS and JTS read it: the polygon has the other rings");
            set.rings.emplace_back();
            set.usable.push_back(false);
            continue;
        }
        for (std::size_t v = 0; v < pts.size(); ++v)
            if (!std::isfinite(pts[v].x) || !std::isfinite(pts[v].y)) {
                c.add_at_vertex(finding_kind::non_finite, k, v, pts[v], "coordinate is not a finite number", "refused",
                                true);
                ok = false;
            }
        const bool closed = pts.front() == pts.back() && pts.size() > 1;
        if (!closed) {
            c.add_at_vertex(finding_kind::unclosed_ring, k, pts.size() - 1, pts.back(),
                            "ring is not closed: last point " + coordinates(pts.back()) + " differs from the first " +
                                coordinates(pts.front()),
                            "refused", true);
            ok = false;
        }
        std::vector<point<double>> ring(pts.begin(), closed ? pts.end() - 1 : pts.end());
        c.report.vertices += ring.size();
        if (polygon::count_distinct(ring) < 3) {
            c.add_at_ring(finding_kind::too_few_vertices, k, pts.front(), "fewer than three distinct vertices",
                          "refused", true);
            ok = false;
        }
        set.rings.push_back(std::move(ring));
        set.usable.push_back(ok);
    }
    return set;
}

/// Reports ring k's repeated and near-repeated vertices, collinear runs and spikes.
inline void check_vertices(collector& c, std::size_t k, const std::vector<point<double>>& ring, double near) {
    const std::size_t n = ring.size();
    for (std::size_t v = 0; v < n; ++v) {
        const point<double>& p = ring[v];
        const point<double>& q = ring[(v + 1) % n];
        if (p == q) {
            c.add_at_vertex(finding_kind::repeated_vertex, k, v, p,
                            "vertex " + std::to_string(v) + " repeated: edge " + std::to_string(v) + " has zero length",
                            "kept as a zero-length edge (tested as a point), so witness edge numbers stay the "
                            "input's");
        } else if (std::max(std::fabs(p.x - q.x), std::fabs(p.y - q.y)) <= near) {
            c.add_at_vertex(finding_kind::near_repeated_vertex, k, v, p,
                            "edge " + std::to_string(v) + " is shorter than " +
                                shortest_decimal(c.options.relative_tolerance) +
                                " of the polygon's extent (the longer side of its bounding box)",
                            "kept as it is; exact and certified modes decide on it exactly, float and double may "
                            "not");
        }
        // The turn at v, between the nearest distinct neighbours.
        std::size_t before = (v + n - 1) % n, after = (v + 1) % n;
        while (ring[before] == p && before != v) before = (before + n - 1) % n;
        while (ring[after] == p && after != v) after = (after + 1) % n;
        if (ring[before] == p || ring[after] == p || (v > 0 && ring[v - 1] == p)) continue;
        if (exact_orientation(ring[before], p, ring[after]) != 0) continue;
        if (within_collinear_segment(p, ring[before], ring[after]))
            c.add_at_vertex(finding_kind::collinear_run, k, v, p,
                            "vertex " + std::to_string(v) + " lies on the line of its neighbours",
                            "kept: a straight run of several edges, each tested as an edge");
        else
            c.add_at_vertex(finding_kind::spike, k, v, p,
                            "the ring turns back at vertex " + std::to_string(v) + " (a spike of zero width)",
                            "kept: the spike's two edges bound no area; touching it is a collision");
    }
}

/// Reports ring k's zero or near-zero area and reversed orientation; returns
/// the turn the polygon stores it with (-1 when reversed, else 1).
inline int check_area_and_orientation(collector& c, std::size_t k, const std::vector<point<double>>& ring,
                                      ring_role role) {
    // The exact sign of the shoelace sum, its magnitude in long double.
    const std::size_t n = ring.size();
    long double area = 0;
    for (std::size_t v = 0; v < n; ++v) {
        const point<double>& p = ring[v];
        const point<double>& q = ring[(v + 1) % n];
        area += static_cast<long double>(p.x) * q.y - static_cast<long double>(q.x) * p.y;
    }
    const int sign = polygon::signed_area_sign(ring);
    const bool hole = role == ring_role::hole;
    const bool reversed = sign != 0 && (sign > 0) == hole;
    box bounds;
    for (const auto& p : ring) bounds.add(p);
    const double w = bounds.max_x - bounds.min_x, h = bounds.max_y - bounds.min_y;
    const long double tolerance = static_cast<long double>(c.options.relative_tolerance);
    if (sign == 0 && all_collinear(ring)) {
        c.add_at_ring(finding_kind::zero_area, k, ring[0], "the ring's vertices all lie on one line: zero area",
                      "kept: its edges still collide; it bounds no region (winding number 0 off its edges)");
    } else if (sign == 0) {
        c.add_at_ring(finding_kind::zero_area, k, ring[0],
                      "the ring's signed area is zero: lobes of opposite turn cancel (a figure eight)",
                      "kept in its input orientation: each lobe has winding number +1 or -1 and is region; only "
                      "the signed sum is zero");
    } else if (std::fabs(area) / 2 <= tolerance * (static_cast<long double>(w) * w + static_cast<long double>(h) * h)) {
        c.add_at_ring(finding_kind::near_zero_area, k, ring[0],
                      "the ring's area is almost zero against its size (the square of its box's diagonal)",
                      "kept as it is; its orientation is decided exactly");
    }
    if (!reversed) return 1;
    c.add_at_ring(finding_kind::reversed_orientation, k, ring[0],
                  std::string(hole ? "hole" : "outer ring") + " is " + (hole ? "counter-clockwise" : "clockwise"),
                  "reversed when stored (orientation decided exactly); witnesses keep the input's edge numbers");
    return -1;
}

/// Reports the pairs of edges that meet, within a ring and between rings; returns which rings meet.
inline meetings check_meeting_edges(collector& c, const ring_set& set) {
    std::vector<std::vector<point<double>>> live;
    std::vector<std::size_t> live_index;
    for (std::size_t k = 0; k < set.rings.size(); ++k)
        if (set.usable[k]) {
            live.push_back(set.rings[k]);
            live_index.push_back(k);
        }
    meetings m{std::vector<bool>(set.rings.size(), false), std::vector<bool>(set.rings.size(), false)};
    meeting_edges(live, [&](const edge_ref& f, const edge_ref& e) {
        if (f.ring == e.ring) {
            m.itself[live_index[f.ring]] = true;
        } else {
            m.other[live_index[f.ring]] = true;
            m.other[live_index[e.ring]] = true;
        }
        finding g{f.ring == e.ring ? finding_kind::self_intersection : finding_kind::rings_meet};
        g.ring = live_index[f.ring];
        g.vertex = f.index;
        g.other_ring = live_index[e.ring];
        g.other_vertex = e.index;
        g.at = f.a;
        if (f.ring == e.ring) {
            g.what = "edges " + std::to_string(f.index) + " and " + std::to_string(e.index) + " meet";
            g.effect =
                "kept: the region is where the rings' winding numbers (outer +1, hole -1) do not sum to "
                "0, and every edge is boundary";
        } else {
            g.what = "edge " + std::to_string(f.index) + " of ring " + std::to_string(live_index[f.ring]) +
                     " meets edge " + std::to_string(e.index) + " of ring " + std::to_string(live_index[e.ring]);
            g.effect =
                "kept: rings may touch or cross; the region is where the rings' winding numbers (outer +1, "
                "hole -1) do not sum to 0, and every edge is boundary";
        }
        c.add(g);
    });
    return m;
}

/// Reports holes outside every shell and rings nested where the others already wind.
inline void check_nesting(collector& c, const std::vector<wkt_ring>& input, const ring_set& set,
                          const std::vector<int>& stored_turn, const meetings& m) {
    // The winding number the other rings give about a ring that meets none
    // of them (constant along it), and so what its inside is.
    const auto& rings = set.rings;
    for (std::size_t k = 0; k < rings.size(); ++k) {
        if (!set.usable[k] || m.other[k] || m.itself[k]) continue;
        const point<double>& q = rings[k][0];
        int w = 0;
        for (std::size_t s = 0; s < rings.size(); ++s)
            if (s != k && set.usable[s]) w += stored_turn[s] * exact_winding(q, rings[s]).value_or(0);
        const bool hole = input[k].role == ring_role::hole;
        if (w == (hole ? 1 : 0)) continue;  // an outer ring outside the others, a hole in one shell
        const int inside = w + (hole ? -1 : 1);
        if (hole && w == 0) {
            c.add_at_ring(finding_kind::hole_outside_shell, k, q,
                          "no outer ring winds around the hole (the other rings' winding number there is 0)",
                          "kept: the region is where the winding number is not 0, and inside this hole it is -1: "
                          "the hole's inside counts as region");
            continue;
        }
        c.add_at_ring(finding_kind::nested_ring, k, q,
                      std::string(hole ? "the hole" : "the outer ring") +
                          " lies where the other rings' winding number is " + std::to_string(w) +
                          (hole ? "" : " (a shell inside a shell)"),
                      "kept: inside it the winding number is " + std::to_string(inside) +
                          (inside != 0 ? ", region as around it: the ring adds or removes no region (its edges are "
                                         "still boundary)"
                                       : ", not region: the ring cuts its inside out of the region around it"));
    }
}

/// Reports each point that is a vertex at two places of the rings that are not consecutive.
inline void check_non_manifold_vertices(collector& c, const ring_set& set) {
    struct place {
        point<double> p;
        std::size_t ring, vertex;
    };
    const auto& rings = set.rings;
    std::vector<place> all;
    for (std::size_t k = 0; k < rings.size(); ++k)
        if (set.usable[k])
            for (std::size_t v = 0; v < rings[k].size(); ++v) all.push_back({rings[k][v], k, v});
    std::sort(all.begin(), all.end(), [](const place& a, const place& b) {
        return std::tie(a.p.x, a.p.y, a.ring, a.vertex) < std::tie(b.p.x, b.p.y, b.ring, b.vertex);
    });
    for (std::size_t i = 0; i + 1 < all.size(); ++i) {
        const place &a = all[i], &b = all[i + 1];
        if (!(a.p == b.p)) continue;
        const std::size_t n = rings[a.ring].size();
        const bool consecutive = a.ring == b.ring && ((a.vertex + 1) % n == b.vertex || (b.vertex + 1) % n == a.vertex);
        if (consecutive) continue;
        finding f{finding_kind::non_manifold_vertex};
        f.ring = a.ring;
        f.vertex = a.vertex;
        f.other_ring = b.ring;
        f.other_vertex = b.vertex;
        f.at = a.p;
        f.what = "the point " + coordinates(a.p) + " is vertex " + std::to_string(a.vertex) + " of ring " +
                 std::to_string(a.ring) + " and vertex " + std::to_string(b.vertex) + " of ring " +
                 std::to_string(b.ring);
        f.effect = "kept: rings may touch at vertices; each occurrence is its own vertex";
        c.add(f);
    }
}

/// Builds the polygon as the library would, when nothing refused the input so far; its refusal refuses the input.
inline std::optional<polygon> library_polygon(collector& c, const std::vector<wkt_ring>& input, const ring_set& set) {
    std::optional<polygon> whole;
    if (!c.report.accepted) return whole;
    std::vector<ring_input> all;
    for (std::size_t k = 0; k < set.rings.size(); ++k)
        if (!set.rings[k].empty()) all.push_back({set.rings[k], input[k].role});
    try {
        whole.emplace(std::move(all));
    } catch (const invalid_input& e) {
        c.refuse(e.what());
    }
    return whole;
}

/// Reports each edge whose line passes through the polygon's centroid (a flat covering triangle).
inline void check_centroid_on_edge_lines(collector& c, const polygon& whole, const ring_set& set) {
    const point<double>& o = whole.centroid();
    const auto& rings = set.rings;
    for (std::size_t k = 0; k < rings.size(); ++k)
        for (std::size_t v = 0, n = rings[k].size(); v < n; ++v) {
            const point<double>& a = rings[k][v];
            const point<double>& b = rings[k][(v + 1) % n];
            if (a == b || exact_orientation(o, a, b) != 0) continue;
            c.add_at_vertex(finding_kind::centroid_on_edge_line, k, v, a,
                            "the centroid " + coordinates(o) + " lies on the line of edge " + std::to_string(v) +
                                ": its covering triangle is flat, its cone empty",
                            "kept: the flat triangle adds nothing to the inclusion test; points on that line are "
                            "located by the neighbouring cones");
        }
}

/// The magnitude above which (or below whose inverse) a nonzero coordinate
/// is reported as beyond_double_products: products of up to four
/// coordinates (a squared distance against a squared length times a
/// squared bound, as the distance predicates compare them) then leave
/// double's normal range, 2^-1022 to 2^1024 (2^2000 overflows, 2^-2000
/// underflows), where a predicate evaluated in double without scaling
/// loses its error bound.
inline constexpr double double_products_limit = 0x1p500;

/// Reports coordinates beyond float's range or inexact in float, and those whose products leave double's range.
inline void check_number_ranges(collector& c, const ring_set& set) {
    const auto& rings = set.rings;
    for (std::size_t k = 0; k < rings.size(); ++k)
        for (std::size_t v = 0; v < rings[k].size(); ++v) {
            const point<double>& p = rings[k][v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
            const double m = std::max(std::fabs(p.x), std::fabs(p.y));
            const double lo = std::min(std::fabs(p.x) > 0 ? std::fabs(p.x) : HUGE_VAL,
                                       std::fabs(p.y) > 0 ? std::fabs(p.y) : HUGE_VAL);
            if (m > FLT_MAX)
                c.add_at_vertex(finding_kind::beyond_float, k, v, p, "a coordinate is beyond float's range",
                                "detectors in float refuse the polygon (invalid_input): use double or wider");
            else if (static_cast<double>(static_cast<float>(p.x)) != p.x ||
                     static_cast<double>(static_cast<float>(p.y)) != p.y)
                c.add_at_vertex(finding_kind::inexact_in_float, k, v, p, "a coordinate is not exact in float",
                                "float mode rounds it: its answers are for a moved vertex");
            if (m > double_products_limit || lo < 1 / double_products_limit)
                c.add_at_vertex(finding_kind::beyond_double_products, k, v, p,
                                "products of coordinates leave double's normal range",
                                "the library's filters scale; double's own predicates may be wrong there; exact, "
                                "certified and interval stay exact");
        }
}

}  // namespace audit_detail

/// Audits the rings as read (closing points included where the input has them).
/// Never throws on bad input: what polygon's constructor would refuse is a
/// finding with `rejects` set and makes `accepted` false. Every finding but
/// the near_* ones is decided exactly (orientation by the exact fixed-point sum,
/// coordinate comparisons, the exact shoelace sign): repeated vertices,
/// collinear runs and spikes, edges that meet, ring orientation and zero area,
/// holes outside shells, the centroid (the library's, rounded to double) on
/// an edge's line, number ranges. The near_* findings
/// compare against the tolerance. Edges that meet are found by a sweep over
/// x: O(n log n + n a) for n edges of which at most a overlap in x at once.
///
/// The checks, in the order they run and report:
///
///     rings = read each input ring, closing point dropped; report an empty
///             ring, a non-finite coordinate, an unclosed ring, fewer than
///             three distinct vertices (all but a lone empty ring refuse the
///             input, and make the ring unusable for what follows)
///     near  = relative_tolerance * the extent of all finite vertices
///     for each usable ring k:
///         its vertices: repeated, nearer than `near` to the next, on the
///             line of their neighbours (a collinear run or a spike)
///         its area and turn: zero area (all on one line, or cancelling
///             lobes), near-zero area, reversed orientation; remember the
///             turn the polygon stores it with
///     edges that meet (a sweep over x): within a ring, between two rings
///     for each usable ring that meets no ring: the winding number of the
///         others around it (stored turns): a hole outside every shell, a
///         ring nested where the others already wind
///     points that are vertices at two places not consecutive on a ring
///     if nothing refused the input: build the polygon as the library does
///         (its refusal refuses the input); report the edges whose line
///         passes through its centroid
///     coordinates beyond float, inexact in float, or whose products leave
///         double's normal range
inline audit_report audit_rings(const std::vector<wkt_ring>& input, const audit_options& o = {}) {
    using namespace audit_detail;
    collector c(o);
    const ring_set set = read_rings(c, input);
    const double near = o.relative_tolerance * extent_of(set.rings);
    std::vector<int> stored_turn(set.rings.size(), 1);  // -1 for a ring stored reversed
    for (std::size_t k = 0; k < set.rings.size(); ++k) {
        if (!set.usable[k]) continue;
        check_vertices(c, k, set.rings[k], near);
        stored_turn[k] = check_area_and_orientation(c, k, set.rings[k], input[k].role);
    }
    const meetings m = check_meeting_edges(c, set);
    check_nesting(c, input, set, stored_turn, m);
    check_non_manifold_vertices(c, set);
    if (const std::optional<polygon> whole = library_polygon(c, input, set))
        check_centroid_on_edge_lines(c, *whole, set);
    check_number_ranges(c, set);
    return c.report;
}

}  // namespace influence2d
