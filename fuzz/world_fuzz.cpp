// SPDX-License-Identifier: BSL-1.0
// libFuzzer target: the world on arbitrary small scenes. The bytes give one
// to three shapes (as detector_fuzz makes A and B: 1 to 3 rings of 3 to 8
// vertices k / 16 about offsets of their own, all scaled by 2^e, |e| < 64),
// two to seven bodies (a shape, fixed or not, a pose), a distance, whether
// the world keeps coherence, and one to five steps; at each step each body
// stays, slides by a small or a whole grid unit, turns a little, jumps to a
// new pose or is removed, and now and then a body is added. After every
// step the certified world and the world in exact rationals, witnesses on,
// must report the contacts of the independent exact reference
// (support/world_reference.hpp: every pair placed on CGAL's kernel), and
// their events the difference of the reference's contacts. Then the bodies
// left unturned, translated in double (exact: every coordinate a multiple of
// 2^(e-12) below 2^(e+8)), make a layer whose join (certified_layer_pairs,
// one layer and the layer against itself) must give the reference's pairs.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <vector>

#include "fuzz_input.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/world/world.hpp"
#include "support/shapes.hpp"
#include "support/world_reference.hpp"

namespace {

// A pose on the scene's grid (translations k / 4 scaled by 2^e, exact), its
// angle a multiple of 1/32 rad or 0.
influence2d::pose make_pose(fuzz_input::bytes& in, int e) {
    const double tx = std::ldexp(in.signed_over(4), e), ty = std::ldexp(in.signed_over(4), e);
    return {tx, ty, in.next() % 2 == 0 ? 0.0 : in.signed_over(32)};
}

// The contacts that begin and end between `last` and `now` (both sorted),
// as the world's events list them.
std::vector<influence2d::contact_event> differences(const std::vector<influence2d::body_pair>& last,
                                                    const std::vector<influence2d::body_pair>& now) {
    std::vector<influence2d::contact_event> out;
    std::size_t i = 0, j = 0;
    while (i < last.size() || j < now.size()) {
        if (j == now.size() || (i < last.size() && last[i] < now[j]))
            out.push_back({last[i++], false});
        else if (i == last.size() || now[j] < last[i])
            out.push_back({now[j++], true});
        else {
            ++i;
            ++j;
        }
    }
    return out;
}

template <class World>
bool same_step(World& w, const std::vector<influence2d::body_pair>& want,
               const std::vector<influence2d::contact_event>& events) {
    const std::vector<influence2d::body_pair> got = w.step();
    if (got != want || w.witnesses().size() != got.size() || w.events().size() != events.size()) return false;
    for (std::size_t k = 0; k < events.size(); ++k)
        if (!(w.events()[k].bodies == events[k].bodies) || w.events()[k].begins != events[k].begins) return false;
    return true;
}

// The unturned live bodies as a layer at their places: its join, one layer
// and two, against the reference on the same bodies (none fixed).
bool same_layer(const std::vector<influence2d::polygon>& shapes, const std::vector<test_world::body_state>& bodies,
                double within) {
    std::vector<influence2d::polygon> layer;
    std::vector<test_world::body_state> as_bodies;
    for (const test_world::body_state& b : bodies)
        if (b.alive && b.where.theta == 0) {
            layer.push_back(test_shapes::translated(shapes[b.shape], b.where.tx, b.where.ty));
            as_bodies.push_back({b.shape, b.where, false, true});
        }
    const std::vector<influence2d::body_pair> want = test_world::reference_contacts(shapes, as_bodies, within);
    if (influence2d::certified_layer_pairs(layer, within) != want) return false;
    // The layer against itself: each pair both ways, and each polygon with itself.
    std::vector<influence2d::body_pair> both;
    for (const influence2d::body_pair& p : want) {
        both.push_back(p);
        both.push_back({p.second, p.first});
    }
    for (std::uint32_t i = 0; i < layer.size(); ++i) both.push_back({i, i});
    std::sort(both.begin(), both.end());
    return influence2d::certified_layer_pairs(layer, layer, within) == both;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace influence2d;
    fuzz_input::bytes in{data, size};
    const int e = static_cast<std::int8_t>(in.next()) % 64;  // a scale of 2^e, |e| < 64
    try {
        std::vector<polygon> shapes;
        for (std::size_t k = 1 + in.next() % 3; k > 0; --k) shapes.push_back(fuzz_input::polygon(in, e));
        world_options o;
        o.witness = true;
        o.within = in.next() % 4 == 0 ? std::ldexp((in.next() % 8) / 8.0, e) : 0.0;
        o.coherence = in.next() % 4 != 0;
        certified_world certified(o);
        world<exact_rational> exact(o);
        for (const polygon& p : shapes) {
            certified.add_shape(p);
            exact.add_shape(p);
        }
        std::vector<test_world::body_state> bodies;
        const auto add = [&] {
            test_world::body_state b{in.next() % shapes.size(), make_pose(in, e), in.next() % 4 == 0};
            certified.add_body(static_cast<std::uint32_t>(b.shape), b.where, b.fixed);
            exact.add_body(static_cast<std::uint32_t>(b.shape), b.where, b.fixed);
            bodies.push_back(b);
        };
        for (std::size_t k = 2 + in.next() % 6; k > 0; --k) add();
        std::vector<body_pair> last;
        for (std::size_t step = 0, steps = 1 + in.next() % 5; step < steps; ++step) {
            if (step > 0) {
                for (std::size_t i = 0; i < bodies.size(); ++i) {
                    if (!bodies[i].alive) continue;
                    pose& q = bodies[i].where;
                    switch (in.next() % 8) {
                    case 0:
                    case 1: continue;  // stays
                    case 2: q.tx += std::ldexp(in.signed_over(1024), e); break;
                    case 3: q.ty += std::ldexp(in.signed_over(16), e); break;  // a grid unit: exact touching
                    case 4:
                        q.theta += in.signed_over(4096);
                        q.tx += std::ldexp(in.signed_over(4096), e);
                        break;
                    case 5: q = make_pose(in, e); break;
                    case 6: q.tx += std::ldexp(in.signed_over(16), e); break;
                    default:
                        bodies[i].alive = false;
                        certified.remove(static_cast<std::uint32_t>(i));
                        exact.remove(static_cast<std::uint32_t>(i));
                        continue;
                    }
                    certified.move(static_cast<std::uint32_t>(i), q);
                    exact.move(static_cast<std::uint32_t>(i), q);
                }
                if (in.next() % 4 == 0) add();
            }
            const std::vector<body_pair> want = test_world::reference_contacts(shapes, bodies, o.within);
            const std::vector<contact_event> events = differences(last, want);
            if (!same_step(certified, want, events) || !same_step(exact, want, events)) std::abort();
            last = want;
        }
        if (!same_layer(shapes, bodies, o.within)) std::abort();
    } catch (const invalid_input&) {
        // fewer than three distinct vertices: refused, as it must be
    }
    return 0;
}
