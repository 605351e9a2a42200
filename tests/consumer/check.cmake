# Run by CTest (tests/CMakeLists.txt) with cmake -P. Builds tests/consumer as a separate
# project, with the compiler, launcher, generator and build type of drange's own build.
#   MODE=find_package      installs drange's build tree (every component) into WORK/prefix,
#                          checks the installed command runs, then configures the consumer
#                          with find_package against that prefix, builds it and runs it.
#   MODE=add_subdirectory  configures the consumer with add_subdirectory on the source tree
#                          and checks that drange's tests and Python module stay out of it.
#                          It stops there: building would compile the whole library again.
# Inputs: MODE, SOURCE_DIR, BUILD_DIR (drange's), WORK (a scratch folder, emptied first),
# GENERATOR, CXX_COMPILER, CXX_LAUNCHER, BUILD_TYPE.
cmake_minimum_required(VERSION 3.20)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    list(JOIN ARGN " " command)
    message(FATAL_ERROR "failed (${rc}): ${command}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK})
set(consumer_build ${WORK}/build)
set(configure ${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR} -B ${consumer_build} -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER}
    -DCMAKE_BUILD_TYPE=${BUILD_TYPE})

if(MODE STREQUAL "find_package")
  set(prefix ${WORK}/prefix)
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  run(${prefix}/bin/drange --version)
  # Only the scratch prefix may provide the package, not an earlier install elsewhere.
  run(${configure} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
  file(STRINGS ${consumer_build}/CMakeCache.txt found REGEX "^drange_DIR:")
  string(FIND "${found}" "drange_DIR:PATH=${prefix}/" at)
  if(NOT at EQUAL 0)
    message(FATAL_ERROR "the package was not taken from ${prefix}: ${found}")
  endif()
  run(${CMAKE_COMMAND} --build ${consumer_build} -j2)
  run(${consumer_build}/consumer)
elseif(MODE STREQUAL "add_subdirectory")
  run(${configure} -DDRANGE_SOURCE_DIR=${SOURCE_DIR})
  foreach(option DRANGE_BUILD_TESTS DRANGE_BUILD_PYTHON DRANGE_INSTALL)
    file(STRINGS ${consumer_build}/CMakeCache.txt value REGEX "^${option}:BOOL=")
    if(NOT value STREQUAL "${option}:BOOL=OFF")
      message(FATAL_ERROR "${option} should default to OFF under add_subdirectory: '${value}'")
    endif()
  endforeach()
else()
  message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()
