// SPDX-License-Identifier: BSL-1.0
// influence2d._core.audit: the input audit (audit/audit.hpp) of polygons
// given as WKT text, WKB bytes or Polygons (their rings as given), on all
// cores with the GIL released; each finding a dict.

#include <string>
#include <vector>

#include "bindings.hpp"
#include "influence2d/audit/audit.hpp"
#include "influence2d/query/batch.hpp"
#include "wkb.hpp"

namespace influence2d::python {

namespace {

/// The rings of one item as given: WKT text and WKB bytes read without the
/// geometric checks (the audit reports what the readers refuse), a
/// Polygon's rings as it was given them.
std::vector<wkt_ring> rings_of(const py::handle& item, const std::string& source) {
    if (py::isinstance<py::str>(item)) return read_wkt_rings(item.cast<std::string>(), source);
    if (py::isinstance<py::bytes>(item)) {
        const std::string_view view = item.cast<py::bytes>();
        return wkb_reader(view.data(), view.size(), source).rings();
    }
    if (py::isinstance<py_polygon>(item)) return item.cast<const py_polygon&>().source;
    throw invalid_input(source + ": expected WKT text, WKB bytes or a Polygon");
}

py::object optional_index(const std::optional<std::size_t>& i) {
    return i ? py::object(py::int_(*i)) : py::object(py::none());
}

py::dict finding_dict(const finding& f) {
    py::dict d;
    d["kind"] = finding_name(f.kind);
    d["ring"] = f.ring;
    d["vertex"] = optional_index(f.vertex);
    d["other_ring"] = optional_index(f.other_ring);
    d["other_vertex"] = optional_index(f.other_vertex);
    d["x"] = f.at.x;
    d["y"] = f.at.y;
    d["what"] = f.what;
    d["effect"] = f.effect;
    d["rejects"] = f.rejects;
    return d;
}

/// One report: accepted, rejection, total, counts by kind and the findings.
py::dict report_dict(const audit_report& r) {
    py::dict d;
    d["accepted"] = r.accepted;
    d["rejection"] = r.rejection;
    d["total"] = r.total;
    d["rings"] = r.rings;
    d["vertices"] = r.vertices;
    py::dict counts;
    for (std::size_t k = 0; k < finding_kind_count; ++k)
        if (r.counts[k] > 0) counts[finding_name(static_cast<finding_kind>(k))] = r.counts[k];
    d["counts"] = counts;
    py::list findings;
    for (const finding& f : r.findings) findings.append(finding_dict(f));
    d["findings"] = findings;
    return d;
}

py::list audit_many(const py::sequence& items, const std::string& name, std::size_t max_per_kind, long threads) {
    const unsigned t = threads_of(threads);
    std::vector<std::vector<wkt_ring>> rings(items.size());
    for (std::size_t k = 0; k < items.size(); ++k)
        rings[k] =
            rings_of(items[k], items.size() == 1 && name == "polygon" ? name : name + "[" + std::to_string(k) + "]");
    std::vector<audit_report> reports(rings.size());
    audit_options o;
    o.max_per_kind = max_per_kind;
    {
        py::gil_scoped_release release;
        run_in_blocks(rings.size(), t, [&](std::size_t first, std::size_t last) {
            for (std::size_t k = first; k < last; ++k) reports[k] = audit_rings(rings[k], o);
        });
    }
    py::list out;
    for (const audit_report& r : reports) out.append(report_dict(r));
    return out;
}

}  // namespace

void bind_audit(py::module_& m) {
    m.def("audit", &audit_many, py::arg("items"), py::arg("name"), py::arg("max_per_kind"), py::arg("threads"));
}

}  // namespace influence2d::python
