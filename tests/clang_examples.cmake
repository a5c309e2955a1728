# SPDX-License-Identifier: BSL-1.0
# The test clang_examples: every example under tests/examples/ compiles with
# clang++ as well as with the build's compiler, in C++17 and C++20, with the
# developer warnings and none reported. The examples instantiate the
# library's templates as users do (clang checks a template's body as it
# instantiates it, even with -fsyntax-only), so a construct one compiler
# accepts and the other refuses fails here rather than in a user's build.
#
# Included at the end of tests/CMakeLists.txt, this file adds the test when
# clang++ is found (not in the sanitizer build: the check is the same there).
# Run as a script, it is the test itself:
#   cmake -DCLANGXX=... -DSOURCE_DIR=... -P clang_examples.cmake
if(CMAKE_SCRIPT_MODE_FILE)
    file(GLOB examples "${SOURCE_DIR}/tests/examples/*.cpp")
    list(LENGTH examples count)
    if(count EQUAL 0)
        message(FATAL_ERROR "no example found under ${SOURCE_DIR}/tests/examples")
    endif()
    set(failed "")
    foreach(standard IN ITEMS c++17 c++20)
        foreach(example IN LISTS examples)
            execute_process(COMMAND "${CLANGXX}" -std=${standard} -fsyntax-only -Wall -Wextra -Wpedantic -Wshadow
                -Wconversion -Wno-sign-conversion -I "${SOURCE_DIR}/include" "${example}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
            if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
                string(APPEND failed "${example} (-std=${standard}):\n${err}\n")
            endif()
        endforeach()
    endforeach()
    if(NOT failed STREQUAL "")
        message(FATAL_ERROR "examples that clang++ refuses or warns about:\n${failed}")
    endif()
    message(STATUS "${count} examples compile with ${CLANGXX} in C++17 and C++20 without warnings")
    return()
endif()

find_program(INFLUENCE2D_CLANGXX NAMES clang++-14 clang++)
if(NOT INFLUENCE2D_CLANGXX)
    message(STATUS "influence2d: clang++ not found: the test clang_examples is left out")
elseif(NOT INFLUENCE2D_SANITIZE)
    add_test(NAME clang_examples COMMAND ${CMAKE_COMMAND} -DCLANGXX=${INFLUENCE2D_CLANGXX}
        -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/clang_examples.cmake)
endif()
