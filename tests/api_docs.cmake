# SPDX-License-Identifier: BSL-1.0
# The test api_docs: Doxygen runs over the public headers with docs/Doxyfile
# and must print no warning, so that every public entity outside the detail
# namespaces carries a comment and every comment parses. The reference it
# builds is left in <build>/tests/api_docs/html.
#
# Included at the end of tests/CMakeLists.txt, this file adds the test when
# doxygen is found. Run as a script, it is the test itself:
#   cmake -DDOXYGEN=... -DSOURCE_DIR=... -DOUTPUT_DIR=... -P api_docs.cmake
if(CMAKE_SCRIPT_MODE_FILE)
    file(REMOVE_RECURSE "${OUTPUT_DIR}")
    file(MAKE_DIRECTORY "${OUTPUT_DIR}")
    # docs/Doxyfile takes its output directory from the environment.
    set(ENV{INFLUENCE2D_DOCS_DIR} "${OUTPUT_DIR}")
    execute_process(COMMAND "${DOXYGEN}" docs/Doxyfile WORKING_DIRECTORY "${SOURCE_DIR}"
        RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    string(STRIP "${err}" err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "doxygen failed (${rc}):\n${out}\n${err}")
    endif()
    if(NOT err STREQUAL "")
        # Printed as they are (FATAL_ERROR would rewrap them), and kept.
        file(WRITE "${OUTPUT_DIR}/warnings.txt" "${err}\n")
        message("${err}")
        string(REGEX MATCHALL "warning:" found "${err}")
        list(LENGTH found count)
        message(FATAL_ERROR "doxygen printed ${count} warning(s), listed above and in ${OUTPUT_DIR}/warnings.txt")
    endif()
    message(STATUS "API reference without warnings: ${OUTPUT_DIR}/html/index.html")
    return()
endif()

# The headers are the same in every configuration: checked in the ordinary
# build only, not again in the sanitizer build.
find_package(Doxygen QUIET)
if(DOXYGEN_FOUND AND NOT INFLUENCE2D_SANITIZE)
    add_test(NAME api_docs COMMAND ${CMAKE_COMMAND} -DDOXYGEN=${DOXYGEN_EXECUTABLE}
        -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/api_docs
        -P ${CMAKE_CURRENT_LIST_FILE})
elseif(NOT DOXYGEN_FOUND)
    message(STATUS "doxygen not found: the test api_docs is not added")
endif()
