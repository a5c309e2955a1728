// SPDX-License-Identifier: BSL-1.0
// libFuzzer target: the WKT reader and the audit on arbitrary text. Either
// refuses with invalid_input or returns; an accepted polygon is written back
// and must read back to the same vertices.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "influence2d/audit/audit.hpp"
#include "influence2d/io/wkt.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace influence2d;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)audit_rings(read_wkt_rings(text, "<fuzz>"));
    } catch (const invalid_input&) {}
    try {
        const polygon p = read_wkt(text, "<fuzz>");
        const polygon q = read_wkt(to_wkt(p), "<round trip>");
        if (q.vertices() != p.vertices()) std::abort();
    } catch (const invalid_input&) {}
    return 0;
}
