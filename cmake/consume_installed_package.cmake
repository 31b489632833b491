# Run with cmake -P. Installs the build tree into a fresh prefix, then configures, builds and runs
# an outside project that does find_package(Distortion_optimization REQUIRED).
# Inputs (-D): BUILD_DIR, PREFIX, CONSUMER_SOURCE_DIR, CONSUMER_BINARY_DIR, GENERATOR,
#              CXX_COMPILER, and optionally CONFIG, CXX_COMPILER_LAUNCHER.
cmake_minimum_required(VERSION 3.16)

foreach(var BUILD_DIR PREFIX CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "consume_installed_package: -D${var}=... is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()
# The consumer is built as a user's debug build: CGAL's and Eigen's assertions on (the package's
# own builds are Release; c3t3_from_tetrahedra() once failed an assertion of CGAL's there).
set(CONSUMER_CONFIG Debug)

function(run_step what)
  message(STATUS "consume_installed_package: ${what}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "consume_installed_package: ${what} failed (${result})")
  endif()
endfunction()

file(REMOVE_RECURSE "${PREFIX}" "${CONSUMER_BINARY_DIR}")

run_step("install into ${PREFIX}"
  "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}" --config "${CONFIG}")

set(launcher_arg "")
if(CXX_COMPILER_LAUNCHER)
  set(launcher_arg "-DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_COMPILER_LAUNCHER}")
endif()
run_step("configure the consumer"
  "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${CONSUMER_BINARY_DIR}"
  -G "${GENERATOR}"
  "-DCMAKE_BUILD_TYPE=${CONSUMER_CONFIG}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
  ${launcher_arg}
  "-DCMAKE_PREFIX_PATH=${PREFIX}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)

run_step("build the consumer"
  "${CMAKE_COMMAND}" --build "${CONSUMER_BINARY_DIR}" --config "${CONSUMER_CONFIG}")

set(exe "${CONSUMER_BINARY_DIR}/consumer")
if(NOT EXISTS "${exe}" AND EXISTS "${CONSUMER_BINARY_DIR}/${CONSUMER_CONFIG}/consumer")
  set(exe "${CONSUMER_BINARY_DIR}/${CONSUMER_CONFIG}/consumer")
endif()
run_step("run the consumer" "${exe}")
