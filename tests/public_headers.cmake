# SPDX-License-Identifier: BSL-1.0
# The test public_headers: every header under include/ compiles on its own
# (a translation unit holding only its #include), with the developer
# warnings, so that a user may include any one of them first.
#
# Included at the end of tests/CMakeLists.txt, this file adds the test (not in
# the sanitizer build: the check is the same there). Run as a script, it is
# the test itself:
#   cmake -DCXX=... -DSOURCE_DIR=... -DWORK_DIR=... -P public_headers.cmake
if(CMAKE_SCRIPT_MODE_FILE)
    file(GLOB_RECURSE headers RELATIVE "${SOURCE_DIR}/include" "${SOURCE_DIR}/include/*.hpp")
    list(LENGTH headers count)
    if(count EQUAL 0)
        message(FATAL_ERROR "no header found under ${SOURCE_DIR}/include")
    endif()
    file(MAKE_DIRECTORY "${WORK_DIR}")
    set(failed "")
    foreach(header IN LISTS headers)
        set(unit "${WORK_DIR}/unit.cpp")
        file(WRITE "${unit}" "#include \"${header}\"\n")
        execute_process(COMMAND "${CXX}" -std=c++17 -fsyntax-only -Wall -Wextra -Wpedantic -Wshadow -Wconversion
            -Wno-sign-conversion -I "${SOURCE_DIR}/include" "${unit}"
            RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
        if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
            string(APPEND failed "${header}:\n${err}\n")
        endif()
    endforeach()
    if(NOT failed STREQUAL "")
        message(FATAL_ERROR "headers that do not compile alone without warnings:\n${failed}")
    endif()
    message(STATUS "${count} public headers compile alone")
    return()
endif()

if(NOT INFLUENCE2D_SANITIZE)
    add_test(NAME public_headers COMMAND ${CMAKE_COMMAND} -DCXX=${CMAKE_CXX_COMPILER} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
        -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/public_headers -P ${CMAKE_CURRENT_SOURCE_DIR}/public_headers.cmake)
endif()
