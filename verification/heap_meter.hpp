// SPDX-License-Identifier: BSL-1.0
#pragma once
// Heap use of a piece of work: the bytes allocated through the global
// operator new (C++ code: the library, CGAL, Boost.Geometry, GEOS) and through
// GMP (CGAL's exact numbers) while the meter is on, and their peak.
//
// The counting operator new / delete live in verification/heap_meter.cpp
// (the library influence2d_peers), linked into influence2d-bench and the
// tests that ask for them; elsewhere heap_meter::available() is false and
// nothing is counted. Off, the count costs one branch per allocation.

#include <cstddef>

namespace influence2d::verification {

struct heap_meter {
    /// Whether counting allocators are linked into this program.
    static bool available();
    /// Starts counting from zero bytes live; the peak is reset.
    static void start();
    /// Stops counting; returns the peak of live bytes since start().
    static std::size_t stop();
};

}  // namespace influence2d::verification
