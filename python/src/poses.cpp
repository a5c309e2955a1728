// SPDX-License-Identifier: BSL-1.0
// What every batch call checks first: the number type's name, the threads,
// and the pose array, read in place (never copied) once it is an (n, 3)
// float64 C-contiguous array of finite values.

#include <cmath>
#include <string>

#include "bindings.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/shortest_decimal.hpp"

namespace influence2d::python {

number_kind number_kind_of(const std::string& name) {
    if (name == "double") return number_kind::double_type;
    if (name == "certified") return number_kind::certified_type;
    if (name == "exact") return number_kind::exact_type;
    throw invalid_input("number_type '" + name +
                        "' is not one of 'double' (rounded), 'certified' (exact at about double's cost) or "
                        "'exact' (CGAL's exact rationals)");
}

unsigned threads_of(long threads) {
    if (threads < 0 || threads > 4096)
        throw invalid_input("threads is " + std::to_string(threads) + ": expected 0 (every core) to 4096");
    return static_cast<unsigned>(threads);
}

// A pose is three doubles, so that a row of the array is one.
static_assert(sizeof(pose) == 3 * sizeof(double) && alignof(pose) == alignof(double));

std::string shape_text(const py::array& a) {
    std::string s;
    for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
    return "(" + s + (a.ndim() == 1 ? ",)" : ")");
}

pose_rows pose_rows_of(const py::array& poses, const char* what) {
    if (poses.ndim() != 2 || poses.shape(1) != 3)
        throw invalid_input(std::string(what) + ": expected an array of shape (n, 3) (tx, ty, theta), got shape " +
                            shape_text(poses));
    if (!poses.dtype().equal(py::dtype::of<double>()))
        throw invalid_input(std::string(what) + ": expected dtype float64, got " + std::string(py::str(poses.dtype())));
    if (!(poses.flags() & py::array::c_style))
        throw invalid_input(std::string(what) + ": expected a C-contiguous array (numpy.ascontiguousarray)");
    pose_rows r{static_cast<const pose*>(poses.data()), static_cast<std::size_t>(poses.shape(0))};
    static const char* const names[] = {"tx", "ty", "theta"};
    for (std::size_t k = 0; k < r.count; ++k) {
        const pose& p = r.rows[k];
        if ((p.tx - p.tx) + (p.ty - p.ty) + (p.theta - p.theta) == 0) continue;  // all finite
        const double v[] = {p.tx, p.ty, p.theta};
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(v[c]))
                throw invalid_input(std::string(what) + "[" + std::to_string(k) + ", " + std::to_string(c) + "] (" +
                                    names[c] + ") is " + shortest_decimal(v[c]) + ": not a finite number");
    }
    return r;
}

}  // namespace influence2d::python
