# SPDX-License-Identifier: BSL-1.0
# The test header_layers: the library's headers include downwards only, and
# every detail namespace is used in its own file alone (docs/architecture.md
# draws the layers).
#
# Layers, lowest first; a header may include headers of a lower layer, or of
# its own directory:
#    0  assert.hpp, version.hpp
#    1  number/       number types, their traits, the filter's fallback
#    2  core/         point, box, polygon, pose, feature, invalid_input, prefetch, shortest_decimal
#    3  predicates/   every sign decision
#    4  covering/     triangle covering, point location
#    5  influence/    influence areas, extended areas, bounds, edge grid and tree
#    6  scene/        prepared polygons, polygons placed in a frame
#    7  detect/       frame detectors with state, their results
#    8  query/        one-shot questions, both posed, batches
#    9  distance/     separation and closest features
#   10  motion/       first contact, exit distance, pose generators
#   11  exact/        the filtered, certified and interval entry points
#   12  io/, adapters/
#   13  audit/
#   14  influence2d.hpp (the umbrella)
#
# Included at the end of tests/CMakeLists.txt, this file adds the test. Run
# as a script, it is the test itself:
#   cmake -DSOURCE_DIR=... -P header_layers.cmake
if(CMAKE_SCRIPT_MODE_FILE)
    set(layer_names "assert;version;number;core;predicates;covering;influence;scene;detect;query;distance;motion;world;exact;io;adapters;audit;influence2d")
    set(layer_ranks "0;0;1;2;3;4;5;6;7;8;9;10;11;12;13;13;14;15")
    # The layer of a header path relative to include/influence2d/: its
    # directory, or its stem for the top-level headers.
    function(layer_of path out)
        string(REGEX REPLACE "^([a-z0-9_]+)[/.].*$" "\\1" name "${path}")
        list(FIND layer_names "${name}" index)
        if(index EQUAL -1)
            set(${out} "" PARENT_SCOPE)
        else()
            list(GET layer_ranks ${index} rank)
            set(${out} "${rank}" PARENT_SCOPE)
        endif()
    endfunction()

    file(GLOB_RECURSE headers RELATIVE "${SOURCE_DIR}/include/influence2d" "${SOURCE_DIR}/include/influence2d/*.hpp")
    list(LENGTH headers count)
    if(count EQUAL 0)
        message(FATAL_ERROR "no header found under ${SOURCE_DIR}/include/influence2d")
    endif()
    set(failed "")
    set(edges 0)
    foreach(header IN LISTS headers)
        layer_of("${header}" rank)
        if(rank STREQUAL "")
            string(APPEND failed "${header}: in no layer (add its directory to header_layers.cmake and docs/architecture.md)\n")
            continue()
        endif()
        string(REGEX REPLACE "/[^/]*$" "" directory "${header}")
        file(STRINGS "${SOURCE_DIR}/include/influence2d/${header}" includes REGEX "^#include [\"<]influence2d/")
        foreach(line IN LISTS includes)
            string(REGEX REPLACE "^#include [\"<]influence2d/([^\">]+)[\">].*$" "\\1" target "${line}")
            math(EXPR edges "${edges} + 1")
            layer_of("${target}" target_rank)
            string(REGEX REPLACE "/[^/]*$" "" target_directory "${target}")
            if(target_rank STREQUAL "")
                string(APPEND failed "${header}: includes ${target}, in no layer\n")
            elseif(NOT target_rank LESS rank AND NOT (target_directory STREQUAL directory AND header MATCHES "/"))
                string(APPEND failed "${header} (layer ${rank}): includes ${target} (layer ${target_rank}), not below it\n")
            endif()
        endforeach()
    endforeach()

    # Detail namespaces: NAME_detail:: only in the file that opens namespace NAME_detail.
    set(detail_uses 0)
    file(GLOB_RECURSE sources "${SOURCE_DIR}/include/*.hpp" "${SOURCE_DIR}/src/*.hpp" "${SOURCE_DIR}/src/*.cpp"
        "${SOURCE_DIR}/verification/*.hpp" "${SOURCE_DIR}/verification/*.cpp" "${SOURCE_DIR}/tests/*.hpp"
        "${SOURCE_DIR}/tests/*.cpp" "${SOURCE_DIR}/fuzz/*.cpp")
    foreach(source IN LISTS sources)
        file(READ "${source}" text)
        string(REGEX MATCHALL "[A-Za-z0-9_]*detail::" used "${text}")
        list(REMOVE_DUPLICATES used)
        foreach(namespace IN LISTS used)
            math(EXPR detail_uses "${detail_uses} + 1")
            string(REGEX REPLACE "::$" "" namespace "${namespace}")
            if(NOT text MATCHES "namespace (influence2d::)?${namespace} {")
                file(RELATIVE_PATH where "${SOURCE_DIR}" "${source}")
                string(APPEND failed "${where}: uses ${namespace}::, a detail namespace of another file\n")
            endif()
        endforeach()
    endforeach()

    if(NOT failed STREQUAL "")
        message(FATAL_ERROR "the layers are broken:\n${failed}")
    endif()
    message(STATUS "${count} headers, ${edges} includes, all downwards; ${detail_uses} detail namespace uses, each in its own file")
    return()
endif()

add_test(NAME header_layers COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/header_layers.cmake)
