// SPDX-License-Identifier: BSL-1.0
// The vectorised queries on one pair: whether A and B posed meet, their
// separation, the first contact of a motion; each over an array of poses,
// the GIL released, on all cores (run_in_blocks, one contiguous block of
// poses per thread, as collide_batch).

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "bindings.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/query/batch.hpp"

namespace influence2d::python {

namespace {

/// A value of NT as the nearest double.
template <class NT>
double as_double(const NT& x) {
    if constexpr (std::is_same_v<NT, double>)
        return x;
    else
        return nearest_double(x);
}

/// answer(query, k, pose k) for every pose k, each block of poses with its
/// own query object make(A, B) on the polygons prepared once in NT; with a
/// shift (batch_range_shift, core/range_scaling.hpp), on the polygons and
/// poses scaled by 2^shift.
template <class NT, class Make, class Answer>
void on_prepared(const polygon& a, const polygon& b, const pose_rows& poses, int shift, unsigned threads, Make&& make,
                 Answer&& answer) {
    const auto pa = prepare_static<NT>(a, shift);
    const auto pb = prepare_moving<NT>(b, shift);
    run_in_blocks(poses.count, threads, [&](std::size_t first, std::size_t last) {
        if (first == last) return;
        auto query = make(pa, pb);
        for (std::size_t k = first; k < last; ++k)
            answer(query, k, shift ? scaled_by_power_of_two(poses.rows[k], shift) : poses.rows[k]);
    });
}

/// A detector in `kind` per block, over the poses: collides for each.
void intersects_into(const polygon& a, const polygon& b, const pose_rows& poses, number_kind kind, unsigned threads,
                     bool* out) {
    const auto in = [&](auto tag) {
        using NT = decltype(tag);
        on_prepared<NT>(
            a, b, poses, batch_range_shift<NT>(a, b, poses.rows, poses.count), threads,
            [](const auto& pa, const auto& pb) { return detector<NT>(pa, pb); },
            [&](detector<NT>& d, std::size_t k, const pose& q) { out[k] = d.collide(q).collides; });
    };
    switch (kind) {
    case number_kind::double_type: return in(double{});
    case number_kind::exact_type: return in(exact_rational{});
    case number_kind::certified_type:
        return run_in_blocks(poses.count, threads, [&](std::size_t first, std::size_t last) {
            if (first == last) return;
            certified_detector<detector> d(a, b);
            for (std::size_t k = first; k < last; ++k) out[k] = d.collide(poses.rows[k]).collides;
        });
    }
}

py::array_t<bool> intersects(const py_polygon& a, const py_polygon& b, const py::array& poses,
                             const std::string& number_type, long threads) {
    const number_kind kind = number_kind_of(number_type);
    const unsigned t = threads_of(threads);
    const pose_rows rows = pose_rows_of(poses, "poses");
    py::array_t<bool> out(static_cast<py::ssize_t>(rows.count));
    bool* o = out.mutable_data();
    {
        py::gil_scoped_release release;
        intersects_into(a.shape, b.shape, rows, kind, t, o);
    }
    return out;
}

/// The separation's answers, one row per pose: the distance, and with
/// features the closest features (kind 0 vertex, 1 edge, 2 interior; input
/// numbers) and points.
struct separation_arrays {
    py::array_t<double> distance;
    py::array_t<std::int8_t> static_kind, moving_kind;
    py::array_t<std::int64_t> static_index, moving_index;
    py::array_t<double> static_point, moving_point;

    explicit separation_arrays(std::size_t n)
        : distance(static_cast<py::ssize_t>(n)),
          static_kind(static_cast<py::ssize_t>(n)),
          moving_kind(static_cast<py::ssize_t>(n)),
          static_index(static_cast<py::ssize_t>(n)),
          moving_index(static_cast<py::ssize_t>(n)),
          static_point({static_cast<py::ssize_t>(n), py::ssize_t{2}}),
          moving_point({static_cast<py::ssize_t>(n), py::ssize_t{2}}) {}
};

/// Raw pointers into separation_arrays, written with the GIL released.
struct separation_out {
    double* distance;
    std::int8_t *static_kind, *moving_kind;
    std::int64_t *static_index, *moving_index;
    double *static_point, *moving_point;

    void put(std::size_t k, double d, const feature& fs, const feature& fm, const point<double>& ps,
             const point<double>& pm) const {
        distance[k] = d;
        static_kind[k] = static_cast<std::int8_t>(fs.kind);
        moving_kind[k] = static_cast<std::int8_t>(fm.kind);
        static_index[k] = fs.kind == feature_kind::interior ? -1 : static_cast<std::int64_t>(fs.index);
        moving_index[k] = fm.kind == feature_kind::interior ? -1 : static_cast<std::int64_t>(fm.index);
        static_point[2 * k] = ps.x;
        static_point[2 * k + 1] = ps.y;
        moving_point[2 * k] = pm.x;
        moving_point[2 * k + 1] = pm.y;
    }
};

void separation_into(const polygon& a, const polygon& b, const pose_rows& poses, number_kind kind, unsigned threads,
                     const separation_out& out) {
    const auto in = [&](auto tag) {
        using NT = decltype(tag);
        // Scaled by 2^shift, the lengths come back scaled by 2^-shift: the
        // distance from the scaled squared distance, which double holds.
        const int shift = batch_range_shift<NT>(a, b, poses.rows, poses.count);
        const auto back = [shift](double x) { return std::ldexp(x, -shift); };
        on_prepared<NT>(
            a, b, poses, shift, threads, [](const auto& pa, const auto& pb) { return separation_query<NT>(pa, pb); },
            [&](separation_query<NT>& query, std::size_t k, const pose& q) {
                const separation_result<NT> r = query(q);
                out.put(k, back(distance_of<NT>(r.squared_distance)), r.static_feature, r.moving_feature,
                        {back(as_double(r.static_point.x)), back(as_double(r.static_point.y))},
                        {back(as_double(r.moving_point.x)), back(as_double(r.moving_point.y))});
            });
    };
    switch (kind) {
    case number_kind::double_type: return in(double{});
    case number_kind::exact_type: return in(exact_rational{});
    case number_kind::certified_type:
        return run_in_blocks(poses.count, threads, [&](std::size_t first, std::size_t last) {
            if (first == last) return;
            certified_separation_query query(a, b);
            for (std::size_t k = first; k < last; ++k) {
                const certified_separation_result r = query(poses.rows[k]);
                out.put(k, r.distance, r.static_feature, r.moving_feature, r.static_point, r.moving_point);
            }
        });
    }
}

py::tuple separation(const py_polygon& a, const py_polygon& b, const py::array& poses, const std::string& number_type,
                     long threads) {
    const number_kind kind = number_kind_of(number_type);
    const unsigned t = threads_of(threads);
    const pose_rows rows = pose_rows_of(poses, "poses");
    separation_arrays arrays(rows.count);
    const separation_out out{arrays.distance.mutable_data(),     arrays.static_kind.mutable_data(),
                             arrays.moving_kind.mutable_data(),  arrays.static_index.mutable_data(),
                             arrays.moving_index.mutable_data(), arrays.static_point.mutable_data(),
                             arrays.moving_point.mutable_data()};
    {
        py::gil_scoped_release release;
        separation_into(a.shape, b.shape, rows, kind, t, out);
    }
    return py::make_tuple(arrays.distance, arrays.static_kind, arrays.static_index, arrays.moving_kind,
                          arrays.moving_index, arrays.static_point, arrays.moving_point);
}

/// The turning model named `name` ("angle-linear", "rational"); throws
/// invalid_input naming it otherwise.
turning_model turning_model_of(const std::string& name) {
    if (name == "angle-linear") return turning_model::angle_linear;
    if (name == "rational") return turning_model::rational;
    throw invalid_input("motion '" + name + "' is not a turning model: expected 'angle-linear' or 'rational'");
}

/// Each motion's contact, time (NaN without contact; where the step limit
/// stopped for a motion it left undecided) and whether it was left so.
void first_contact_into(const polygon& a, const polygon& b, const pose_rows& from, const pose_rows& to,
                        number_kind kind, const sweep_options& options, unsigned threads, bool* contact, double* time,
                        bool* limited) {
    run_in_blocks(from.count, threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            const pose &p = from.rows[k], &q = to.rows[k];
            contact_result<double> r;
            switch (kind) {
            case number_kind::certified_type: r = certified_first_contact(a, b, p, q, options); break;
            case number_kind::double_type: r = first_contact<double>(a, b, p, q, options); break;
            case number_kind::exact_type: {
                const contact_result<exact_rational> x = first_contact<exact_rational>(a, b, p, q, options);
                r = {x.contact, nearest_double(time_fraction<exact_rational>{x.time, exact_rational(1)}),
                     x.static_feature, x.moving_feature, x.step_limit};
                break;
            }
            }
            contact[k] = r.contact;
            limited[k] = r.step_limit;
            time[k] = r.contact || r.step_limit ? r.time : std::numeric_limits<double>::quiet_NaN();
        }
    });
}

py::tuple first_contact_batch(const py_polygon& a, const py_polygon& b, const py::array& start, const py::array& end,
                              const std::string& number_type, const std::string& motion, long threads, long max_steps) {
    const number_kind kind = number_kind_of(number_type);
    sweep_options options;
    options.model = turning_model_of(motion);
    if (max_steps < 0) throw invalid_input("max_steps is " + std::to_string(max_steps) + ": expected 0 or more");
    options.max_steps = static_cast<std::size_t>(max_steps);
    const unsigned t = threads_of(threads);
    const pose_rows from = pose_rows_of(start, "start_poses");
    const pose_rows to = pose_rows_of(end, "end_poses");
    if (from.count != to.count)
        throw invalid_input("start_poses has " + std::to_string(from.count) + " rows and end_poses " +
                            std::to_string(to.count) + ": expected one end pose per start pose");
    py::array_t<bool> contact(static_cast<py::ssize_t>(from.count));
    py::array_t<double> time(static_cast<py::ssize_t>(from.count));
    py::array_t<bool> limited(static_cast<py::ssize_t>(from.count));
    bool* c = contact.mutable_data();
    double* tm = time.mutable_data();
    bool* lim = limited.mutable_data();
    {
        py::gil_scoped_release release;
        first_contact_into(a.shape, b.shape, from, to, kind, options, t, c, tm, lim);
    }
    return py::make_tuple(contact, time, limited);
}

}  // namespace

void bind_queries(py::module_& m) {
    m.def("intersects", &intersects, py::arg("a"), py::arg("b"), py::arg("poses"), py::arg("number_type"),
          py::arg("threads"));
    m.def("separation", &separation, py::arg("a"), py::arg("b"), py::arg("poses"), py::arg("number_type"),
          py::arg("threads"));
    m.def("first_contact", &first_contact_batch, py::arg("a"), py::arg("b"), py::arg("start_poses"),
          py::arg("end_poses"), py::arg("number_type"), py::arg("motion"), py::arg("threads"), py::arg("max_steps"));
}

}  // namespace influence2d::python
