# SPDX-License-Identifier: BSL-1.0
# The test package_consumer: installs the library from BUILD_DIR into a fresh
# prefix under WORK_DIR, then configures, builds and runs tests/consumer three
# ways (find_package of the installed package, add_subdirectory, FetchContent),
# and compiles the README's example and the adapter use with the flags and
# libraries pkg-config gives.
#   cmake -DSOURCE_DIR=... -DBUILD_DIR=... -DWORK_DIR=... -DCXX=... -P run.cmake
function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
    endif()
    set(run_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f include/influence2d/influence2d.hpp share/cmake/influence2d/influence2dConfig.cmake
        share/cmake/influence2d/influence2dConfigVersion.cmake share/pkgconfig/influence2d.pc)
    if(NOT EXISTS ${prefix}/${f})
        message(FATAL_ERROR "not installed: ${f}")
    endif()
endforeach()

foreach(use package subdirectory fetchcontent)
    set(dir ${WORK_DIR}/${use})
    run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${dir} -DCMAKE_BUILD_TYPE=Release
        -DCMAKE_CXX_COMPILER=${CXX} -DINFLUENCE2D_USE=${use} -DINFLUENCE2D_SOURCE=${SOURCE_DIR}
        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
    run(${CMAKE_COMMAND} --build ${dir})
    run(${dir}/readme_example)
    if(NOT run_output MATCHES "x = 3.0  collides = 1")
        message(FATAL_ERROR "${use}: unexpected output of readme_example:\n${run_output}")
    endif()
    run(${dir}/exact_mode)
    message(STATUS "${use}: ${run_output}")
    run(${dir}/adapters)
    message(STATUS "${use}: ${run_output}")
endforeach()

find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG)
    set(ENV{PKG_CONFIG_PATH} ${prefix}/share/pkgconfig)
    run(${PKG_CONFIG} --cflags influence2d)
    string(STRIP "${run_output}" cflags)
    separate_arguments(cflags UNIX_COMMAND "${cflags}")
    run(${PKG_CONFIG} --libs influence2d)
    string(STRIP "${run_output}" libs)
    separate_arguments(libs UNIX_COMMAND "${libs}")
    run(${CXX} ${cflags} ${SOURCE_DIR}/tests/examples/readme_example.cpp ${libs} -o ${WORK_DIR}/readme_example_pc)
    run(${WORK_DIR}/readme_example_pc)
    message(STATUS "pkg-config: ${run_output}")
    run(${CXX} ${cflags} ${SOURCE_DIR}/tests/consumer/adapters.cpp ${libs} -o ${WORK_DIR}/adapters_pc)
    run(${WORK_DIR}/adapters_pc)
    message(STATUS "pkg-config: ${run_output}")
else()
    message(STATUS "pkg-config not found: the pkg-config file is installed but not tried")
endif()
