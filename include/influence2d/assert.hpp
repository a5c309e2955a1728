// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// INFLUENCE2D_ASSERT: the library's internal invariants, checked only when
/// INFLUENCE2D_ENABLE_ASSERTS is defined. The repository's tests and tool
/// define it (cmake/developer_flags.cmake); a user's build compiles every
/// assertion to nothing unless it defines the macro too. An assertion guards
/// a state the library itself must never reach (an index out of its range, a
/// ring stored the wrong way round): invalid input is reported by exceptions
/// (invalid_input), never by an assertion.

#include <cstdio>
#include <cstdlib>

namespace influence2d::assert_detail {

/// Prints "file:line: influence2d assertion `condition' failed: message" to
/// stderr and aborts: the failure of an INFLUENCE2D_ASSERT.
[[noreturn]] inline void assertion_failed(const char* condition, const char* message, const char* file,
                                          int line) noexcept {
    std::fprintf(stderr, "%s:%d: influence2d assertion `%s' failed: %s\n", file, line, condition, message);
    std::fflush(stderr);
    std::abort();
}

}  // namespace influence2d::assert_detail

#if defined(INFLUENCE2D_ENABLE_ASSERTS)
/// Checks the invariant `cond` (anything convertible to bool); when it is
/// false, prints the file, the line, `cond` and `message` (a C string) to
/// stderr and aborts. Without INFLUENCE2D_ENABLE_ASSERTS, `cond` is neither
/// evaluated nor costs anything, but must still compile.
#define INFLUENCE2D_ASSERT(cond, message)           \
    (static_cast<bool>(cond) ? static_cast<void>(0) \
                             : ::influence2d::assert_detail::assertion_failed(#cond, message, __FILE__, __LINE__))
#else
/// Checks the invariant `cond` when INFLUENCE2D_ENABLE_ASSERTS is defined;
/// here it is not, so `cond` is only type-checked (in an unevaluated
/// operand) and `message` ignored.
#define INFLUENCE2D_ASSERT(cond, message) static_cast<void>(sizeof(static_cast<bool>(cond)))
#endif
