# The installed package as an outside project sees it (ctest runs this with cmake -P):
#   1. `cmake --install` the build into WORK/installed, then move it to WORK/prefix (the package
#      must not depend on where it was installed);
#   2. configure and build examples/embedded against it with find_package(sled);
#   3. run the flagship through the library API (run_scene) and through the installed `sled`,
#      and check both write the same timeseries.csv, byte for byte, as the build tree's `sled`;
#   4. build and run the C++-built scene (frontal_sled_builder --run);
#   5. check the installed `sled` reads its standard library from PREFIX/share/sled/stdlib.
# Variables: BUILD_DIR, SOURCE_DIR, WORK_DIR, GENERATOR, CXX_COMPILER, LAUNCHER (may be empty),
# SLED (the build tree's program).
cmake_minimum_required(VERSION 3.22)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "install test: ${what} failed (${status}):\n${out}\n${err}")
  endif()
  set(run_out "${out}" PARENT_SCOPE)
  set(run_err "${err}" PARENT_SCOPE)
endfunction()

function(expect_same_file first second)
  file(SHA256 "${first}" a)
  file(SHA256 "${second}" b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "install test: ${first} and ${second} differ")
  endif()
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
run("cmake --install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/installed")
file(RENAME "${WORK_DIR}/installed" "${prefix}")
foreach(file bin/sled include/sled/sled.h include/sled/runtime/model/model.h
             include/sled/lang/diagnostics/diagnostic_kinds.def lib/cmake/sled/sledConfig.cmake
             share/sled/stdlib/humans/male50.sled)
  if(NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "install test: the install has no ${file}")
  endif()
endforeach()

set(configure "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/examples/embedded" -B "${WORK_DIR}/build"
    -G "${GENERATOR}" "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
if(LAUNCHER)
  list(APPEND configure "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
endif()
run("configuring examples/embedded against the install" ${configure})
run("building examples/embedded" "${CMAKE_COMMAND}" --build "${WORK_DIR}/build")

set(flagship "${SOURCE_DIR}/examples/frontal_sled.sled")
run("run_scene on the flagship" "${WORK_DIR}/build/run_scene" "${flagship}" "${WORK_DIR}/api")
if(NOT run_out MATCHES "hic15\\(occupant.head\\) = ")
  message(FATAL_ERROR "install test: run_scene printed no HIC:\n${run_out}")
endif()
run("the installed sled on the flagship" "${prefix}/bin/sled" run "${flagship}" -o
    "${WORK_DIR}/installed_sled")
run("the build tree's sled on the flagship" "${SLED}" run "${flagship}" -o "${WORK_DIR}/tree_sled")
expect_same_file("${WORK_DIR}/api/timeseries.csv" "${WORK_DIR}/tree_sled/timeseries.csv")
expect_same_file("${WORK_DIR}/installed_sled/timeseries.csv" "${WORK_DIR}/tree_sled/timeseries.csv")

run("frontal_sled_builder --run" "${WORK_DIR}/build/frontal_sled_builder" --run
    "${WORK_DIR}/builder")
if(NOT run_out MATCHES "scenario \"frontal sled" OR NOT EXISTS "${WORK_DIR}/builder/summary.json")
  message(FATAL_ERROR "install test: frontal_sled_builder printed no scene or wrote no run")
endif()

# The installed sled's standard library is the one beside it: a missing module names its path.
file(WRITE "${WORK_DIR}/missing.sled"
     "scenario \"s\" {\n  import std.no_such_module as x\n  time { end = 1 ms }\n}\n")
execute_process(COMMAND "${prefix}/bin/sled" check "${WORK_DIR}/missing.sled"
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
string(FIND "${err}" "${prefix}/share/sled/stdlib/no_such_module.sled" at)
if(NOT status EQUAL 1 OR at EQUAL -1)
  message(FATAL_ERROR "install test: the installed sled does not look in its own share/sled "
                      "(exit ${status}):\n${err}")
endif()
message(STATUS "install test: passed in ${WORK_DIR}")
