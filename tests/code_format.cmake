# SPDX-License-Identifier: BSL-1.0
# The test code_format: every C++ file of the project is as clang-format
# leaves it with the project's .clang-format (added when clang-format is
# found). Run as a script, it is the test itself:
#   cmake -DCLANG_FORMAT=... -DSOURCE_DIR=... -P code_format.cmake
if(CMAKE_SCRIPT_MODE_FILE)
    file(GLOB_RECURSE sources RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/include/*.hpp" "${SOURCE_DIR}/src/*.hpp"
        "${SOURCE_DIR}/src/*.cpp" "${SOURCE_DIR}/verification/*.hpp" "${SOURCE_DIR}/verification/*.cpp"
        "${SOURCE_DIR}/tests/*.hpp" "${SOURCE_DIR}/tests/*.cpp" "${SOURCE_DIR}/fuzz/*.cpp"
        "${SOURCE_DIR}/scripts/*.cpp" "${SOURCE_DIR}/python/*.hpp" "${SOURCE_DIR}/python/*.cpp")
    list(LENGTH sources count)
    if(count EQUAL 0)
        message(FATAL_ERROR "no C++ file found under ${SOURCE_DIR}")
    endif()
    execute_process(COMMAND "${CLANG_FORMAT}" --dry-run --Werror ${sources} WORKING_DIRECTORY "${SOURCE_DIR}"
        RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "files not as clang-format leaves them (clang-format -i FILE mends them):\n${err}")
    endif()
    message(STATUS "${count} C++ files as clang-format leaves them")
    return()
endif()

find_program(INFLUENCE2D_CLANG_FORMAT NAMES clang-format-14 clang-format)
if(INFLUENCE2D_CLANG_FORMAT AND NOT INFLUENCE2D_SANITIZE)
    add_test(NAME code_format COMMAND ${CMAKE_COMMAND} -DCLANG_FORMAT=${INFLUENCE2D_CLANG_FORMAT}
        -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/code_format.cmake)
else()
    message(STATUS "influence2d: clang-format not found: the test code_format is left out")
endif()
