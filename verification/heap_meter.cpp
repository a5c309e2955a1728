// SPDX-License-Identifier: BSL-1.0
// The counting allocators behind verification/heap_meter.hpp: the global
// operator new / delete of the tool, and GMP's memory functions. Blocks are
// measured with malloc_usable_size, so a block freed after stop() or allocated
// before start() cannot unbalance the count beyond clamping at zero.

#include <gmp.h>
#include <malloc.h>

#include <cstdlib>
#include <cstring>
#include <new>

#include "verification/heap_meter.hpp"

namespace {

bool counting = false;
std::size_t live = 0, peak = 0;

void on_alloc(void* p) {
    if (!counting || !p) return;
    live += malloc_usable_size(p);
    if (live > peak) peak = live;
}

void on_free(void* p) {
    if (!counting || !p) return;
    const std::size_t n = malloc_usable_size(p);
    live = live > n ? live - n : 0;
}

void* allocate(std::size_t n) {
    void* p = std::malloc(n ? n : 1);
    if (!p) throw std::bad_alloc();
    on_alloc(p);
    return p;
}

void* allocate_aligned(std::size_t n, std::align_val_t a) {
    const std::size_t align = static_cast<std::size_t>(a);
    void* p = std::aligned_alloc(align, (n + align - 1) / align * align);
    if (!p) throw std::bad_alloc();
    on_alloc(p);
    return p;
}

void release(void* p) {
    on_free(p);
    std::free(p);
}

void* gmp_allocate(std::size_t n) {
    void* p = std::malloc(n);
    if (!p) std::abort();  // GMP's own behaviour on exhaustion
    on_alloc(p);
    return p;
}

void* gmp_reallocate(void* p, std::size_t, std::size_t n) {
    on_free(p);
    void* q = std::realloc(p, n);
    if (!q) std::abort();
    on_alloc(q);
    return q;
}

void gmp_release(void* p, std::size_t) { release(p); }

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return allocate(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return allocate(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new(std::size_t n, std::align_val_t a) { return allocate_aligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate_aligned(n, a); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }

namespace influence2d::verification {

bool heap_meter::available() { return true; }

void heap_meter::start() {
    static const bool gmp_hooked = [] {
        mp_set_memory_functions(&gmp_allocate, &gmp_reallocate, &gmp_release);
        return true;
    }();
    (void)gmp_hooked;
    live = 0;
    peak = 0;
    counting = true;
}

std::size_t heap_meter::stop() {
    counting = false;
    return peak;
}

}  // namespace influence2d::verification
