# SPDX-License-Identifier: BSL-1.0
# Flags for what this repository builds itself (tool, tests); never exported.
add_library(influence2d_developer_flags INTERFACE)
target_compile_options(influence2d_developer_flags INTERFACE
    -ffp-contract=off -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
# The library's internal invariants (INFLUENCE2D_ASSERT, assert.hpp) are
# checked in everything built with these flags.
target_compile_definitions(influence2d_developer_flags INTERFACE INFLUENCE2D_ENABLE_ASSERTS)
if(INFLUENCE2D_SANITIZE)
    target_compile_options(influence2d_developer_flags INTERFACE
        -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
        # GCC 12 under ASan reports a maybe-uninitialized std::pair inside CGAL's
        # Epic_converter (a known false positive in third-party code).
        -Wno-maybe-uninitialized)
    target_link_options(influence2d_developer_flags INTERFACE -fsanitize=address,undefined)
endif()
