// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether the processor may fetch memory that a loop will read a few items
/// later: a hint, never a read, and never a change to any answer.

namespace influence2d {

/// Asks the processor to bring the cache line that holds `at` into its
/// caches, without waiting for it (GCC's and Clang's __builtin_prefetch; no
/// effect with other compilers). `at` need not point to valid memory: a
/// prefetch never faults. Loops over many bodies whose data lies anywhere in
/// memory ask for an item's data a few items ahead, each read once the read
/// it depends on was asked for (world.hpp).
inline void prefetch(const void* at) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(at);
#else
    (void)at;
#endif
}

}  // namespace influence2d
