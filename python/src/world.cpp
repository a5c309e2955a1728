// SPDX-License-Identifier: BSL-1.0
// influence2d._core.World: the library's world (world/world.hpp) of many
// bodies moved step by step, with ids and poses in numpy arrays. Every batch
// (bodies added, moved, removed) is checked whole before the world changes,
// so a refused call leaves it as it was; a step runs with the GIL released.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/world/world.hpp"

namespace influence2d::python {

namespace {

/// A world of any number type, behind one interface.
struct world_source {
    virtual ~world_source() = default;
    virtual void add_shape(const polygon& p) = 0;
    virtual void add_body(std::uint32_t shape, const pose& q, bool fixed) = 0;
    virtual void move(std::uint32_t body, const pose& q) = 0;
    virtual void remove(std::uint32_t body) = 0;
    virtual void step() = 0;
    virtual const std::vector<body_pair>& contacts() const = 0;
    virtual const std::vector<contact_witness>& witnesses() const = 0;
    virtual const std::vector<contact_event>& events() const = 0;
    virtual const world_statistics& statistics() const = 0;
};

template <class W>
struct world_source_of final : world_source {
    explicit world_source_of(const world_options& o) : w(o) {}
    void add_shape(const polygon& p) override { w.add_shape(p); }
    void add_body(std::uint32_t shape, const pose& q, bool fixed) override { w.add_body(shape, q, fixed); }
    void move(std::uint32_t body, const pose& q) override { w.move(body, q); }
    void remove(std::uint32_t body) override { w.remove(body); }
    void step() override { w.step(); }
    const std::vector<body_pair>& contacts() const override { return w.contacts(); }
    const std::vector<contact_witness>& witnesses() const override { return w.witnesses(); }
    const std::vector<contact_event>& events() const override { return w.events(); }
    const world_statistics& statistics() const override { return w.statistics(); }
    W w;
};

std::unique_ptr<world_source> make_world(number_kind kind, const world_options& o) {
    switch (kind) {
    case number_kind::double_type: return std::make_unique<world_source_of<world<double>>>(o);
    case number_kind::exact_type: return std::make_unique<world_source_of<world<exact_rational>>>(o);
    case number_kind::certified_type: break;
    }
    return std::make_unique<world_source_of<certified_world>>(o);
}

/// An (n,) int64 C-contiguous array of ids, read in place.
using id_array = py::array_t<std::int64_t, py::array::c_style>;

/// The ids of `a` (1-D), checked against `count` ids in all.
const std::int64_t* ids_of(const id_array& a, const char* what, std::size_t count, const char* kind) {
    if (a.ndim() != 1)
        throw invalid_input(std::string(what) + ": expected a 1-D array of ids, got shape " + shape_text(a));
    const std::int64_t* v = a.data();
    for (py::ssize_t k = 0; k < a.shape(0); ++k)
        if (v[k] < 0 || static_cast<std::uint64_t>(v[k]) >= count)
            throw invalid_input(std::string(what) + "[" + std::to_string(k) + "] is " + std::to_string(v[k]) + ": no " +
                                kind + " " + std::to_string(v[k]) + " (there are " + std::to_string(count) + ")");
    return v;
}

class py_world {
public:
    py_world(const std::string& number_type, double within, bool witness, bool coherence, long threads) {
        world_options o;
        o.within = within;
        o.witness = witness;
        o.coherence = coherence;
        o.threads = threads_of(threads);
        source_ = make_world(number_kind_of(number_type), o);  // throws for a distance < 0, NaN or infinite
        options_ = o;
    }

    /// Adds the shapes in order; returns the id of the first (the others
    /// follow). Nothing is added unless every item is a Polygon with a ring
    /// (the world takes every such polygon in its three types).
    std::int64_t add_shapes(const py::list& shapes) {
        std::vector<const polygon*> all;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            const py::object item = shapes[k];
            if (!py::isinstance<py_polygon>(item))
                throw invalid_input("shapes[" + std::to_string(k) + "] is not a Polygon");
            all.push_back(&item.cast<const py_polygon&>().shape);
            if (all.back()->size() == 0) throw invalid_input("shapes[" + std::to_string(k) + "] is empty");
        }
        const std::lock_guard<std::mutex> hold(mutex_);
        const std::int64_t first = static_cast<std::int64_t>(shape_count_);
        for (const polygon* p : all) {
            source_->add_shape(*p);
            ++shape_count_;
        }
        return first;
    }

    /// Adds a body for each row (shape id, pose, fixed); returns the id of
    /// the first (the others follow in order). Nothing is added unless
    /// every row is valid.
    std::int64_t add_bodies(const id_array& shapes, const py::array& poses, const py::array_t<bool>& fixed) {
        const pose_rows rows = pose_rows_of(poses, "poses");
        const std::lock_guard<std::mutex> hold(mutex_);
        const std::int64_t* s = ids_of(shapes, "shapes", shape_count_, "shape");
        if (static_cast<std::size_t>(shapes.shape(0)) != rows.count)
            throw invalid_input("shapes and poses: " + std::to_string(shapes.shape(0)) + " shape ids for " +
                                std::to_string(rows.count) + " poses");
        if (fixed.ndim() != 1 || static_cast<std::size_t>(fixed.shape(0)) != rows.count)
            throw invalid_input("fixed: expected " + std::to_string(rows.count) + " flags, got shape " +
                                shape_text(fixed));
        if (alive_.size() + rows.count > std::size_t{UINT32_MAX} + 1)
            throw invalid_input("add_bodies: a world holds at most 2^32 bodies");
        const std::int64_t first = static_cast<std::int64_t>(alive_.size());
        const auto f = fixed.unchecked<1>();
        for (std::size_t k = 0; k < rows.count; ++k) {
            source_->add_body(static_cast<std::uint32_t>(s[k]), rows.rows[k], f(static_cast<py::ssize_t>(k)));
            alive_.push_back(1);
        }
        return first;
    }

    /// Moves each body listed to its row's pose; nothing moves unless every
    /// row is valid (a body alive, listed once, its pose finite).
    void move(const id_array& bodies, const py::array& poses) {
        const pose_rows rows = pose_rows_of(poses, "poses");
        const std::lock_guard<std::mutex> hold(mutex_);
        const std::int64_t* b = live_ids(bodies, "bodies");
        if (static_cast<std::size_t>(bodies.shape(0)) != rows.count)
            throw invalid_input("bodies and poses: " + std::to_string(bodies.shape(0)) + " bodies for " +
                                std::to_string(rows.count) + " poses");
        for (std::size_t k = 0; k < rows.count; ++k) source_->move(static_cast<std::uint32_t>(b[k]), rows.rows[k]);
    }

    /// Removes each body listed; nothing is removed unless every one is
    /// alive and listed once.
    void remove(const id_array& bodies) {
        const std::lock_guard<std::mutex> hold(mutex_);
        const std::int64_t* b = live_ids(bodies, "bodies");
        for (py::ssize_t k = 0; k < bodies.shape(0); ++k) {
            source_->remove(static_cast<std::uint32_t>(b[k]));
            alive_[static_cast<std::size_t>(b[k])] = 0;
        }
    }

    /// Steps the world; returns its contacts.
    py::array_t<std::int64_t> step() {
        {
            py::gil_scoped_release release;
            const std::lock_guard<std::mutex> hold(mutex_);
            source_->step();
        }
        return contacts();
    }

    /// The contacts after the last step, an (n, 2) array sorted.
    py::array_t<std::int64_t> contacts() const {
        const std::lock_guard<std::mutex> hold(mutex_);
        return pair_array(source_->contacts(), [](const body_pair& p) { return p; });
    }

    /// The contacts that began or ended at the last step: the (n, 2) pairs
    /// and whether each began.
    std::pair<py::array_t<std::int64_t>, py::array_t<bool>> events() const {
        const std::lock_guard<std::mutex> hold(mutex_);
        const std::vector<contact_event>& e = source_->events();
        py::array_t<bool> begins(static_cast<py::ssize_t>(e.size()));
        for (std::size_t k = 0; k < e.size(); ++k) begins.mutable_data()[k] = e[k].begins;
        return {pair_array(e, [](const contact_event& v) { return v.bodies; }), begins};
    }

    /// Each contact's witness: the two bodies' feature kinds (0 vertex, 1
    /// edge, 2 interior) and input indices (-1 for the interior).
    py::tuple witnesses() const {
        if (!options_.witness)
            throw invalid_input("witnesses: the world was made without witness=True (it keeps none)");
        const std::lock_guard<std::mutex> hold(mutex_);
        const std::vector<contact_witness>& w = source_->witnesses();
        const auto n = static_cast<py::ssize_t>(w.size());
        py::array_t<std::int8_t> first_kind(n), second_kind(n);
        py::array_t<std::int64_t> first_index(n), second_index(n);
        const auto index = [](const feature& f) {
            return f.kind == feature_kind::interior ? std::int64_t{-1} : static_cast<std::int64_t>(f.index);
        };
        for (std::size_t k = 0; k < w.size(); ++k) {
            first_kind.mutable_data()[k] = static_cast<std::int8_t>(w[k].first.kind);
            second_kind.mutable_data()[k] = static_cast<std::int8_t>(w[k].second.kind);
            first_index.mutable_data()[k] = index(w[k].first);
            second_index.mutable_data()[k] = index(w[k].second);
        }
        return py::make_tuple(first_kind, first_index, second_kind, second_index);
    }

    /// The world's counters (world_statistics) by name.
    py::dict statistics() const {
        const std::lock_guard<std::mutex> hold(mutex_);
        const world_statistics& s = source_->statistics();
        py::dict d;
        d["steps"] = s.steps;
        d["moved"] = s.moved;
        d["escaped"] = s.escaped;
        d["rebuilds"] = s.rebuilds;
        d["candidates"] = s.candidates;
        d["carried"] = s.carried;
        d["witness_hits"] = s.witness_hits;
        d["separated"] = s.separated;
        d["found_apart"] = s.found_apart;
        d["nearby_edges"] = s.nearby_edges;
        d["exact_pairs"] = s.exact_pairs;
        d["contacts"] = s.contacts;
        return d;
    }

    std::size_t body_count() const {
        const std::lock_guard<std::mutex> hold(mutex_);
        return alive_.size();
    }
    std::size_t shape_count() const {
        const std::lock_guard<std::mutex> hold(mutex_);
        return shape_count_;
    }
    /// Whether each body is alive (not removed), by id.
    py::array_t<bool> alive() const {
        const std::lock_guard<std::mutex> hold(mutex_);
        py::array_t<bool> out(static_cast<py::ssize_t>(alive_.size()));
        for (std::size_t k = 0; k < alive_.size(); ++k) out.mutable_data()[k] = alive_[k] != 0;
        return out;
    }

private:
    template <class T, class F>
    static py::array_t<std::int64_t> pair_array(const std::vector<T>& items, F pair_of) {
        py::array_t<std::int64_t> out({static_cast<py::ssize_t>(items.size()), py::ssize_t{2}});
        std::int64_t* o = out.mutable_data();
        for (std::size_t k = 0; k < items.size(); ++k) {
            const body_pair p = pair_of(items[k]);
            o[2 * k] = p.first;
            o[2 * k + 1] = p.second;
        }
        return out;
    }

    // The ids of `bodies`, each a body alive and listed once (the caller
    // holds the mutex); the first refused place, in order, is named. The
    // repeats are found among the listed ids sorted (O(k log k) for k ids,
    // whatever the number of bodies).
    const std::int64_t* live_ids(const id_array& bodies, const char* what) {
        const std::int64_t* b = ids_of(bodies, what, alive_.size(), "body");
        const py::ssize_t n = bodies.shape(0);
        std::vector<std::pair<std::int64_t, py::ssize_t>> sorted(static_cast<std::size_t>(n));
        for (py::ssize_t k = 0; k < n; ++k) sorted[static_cast<std::size_t>(k)] = {b[k], k};
        std::sort(sorted.begin(), sorted.end());
        py::ssize_t repeat = n, before = 0;  // the first place whose id came before, and that earlier place
        for (std::size_t m = 1; m < sorted.size(); ++m)
            if (sorted[m].first == sorted[m - 1].first && sorted[m].second < repeat) {
                repeat = sorted[m].second;
                before = sorted[m - 1].second;
            }
        for (py::ssize_t k = 0; k < n; ++k) {
            if (!alive_[static_cast<std::size_t>(b[k])])
                throw invalid_input(std::string(what) + "[" + std::to_string(k) + "] is " + std::to_string(b[k]) +
                                    ": the body was removed");
            if (k == repeat)
                throw invalid_input(std::string(what) + "[" + std::to_string(k) + "] is " + std::to_string(b[k]) +
                                    ", listed already at [" + std::to_string(before) + "]");
        }
        return b;
    }

    world_options options_;
    std::unique_ptr<world_source> source_;
    std::size_t shape_count_ = 0;
    std::vector<char> alive_;  // by body id: not removed
    mutable std::mutex mutex_;
};

}  // namespace

void bind_world(py::module_& m) {
    py::class_<py_world>(m, "World")
        .def(py::init<const std::string&, double, bool, bool, long>(), py::arg("number_type"), py::arg("within"),
             py::arg("witness"), py::arg("coherence"), py::arg("threads"))
        .def("add_shapes", &py_world::add_shapes, py::arg("shapes"))
        .def("add_bodies", &py_world::add_bodies, py::arg("shapes"), py::arg("poses"), py::arg("fixed"))
        .def("move", &py_world::move, py::arg("bodies"), py::arg("poses"))
        .def("remove", &py_world::remove, py::arg("bodies"))
        .def("step", &py_world::step)
        .def("contacts", &py_world::contacts)
        .def("events", &py_world::events)
        .def("witnesses", &py_world::witnesses)
        .def("statistics", &py_world::statistics)
        .def("alive", &py_world::alive)
        .def_property_readonly("body_count", &py_world::body_count)
        .def_property_readonly("shape_count", &py_world::shape_count);
}

}  // namespace influence2d::python
