# SPDX-License-Identifier: BSL-1.0
# Compile-fail tests: programs that misuse the library must be refused, and
# the first error the compiler prints must be the library's own static_assert
# naming the fix, not a missing member deep inside a template.
#
# Included at the end of tests/CMakeLists.txt, this file adds one test per
# case below. Run as a script, it is one test:
#   cmake -DCXX=... -DSOURCE_DIR=... -DUNIT=... -DEXPECT=... [-DDEFINES=...] -P compile_fail.cmake
# It passes when compiling UNIT fails and the compiler's first "error:" line
# contains EXPECT.
if(CMAKE_SCRIPT_MODE_FILE)
    set(flags -std=c++17 -fsyntax-only -I "${SOURCE_DIR}/include")
    foreach(define IN LISTS DEFINES)
        list(APPEND flags "-D${define}")
    endforeach()
    execute_process(COMMAND "${CXX}" ${flags} "${UNIT}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 0)
        message(FATAL_ERROR "${UNIT} compiled, but must not")
    endif()
    string(REGEX MATCH "error:[^\n]*" first "${err}")
    if(first STREQUAL "")
        message(FATAL_ERROR "${UNIT} failed without an error line:\n${err}")
    endif()
    string(FIND "${first}" "${EXPECT}" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "the first error does not say \"${EXPECT}\":\n${first}\n\nall the output:\n${err}")
    endif()
    message(STATUS "refused as expected: ${first}")
    return()
endif()

# Not in the sanitizer build: the check is the same there.
if(NOT INFLUENCE2D_SANITIZE)
    function(influence2d_compile_fail name unit expect)
        add_test(NAME compile_fail_${name} COMMAND ${CMAKE_COMMAND} -DCXX=${CMAKE_CXX_COMPILER}
            -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DUNIT=${CMAKE_CURRENT_LIST_DIR}/${unit} "-DEXPECT=${expect}"
            "-DDEFINES=${ARGN}" -P ${CMAKE_CURRENT_LIST_DIR}/compile_fail.cmake)
    endfunction()
    influence2d_compile_fail(number_traits unadapted_number_type.cpp "specialise influence2d::number_traits")
    influence2d_compile_fail(point_traits unadapted_point_type.cpp "specialise influence2d::point_traits")
    influence2d_compile_fail(point_traits_builder unadapted_point_type.cpp "specialise influence2d::point_traits"
        INFLUENCE2D_THROUGH_BUILDER)
endif()
