// SPDX-License-Identifier: BSL-1.0
// influence2d.InvalidInput, a ValueError: what the library refuses
// (invalid_input) and what this module refuses on its own (std::invalid_argument
// and std::out_of_range from an option), with the message naming the value
// and its place.

#include <stdexcept>

#include "bindings.hpp"
#include "influence2d/core/invalid_input.hpp"

namespace influence2d::python {

void bind_errors(py::module_& m) {
    static py::exception<invalid_input> invalid(m, "InvalidInput", PyExc_ValueError);
    invalid.doc() =
        "Input the library refuses: a non-finite coordinate or pose component, an empty polygon or one with too "
        "few vertices, malformed WKT or WKB, an array of the wrong shape or dtype, an unknown number type. "
        "The message names the value and its index.\n\n"
        ">>> import numpy as np, influence2d\n"
        ">>> square = \"POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\"\n"
        ">>> try:\n"
        "...     influence2d.intersects(square, square, np.array([[0.0, 0.0, np.nan]]))\n"
        "... except ValueError as e:\n"
        "...     print(type(e).__name__, e)\n"
        "InvalidInput poses[0, 2] (theta) is nan: not a finite number\n";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const invalid_input& e) {
            invalid(e.what());
        } catch (const std::invalid_argument& e) {
            invalid(e.what());
        }
    });
}

}  // namespace influence2d::python
