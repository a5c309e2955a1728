# SPDX-License-Identifier: BSL-1.0
# The test public_headers: every header under include/ compiles on its own
# (a translation unit holding only its #include), with the developer
# warnings, so that a user may include any one of them first; and each pulls
# in no third-party header beyond what it promises. The target
# influence2d::influence2d carries the standard library alone: a header
# that reaches CGAL, GMP, MPFR or Boost from the compiler's search path
# (where Debian puts them, so that compiling would not notice) fails unless
# it is one of
#   number/cgal.hpp, adapters/cgal.hpp, exact/*     CGAL (and its GMP, MPFR, Boost)
#   number/multiprecision.hpp, io/*, audit/*,
#   adapters/boost_geometry.hpp                     Boost's headers
# (the dependencies of the targets influence2d::cgal and Boost::headers).
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
            -Wno-sign-conversion -MD -MF "${WORK_DIR}/unit.d" -I "${SOURCE_DIR}/include" "${unit}"
            RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
        if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
            string(APPEND failed "${header}:\n${err}\n")
            continue()
        endif()
        # What the header may reach beyond the standard library.
        if(header MATCHES "^influence2d/(number/cgal|adapters/cgal|exact/[a-z_]+)\\.hpp$")
            set(allowed "CGAL|boost|gmp|mpfr")
        elseif(header MATCHES "^influence2d/(number/multiprecision|io/[a-z_]+|audit/[a-z_]+|adapters/boost_geometry)\\.hpp$")
            set(allowed "boost")
        else()
            set(allowed "")
        endif()
        file(READ "${WORK_DIR}/unit.d" deps)
        string(REGEX MATCHALL "/(CGAL|boost|gmp[a-z]*|mpfr[a-z0-9]*)[/.]" reached "${deps}")
        set(libraries "")
        foreach(dependency IN LISTS reached)
            string(REGEX REPLACE "^/([a-zA-Z0-9]+)[/.]$" "\\1" dependency "${dependency}")
            string(REGEX REPLACE "^(gmp|mpfr)[a-z0-9]*$" "\\1" dependency "${dependency}")
            list(APPEND libraries "${dependency}")
        endforeach()
        list(REMOVE_DUPLICATES libraries)
        foreach(dependency IN LISTS libraries)
            if(allowed STREQUAL "" OR NOT dependency MATCHES "^(${allowed})$")
                string(APPEND failed "${header}: includes ${dependency}'s headers, which it does not promise\n")
            endif()
        endforeach()
    endforeach()
    if(NOT failed STREQUAL "")
        message(FATAL_ERROR "headers that do not compile alone without warnings, or reach what they do not promise:\n${failed}")
    endif()
    message(STATUS "${count} public headers compile alone and reach only what they promise")
    return()
endif()

if(NOT INFLUENCE2D_SANITIZE)
    add_test(NAME public_headers COMMAND ${CMAKE_COMMAND} -DCXX=${CMAKE_CXX_COMPILER} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
        -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/public_headers -P ${CMAKE_CURRENT_SOURCE_DIR}/public_headers.cmake)
endif()
