// SPDX-License-Identifier: BSL-1.0
// The extension influence2d._core: the library's queries on numpy arrays.
// The public interface, with its documentation, is the package's Python
// modules (python/influence2d/); this module is what they call.

#include "bindings.hpp"
#include "influence2d/version.hpp"

PYBIND11_MODULE(_core, m) {
    using namespace influence2d::python;
    m.doc() = "The influence2d library's queries, called by the influence2d package.";
    m.attr("__version__") = INFLUENCE2D_VERSION;
    bind_errors(m);
    bind_polygon(m);
    bind_queries(m);
    bind_detector(m);
    bind_pairs(m);
    bind_audit(m);
    bind_study(m);
    bind_world(m);
}
