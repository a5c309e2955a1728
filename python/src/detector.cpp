// SPDX-License-Identifier: BSL-1.0
// influence2d._core.Detector: one frame detector kept across calls, so that
// consecutive poses keep its coherence (the candidate edges of the last
// frame); frames answered in order with the GIL released.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "influence2d/core/shortest_decimal.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d::python {

namespace {

/// A detector of any type, behind one interface.
struct frame_source {
    virtual ~frame_source() = default;
    virtual frame_result collide(const pose& p) = 0;
    /// The frame's answer, its witnesses written into `pairs` (cleared
    /// first, its capacity kept).
    virtual bool collide(const pose& p, std::vector<edge_pair>& pairs) = 0;
    virtual std::size_t exact_frames() const { return 0; }
};

template <class D>
struct frame_source_of final : frame_source {
    template <class... Args>
    explicit frame_source_of(Args&&... args) : d(std::forward<Args>(args)...) {}
    frame_result collide(const pose& p) override { return d.collide(p); }
    bool collide(const pose& p, std::vector<edge_pair>& pairs) override { return d.collide(p, pairs); }
    std::size_t exact_frames() const override {
        if constexpr (std::is_same_v<D, certified_detector<detector>>)
            return d.exact_frames();
        else
            return 0;
    }
    D d;
};

std::unique_ptr<frame_source> make_source(number_kind kind, const polygon& a, const polygon& b,
                                          const detector_options& o) {
    switch (kind) {
    case number_kind::double_type: return std::make_unique<frame_source_of<detector<double>>>(a, b, o);
    case number_kind::exact_type: return std::make_unique<frame_source_of<detector<exact_rational>>>(a, b, o);
    case number_kind::certified_type: break;
    }
    return std::make_unique<frame_source_of<certified_detector<detector>>>(a, b, o);
}

class py_detector {
public:
    py_detector(const py_polygon& a, const py_polygon& b, const std::string& number_type, bool witness, double within)
        : kind_(number_kind_of(number_type)), a_(a.shape), b_(b.shape) {
        if (!(within >= 0) || !std::isfinite(within))
            throw invalid_input("within is " + shortest_decimal(within) + ": expected a finite number >= 0");
        options_.distance = within;
        options_.witness = witness;
        py::gil_scoped_release release;
        source_ = make_source(kind_, a_, b_, options_);
    }

    /// Whether A and B posed by each row meet (are within `within`), in order.
    py::array_t<bool> collide(const py::array& poses) {
        const pose_rows rows = pose_rows_of(poses, "poses");
        py::array_t<bool> out(static_cast<py::ssize_t>(rows.count));
        bool* o = out.mutable_data();
        py::gil_scoped_release release;
        const std::lock_guard<std::mutex> hold(mutex_);
        for (std::size_t k = 0; k < rows.count; ++k) o[k] = source_->collide(rows.rows[k]).collides;
        return out;
    }

    /// The edge pairs (static edge, moving edge) within `within` at one pose,
    /// from a detector asked for witnesses (built on first use when this one
    /// was not), and whether the frame collides.
    std::pair<bool, std::vector<std::pair<std::size_t, std::size_t>>> witness(double tx, double ty, double theta) {
        const double row[3] = {tx, ty, theta};
        const py::array one({py::ssize_t{1}, py::ssize_t{3}}, row);
        const pose p = pose_rows_of(one, "pose").rows[0];
        std::vector<std::pair<std::size_t, std::size_t>> pairs;
        frame_result r;
        {
            py::gil_scoped_release release;
            const std::lock_guard<std::mutex> hold(mutex_);
            r = witnessing().collide(p);
        }
        for (const edge_pair& e : r.pairs) pairs.emplace_back(e.static_edge, e.moving_edge);
        return {r.collides, pairs};
    }

    /// Each pose's frame in order, from the detector that witnesses (as
    /// witness()): whether it collides, an (n,) bool array, and its edge
    /// pairs within `within`, a (k, 3) array of rows (pose's row, static
    /// edge, moving edge), by row and, within a row, as witness() orders
    /// them.
    std::pair<py::array_t<bool>, py::array_t<std::int64_t>> witnesses(const py::array& poses) {
        const pose_rows rows = pose_rows_of(poses, "poses");
        py::array_t<bool> collides(static_cast<py::ssize_t>(rows.count));
        bool* c = collides.mutable_data();
        std::vector<std::int64_t> found;  // (row, static edge, moving edge) after one another
        {
            py::gil_scoped_release release;
            const std::lock_guard<std::mutex> hold(mutex_);
            frame_source& source = witnessing();
            std::vector<edge_pair> pairs;
            for (std::size_t k = 0; k < rows.count; ++k) {
                c[k] = source.collide(rows.rows[k], pairs);
                for (const edge_pair& e : pairs)
                    found.insert(found.end(), {static_cast<std::int64_t>(k), static_cast<std::int64_t>(e.static_edge),
                                               static_cast<std::int64_t>(e.moving_edge)});
            }
        }
        py::array_t<std::int64_t> out({static_cast<py::ssize_t>(found.size() / 3), py::ssize_t{3}});
        std::copy(found.begin(), found.end(), out.mutable_data());
        return {collides, out};
    }

    std::size_t exact_frames() const {
        const std::lock_guard<std::mutex> hold(mutex_);
        return source_->exact_frames() + (witness_ ? witness_->exact_frames() : 0);
    }

private:
    /// The source whose frames gather witnesses: this detector's when it
    /// was asked for them, else one built on first use (the caller holds
    /// the mutex).
    frame_source& witnessing() {
        if (options_.witness) return *source_;
        if (!witness_) {
            detector_options o = options_;
            o.witness = true;
            witness_ = make_source(kind_, a_, b_, o);
        }
        return *witness_;
    }

    number_kind kind_;
    polygon a_, b_;
    detector_options options_;
    std::unique_ptr<frame_source> source_, witness_;
    mutable std::mutex mutex_;
};

}  // namespace

void bind_detector(py::module_& m) {
    py::class_<py_detector>(m, "Detector")
        .def(py::init<const py_polygon&, const py_polygon&, const std::string&, bool, double>(), py::arg("a"),
             py::arg("b"), py::arg("number_type"), py::arg("witness"), py::arg("within"))
        .def("collide", &py_detector::collide, py::arg("poses"))
        .def("witness", &py_detector::witness, py::arg("tx"), py::arg("ty"), py::arg("theta"))
        .def("witnesses", &py_detector::witnesses, py::arg("poses"))
        .def_property_readonly("exact_frames", &py_detector::exact_frames);
}

}  // namespace influence2d::python
