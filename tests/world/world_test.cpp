// SPDX-License-Identifier: BSL-1.0
// Many bodies (world/world.hpp) and layers (world/layer_pairs.hpp) against an
// independent exact reference: every pair of bodies placed exactly on CGAL's
// Cartesian kernel over exact rationals and tested by its own predicates
// (support/exact_regions.hpp; CGAL's squared_distance for a distance), never
// the world's broad phase, witnesses or the library's pair tests. Random
// scenes with multipolygons, holes and islands, bodies that touch exactly,
// nest, sit far from the origin, move, stay, appear and disappear; serial
// against parallel, coherence on and off, events against the contacts'
// differences.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/neighbours.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"
#include "support/world_reference.hpp"

#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/exact/certified_intersects.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/convexity.hpp"
#include "influence2d/predicates/shared_vertex.hpp"
#include "influence2d/query/both_posed.hpp"
#include "influence2d/world/layer_pairs.hpp"
#include "influence2d/world/world.hpp"
#include "verification/world_scenes.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;
using test_world::body_state;
using test_world::exact_within;
using test_world::reference_contacts;

/// The shapes and the bodies added to world w.
template <class World>
void add_to(World& w, const std::vector<polygon>& shapes, const std::vector<body_state>& bodies) {
    for (const polygon& p : shapes) w.add_shape(p);
    for (const body_state& b : bodies) w.add_body(static_cast<std::uint32_t>(b.shape), b.where, b.fixed);
}

/// The box of p posed by q, in double (for laying out a test scene).
box placed_box(const polygon& p, const pose& q) {
    const rotation_pose t(q);
    box b;
    for (const point<double>& v : p.vertices()) b.add(t.apply<double>(v));
    return b;
}

std::string show_pairs(const std::vector<body_pair>& v) {
    std::ostringstream s;
    for (const body_pair& p : v) s << '(' << p.first << ',' << p.second << ')';
    return s.str();
}

/// The cells of an n x n grid over corners jittered by multiples of 1/64
/// (shared borders at every slope; every third cell with a repeated
/// vertex, an edge of length 0), each a shape about its cell's own origin
/// and a body at its cell's place (i, j) by a translation.
void jittered_cells(rng& g, int n, std::vector<polygon>& shapes, std::vector<body_state>& bodies) {
    std::vector<std::vector<point<double>>> corner(n + 1, std::vector<point<double>>(n + 1));
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            corner[i][j] = {i + static_cast<double>(g.index(33)) / 64 - 0.25,
                            j + static_cast<double>(g.index(33)) / 64 - 0.25};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            ring_input ring;
            for (const point<double>& c : {corner[i][j], corner[i + 1][j], corner[i + 1][j + 1], corner[i][j + 1]})
                ring.vertices.push_back({c.x - i, c.y - j});  // about the cell's own origin
            if (shapes.size() % 3 == 0) ring.vertices.insert(ring.vertices.begin() + 1, ring.vertices[1]);
            shapes.push_back(polygon({ring}));
            bodies.push_back({shapes.size() - 1, {static_cast<double>(i), static_cast<double>(j), 0}, false});
        }
}

/// The jittered cells of an n x n grid (jittered_cells) stepped `steps`
/// times in a certified world and a world in exact rationals, each step
/// REQUIREd to give the exact reference's contacts, which are returned.
/// At each step after the first each cell is, with chance 0.3, slid by
/// `slide` (which moves its pose and says whether it did), else with
/// chance 0.3 put back at its place, else left where it is.
template <class Slide>
std::vector<std::vector<body_pair>> slid_cells_as_the_reference(rng& g, int n, int steps, certified_world& certified,
                                                                world<exact_rational>& exact, Slide slide) {
    std::vector<polygon> shapes;
    std::vector<body_state> bodies;
    jittered_cells(g, n, shapes, bodies);
    add_to(certified, shapes, bodies);
    add_to(exact, shapes, bodies);
    std::vector<std::vector<body_pair>> contacts;
    for (int step = 0; step < steps; ++step) {
        if (step > 0)
            for (std::size_t k = 0; k < bodies.size(); ++k) {
                pose& q = bodies[k].where;
                const bool slid = g.chance(0.3) && slide(q);
                if (!slid) {
                    if (!g.chance(0.3)) continue;
                    q = {static_cast<double>(k / n), static_cast<double>(k % n), 0};  // back to its place
                }
                certified.move(static_cast<std::uint32_t>(k), q);
                exact.move(static_cast<std::uint32_t>(k), q);
            }
        contacts.push_back(reference_contacts(shapes, bodies, 0));
        INFO("step " << step);
        REQUIRE(show_pairs(certified.step()) == show_pairs(contacts.back()));
        REQUIRE(show_pairs(exact.step()) == show_pairs(contacts.back()));
    }
    return contacts;
}

/// p mirrored across the diagonal (x and y swapped) when `mirrored`, then
/// scaled by 2^scale, then moved by `shift` (exact when the sums are): each
/// ring keeping its role.
point<double> mapped_point(point<double> p, bool mirrored, int scale, point<double> shift = {0, 0}) {
    if (mirrored) std::swap(p.x, p.y);
    return {std::ldexp(p.x, scale) + shift.x, std::ldexp(p.y, scale) + shift.y};
}
polygon mapped_polygon(const polygon& p, bool mirrored, int scale, point<double> shift = {0, 0}) {
    std::vector<ring_input> rings;
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
        ring_input ring;
        ring.role = p.role(r);
        for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i)
            ring.vertices.push_back(mapped_point(p.vertex(i), mirrored, scale, shift));
        rings.push_back(ring);
    }
    return polygon(rings);
}

/// The pairs of polygons, one of `first` and one of `second` (i < j when
/// both are one layer), whose boxes' x-intervals overlap: the tests a sweep
/// along x would make.
std::size_t x_overlaps(const std::vector<polygon>& first, const std::vector<polygon>& second) {
    const bool same = &first == &second;
    std::size_t count = 0;
    for (std::size_t i = 0; i < first.size(); ++i)
        for (std::size_t j = same ? i + 1 : 0; j < second.size(); ++j) {
            const box a = first[i].bounds(), b = second[j].bounds();
            count += a.min_x <= b.max_x && b.min_x <= a.max_x ? 1 : 0;
        }
    return count;
}

/// Random shapes: multipolygons with holes and islands, and a few large
/// swallowers that nest others.
std::vector<polygon> random_shapes(rng& g, std::size_t count) {
    std::vector<polygon> out;
    for (std::size_t k = 0; k < count; ++k)
        out.push_back(k % 4 == 3 ? test_scenes::random_swallower(g).to_polygon()
                                 : test_scenes::random_multi(g, 6, 5).to_polygon());
    return out;
}

/// A pose within the scene's square [origin - extent, origin + extent]^2,
/// snapped and unturned half of the time (exact touching), turned at random
/// otherwise.
pose random_pose(rng& g, point<double> origin, double extent) {
    const double x = origin.x + g.uniform(-extent, extent), y = origin.y + g.uniform(-extent, extent);
    if (g.chance(0.5)) return {test_scenes::snap(x), test_scenes::snap(y), 0};
    return {x, y, g.uniform(-3.2, 3.2)};
}

/// Two worlds of double with witnesses, one serial and one on two threads,
/// holding the same n bodies of `shapes` at random poses within `reach` of
/// the origin (every `fixed_every`-th body fixed), moved and removed alike.
struct serial_and_parallel {
    world<double> serial, parallel;
    std::vector<pose> where;  // each body's pose

    serial_and_parallel(rng& g, const std::vector<polygon>& shapes, std::size_t n, double reach,
                        std::size_t fixed_every)
        : serial(with_witness(1)), parallel(with_witness(2)), where(n) {
        for (const polygon& p : shapes) {
            serial.add_shape(p);
            parallel.add_shape(p);
        }
        for (std::size_t i = 0; i < n; ++i) {
            where[i] = random_pose(g, {0, 0}, reach);
            const auto s = static_cast<std::uint32_t>(g.index(shapes.size()));
            serial.add_body(s, where[i], i % fixed_every == 0);
            parallel.add_body(s, where[i], i % fixed_every == 0);
        }
    }
    static world_options with_witness(unsigned threads) {
        world_options o;
        o.witness = true;
        o.threads = threads;
        return o;
    }
    void move(std::size_t i, const pose& q) {
        where[i] = q;
        serial.move(static_cast<std::uint32_t>(i), q);
        parallel.move(static_cast<std::uint32_t>(i), q);
    }
    void remove(std::size_t i) {
        serial.remove(static_cast<std::uint32_t>(i));
        parallel.remove(static_cast<std::uint32_t>(i));
    }
    /// Both worlds stepped: the same contacts, witnesses, events and carried
    /// pairs; the number of contacts.
    std::size_t step() {
        const std::vector<body_pair> ra = serial.step(), rb = parallel.step();
        REQUIRE(show_pairs(ra) == show_pairs(rb));
        REQUIRE(serial.witnesses().size() == parallel.witnesses().size());
        std::size_t same_witness = 0;
        for (std::size_t k = 0; k < ra.size(); ++k)
            same_witness += serial.witnesses()[k].first.index == parallel.witnesses()[k].first.index &&
                            serial.witnesses()[k].second.index == parallel.witnesses()[k].second.index;
        CHECK(same_witness == ra.size());
        REQUIRE(serial.events().size() == parallel.events().size());
        std::size_t same_event = 0;
        for (std::size_t k = 0; k < serial.events().size(); ++k)
            same_event += serial.events()[k].bodies == parallel.events()[k].bodies &&
                          serial.events()[k].begins == parallel.events()[k].begins;
        CHECK(same_event == serial.events().size());
        CHECK(serial.statistics().carried == parallel.statistics().carried);
        return ra.size();
    }
};

/// Runs a random scene of `steps` steps through a world and the reference,
/// checking every step's contacts and the events; a coherent move is up to
/// `stride` in each coordinate (a tenth of it in radians), and a move is a
/// jump to a random pose with chance `jumps`. Returns the
/// world's statistics.
template <class World>
world_statistics check_world_scene(std::uint64_t seed, point<double> origin, double within, int steps,
                                   world_options options, double stride = 1, double jumps = 0.2) {
    rng g(seed);
    const std::vector<polygon> shapes = random_shapes(g, 6);
    options.within = within;
    World w(options);
    for (const polygon& p : shapes) w.add_shape(p);
    std::vector<body_state> bodies;
    const double extent = 40;
    std::vector<body_pair> last;
    std::size_t contacts = 0, ends = 0;
    for (int step = 0; step < steps; ++step) {
        // New bodies at the first step and now and then; moves, removals.
        const std::size_t adds = step == 0 ? 24 : g.index(3);
        for (std::size_t k = 0; k < adds; ++k) {
            body_state b{g.index(shapes.size()), random_pose(g, origin, extent), g.chance(0.25)};
            w.add_body(static_cast<std::uint32_t>(b.shape), b.where, b.fixed);
            bodies.push_back(b);
        }
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (!bodies[i].alive || step == 0) continue;
            if (g.chance(0.05)) {
                bodies[i].alive = false;
                w.remove(static_cast<std::uint32_t>(i));
            } else if (g.chance(0.6)) {
                // A small step (coherent) or a jump.
                pose& q = bodies[i].where;
                q = !g.chance(jumps) ? pose{q.tx + g.uniform(-stride, stride), q.ty + g.uniform(-stride, stride),
                                            q.theta + g.uniform(-stride, stride) / 10}
                                     : random_pose(g, origin, extent);
                w.move(static_cast<std::uint32_t>(i), q);
            }
        }
        const std::vector<body_pair> got = w.step();
        const std::vector<body_pair> want = reference_contacts(shapes, bodies, within);
        INFO("seed " << seed << " step " << step << " origin " << origin.x << " within " << within);
        REQUIRE(show_pairs(got) == show_pairs(want));
        // Events: the difference of the contacts.
        std::vector<body_pair> begun, ended;
        std::set_difference(want.begin(), want.end(), last.begin(), last.end(), std::back_inserter(begun));
        std::set_difference(last.begin(), last.end(), want.begin(), want.end(), std::back_inserter(ended));
        std::vector<body_pair> got_begun, got_ended;
        for (const contact_event& e : w.events()) (e.begins ? got_begun : got_ended).push_back(e.bodies);
        CHECK(show_pairs(got_begun) == show_pairs(begun));
        CHECK(show_pairs(got_ended) == show_pairs(ended));
        if (options.witness) CHECK(w.witnesses().size() == got.size());
        last = want;
        contacts += want.size();
        ends += ended.size();
    }
    CHECK(contacts > 0);  // the scene has contacts to compare
    CHECK(ends > 0);      // and some of them end
    return w.statistics();
}

/// The pairs (i, j), i < j, of a layer at its own coordinates whose closed
/// regions meet: every pair whose boxes meet, both placed in exact
/// rationals (CGAL, test_exact::regions_meet).
std::vector<body_pair> exact_layer_pairs(const std::vector<polygon>& layer) {
    std::vector<test_exact::placed_shape> exact;
    for (const polygon& p : layer) exact.push_back(test_exact::place(p, 0, 0, 0));
    std::vector<body_pair> want;
    for (std::size_t i = 0; i < layer.size(); ++i)
        for (std::size_t j = i + 1; j < layer.size(); ++j)
            if (boxes_overlap(layer[i].bounds(), layer[j].bounds()) && test_exact::regions_meet(exact[i], exact[j]))
                want.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
    return want;
}

/// A layer's polygons of even index and those of odd index, as two layers.
std::pair<std::vector<polygon>, std::vector<polygon>> even_and_odd(const std::vector<polygon>& layer) {
    std::pair<std::vector<polygon>, std::vector<polygon>> out;
    for (std::size_t k = 0; k < layer.size(); ++k) (k % 2 ? out.second : out.first).push_back(layer[k]);
    return out;
}

/// The pairs of a one-layer answer between a polygon of even index and one
/// of odd index, as the answers of the two layers of even_and_odd: the
/// even ones against the odd ones, and the odd ones against the even ones
/// (each sorted).
std::pair<std::vector<body_pair>, std::vector<body_pair>> even_odd_pairs(const std::vector<body_pair>& pairs) {
    std::pair<std::vector<body_pair>, std::vector<body_pair>> out;
    for (const body_pair& p : pairs)
        if (p.first % 2 != p.second % 2) {
            const std::uint32_t e = p.first % 2 ? p.second : p.first, o = p.first % 2 ? p.first : p.second;
            out.first.push_back({e / 2, o / 2});
            out.second.push_back({o / 2, e / 2});
        }
    std::sort(out.first.begin(), out.first.end());
    std::sort(out.second.begin(), out.second.end());
    return out;
}

/// Checks the joins of `layer` (certified, in exact rationals and in
/// double: at their own coordinates the layers of these tests are decided
/// exactly in double too) and of its polygons of even and of odd index as
/// two layers, both ways, against `want`, the one layer's pairs by the
/// exact reference.
void check_joins(const std::vector<polygon>& layer, const std::vector<body_pair>& want) {
    CHECK(show_pairs(certified_layer_pairs(layer)) == show_pairs(want));
    CHECK(show_pairs(layer_pairs<exact_rational>(layer)) == show_pairs(want));
    CHECK(show_pairs(layer_pairs<double>(layer)) == show_pairs(want));
    const auto [even, odd] = even_and_odd(layer);
    const auto [want_eo, want_oe] = even_odd_pairs(want);
    CHECK(show_pairs(certified_layer_pairs(even, odd)) == show_pairs(want_eo));
    CHECK(show_pairs(certified_layer_pairs(odd, even)) == show_pairs(want_oe));
    CHECK(show_pairs(layer_pairs<exact_rational>(odd, even)) == show_pairs(want_oe));
    CHECK(show_pairs(layer_pairs<double>(odd, even)) == show_pairs(want_oe));
}

}  // namespace

TEST_CASE("world: certified contacts are the exact reference's on random scenes", "[world]") {
    const int scenes = test_effort::scaled(6);
    world_options o;
    for (int s = 0; s < scenes; ++s) {
        o.coherence = s % 2 == 0;
        o.witness = s % 3 == 0;
        check_world_scene<certified_world>(100 + s, {0, 0}, 0, 12, o);
    }
    CHECK(scenes > 0);
}

TEST_CASE("world: far from the origin and within a distance", "[world]") {
    world_options o;
    check_world_scene<certified_world>(200, {1e9, -3e8}, 0, 8, o);
    check_world_scene<certified_world>(201, {0, 0}, 0.75, 8, o);
    check_world_scene<certified_world>(202, {-5e6, 5e6}, 2.5, 6, o);
}

TEST_CASE("world: small moves stay in the enlarged boxes and the contacts stay the reference's", "[world]") {
    // Most moves small enough that a body's box stays in its enlarged box
    // (no tree rebuilt, the near pairs kept), contacts persisting over many
    // steps (their witnesses tried first), some bodies nested in others.
    for (const bool coherence : {true, false}) {
        world_options o;
        o.coherence = coherence;
        const world_statistics st = check_world_scene<certified_world>(500 + coherence, {0, 0}, 0, 20, o, 0.05, 0.02);
        INFO("escaped " << st.escaped << " of " << st.moved << " moved");
        CHECK(st.escaped * 2 < st.moved);  // most moved bodies stayed in their enlarged boxes
        INFO("witness hits " << st.witness_hits << ", contacts " << st.contacts << ", separated " << st.separated
                             << ", found apart " << st.found_apart << ", by nearby edges " << st.nearby_edges);
        if (coherence) CHECK(st.witness_hits * 4 > st.contacts);  // persisting contacts kept their witness
        if (coherence) CHECK(st.separated > 20);                  // pairs apart kept their separating edge
        // Pairs new or parted found apart before the one-shot test, and
        // edges that parted answered by their neighbours: the contacts above
        // are the reference's with both routes taken.
        if (coherence) CHECK(st.found_apart > 0);
        if (coherence) CHECK(st.nearby_edges > 0);
        if (!coherence) CHECK(st.separated + st.found_apart + st.nearby_edges == 0);
    }
    world_options o;
    const world_statistics st = check_world_scene<certified_world>(502, {4e6, -2e6}, 0.25, 12, o, 0.05, 0.02);
    CHECK(st.escaped * 2 < st.moved);
}

TEST_CASE("world: the paper's trajectories for many bodies, the exact reference's at every step", "[world]") {
    // The time study's scene (verification/world_scenes.hpp): cells of a
    // fixed family polygon A and a polygon B on the paper's circular
    // trajectory (within the gap of 9, never touching) or linear one (ending
    // inside A), every cell turned. The certified world with and without
    // coherence, and double (no pose of the scene lies within rounding of a
    // contact), against the all-pairs exact reference at every step.
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const verification::world_scene s = verification::make_world_scene("trajectories", 120, 16, seed);
        world_options coherent, fresh;
        coherent.witness = true;
        fresh.coherence = false;
        certified_world a(coherent), b(fresh);
        world<double> c(coherent);
        std::vector<test_world::body_state> state;
        for (const polygon& p : s.shapes) {
            a.add_shape(p);
            b.add_shape(p);
            c.add_shape(p);
        }
        std::size_t most = 0, least = s.shape_of.size();
        for (std::size_t t = 0; t < s.steps.size(); ++t) {
            for (std::uint32_t k = 0; k < s.shape_of.size(); ++k) {
                if (t == 0) {
                    state.push_back({s.shape_of[k], s.steps[0][k], s.fixed[k], true});
                    a.add_body(s.shape_of[k], s.steps[0][k], s.fixed[k]);
                    b.add_body(s.shape_of[k], s.steps[0][k], s.fixed[k]);
                    c.add_body(s.shape_of[k], s.steps[0][k], s.fixed[k]);
                    continue;
                }
                const pose &now = s.steps[t][k], &was = s.steps[t - 1][k];
                if (now.tx != was.tx || now.ty != was.ty || now.theta != was.theta) {
                    state[k].where = s.steps[t][k];
                    a.move(k, s.steps[t][k]);
                    b.move(k, s.steps[t][k]);
                    c.move(k, s.steps[t][k]);
                }
            }
            const std::vector<body_pair> expected = test_world::reference_contacts(s.shapes, state, 0);
            INFO("seed " << seed << ", step " << t);
            CHECK(a.step() == expected);
            CHECK(b.step() == expected);
            CHECK(c.step() == expected);
            most = std::max(most, expected.size());
            least = std::min(least, expected.size());
        }
        INFO("seed " << seed << ": contacts from " << least << " to " << most);
        CHECK(most > least);  // linear cells came into contact during the run
        // Circular cells came near (their boxes met) and were kept apart by a
        // separating edge from step to step.
        CHECK(a.statistics().separated > 0);
    }
}

TEST_CASE("world: the exact type alone gives the same contacts", "[world]") {
    world_options o;
    check_world_scene<world<exact_rational>>(300, {0, 0}, 0, 5, o);
    check_world_scene<world<exact_rational>>(301, {3e7, 1e7}, 0.5, 4, o);
}

TEST_CASE("world: the contacts do not depend on the numbering, the shapes' order, a mirror or a power-of-two scale",
          "[world]") {
    // One random scene run through certified worlds that differ only in
    // what must not change the answer: the bodies added in another order
    // (other ids), the shapes added in reverse, the scene mirrored across the
    // diagonal (x and y swapped, every angle negated: the cosine is even and
    // the sine odd in double too, so each posed region is the exact mirror),
    // and scaled by 2^-40, 2^40 or 2^-1000 (shapes and translations). The
    // first world is held to the exact reference, the others to it.
    for (int round = 0; round < test_effort::scaled(4); ++round) {
        rng g(900 + static_cast<std::uint64_t>(round));
        const std::vector<polygon> shapes = random_shapes(g, 5);
        const std::size_t n = 30, steps = 6;
        std::vector<std::vector<body_state>> scene(steps);
        for (std::size_t i = 0; i < n; ++i)
            scene[0].push_back({g.index(shapes.size()), random_pose(g, {0, 0}, 20), g.chance(0.2)});
        for (std::size_t s = 1; s < steps; ++s) {
            scene[s] = scene[s - 1];
            for (body_state& b : scene[s])
                if (!b.fixed && g.chance(0.7))
                    b.where = g.chance(0.15) ? random_pose(g, {0, 0}, 20)
                                             : pose{b.where.tx + g.uniform(-1, 1), b.where.ty + g.uniform(-1, 1),
                                                    b.where.theta + g.uniform(-0.1, 0.1)};
        }
        std::vector<std::uint32_t> order(n);  // the order in which the bodies are added
        for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
        for (std::size_t i = n; i-- > 1;) std::swap(order[i], order[g.index(i + 1)]);
        struct variant {
            bool reordered, mirrored;
            int scale;  // a power of two
        };
        const variant variants[] = {{false, false, 0},   {true, false, 0}, {true, true, 0},
                                    {false, false, -40}, {true, true, 40}, {false, true, -1000}};
        std::vector<std::vector<body_pair>> first;
        for (const variant& v : variants) {
            INFO("round " << round << ", reordered " << v.reordered << ", mirrored " << v.mirrored << ", scale 2^"
                          << v.scale);
            const auto mapped_pose = [&](const pose& q) {
                const point<double> t = mapped_point({q.tx, q.ty}, v.mirrored, v.scale);
                return pose{t.x, t.y, v.mirrored ? -q.theta : q.theta};
            };
            certified_world w;
            std::vector<std::uint32_t> shape_id(shapes.size()), body_id(n);
            for (std::size_t k = 0; k < shapes.size(); ++k) {
                const std::size_t s = v.reordered ? shapes.size() - 1 - k : k;
                shape_id[s] = w.add_shape(mapped_polygon(shapes[s], v.mirrored, v.scale));
            }
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t i = v.reordered ? order[k] : k;
                const body_state& b = scene[0][i];
                body_id[i] = w.add_body(shape_id[b.shape], mapped_pose(b.where), b.fixed);
            }
            std::vector<std::uint32_t> scene_id(n);
            for (std::size_t i = 0; i < n; ++i) scene_id[body_id[i]] = static_cast<std::uint32_t>(i);
            for (std::size_t s = 0; s < steps; ++s) {
                for (std::size_t i = 0; s > 0 && i < n; ++i) {
                    const pose &now = scene[s][i].where, &was = scene[s - 1][i].where;
                    if (now.tx != was.tx || now.ty != was.ty || now.theta != was.theta)
                        w.move(body_id[i], mapped_pose(now));
                }
                std::vector<body_pair> got;
                for (const body_pair& p : w.step()) {
                    const std::uint32_t a = scene_id[p.first], b = scene_id[p.second];
                    got.push_back({std::min(a, b), std::max(a, b)});
                }
                std::sort(got.begin(), got.end());
                INFO("step " << s);
                if (first.size() < steps) {
                    REQUIRE(show_pairs(got) == show_pairs(reference_contacts(shapes, scene[s], 0)));
                    first.push_back(got);
                } else {
                    CHECK(show_pairs(got) == show_pairs(first[s]));
                }
            }
        }
        std::size_t contacts = 0;
        for (const std::vector<body_pair>& c : first) contacts += c.size();
        CHECK(contacts > 0);
    }
}

TEST_CASE("world: threads and coherence change nothing", "[world]") {
    rng g(400);
    const std::vector<polygon> shapes = random_shapes(g, 5);
    world_options serial, parallel, plain;
    parallel.threads = 2;
    plain.coherence = false;
    certified_world a(serial), b(parallel), c(plain);
    for (const polygon& p : shapes) {
        a.add_shape(p);
        b.add_shape(p);
        c.add_shape(p);
    }
    const std::size_t n = 400;
    std::vector<pose> where(n);
    for (std::size_t i = 0; i < n; ++i) {
        where[i] = random_pose(g, {0, 0}, 120);
        const auto s = static_cast<std::uint32_t>(g.index(shapes.size()));
        const bool fixed = i % 7 == 0;
        a.add_body(s, where[i], fixed);
        b.add_body(s, where[i], fixed);
        c.add_body(s, where[i], fixed);
    }
    std::size_t contacts = 0;
    for (int step = 0; step < 10; ++step) {
        const std::vector<body_pair> ra = a.step(), rb = b.step(), rc = c.step();
        REQUIRE(show_pairs(ra) == show_pairs(rb));
        REQUIRE(show_pairs(ra) == show_pairs(rc));
        contacts += ra.size();
        for (std::size_t i = 0; i < n; ++i) {
            if (i % 7 == 0 || g.chance(0.3)) continue;
            where[i] = {where[i].tx + g.uniform(-0.5, 0.5), where[i].ty + g.uniform(-0.5, 0.5),
                        where[i].theta + g.uniform(-0.05, 0.05)};
            a.move(static_cast<std::uint32_t>(i), where[i]);
            b.move(static_cast<std::uint32_t>(i), where[i]);
            c.move(static_cast<std::uint32_t>(i), where[i]);
        }
    }
    CHECK(contacts > 100);  // the scene has contacts to compare
    CHECK(a.statistics().witness_hits > 0);
    CHECK(c.statistics().witness_hits == 0);
}

TEST_CASE("world: thousands of bodies on two threads, the joins and candidates shared, as on one", "[world]") {
    // Enough bodies and near pairs for the broad phase's parallel passes
    // (world.hpp: parallel_join_bodies, parallel_near_pairs): steps where
    // every body jumps (the joins) and steps of small moves, with witnesses.
    rng g(410);
    const std::vector<polygon> shapes = random_shapes(g, 5);
    const std::size_t n = 5000;
    serial_and_parallel w(g, shapes, n, 250, 11);
    const int steps = std::max(2, test_effort::scaled(6));
    std::vector<char> alive(n, 1);
    std::size_t contacts = 0, ended = 0;
    for (int step = 0; step < steps; ++step) {
        INFO("step " << step);
        contacts += w.step();
        for (const contact_event& e : w.serial.events()) ended += e.begins ? 0 : 1;
        const bool jump = step % 2 == 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (i % 11 == 0 || !alive[i]) continue;
            // (A few bodies removed on steps of small moves: their contacts
            // end at the next step.)
            if (!jump && i % 97 == static_cast<std::size_t>(step)) {
                w.remove(i);
                alive[i] = false;
                continue;
            }
            const pose& at = w.where[i];
            w.move(i, jump ? random_pose(g, {0, 0}, 250)
                           : pose{at.tx + g.uniform(-0.3, 0.3), at.ty + g.uniform(-0.3, 0.3),
                                  at.theta + g.uniform(-0.03, 0.03)});
        }
    }
    INFO("contacts " << contacts << ", candidates " << w.serial.statistics().candidates);
    CHECK(contacts > 1000);
    CHECK(ended > 0);
    // Past the thresholds of the parallel passes: more bodies than 4,096 and
    // more candidates a step (so more near pairs) than 16,384.
    CHECK(w.serial.statistics().candidates > 16384 * static_cast<std::size_t>(steps));
    CHECK(w.parallel.statistics().rebuilds == w.serial.statistics().rebuilds);
}

TEST_CASE("world: many escaped bodies among more that stay, their queries shared by two threads, as on one",
          "[world]") {
    // Over 1,024 bodies leave their enlarged boxes at a step, fewer than a
    // quarter of all (world.hpp: parallel_escaped_queries): their queries of
    // the trees are shared among the threads; the answers must be the serial
    // run's, witnesses and events included.
    rng g(420);
    const std::vector<polygon> shapes = random_shapes(g, 5);
    const std::size_t n = 6000;
    serial_and_parallel w(g, shapes, n, 300, 13);
    const int steps = 4;
    std::size_t contacts = 0;
    for (int step = 0; step < steps; ++step) {
        INFO("step " << step);
        contacts += w.step();
        // 1,300 free bodies moved by a few units (out of their enlarged
        // boxes), the others left where they are.
        for (std::size_t k = 0; k < 1300; ++k) {
            std::size_t i = g.index(n);
            while (i % 13 == 0) i = g.index(n);
            const pose& at = w.where[i];
            w.move(i, {at.tx + g.uniform(-4, 4), at.ty + g.uniform(-4, 4), at.theta + g.uniform(-0.3, 0.3)});
        }
    }
    INFO("contacts " << contacts << ", escaped " << w.serial.statistics().escaped);
    CHECK(contacts > 1000);
    // Past the threshold at the steps after the first: over 1,024 escaped
    // bodies a step, fewer than a quarter of the 6,000.
    CHECK(w.serial.statistics().escaped >= n + 1024 * static_cast<std::size_t>(steps - 1));
    CHECK(w.serial.statistics().escaped < n + 1500 * static_cast<std::size_t>(steps - 1));
    CHECK(w.parallel.statistics().rebuilds == w.serial.statistics().rebuilds);
}

TEST_CASE("world: more moved bodies than the box pass's bound, their boxes made on two threads, as on one", "[world]") {
    // Over 16,384 bodies moved at every step (world.hpp: parallel_boxes):
    // their boxes are made in parallel blocks and the escaped ones listed in
    // the serial order; small moves (most bodies stay in their enlarged
    // boxes) and a jump of every tenth body.
    rng g(430);
    const std::vector<polygon> shapes = random_shapes(g, 5);
    const std::size_t n = 17000;
    serial_and_parallel w(g, shapes, n, 460, 1000);
    const int steps = 3;
    std::size_t contacts = 0;
    for (int step = 0; step < steps; ++step) {
        INFO("step " << step);
        contacts += w.step();
        for (std::size_t i = 0; i < n; ++i) {
            if (i % 1000 == 0) continue;  // (fixed)
            const pose& at = w.where[i];
            w.move(i, i % 10 == static_cast<std::size_t>(step)
                          ? random_pose(g, {0, 0}, 460)
                          : pose{at.tx + g.uniform(-0.3, 0.3), at.ty + g.uniform(-0.3, 0.3),
                                 at.theta + g.uniform(-0.03, 0.03)});
        }
    }
    contacts += w.step();
    INFO("contacts " << contacts << ", moved " << w.serial.statistics().moved);
    CHECK(contacts > 1000);
    // Past the bound at every step after the first: 16,983 free bodies moved.
    CHECK(w.serial.statistics().moved >= n + 16384 * static_cast<std::size_t>(steps));
    CHECK(w.serial.statistics().escaped > 0);
    CHECK(w.parallel.statistics().rebuilds == w.serial.statistics().rebuilds);
}

TEST_CASE("world: squares sharing edges and corners touch exactly", "[world]") {
    // A 6 x 6 grid of unit squares, every fourth one fixed: each touches its
    // 8 neighbours (edges and corners), none else; after a shift of the
    // free ones by 2^-40 to the right, a free square no longer touches its
    // fixed neighbours except on the shifted side.
    certified_world w;
    const auto s = w.add_shape(test_shapes::square(0, 0, 1));
    const int n = 6;
    for (int i = 0; i < n * n; ++i)
        w.add_body(s, {static_cast<double>(i % n), static_cast<double>(i / n), 0}, i % 4 == 0);
    std::vector<body_pair> want;
    for (int i = 0; i < n * n; ++i)
        for (int j = i + 1; j < n * n; ++j) {
            const bool near = std::abs(i % n - j % n) <= 1 && std::abs(i / n - j / n) <= 1;
            if (near && !(i % 4 == 0 && j % 4 == 0))
                want.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        }
    CHECK(show_pairs(w.step()) == show_pairs(want));
    // Every body: the same poses again change nothing.
    for (int i = 0; i < n * n; ++i)
        w.move(static_cast<std::uint32_t>(i), {static_cast<double>(i % n), static_cast<double>(i / n), 0});
    CHECK(show_pairs(w.step()) == show_pairs(want));
    CHECK(w.events().empty());
}

TEST_CASE("world: cells slid on a grid, their witness edges decided on the doubles, as the reference", "[world]") {
    // The cells of a jittered grid (shared borders at every slope; every
    // third cell with a repeated vertex, an edge of length 0), each a body
    // at its cell's place by a translation. At each step some cells slide by
    // a multiple of 1/64 along an axis, or back to their place: every posed
    // vertex a double, so that the witness edges and their neighbours are
    // tested again on those doubles (translated_exactly), the contacts
    // touching exactly along the borders or overlapping by a few 1/64. The
    // certified world and the world in exact rationals, each step against
    // the exact reference.
    rng g(20261206);
    certified_world certified;
    world<exact_rational> exact;
    const std::vector<std::vector<body_pair>> contacts =
        slid_cells_as_the_reference(g, 5, 16, certified, exact, [&](pose& q) {
            (g.chance(0.5) ? q.tx : q.ty) += static_cast<double>(static_cast<int>(g.index(17)) - 8) / 64;
            return true;
        });
    std::size_t touching_steps = 0;
    for (const std::vector<body_pair>& want : contacts) touching_steps += want.size() >= 40 ? 1 : 0;
    // The 40 pairs that share a border (and the 32 that share a corner)
    // touch at the start and again whenever their cells came back;
    // witnesses and their neighbours were tried.
    CHECK(touching_steps >= 2);
    for (const world_statistics& st : {certified.statistics(), exact.statistics()}) {
        INFO("witness hits " << st.witness_hits << ", by nearby edges " << st.nearby_edges);
        CHECK(st.witness_hits > 100);
        CHECK(st.nearby_edges > 0);
    }
}

TEST_CASE("world: cells slid by less than their vertices' last place, decided where they stand, as the reference",
          "[world]") {
    // The jittered cells, sliding by 2^-51 along an axis (a cell below 4 on
    // it: its translation stays a double, while vertex + translation
    // beyond 4 rounds to a multiple of 2^-50) or back to their place. A pair
    // touching along a border and then slid apart by 2^-51 is apart exactly,
    // and touching still on the rounded sums: its witness edges must be
    // tested again where the bodies stand (in NT), not on those doubles.
    // The certified world and the world in exact rationals, each step
    // against the exact reference.
    rng g(20261207);
    certified_world certified;
    world<exact_rational> exact;
    const std::vector<std::vector<body_pair>> contacts =
        slid_cells_as_the_reference(g, 5, 24, certified, exact, [&](pose& q) {
            double& t = g.chance(0.5) ? q.tx : q.ty;
            if (t >= 4) return false;
            t += g.chance(0.5) ? 0x1p-51 : -0x1p-51;
            return true;
        });
    std::size_t apart_by_a_hair = 0;  // pairs that touched at the step before and are apart now
    for (std::size_t step = 1; step < contacts.size(); ++step)
        for (const body_pair& p : contacts[step - 1])
            apart_by_a_hair += std::binary_search(contacts[step].begin(), contacts[step].end(), p) ? 0 : 1;
    CHECK(apart_by_a_hair > 10);
    for (const world_statistics& st : {certified.statistics(), exact.statistics()}) {
        INFO("witness hits " << st.witness_hits);
        CHECK(st.witness_hits > 100);
    }
}

TEST_CASE("world: pairs kept apart by a hull edge, until they touch exactly", "[world]") {
    // Bodies of every kind (a square, a square with a hole, a C, random
    // multipolygons with holes and islands, a swallower) in pairs: the
    // second of each pair slides along x towards the first, from a gap of
    // 2^-3 between their boxes, by 16 steps of 2^-6 (the squares touch
    // exactly at the 8th) and then 16 steps of a 32nd of the smaller box's
    // width, and back, unturned (every pose exact in double) or turned by a
    // fixed angle; each step against the exact reference. Between the steps
    // a pair's separating edge is tried first: it must fail where the
    // bodies meet, exact touching included.
    rng g(2300);
    std::vector<polygon> shapes = {test_shapes::square(0, 0, 1), test_shapes::square_with_hole(),
                                   test_shapes::c_shape()};
    for (int k = 0; k < 2; ++k) shapes.push_back(test_scenes::random_multi(g, 2, 3).to_polygon());
    shapes.push_back(test_scenes::random_swallower(g).to_polygon());
    for (const double theta : {0.0, 0.3}) {
        certified_world w;
        for (const polygon& p : shapes) w.add_shape(p);
        std::vector<body_state> bodies;
        std::vector<double> start, coarse;  // each moving body's first abscissa and coarse step
        for (std::size_t a = 0; a < shapes.size(); ++a)
            for (std::size_t b = 0; b < shapes.size(); ++b) {
                // Pair (a, b) in a row of its own, far from the others.
                const double y = 1000.0 * static_cast<double>(a * shapes.size() + b);
                const pose pa{0, y, theta};
                const box ba = placed_box(shapes[a], pa), bb = placed_box(shapes[b], {0, y, theta});
                bodies.push_back({a, pa, g.chance(0.5)});
                bodies.push_back({b, {test_scenes::snap(ba.max_x - bb.min_x) + 0x1p-3, y, theta}, false});
                start.push_back(bodies.back().where.tx);
                coarse.push_back(test_scenes::snap(std::min(ba.max_x - ba.min_x, bb.max_x - bb.min_x) / 32) +
                                 test_scenes::grid);
                for (std::size_t k = bodies.size() - 2; k < bodies.size(); ++k)
                    w.add_body(static_cast<std::uint32_t>(bodies[k].shape), bodies[k].where, bodies[k].fixed);
            }
        std::size_t begun = 0;
        for (int step = 0; step <= 64; ++step) {
            const int in = step <= 32 ? step : 64 - step;  // steps taken towards the fixed body
            if (step > 0)
                for (std::size_t k = 1; k < bodies.size(); k += 2) {
                    bodies[k].where.tx =
                        start[k / 2] - 0x1p-6 * std::min(in, 16) - coarse[k / 2] * std::max(in - 16, 0);
                    w.move(static_cast<std::uint32_t>(k), bodies[k].where);
                }
            const std::vector<body_pair> got = w.step(), want = reference_contacts(shapes, bodies, 0);
            INFO("theta " << theta << " step " << step);
            REQUIRE(show_pairs(got) == show_pairs(want));
            for (const contact_event& e : w.events()) begun += e.begins ? 1 : 0;
        }
        const world_statistics& st = w.statistics();
        INFO("separated " << st.separated << ", begun " << begun);
        CHECK(st.separated > 100);                          // the separating edges served
        CHECK(begun * 2 >= shapes.size() * shapes.size());  // and then failed as the bodies met
    }
}

TEST_CASE("world: a separating edge fails when the bodies touch exactly", "[world]") {
    // Two triangles whose boxes overlap while they are apart: A = (0,0),
    // (1,0), (0,1) and B its mirror image (1,1), (0,1), (1,0) moved by
    // (t, t), t from 2^-3 down to -2^-3 by 2^-6 and back: B's hypotenuse
    // lies along A's exactly at t = 0 (touching along a whole edge), and
    // at t = 2^-6 the pair is apart by a separating edge kept from the step
    // before. A second pair: A again, and the triangle (0,1), (1,1), (1,2)
    // moved by (t, 0), whose corner (0, 1) meets A's corner (0, 1) at t = 0
    // (touching at one point), its bottom edge along A's corner after.
    const std::vector<polygon> shapes = {polygon({test_shapes::ring({{0, 0}, {1, 0}, {0, 1}})}),
                                         polygon({test_shapes::ring({{1, 1}, {0, 1}, {1, 0}})}),
                                         polygon({test_shapes::ring({{0, 1}, {1, 1}, {1, 2}})})};
    certified_world w;
    for (const polygon& p : shapes) w.add_shape(p);
    std::vector<body_state> bodies = {
        {0, {0, 0, 0}, true}, {1, {0x1p-3, 0x1p-3, 0}, false}, {0, {10, 0, 0}, true}, {2, {10 + 0x1p-3, 0, 0}, false}};
    for (const body_state& x : bodies) w.add_body(static_cast<std::uint32_t>(x.shape), x.where, x.fixed);
    std::size_t touching = 0;
    for (int step = 0; step <= 32; ++step) {
        const double t = 0x1p-6 * (step <= 16 ? 8 - step : step - 24);
        bodies[1].where = {t, t, 0};
        bodies[3].where = {10 + t, 0, 0};
        w.move(1, bodies[1].where);
        w.move(3, bodies[3].where);
        const std::vector<body_pair> got = w.step(), want = reference_contacts(shapes, bodies, 0);
        INFO("step " << step << " t " << t);
        REQUIRE(show_pairs(got) == show_pairs(want));
        if (t == 0) {
            CHECK(want.size() == 2);  // both pairs touch
            ++touching;
        }
    }
    CHECK(touching == 2);
    CHECK(w.statistics().separated >= 20);  // apart by a kept edge before touching
}

TEST_CASE("world: a kept separating edge is tried where the bodies stand exactly, not where double poses them",
          "[world]") {
    // A: the triangle (0,0), (8,0), (0,8) turned by theta and moved to about
    // (2^20, 2^20), where each posed coordinate rounds by up to 2^-33; its
    // hypotenuse's outward normal points to about (1, 1). B: the unit
    // square, its lower left corner at w. w is sought among the doubles
    // next to the hypotenuse's middle: strictly inside A (left of the
    // hypotenuse posed exactly) and strictly right of the line through the
    // hypotenuse's ends posed in double. B starts 2^-3 further out along
    // (1, 1) (apart: the hypotenuse becomes their separating edge), moves
    // 2^-4 in (the edge still separates them), then 2^-4 more, onto w,
    // where the bodies meet (CGAL's exact reference). A retest of the edge
    // on the doubles alone (separation_holds with no margin for the
    // posing's rounding) keeps them apart: it fails this test. The double
    // world answers for its own posing, as intersects<double> does.
    const polygon triangle({test_shapes::ring({{0, 0}, {8, 0}, {0, 8}})});
    const polygon square({test_shapes::ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}})});
    const auto index_of = [&](point<double> v) {
        const auto& vs = triangle.vertices();
        return static_cast<std::size_t>(std::find(vs.begin(), vs.end(), v) - vs.begin());
    };
    const std::size_t i8 = index_of({8, 0}), j8 = index_of({0, 8});
    REQUIRE(i8 < 3);
    REQUIRE(j8 < 3);
    const auto exact = [](point<double> v) { return test_exact::point_2(v.x, v.y); };
    rng g(2611);
    const int wanted = std::max(2, test_effort::scaled(8));
    int found = 0, trials = 0;
    while (found < wanted && trials < 400) {
        ++trials;
        const pose a_at{0x1p20 + g.uniform(0, 1), 0x1p20 + g.uniform(0, 1), g.uniform(0.05, 0.3)};
        const test_exact::placed_shape a_exact = test_exact::place(triangle, a_at);
        const rotation_pose t(a_at);
        const point<double> p = t.apply<double>({8, 0}), q = t.apply<double>({0, 8});
        const point<double> mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
        const double u = std::ldexp(1.0, std::ilogb(mid.x) - 52);
        bool placed = false;
        point<double> w;
        for (int dx = -16; dx <= 16 && !placed; ++dx)
            for (int dy = -16; dy <= 16 && !placed; ++dy) {
                w = {mid.x + dx * u, mid.y + dy * u};
                placed = CGAL::orientation(a_exact.v[i8], a_exact.v[j8], exact(w)) == CGAL::LEFT_TURN &&
                         CGAL::orientation(exact(p), exact(q), exact(w)) == CGAL::RIGHT_TURN;
            }
        if (!placed) continue;
        ++found;
        INFO("trial " << trials << " w " << w.x << " " << w.y);
        // (The exact and certified worlds answer for the exact poses; the
        // double world for its own posing, as intersects<double> does.)
        const auto run = [&](auto world_type, bool meet) {
            decltype(world_type) world;
            world.add_shape(triangle);
            world.add_shape(square);
            world.add_body(0, a_at, true);
            world.add_body(1, {w.x + 0x1p-3, w.y + 0x1p-3, 0});
            CHECK(world.step().empty());
            world.move(1, {w.x + 0x1p-4, w.y + 0x1p-4, 0});
            CHECK(world.step().empty());
            CHECK(world.statistics().separated == 1);  // the edge was kept, and tried
            world.move(1, {w.x, w.y, 0});
            const std::vector<body_pair> got = world.step();
            REQUIRE(got.size() == (meet ? 1u : 0u));
            if (meet) CHECK((got[0].first == 0 && got[0].second == 1));
        };
        run(certified_world{}, true);
        run(world<exact_rational>{}, true);
        run(world<double>{}, intersects<double>(triangle, a_at, square, pose{w.x, w.y, 0}));
        // B placed on w at once: a new pair, answered by the one-shot test on
        // the two posed placings, whose filters must allow for the posing's
        // rounding (a margin of 0 there misses the meeting).
        certified_world at_once;
        at_once.add_shape(triangle);
        at_once.add_shape(square);
        at_once.add_body(0, a_at, true);
        at_once.add_body(1, {w.x, w.y, 0});
        CHECK(at_once.step().size() == 1);
        // The reference: B's corner w lies in A's region, exactly.
        CHECK(test_exact::regions_meet(a_exact, test_exact::place(square, pose{w.x, w.y, 0})));
    }
    CHECK(found == wanted);
}

TEST_CASE("world: a turned body touching exactly where its vertex in double rounds off the other's box", "[world]") {
    // A: the unit square where it stands (its doubles are the decisions'
    // own). B: a thin triangle led by its vertex q = (qx, qy), turned by
    // theta and moved by (tx, ty), tx sought among the doubles next to
    // 1 - (c*qx - s*qy) so that q posed exactly (CGAL) lands on A's right
    // side x = 1 or just inside it, while q posed in double (three
    // roundings, of products near 2) lands beyond it: B's box in double
    // misses A's by a few units in the last place. Every other vertex of B
    // lies further right. The pair is new at its step, so the one-shot test
    // answers it, on a turned placing whose filters must allow for its
    // rounding (with no margin for it, the boxes keep the bodies apart).
    // Both orders of the bodies, certified and exact worlds, against the
    // reference; the double world answers for its own posing.
    const polygon square({test_shapes::ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}})});
    rng g(2718);
    const int wanted = std::max(3, test_effort::scaled(12));
    int found = 0, trials = 0;
    while (found < wanted && trials < 2000) {
        ++trials;
        const point<double> q{g.uniform(1.5, 2), g.uniform(1.5, 2)};
        const polygon thin({test_shapes::ring({q, {q.x + 6, q.y - 0.25}, {q.x + 6, q.y + 0.25}})});
        const double theta = g.uniform(0.05, 0.3);
        const rotation_pose turn(pose{0, 0, theta});
        const point<double> at_zero = turn.apply<double>(q);
        const double ty = 0.5 - at_zero.y;
        const double base = 1 - at_zero.x;
        double tx = base;
        bool placed = false;
        for (int k = -12; k <= 12 && !placed; ++k) {
            tx = base + k * std::ldexp(1.0, std::ilogb(base) - 52);
            const pose b_at{tx, ty, theta};
            const test_exact::placed_shape exact_b = test_exact::place(thin, b_at);
            placed = rotation_pose(b_at).apply<double>(q).x > 1 && exact_b.v[0].x() <= 1;
        }
        if (!placed) continue;
        ++found;
        const pose b_at{tx, ty, theta};
        INFO("trial " << trials << " theta " << theta << " tx " << tx);
        REQUIRE(test_exact::regions_meet(test_exact::place(square, pose{0, 0, 0}), test_exact::place(thin, b_at)));
        const auto contacts = [&](auto world_type, bool square_first) {
            decltype(world_type) world;
            world.add_shape(square);
            world.add_shape(thin);
            if (square_first) world.add_body(0, pose{0, 0, 0}, true);
            world.add_body(1, b_at);
            if (!square_first) world.add_body(0, pose{0, 0, 0}, true);
            return world.step().size();
        };
        for (const bool square_first : {true, false}) {
            CHECK(contacts(certified_world{}, square_first) == 1);
            CHECK(contacts(world<exact_rational>{}, square_first) == 1);
            CHECK(contacts(world<double>{}, square_first) ==
                  (intersects<double>(square, pose{0, 0, 0}, thin, b_at) ? 1u : 0u));
        }
    }
    CHECK(found == wanted);
}

TEST_CASE("world: turned bodies touching at the edge of their bounding discs", "[world]") {
    // An octagon whose vertices (+-2, 0) and (0, +-2) lie on its bounding
    // disc (radius 2) and whose other vertices lie inside it. Body A of
    // each pair stands at the origin turned by theta near a multiple of a
    // quarter turn, and body B, the same turned alike, at (4c, 4s) (c, s
    // the doubles of theta; the translation is exact): B's vertex (-2, 0)
    // lands exactly on A's (2, 0), at A's farthest point along the axis
    // nearest the turn, where the bodies' boxes are their discs' (a turned
    // octagon's corner box is wider). A third body stands 2^-30 further
    // along the axis. Every answer against the exact reference, in the
    // certified and the exact world; a disc one part in a thousand too small
    // loses the touching pairs.
    const std::vector<polygon> shapes = {polygon({test_shapes::ring(
        {{2, 0}, {1.25, 1.25}, {0, 2}, {-1.25, 1.25}, {-2, 0}, {-1.25, -1.25}, {0, -2}, {1.25, -1.25}})})};
    rng g(2500);
    std::vector<body_state> bodies;
    const int pairs = std::max(4, test_effort::scaled(24));
    for (int k = 0; k < pairs; ++k) {
        const double theta = M_PI / 2 * (k % 4) + g.uniform(-0.05, 0.05);
        const rotation_pose q(pose{0, 0, theta});
        const double away = std::ldexp(1.0, -30) * (k % 4 == 2 ? -1 : 1);
        bodies.push_back({0, {0, 0, theta}, k % 2 == 0});
        bodies.push_back({0, {4 * q.c, 4 * q.s, theta}, false});
        bodies.push_back({0, {4 * q.c + away, 4 * q.s, theta}, false});
    }
    certified_world certified;
    world<exact_rational> exact;
    add_to(certified, shapes, bodies);
    add_to(exact, shapes, bodies);
    const std::vector<body_pair> want = reference_contacts(shapes, bodies, 0);
    CHECK(show_pairs(certified.step()) == show_pairs(want));
    CHECK(show_pairs(exact.step()) == show_pairs(want));
    std::size_t touching = 0;
    for (const body_pair& p : want) touching += p.second == p.first + 1 && p.first % 3 == 0 ? 1 : 0;
    CHECK(touching == static_cast<std::size_t>(pairs));  // every A and its B touch
}

TEST_CASE("world: the pairs answered again in exact rationals are counted", "[world]") {
    // Unit squares turned by 0.3: B stands at (c, s), so that its left edge
    // lies exactly on A's right edge (posed in double, their vertices are
    // rounded, and the filter cannot settle that they touch); C stands
    // three units further. Certified answers the touching pair again in
    // exact rationals, at every step it is tested; the apart pairs, and
    // every pair of the double and exact worlds, need no such answer.
    const rotation_pose q(pose{0, 0, 0.3});
    const std::vector<pose> where = {{0, 0, 0.3}, {q.c, q.s, 0.3}, {4 * q.c, 4 * q.s, 0.3}};
    certified_world certified;
    world<double> rounded;
    world<exact_rational> exact;
    const auto s = certified.add_shape(test_shapes::square(0, 0, 1));
    rounded.add_shape(test_shapes::square(0, 0, 1));
    exact.add_shape(test_shapes::square(0, 0, 1));
    for (const pose& p : where) {
        certified.add_body(s, p);
        rounded.add_body(s, p);
        exact.add_body(s, p);
    }
    const std::string want = show_pairs({{0, 1}});
    for (int step = 1; step <= 3; ++step) {
        INFO(step);
        CHECK(show_pairs(certified.step()) == want);
        CHECK(show_pairs(exact.step()) == want);
        rounded.step();
        CHECK(certified.statistics().exact_pairs == static_cast<std::size_t>(step));
        CHECK(rounded.statistics().exact_pairs == 0);
        CHECK(exact.statistics().exact_pairs == 0);
        for (std::uint32_t i = 0; i < 2; ++i) {  // moved to where they stand: tested again
            certified.move(i, where[i]);
            rounded.move(i, where[i]);
            exact.move(i, where[i]);
        }
    }
}

TEST_CASE("world: bad input is refused with invalid_input", "[world]") {
    world_options o;
    o.within = -1;
    CHECK_THROWS_AS(world<double>(o), invalid_input);
    o.within = std::nan("");
    CHECK_THROWS_AS(world<double>(o), invalid_input);
    o.within = -1e-20;  // named as given, not as a fixed six decimals (-0.000000)
    CHECK_THROWS_WITH(world<double>(o), "world: the distance -1e-20 is not a finite number >= 0");
    CHECK_THROWS_WITH(layer_pairs<double>(std::vector<polygon>{test_shapes::square(0, 0, 1)}, -2.5e-300),
                      "layer_pairs: the distance -2.5e-300 is not a finite number >= 0");
    world<double> w;
    CHECK_THROWS_AS(w.add_shape(polygon{}), invalid_input);
    const auto s = w.add_shape(test_shapes::square(0, 0, 1));
    CHECK_THROWS_AS(w.add_body(s + 1, {}), invalid_input);
    CHECK_THROWS_AS(w.add_body(s, {std::nan(""), 0, 0}), invalid_input);
    const auto b = w.add_body(s, {});
    CHECK_THROWS_AS(w.move(b, {0, HUGE_VAL, 0}), invalid_input);
    CHECK_THROWS_AS(w.move(b + 1, {}), invalid_input);
    w.remove(b);
    CHECK_THROWS_AS(w.move(b, {}), invalid_input);
    CHECK_THROWS_AS(w.remove(b), invalid_input);
    CHECK(w.step().empty());
}

TEST_CASE("layer_pairs: one layer and two layers against the exact reference", "[world]") {
    rng g(500);
    for (int round = 0; round < test_effort::scaled(4); ++round) {
        const double within = round % 2 == 0 ? 0 : 0.5;
        const point<double> origin = round == 3 ? point<double>{2e7, 2e7} : point<double>{0, 0};
        std::vector<polygon> first, second;
        const std::vector<polygon> shapes = random_shapes(g, 5);
        std::vector<body_state> as, bs;
        for (int k = 0; k < 30; ++k) {
            // A layer at its own coordinates: shapes posed exactly (snapped
            // translations, no turn), so that the polygon and the posed body
            // are the same point set.
            const body_state b{g.index(shapes.size()),
                               {test_scenes::snap(origin.x + g.uniform(-30, 30)),
                                test_scenes::snap(origin.y + g.uniform(-30, 30)), 0}};
            (k % 2 ? first : second).push_back(test_shapes::translated(shapes[b.shape], b.where.tx, b.where.ty));
            (k % 2 ? as : bs).push_back(b);
        }
        // One layer: the reference on the bodies (none fixed).
        std::vector<body_state> all_first = as;
        std::vector<polygon> first_shapes(shapes.begin(), shapes.end());
        const std::vector<body_pair> want = reference_contacts(first_shapes, all_first, within);
        INFO("round " << round);
        CHECK(show_pairs(certified_layer_pairs(first, within)) == show_pairs(want));
        CHECK(show_pairs(layer_pairs<exact_rational>(first, within, 2)) == show_pairs(want));
        // Two layers: every (first, second) pair.
        std::vector<body_pair> want2;
        for (std::size_t i = 0; i < as.size(); ++i)
            for (std::size_t j = 0; j < bs.size(); ++j)
                if (exact_within(test_exact::place(shapes[as[i].shape], as[i].where),
                                 test_exact::place(shapes[bs[j].shape], bs[j].where), within))
                    want2.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        CHECK(show_pairs(certified_layer_pairs(first, second, within, 2)) == show_pairs(want2));
    }
    CHECK_THROWS_AS(layer_pairs<double>(std::vector<polygon>{polygon{}}), invalid_input);
    CHECK_THROWS_AS(layer_pairs<double>(std::vector<polygon>{}, -2.0), invalid_input);
}

/// A layer of cells that share long wiggly borders exactly (each border one
/// polyline of many vertices, walked by both cells), as in a cadastre or a
/// map of countries: an n x n grid of cells 10 wide, each side bent away
/// from its line by at most 2.5 sin(pi s) at s along it (so that borders
/// meet only at their corners), some cells left out, some shifted by one
/// grid step (overlapping one neighbour, a hair from another), some with a
/// square hole holding an island that touches the hole at a corner or
/// floats in it.
std::vector<polygon> bordered_cells(rng& g, int n, std::size_t per_side) {
    const double side = 10;
    // Border (i, j, horizontal) runs from lattice point (i, j) to (i + 1, j);
    // vertical from (i, j) to (i, j + 1); interior points only.
    const auto border = [&](double x0, double y0, bool horizontal) {
        std::vector<point<double>> out;
        const double amplitude = 2.5 * g.signed_unit();
        const double phase = g.uniform(0, 6.28);
        for (std::size_t k = 1; k <= per_side; ++k) {
            const double s = static_cast<double>(k) / static_cast<double>(per_side + 1);
            const double off = amplitude * std::sin(3.14159265358979 * s) * (0.7 + 0.3 * std::sin(phase + 17 * s));
            const double along = side * s;
            out.push_back(test_scenes::snap(horizontal ? point<double>{x0 + along, y0 + off}
                                                       : point<double>{x0 + off, y0 + along}));
        }
        return out;
    };
    std::vector<std::vector<std::vector<point<double>>>> horizontal(static_cast<std::size_t>(n)),
        vertical(static_cast<std::size_t>(n + 1));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= n; ++j)
            horizontal[static_cast<std::size_t>(i)].push_back(border(i * side, j * side, true));
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j < n; ++j) vertical[static_cast<std::size_t>(i)].push_back(border(i * side, j * side, false));
    std::vector<polygon> out;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            if (g.chance(0.1)) continue;
            const std::size_t ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
            ring_input outer;
            const auto corner = [&](int a, int b) { outer.vertices.push_back({a * side, b * side}); };
            const auto walk = [&](const std::vector<point<double>>& pts, bool reversed) {
                if (reversed)
                    outer.vertices.insert(outer.vertices.end(), pts.rbegin(), pts.rend());
                else
                    outer.vertices.insert(outer.vertices.end(), pts.begin(), pts.end());
            };
            corner(i, j);
            walk(horizontal[ui][uj], false);
            corner(i + 1, j);
            walk(vertical[ui + 1][uj], false);
            corner(i + 1, j + 1);
            walk(horizontal[ui][uj + 1], true);
            corner(i, j + 1);
            walk(vertical[ui][uj], true);
            const double shift = g.chance(0.15) ? test_scenes::grid * (g.chance(0.5) ? 1 : -1) : 0;
            for (point<double>& v : outer.vertices) v.x += shift;
            std::vector<ring_input> rings{outer};
            if (g.chance(0.2)) {
                // A square hole of side 2 about the centre, and an island in it.
                const double cx = i * side + side / 2 + shift, cy = j * side + side / 2;
                ring_input hole;
                hole.role = ring_role::hole;
                hole.vertices = {{cx - 1, cy - 1}, {cx + 1, cy - 1}, {cx + 1, cy + 1}, {cx - 1, cy + 1}};
                rings.push_back(hole);
                const double gap = g.chance(0.5) ? 0 : test_scenes::grid;
                ring_input island;
                island.vertices = {{cx - 1 + gap, cy - 1 + gap}, {cx, cy - 0.5}, {cx + 0.5, cy + 0.5}};
                out.push_back(polygon({island}));
            }
            out.push_back(polygon(rings));
        }
    return out;
}

/// The vertices of the pairs' polygons, both polygons of each pair counted
/// (as layer_pairs weighs its candidates against join_parallel_vertices).
std::size_t vertices_in_pairs(const std::vector<polygon>& layer, const std::vector<body_pair>& pairs) {
    std::size_t n = 0;
    for (const body_pair& q : pairs) n += layer[q.first].size() + layer[q.second].size();
    return n;
}

TEST_CASE("layer_pairs: cells along long shared borders against the exact reference", "[world]") {
    // Cells of about 4 x 40 edges: many runs each, their boundaries
    // touching along whole borders, so that the edge pairs are sought where
    // runs overlap (overlapping_run_pairs). One layer and two (the cells
    // split in two), meeting and within a distance.
    rng g(502);
    std::size_t meeting_pairs = 0;
    const int rounds = test_effort::scaled(4);
    for (int round = 0; round < rounds; ++round) {
        const std::vector<polygon> layer = bordered_cells(g, 4 + round % 2, 30 + 10 * static_cast<std::size_t>(round));
        const double within = round == 1 ? 0.01 : round == 3 ? test_scenes::grid / 2 : 0;
        std::vector<test_exact::placed_shape> placed;
        for (const polygon& p : layer) placed.push_back(test_exact::place(p, pose{}));
        std::vector<body_pair> want;
        for (std::size_t i = 0; i < layer.size(); ++i)
            for (std::size_t j = i + 1; j < layer.size(); ++j)
                if (exact_within(placed[i], placed[j], within))
                    want.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        meeting_pairs += want.size();
        INFO("round " << round << ", " << layer.size() << " polygons");
        CHECK(show_pairs(certified_layer_pairs(layer, within)) == show_pairs(want));
        CHECK(show_pairs(layer_pairs<exact_rational>(layer, within)) == show_pairs(want));
        CHECK(show_pairs(layer_pairs<double>(layer, within, 2)) == show_pairs(layer_pairs<double>(layer, within, 1)));
        // Two layers: alternate polygons.
        std::vector<polygon> first, second;
        std::vector<std::size_t> first_index, second_index;
        for (std::size_t k = 0; k < layer.size(); ++k) {
            (k % 2 ? second : first).push_back(layer[k]);
            (k % 2 ? second_index : first_index).push_back(k);
        }
        std::vector<body_pair> want2;
        for (std::size_t i = 0; i < first.size(); ++i)
            for (std::size_t j = 0; j < second.size(); ++j)
                if (exact_within(placed[first_index[i]], placed[second_index[j]], within))
                    want2.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        CHECK(show_pairs(certified_layer_pairs(first, second, within)) == show_pairs(want2));
        // Roles swapped: the same pairs, each turned round.
        std::vector<body_pair> swapped;
        for (const body_pair& q : want2) swapped.push_back({q.second, q.first});
        std::sort(swapped.begin(), swapped.end());
        CHECK(show_pairs(layer_pairs<exact_rational>(second, first, within)) == show_pairs(swapped));
    }
    // Not vacuous: most neighbours touch (some 40 pairs a round).
    CHECK(meeting_pairs >= 20 * static_cast<std::size_t>(rounds));
}

TEST_CASE("layer_pairs: a layer whose candidates hold enough vertices for threads gives the serial answers",
          "[world]") {
    // Cells of 4 x 40 edges on a 7 x 7 grid: their candidates hold more
    // than join_parallel_vertices vertices (checked below on the meeting
    // pairs alone, a part of the candidates), so that two threads share
    // the tests. Certified and exact on two threads against the exact
    // rationals on one, double on two against double on one.
    rng g(504);
    const std::vector<polygon> layer = bordered_cells(g, 7, 40);
    const std::vector<body_pair> want = layer_pairs<exact_rational>(layer);
    CHECK(vertices_in_pairs(layer, want) >= join_parallel_vertices);
    CHECK(show_pairs(certified_layer_pairs(layer, 0, 2)) == show_pairs(want));
    CHECK(show_pairs(layer_pairs<exact_rational>(layer, 0, 2)) == show_pairs(want));
    CHECK(show_pairs(layer_pairs<double>(layer, 0, 2)) == show_pairs(layer_pairs<double>(layer, 0, 1)));
    const double within = test_scenes::grid / 2;
    CHECK(show_pairs(certified_layer_pairs(layer, within, 2)) ==
          show_pairs(layer_pairs<exact_rational>(layer, within)));
}

/// x moved by -2 to 2 units in the last place, the count drawn from g: a
/// side a layer writes twice, once as the grid line and once a hair off it.
double nudged(double x, rng& g) {
    for (int n = static_cast<int>(g.index(5)) - 2; n != 0; n += n > 0 ? -1 : 1)
        x = std::nextafter(x, n > 0 ? HUGE_VAL : -HUGE_VAL);
    return x;
}

TEST_CASE("layer_pairs: a grid of rectangles whose shared sides are a unit in the last place apart", "[world]") {
    // Axis-parallel rectangles on a grid, as a field of plots is stored:
    // each side shared with a neighbour is written once as the grid line and
    // once moved by 0, 1 or 2 units in the last place either way, so that
    // neighbours touch, overlap by a hair or stand a hair apart. Two closed
    // rectangles meet exactly when their closed boxes do: that is the
    // reference (no polygon test in it). Within a distance, two rectangles
    // are within d when the gaps between their boxes along x and y, taken
    // in exact rationals, have a sum of squares at most d^2. Also at 2^-600
    // and 2^600 times the scale, and against a copy of the grid moved by a
    // translation whose sums are exact.
    rng g(503);
    std::size_t touching = 0, apart_by_a_hair = 0;
    for (int round = 0; round < test_effort::scaled(6); ++round) {
        const double scale = round % 3 == 0 ? 1 : round % 3 == 1 ? 0x1p-600 : 0x1p600;
        const int columns = 12, rows = 9;
        const auto line = [&](int k, double step, double origin) { return scale * (origin + step * k); };
        std::vector<polygon> layer;
        std::vector<box> boxes;
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c) {
                const double x0 = c == 0 ? line(c, 2.51, 1.255) : nudged(line(c, 2.51, 1.255), g);
                const double x1 = line(c + 1, 2.51, 1.255),
                             y0 = r == 0 ? line(r, 3.3, 64.05) : nudged(line(r, 3.3, 64.05), g);
                const double y1 = line(r + 1, 3.3, 64.05);
                layer.push_back(polygon({ring_input{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}}));
                boxes.push_back(box{x0, y0, x1, y1});
            }
        const double within = round >= 3 ? scale * 0x1p-50 : 0;
        std::vector<body_pair> want;
        for (std::size_t i = 0; i < layer.size(); ++i)
            for (std::size_t j = i + 1; j < layer.size(); ++j) {
                const box &a = boxes[i], &b = boxes[j];
                const auto gap = [](double lo_a, double hi_a, double lo_b, double hi_b) {
                    const exact_rational d1 = exact_rational(lo_b) - exact_rational(hi_a),
                                         d2 = exact_rational(lo_a) - exact_rational(hi_b);
                    const exact_rational d = d1 > d2 ? d1 : d2;
                    return d > 0 ? d : exact_rational(0);
                };
                const exact_rational gx = gap(a.min_x, a.max_x, b.min_x, b.max_x),
                                     gy = gap(a.min_y, a.max_y, b.min_y, b.max_y);
                const exact_rational w(within);
                if (gx * gx + gy * gy <= w * w)
                    want.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
                const bool near = std::fabs(a.min_x - b.max_x) <= std::fabs(a.max_x) * 0x1p-50 ||
                                  std::fabs(b.min_x - a.max_x) <= std::fabs(a.max_x) * 0x1p-50;
                if (near && within == 0) (gx == 0 && gy == 0 ? touching : apart_by_a_hair) += 1;
            }
        INFO("round " << round << ", scale " << scale);
        CHECK(show_pairs(certified_layer_pairs(layer, within)) == show_pairs(want));
        CHECK(show_pairs(layer_pairs<exact_rational>(layer, within)) == show_pairs(want));
        CHECK(show_pairs(layer_pairs<double>(layer, within)) == show_pairs(want));
        // The same grid moved by a translation whose sums are exact (a whole
        // number of grid steps at the scale): the pairs between the two
        // layers are the pairs of each with its own copy, and of the copies
        // of the pairs.
        if (within == 0) {
            std::vector<polygon> moved;
            for (const box& b : boxes) {
                const double dx = scale * 2.51 * 4;
                moved.push_back(polygon({ring_input{{{b.min_x + dx, b.min_y},
                                                     {b.max_x + dx, b.min_y},
                                                     {b.max_x + dx, b.max_y},
                                                     {b.min_x + dx, b.max_y}}}}));
            }
            std::vector<body_pair> want2;
            for (std::size_t i = 0; i < layer.size(); ++i)
                for (std::size_t j = 0; j < moved.size(); ++j) {
                    const box b = moved[j].bounds(), &a = boxes[i];
                    if (!(a.max_x < b.min_x || b.max_x < a.min_x || a.max_y < b.min_y || b.max_y < a.min_y))
                        want2.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
                }
            CHECK(show_pairs(certified_layer_pairs(layer, moved)) == show_pairs(want2));
        }
    }
    // Not vacuous: neighbours along x that touch and that stand a hair apart.
    CHECK(touching > 50);
    CHECK(apart_by_a_hair > 50);
}

TEST_CASE("layer_pairs: convex triangles and quadrilaterals sharing their sides exactly, against the exact reference",
          "[world]") {
    // A jittered lattice (random doubles, not snapped), each cell a convex
    // quadrilateral or its two triangles, so that neighbours share their
    // sides and corners exactly; some cells with a corner moved by a unit
    // in the last place, into or out of their neighbours; and small random
    // triangles turned anyhow among them. Small convex pairs take the
    // separating-edge test on their doubles (join_convex_limit), the others
    // bodies_within. The reference: every pair whose boxes meet, its
    // regions placed in exact rationals (CGAL), both layer forms, roles
    // swapped. In double too: every pair here is a convex pair, decided
    // exactly on its doubles (bodies_within in double misses some of the
    // touching ones).
    rng g(509);
    std::size_t touching = 0;
    for (int round = 0; round < test_effort::scaled(4); ++round) {
        const int n = 8;
        const double step = round % 2 == 0 ? 1.0 : 0.37, origin = round >= 2 ? 4096.5 : 0.0;
        std::vector<std::vector<point<double>>> lattice(n + 1, std::vector<point<double>>(n + 1));
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                lattice[i][j] = {origin + step * (i + 0.2 * g.signed_unit()),
                                 origin + step * (j + 0.2 * g.signed_unit())};
        std::vector<polygon> layer;
        const auto add = [&](std::vector<point<double>> ring) {
            if (g.index(6) == 0) {  // a corner nudged by a unit in the last place
                point<double>& c = ring[g.index(ring.size())];
                c.x = std::nextafter(c.x, g.index(2) ? HUGE_VAL : -HUGE_VAL);
            }
            layer.push_back(polygon({ring_input{ring}}));
        };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const point<double>&a = lattice[i][j], &b = lattice[i + 1][j], &c = lattice[i + 1][j + 1],
                      &d = lattice[i][j + 1];
                if (g.index(2) == 0) {
                    add({a, b, c, d});
                } else {
                    add({a, b, c});
                    add({a, c, d});
                }
            }
        for (int k = 0; k < 20; ++k) {
            const point<double> at{origin + step * g.uniform(0, n), origin + step * g.uniform(0, n)};
            const double r = step * g.uniform(0.1, 0.6), t = g.uniform(0, 6.28);
            add({{at.x + r * std::cos(t), at.y + r * std::sin(t)},
                 {at.x + r * std::cos(t + 2.1), at.y + r * std::sin(t + 2.1)},
                 {at.x + r * std::cos(t + 4.2), at.y + r * std::sin(t + 4.2)}});
        }
        const std::vector<body_pair> want = exact_layer_pairs(layer);
        // (Neighbours of the lattice: a shared corner at least.)
        for (const body_pair& p : want) {
            const polygon &a = layer[p.first], &b = layer[p.second];
            bool shared = false;
            for (std::size_t u = 0; u < a.size() && !shared; ++u)
                for (std::size_t v = 0; v < b.size() && !shared; ++v) shared = a.vertex(u) == b.vertex(v);
            touching += shared ? 1 : 0;
        }
        INFO("round " << round);
        check_joins(layer, want);
    }
    // Not vacuous: many pairs meet only along a shared side or corner.
    CHECK(touching > 200);
}

TEST_CASE("layer_pairs: axis-parallel rectangles among quadrilaterals that nearly are, against the exact reference",
          "[world]") {
    // Rectangles on a jittered grid (random doubles as grid lines, so that
    // neighbours share their sides exactly), each ring starting at a random
    // corner and going either way round; some with a corner moved by a unit
    // in the last place along x or y (a quadrilateral that is no longer its
    // own box, convex or not); rectangles spanning a few cells from grid
    // line to grid line, overlapping and touching the others; some with a
    // straight vertex on a side (five vertices), some squares turned by
    // 45 degrees. Two polygons that fill their boxes are answered by the
    // boxes (fills_its_box), the other small convex pairs by the
    // separating-edge test. The reference: every pair whose boxes meet, its
    // regions placed in exact rationals (CGAL), in one layer and two,
    // roles swapped.
    rng g(613);
    std::size_t touching = 0, boxes_meeting = 0;
    const int rounds = test_effort::scaled(4);
    for (int round = 0; round < rounds; ++round) {
        const int n = 9;
        const double step = round % 2 == 0 ? 1.0 : 0.013, origin = round >= 2 ? -7.0e5 : 0.0;
        std::vector<double> xs(n + 1), ys(n + 1);
        for (int k = 0; k <= n; ++k) {
            xs[k] = origin + step * (k + 0.3 * g.signed_unit());
            ys[k] = origin + step * (k + 0.3 * g.signed_unit());
        }
        std::vector<polygon> layer;
        const auto add_box = [&](double x0, double y0, double x1, double y1) {
            std::vector<point<double>> c = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
            if (g.index(5) == 0) {
                point<double>& v = c[g.index(4)];
                double& w = g.index(2) ? v.x : v.y;
                w = std::nextafter(w, g.index(2) ? HUGE_VAL : -HUGE_VAL);
            }
            if (g.index(8) == 0) c.insert(c.begin() + 1, point<double>{x0 + (x1 - x0) * 0.5, y0});
            std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(g.index(c.size())), c.end());
            if (g.index(2)) std::reverse(c.begin(), c.end());
            layer.push_back(polygon({ring_input{c}}));
        };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                if (g.index(4) != 0) add_box(xs[i], ys[j], xs[i + 1], ys[j + 1]);
        for (int k = 0; k < 12; ++k) {
            const std::size_t i = g.index(n - 1), j = g.index(n - 1);
            const std::size_t w = 1 + g.index(3), h = 1 + g.index(3);
            add_box(xs[i], ys[j], xs[std::min<std::size_t>(i + w, n)], ys[std::min<std::size_t>(j + h, n)]);
        }
        for (int k = 0; k < 6; ++k) {
            const double x = xs[g.index(n + 1)], y = ys[g.index(n + 1)], r = step * g.uniform(0.2, 0.8);
            layer.push_back(polygon({ring_input{{{x + r, y}, {x, y + r}, {x - r, y}, {x, y - r}}}}));
        }
        for (std::size_t i = 0; i < layer.size(); ++i)
            for (std::size_t j = i + 1; j < layer.size(); ++j)
                if (boxes_overlap(layer[i].bounds(), layer[j].bounds()) && fills_its_box(layer[i]) &&
                    fills_its_box(layer[j]))
                    ++boxes_meeting;
        const std::vector<body_pair> want = exact_layer_pairs(layer);
        for (const body_pair& p : want) {
            const box &a = layer[p.first].bounds(), &b = layer[p.second].bounds();
            if (a.max_x == b.min_x || b.max_x == a.min_x || a.max_y == b.min_y || b.max_y == a.min_y) ++touching;
        }
        INFO("round " << round);
        check_joins(layer, want);
    }
    // Not vacuous: in each round, many pairs of boxes, and many pairs that
    // meet only along a side or at a corner.
    CHECK(boxes_meeting > 100 * static_cast<std::size_t>(rounds));
    CHECK(touching > 150 * static_cast<std::size_t>(rounds));
}

TEST_CASE(
    "layer_pairs: neighbours that share vertices or miss them by a unit in the last place, against the exact "
    "reference",
    "[world]") {
    // Cells with wavy shared borders (bordered_cells: neighbours repeat the
    // same vertices, so that most meeting pairs share one: share_a_vertex),
    // then some cells moved a unit in the last place along x or y, every
    // vertex (apart from one neighbour by that unit, overlapping another),
    // and some with one vertex moved so: such a pair shares no vertex, or
    // fewer, and the placed route answers it. The reference: every pair
    // whose boxes meet, its regions placed in exact rationals (CGAL); one
    // layer and two, roles swapped; within a distance too.
    rng g(1206);
    // Whether a vertex of a is a unit in the last place from one of b's,
    // along x or y.
    const auto a_unit_from = [](const polygon& a, const polygon& b) {
        for (const point<double>& v : a.vertices())
            for (const point<double>& w : b.vertices())
                if ((v.x == w.x && v.y != w.y && std::nextafter(v.y, w.y) == w.y) ||
                    (v.y == w.y && v.x != w.x && std::nextafter(v.x, w.x) == w.x))
                    return true;
        return false;
    };
    std::size_t sharing = 0, a_unit_apart = 0;
    const int rounds = test_effort::scaled(4);
    for (int round = 0; round < rounds; ++round) {
        std::vector<polygon> layer = bordered_cells(g, 7, 4 + 3 * static_cast<std::size_t>(round));
        for (polygon& p : layer) {
            const std::size_t how = g.index(4);  // 0, 1: as they are; 2: every vertex moved; 3: one vertex
            if (how < 2) continue;
            const bool along_x = g.chance(0.5);
            const double toward = g.chance(0.5) ? HUGE_VAL : -HUGE_VAL;
            const std::size_t only = how == 3 ? g.index(p.size()) : p.size();
            std::vector<ring_input> rings;
            for (std::size_t r = 0; r < p.ring_count(); ++r) {
                ring_input ring{{}, p.role(r)};
                for (std::size_t k = p.ring_begin(r); k < p.ring_end(r); ++k) {
                    point<double> v = p.vertex(k);
                    if (how == 2 || k == only) (along_x ? v.x : v.y) = std::nextafter(along_x ? v.x : v.y, toward);
                    ring.vertices.push_back(v);
                }
                rings.push_back(ring);
            }
            p = polygon(rings);
        }
        const std::vector<body_pair> want = exact_layer_pairs(layer);
        for (std::size_t i = 0; i < layer.size(); ++i)
            for (std::size_t j = i + 1; j < layer.size(); ++j)
                if (boxes_overlap(layer[i].bounds(), layer[j].bounds())) {
                    const bool meets =
                        std::binary_search(want.begin(), want.end(),
                                           body_pair{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
                    if (share_a_vertex(layer[i], layer[j])) {
                        ++sharing;
                        CHECK(meets);
                    } else if (!meets && a_unit_from(layer[i], layer[j])) {
                        ++a_unit_apart;
                    }
                }
        INFO("round " << round << ", " << layer.size() << " polygons");
        check_joins(layer, want);
        // Within a distance below the unit's reach: the same pairs as
        // meeting, plus those a unit apart.
        const std::vector<body_pair> near = certified_layer_pairs(layer, 1e-9);
        CHECK(near.size() >= want.size());
        for (const body_pair& q : want) CHECK(std::find(near.begin(), near.end(), q) != near.end());
    }
    // Not vacuous: in each round, pairs that share a vertex and pairs that
    // miss by a unit in the last place.
    CHECK(sharing > 40 * static_cast<std::size_t>(rounds));
    CHECK(a_unit_apart > 5 * static_cast<std::size_t>(rounds));
}

TEST_CASE("layer_pairs: the candidates and those answered again in exact rationals are counted", "[world]") {
    // Unit squares in a row, 0.5 apart exactly, and a far one. Within 0.5,
    // each neighbour lies exactly at the distance: a sign the certified
    // filter cannot settle, so each such pair is answered again in exact
    // rationals; double and exact rationals never are. The candidates are
    // the pairs whose boxes, grown by within / 2, meet, counted here
    // directly.
    std::vector<polygon> layer;
    for (int k = 0; k < 5; ++k) layer.push_back(test_shapes::square(1.5 * k, 0, 1));
    layer.push_back(test_shapes::square(100, 100, 1));
    const auto boxes_meeting = [&](double within) {
        std::size_t n = 0;
        for (std::size_t i = 0; i < layer.size(); ++i)
            for (std::size_t j = i + 1; j < layer.size(); ++j) {
                const box a = layer[i].bounds().inflated(within / 2), b = layer[j].bounds().inflated(within / 2);
                n += a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y;
            }
        return n;
    };
    REQUIRE(boxes_meeting(0.5) == 4);
    const std::string want = show_pairs({{0, 1}, {1, 2}, {2, 3}, {3, 4}});
    for (unsigned threads : {1u, 2u}) {
        INFO(threads << " threads");
        layer_statistics certified_work, double_work, exact_work;
        CHECK(show_pairs(certified_layer_pairs(layer, 0.5, threads, &certified_work)) == want);
        CHECK(show_pairs(layer_pairs<double>(layer, 0.5, threads, &double_work)) == want);
        CHECK(show_pairs(layer_pairs<exact_rational>(layer, 0.5, threads, &exact_work)) == want);
        CHECK(certified_work.candidates == 4);
        CHECK(double_work.candidates == 4);
        CHECK(exact_work.candidates == 4);
        CHECK(certified_work.exact_pairs == 4);
        CHECK(double_work.exact_pairs == 0);
        CHECK(exact_work.exact_pairs == 0);
        // Meeting only: no candidate.
        layer_statistics meet_work{7, 7};
        CHECK(certified_layer_pairs(layer, 0, threads, &meet_work).empty());
        CHECK(meet_work.candidates == boxes_meeting(0));
        CHECK(meet_work.exact_pairs == 0);
        // Two layers: the even squares against the odd ones (and the far one).
        const std::vector<polygon> even = {layer[0], layer[2], layer[4]}, odd = {layer[1], layer[3], layer[5]};
        layer_statistics two;
        CHECK(show_pairs(certified_layer_pairs(even, odd, 0.5, threads, &two)) ==
              show_pairs({{0, 0}, {1, 0}, {1, 1}, {2, 1}}));
        CHECK(two.candidates == 4);
        CHECK(two.exact_pairs == 4);
    }
}

TEST_CASE("layer_pairs: swept along x or by box trees, the pairs of the exact reference", "[world]") {
    // Long bars across the layer along x, on a grid of halves along y (bars
    // overlapping, touching edge to edge, or apart), three in four
    // polygons, among small squares and triangles on the same grid: every
    // bar's x-interval overlaps every other's, more than
    // sweep_tests_per_box a box, so the candidates come from box trees. The
    // same layer mirrored across the diagonal (x and y swapped: the same
    // pairs) has bars across y instead, and is swept.
    rng g(520);
    for (int round = 0; round < test_effort::scaled(3); ++round) {
        std::vector<polygon> layer, other;
        for (int k = 0; k < 200; ++k) {
            const double y = 0.5 * static_cast<double>(g.index(100)), x = 0.5 * static_cast<double>(g.index(100));
            std::vector<polygon>& into = k % 3 == 0 ? other : layer;
            if (k % 4 != 3)
                into.push_back(polygon({test_shapes::ring({{-1.0 - 0.5 * static_cast<double>(g.index(4)), y},
                                                           {51, y},
                                                           {51, y + 0.5 * static_cast<double>(1 + g.index(2))},
                                                           {-1, y + 0.5}},
                                                          ring_role::outer)}));
            else if (k % 8 == 3)
                into.push_back(test_shapes::square(x, y, 0.5 * static_cast<double>(1 + g.index(3))));
            else
                into.push_back(polygon({test_shapes::ring({{x, y}, {x + 1, y + 0.5}, {x, y + 1}}, ring_role::outer)}));
        }
        std::vector<polygon> layer_m, other_m;
        for (const polygon& p : layer) layer_m.push_back(mapped_polygon(p, true, 0));
        for (const polygon& p : other) other_m.push_back(mapped_polygon(p, true, 0));
        std::vector<test_exact::placed_shape> exact_layer, exact_other;
        for (const polygon& p : layer) exact_layer.push_back(test_exact::place(p, pose{}));
        for (const polygon& p : other) exact_other.push_back(test_exact::place(p, pose{}));
        std::vector<body_pair> want, want2;
        for (std::size_t i = 0; i < layer.size(); ++i) {
            for (std::size_t j = i + 1; j < layer.size(); ++j)
                if (exact_within(exact_layer[i], exact_layer[j], 0))
                    want.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
            for (std::size_t j = 0; j < other.size(); ++j)
                if (exact_within(exact_layer[i], exact_other[j], 0))
                    want2.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        }
        INFO("round " << round << ": " << want.size() << " pairs in the layer, " << want2.size() << " across");
        CHECK(want.size() > 100);
        CHECK(want2.size() > 50);
        // (The premise: as built, more x-overlaps than the sweep's budget,
        // within the layer and across; mirrored, fewer.)
        CHECK(x_overlaps(layer, layer) > sweep_tests_per_box * layer.size());
        CHECK(x_overlaps(layer, other) > sweep_tests_per_box * (layer.size() + other.size()));
        CHECK(x_overlaps(layer_m, layer_m) <= sweep_tests_per_box * layer.size());
        CHECK(x_overlaps(layer_m, other_m) <= sweep_tests_per_box * (layer.size() + other.size()));
        for (const bool swap : {false, true}) {
            INFO((swap ? "mirrored: swept" : "as built: box trees"));
            layer_statistics one, two;
            CHECK(show_pairs(certified_layer_pairs(swap ? layer_m : layer, 0, 1, &one)) == show_pairs(want));
            CHECK(show_pairs(certified_layer_pairs(swap ? layer_m : layer, swap ? other_m : other, 0, 2, &two)) ==
                  show_pairs(want2));
            CHECK(show_pairs(layer_pairs<exact_rational>(swap ? layer_m : layer, 0, 2)) == show_pairs(want));
            CHECK(one.swept == swap);
            CHECK(two.swept == swap);
        }
    }
}

TEST_CASE("layer_pairs: North Carolina's counties mirrored, reordered or scaled by powers of two, the same pairs",
          "[world]") {
    // A real layer whose neighbours share their border vertices exactly,
    // joined as given (held to the exact reference), then mirrored across
    // the diagonal, listed in another order, scaled by 2^-40, 2^40, 2^-700
    // or 2^600 (within scaled alike: the same question), on two threads:
    // the same pairs, renamed back.
    const std::vector<polygon> layer = test_data::real_layer("nc_counties.wkt");
    REQUIRE(layer.size() == 100);
    const std::size_t n = layer.size();
    std::vector<std::size_t> at(n);  // where polygon i is listed when reordered
    for (std::size_t i = 0; i < n; ++i) at[i] = (2 * n - 1 - i + n / 3) % n;
    std::vector<body_state> as_given(n);
    for (std::size_t i = 0; i < n; ++i) as_given[i].shape = i;
    struct variant {
        bool reordered, mirrored;
        int scale;
    };
    const variant variants[] = {
        {false, true, 0}, {true, false, -40}, {true, true, 40}, {false, false, -700}, {true, true, 600}};
    for (const double within : {0.0, 1e-6, 0.01}) {
        INFO("within " << within);
        const std::vector<body_pair> want = certified_layer_pairs(layer, within, 1);
        REQUIRE(show_pairs(want) == show_pairs(reference_contacts(layer, as_given, within)));
        CHECK(want.size() >= 245);
        for (const variant& v : variants) {
            INFO("reordered " << v.reordered << ", mirrored " << v.mirrored << ", scale 2^" << v.scale);
            std::vector<polygon> mapped(n, layer[0]);
            for (std::size_t i = 0; i < n; ++i)
                mapped[v.reordered ? at[i] : i] = mapped_polygon(layer[i], v.mirrored, v.scale);
            std::vector<std::uint32_t> given(n);  // the polygon listed at each place
            for (std::size_t i = 0; i < n; ++i) given[v.reordered ? at[i] : i] = static_cast<std::uint32_t>(i);
            std::vector<body_pair> got;
            for (const body_pair& p : certified_layer_pairs(mapped, std::ldexp(within, v.scale), 2))
                got.push_back({std::min(given[p.first], given[p.second]), std::max(given[p.first], given[p.second])});
            std::sort(got.begin(), got.end());
            CHECK(show_pairs(got) == show_pairs(want));
        }
    }
}

TEST_CASE("world: real borders and plots a hair apart, as bodies translated by vectors that round, the join's pairs",
          "[world]") {
    // A translation poses every vertex exactly (x + tx in rationals), so a
    // layer's bodies all translated by one vector meet as the layer's
    // polygons do where they stand, though x + tx rounds in double: North
    // Carolina's counties (neighbours share their border vertices), and a
    // grid of plots whose shared sides are written twice, the second time
    // moved by up to two units in the last place (touching, overlapping or
    // apart by a hair). The certified world's contacts are the certified
    // join's pairs (held to the exact reference), half the bodies fixed or
    // none, with a distance or without; then the bodies are moved back where
    // the polygons stand, half at a step (the witnesses of the translated
    // step tried there): the same pairs again.
    std::vector<polygon> plots;
    rng g(507);
    for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 10; ++c) {
            const double x0 = nudged(1.255 + 2.51 * c, g), x1 = 1.255 + 2.51 * (c + 1);
            const double y0 = nudged(64.05 + 3.3 * r, g), y1 = 64.05 + 3.3 * (r + 1);
            plots.push_back(polygon({ring_input{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}}));
        }
    std::size_t double_differs = 0;
    const std::vector<polygon> counties = test_data::real_layer("nc_counties.wkt");
    for (const std::vector<polygon>* layer : std::array<const std::vector<polygon>*, 2>{&plots, &counties}) {
        const std::vector<polygon>& shapes = *layer;
        const std::size_t n = shapes.size();
        std::vector<body_state> as_given(n);
        for (std::size_t i = 0; i < n; ++i) as_given[i].shape = i;
        for (const double within : {0.0, 1e-3}) {
            const std::vector<body_pair> join = certified_layer_pairs(shapes, within, 1);
            REQUIRE(show_pairs(join) == show_pairs(reference_contacts(shapes, as_given, within)));
            for (const pose moved : {pose{1e6 + 0.1, -3.7, 0}, pose{-123.456789, 1e-7, 0}})
                for (const bool half_fixed : {false, true}) {
                    INFO((layer == &plots ? "plots" : "counties")
                         << ", within " << within << ", moved by (" << moved.tx << ", " << moved.ty << "), half fixed "
                         << half_fixed);
                    world_options o;
                    o.within = within;
                    o.witness = true;
                    certified_world w(o);
                    world<double> rounded(o);
                    for (std::size_t i = 0; i < n; ++i) {
                        w.add_shape(shapes[i]);
                        rounded.add_shape(shapes[i]);
                        w.add_body(static_cast<std::uint32_t>(i), moved, half_fixed && i % 2 == 0);
                        rounded.add_body(static_cast<std::uint32_t>(i), moved, half_fixed && i % 2 == 0);
                    }
                    std::vector<body_pair> want;
                    for (const body_pair& p : join)
                        if (!(half_fixed && p.first % 2 == 0 && p.second % 2 == 0)) want.push_back(p);
                    CHECK(show_pairs(w.step()) == show_pairs(want));
                    double_differs += rounded.step() != want;
                    for (const std::size_t first : {std::size_t{0}, std::size_t{1}}) {
                        for (std::size_t i = first; i < n; i += 2) w.move(static_cast<std::uint32_t>(i), pose{});
                        w.step();
                    }
                    CHECK(show_pairs(w.contacts()) == show_pairs(want));
                }
        }
    }
    // (Rounded x + tx breaks the plots' hairs: the certified answers are not
    // double's.)
    CHECK(double_differs > 0);
}

TEST_CASE("world: real borders recentred, then turned and slid by 2^-50 to 2^-8 of a degree, the exact reference's",
          "[world]") {
    // Each of North Carolina's counties becomes a shape about its box
    // centre (its vertices less the centre, rounded) and a body posed back
    // at that centre, so that neighbours' shared borders cross, part or
    // overlap by a hair where x - c + c rounds; some bodies are moved off by
    // up to 2^-e, some turned by up to 2^-e rad (e from 8 to 50, one per
    // scene), a quarter fixed. At each of six steps half the free bodies
    // move: back to the centre unturned, slid, turned, or to the next
    // double along x. The certified world's contacts are the exact
    // reference's at every step (every pair placed on CGAL's kernel), within
    // 0 and within 1e-9.
    const std::vector<polygon> counties = test_data::real_layer("nc_counties.wkt");
    std::vector<polygon> shapes;
    std::vector<point<double>> centres;
    for (const polygon& p : counties) {
        const box b = p.bounds();
        const point<double> c{b.min_x / 2 + b.max_x / 2, b.min_y / 2 + b.max_y / 2};
        shapes.push_back(test_shapes::translated(p, -c.x, -c.y));  // (x + -c is x - c, rounded alike)
        centres.push_back(c);
    }
    const std::size_t n = shapes.size();
    std::size_t double_differs = 0;
    for (const double within : {0.0, 1e-9})
        for (std::uint64_t seed = 0; seed < 6; ++seed) {
            rng g(811 + seed);
            const double reach = std::ldexp(1.0, -static_cast<int>(8 + g.index(43)));
            INFO("within " << within << ", seed " << seed << ", moves up to " << reach);
            world_options o;
            o.within = within;
            certified_world w(o);
            world<double> rounded(o);
            std::vector<body_state> bodies(n);
            for (std::size_t i = 0; i < n; ++i) {
                w.add_shape(shapes[i]);
                rounded.add_shape(shapes[i]);
                bodies[i].shape = i;
                bodies[i].where = {centres[i].x + (g.chance(0.5) ? reach * g.signed_unit() : 0.0),
                                   centres[i].y + (g.chance(0.5) ? reach * g.signed_unit() : 0.0),
                                   g.chance(1.0 / 3) ? reach * g.signed_unit() : 0.0};
                bodies[i].fixed = g.chance(0.25);
                w.add_body(static_cast<std::uint32_t>(i), bodies[i].where, bodies[i].fixed);
                rounded.add_body(static_cast<std::uint32_t>(i), bodies[i].where, bodies[i].fixed);
            }
            for (int step = 0; step < 6; ++step) {
                INFO("step " << step);
                if (step > 0)
                    for (std::size_t i = 0; i < n; ++i) {
                        if (bodies[i].fixed || g.chance(0.5)) continue;
                        pose& q = bodies[i].where;
                        switch (g.index(4)) {
                        case 0: q = {centres[i].x, centres[i].y, 0}; break;
                        case 1: q = {q.tx + reach * g.signed_unit(), q.ty + reach * g.signed_unit(), q.theta}; break;
                        case 2: q.theta += reach * g.signed_unit(); break;
                        default: q.tx = std::nextafter(q.tx, g.chance(0.5) ? 1e300 : -1e300); break;
                        }
                        w.move(static_cast<std::uint32_t>(i), q);
                        rounded.move(static_cast<std::uint32_t>(i), q);
                    }
                const std::vector<body_pair> want = reference_contacts(shapes, bodies, within);
                REQUIRE(show_pairs(w.step()) == show_pairs(want));
                double_differs += rounded.step() != want;
            }
        }
    // (The hairs are beyond double's roundings: its answers differ.)
    CHECK(double_differs > 0);
}

/// The rings of p with every vertex rounded to the nearest multiple of
/// `cell` (a power of two, so the rounding is the only change), those with
/// fewer than three distinct vertices left out (none may be left), and the
/// number of vertices that came to repeat the one before them added to
/// `repeats`.
std::vector<ring_input> snapped_rings(const polygon& p, double cell, std::size_t& repeats) {
    std::vector<ring_input> rings;
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
        ring_input ring;
        ring.role = p.role(r);
        for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i) {
            const point<double> v{std::round(p.vertex(i).x / cell) * cell, std::round(p.vertex(i).y / cell) * cell};
            if (!ring.vertices.empty() && ring.vertices.back() == v) ++repeats;
            ring.vertices.push_back(v);
        }
        std::vector<point<double>> distinct = ring.vertices;
        std::sort(distinct.begin(), distinct.end(), [](const point<double>& l, const point<double>& h) {
            return l.x < h.x || (l.x == h.x && l.y < h.y);
        });
        if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() >= 3) rings.push_back(ring);
    }
    return rings;
}

TEST_CASE("layer_pairs: North Carolina's counties snapped to a quarter degree, repeated vertices and gaps of one cell",
          "[world]") {
    // Rounding a real layer's vertices to a grid of 1/4 degree makes what
    // GIS data holds at its worst: runs of repeated vertices, collinear
    // edges, spikes, rings touching themselves and their neighbours along
    // whole edges, and polygons exactly one cell apart (a tie of "within
    // one cell"). The joins at 0, half a cell and one cell, certified and in
    // exact rationals, must be the exact reference's, and so must those of
    // the layer against itself moved by whole cells; so must the one-shot
    // certified_intersects of its pairs, both roles, turned about the moving
    // polygon's centroid or moved by half a cell.
    const double cell = 0.25;
    std::size_t repeats = 0;
    std::vector<polygon> layer;
    for (const polygon& p : test_data::real_layer("nc_counties.wkt"))
        if (std::vector<ring_input> rings = snapped_rings(p, cell, repeats); !rings.empty())
            layer.emplace_back(std::move(rings));
    REQUIRE(layer.size() == 99);  // one county is narrower than a cell
    CHECK(repeats >= 1000);       // premise: a degenerate layer
    std::vector<body_state> as_given(layer.size());
    for (std::size_t i = 0; i < layer.size(); ++i) as_given[i].shape = i;
    std::vector<body_pair> meeting;
    for (const double within : {0.0, cell / 2, cell}) {
        INFO("within " << within);
        const std::vector<body_pair> want = reference_contacts(layer, as_given, within);
        CHECK(show_pairs(certified_layer_pairs(layer, within, 2)) == show_pairs(want));
        CHECK(show_pairs(layer_pairs<exact_rational>(layer, within, 1)) == show_pairs(want));
        if (within == 0) meeting = want;
        if (within == cell) {
            // Premise: some pairs are exactly one cell apart (within it, and
            // not within less).
            const std::vector<body_pair> closer = reference_contacts(layer, as_given, std::nextafter(cell, 0.0));
            CHECK(want.size() >= closer.size() + 5);
        }
    }
    // Two layers: the snapped counties against themselves moved by three
    // cells right and one up (on the grid again, exactly), every pair.
    std::vector<polygon> moved;
    for (const polygon& p : layer) moved.push_back(mapped_polygon(p, false, 0, {3 * cell, cell}));
    std::vector<test_exact::placed_shape> exact_layer, exact_moved;
    for (std::size_t i = 0; i < layer.size(); ++i) {
        exact_layer.push_back(test_exact::place(layer[i], 0, 0, 0));
        exact_moved.push_back(test_exact::place(moved[i], 0, 0, 0));
    }
    for (const double within : {0.0, cell}) {
        INFO("two layers, within " << within);
        std::vector<body_pair> want;
        for (std::size_t i = 0; i < layer.size(); ++i)
            for (std::size_t j = 0; j < moved.size(); ++j)
                if (exact_within(exact_layer[i], exact_moved[j], within))
                    want.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        CHECK(want.size() >= 200);
        CHECK(show_pairs(certified_layer_pairs(layer, moved, within, 2)) == show_pairs(want));
        std::vector<body_pair> swapped;  // the roles swapped, in exact rationals
        for (const body_pair& q : layer_pairs<exact_rational>(moved, layer, within, 1))
            swapped.push_back({q.second, q.first});
        std::sort(swapped.begin(), swapped.end());
        CHECK(show_pairs(swapped) == show_pairs(want));
    }
    REQUIRE(meeting.size() >= 250);
    rng g(29);
    std::size_t meets = 0;
    for (std::size_t k = 0; k < meeting.size(); k += 2)
        for (const bool swapped : {false, true})
            for (int kind = 0; kind < 3; ++kind) {
                const polygon& a = layer[swapped ? meeting[k].second : meeting[k].first];
                const polygon& b = layer[swapped ? meeting[k].first : meeting[k].second];
                const double theta = kind == 0 ? 0 : g.uniform(-1, 1) * (kind == 1 ? 1e-9 : 0.02);
                const point<double> c = b.centroid();
                const double co = std::cos(theta), si = std::sin(theta);
                const double shift = kind == 0 ? cell / 2 * std::round(g.uniform(-1, 1)) : 0;
                const pose q{c.x - (co * c.x - si * c.y) + shift, c.y - (si * c.x + co * c.y), theta};
                const bool want = test_exact::regions_meet(test_exact::place(a, 0, 0, 0), test_exact::place(b, q));
                INFO("pair " << meeting[k].first << ", " << meeting[k].second << (swapped ? " swapped" : "")
                             << " theta " << theta << " shift " << shift);
                CHECK(certified_intersects(a, b, q) == want);
                meets += want;
            }
    CHECK(meets >= 300);  // premise: most poses meet, and not all
    CHECK(meets < 3 * meeting.size());
}

TEST_CASE("layer_pairs: a crowded layer answered by two threads, exact vertices made before they share", "[world]") {
    // Candidates holding enough vertices (join_parallel_vertices, checked on
    // the meeting pairs alone) for the pair tests to run on two threads,
    // each polygon placed once for all its pairs: in exact
    // rationals every vertex is then made before the threads read it. The
    // answers are the exact reference's, in every type and thread count.
    rng g(501);
    const std::vector<polygon> shapes = random_shapes(g, 6);
    std::vector<polygon> layer;
    std::vector<body_state> bodies;
    for (int k = 0; k < 60; ++k) {
        const body_state b{g.index(shapes.size()),
                           {test_scenes::snap(g.uniform(-8, 8)), test_scenes::snap(g.uniform(-8, 8)), 0}};
        layer.push_back(test_shapes::translated(shapes[b.shape], b.where.tx, b.where.ty));
        bodies.push_back(b);
    }
    const std::vector<body_pair> want = reference_contacts(shapes, bodies, 0);
    REQUIRE(vertices_in_pairs(layer, want) >= join_parallel_vertices);
    CHECK(show_pairs(layer_pairs<exact_rational>(layer, 0, 2)) == show_pairs(want));
    CHECK(show_pairs(certified_layer_pairs(layer, 0, 2)) == show_pairs(want));
    CHECK(show_pairs(layer_pairs<double>(layer, 0, 2)) == show_pairs(layer_pairs<double>(layer, 0, 1)));
}
