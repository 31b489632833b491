# Helpers for the test, example and benchmark subdirectories of Distortion_optimization.
#
#   distortion_add_test(NAME src... [LIBRARIES lib...])
#   distortion_add_example(NAME src... [LIBRARIES lib...])
#   distortion_add_benchmark(NAME src... [LIBRARIES lib...])
#   distortion_add_tool(NAME src... [LIBRARIES lib...])
#   distortion_add_library(NAME src...)   a static library the above may link
#
# Each creates the executable target NAME linking CGAL::Distortion_optimization (plus
# CGAL::TBB_support and the define DISTORTION_OPTIMIZATION_HAS_TBB when TBB was found, and
# Distortion_optimization::CHOLMOD_support when CHOLMOD was found, unless NAME ends in
# _without_cholmod), with
# -Wall -Wextra -Wno-maybe-uninitialized and DISTORTION_OPTIMIZATION_DATA_DIR="<build>/data" (tests and
# examples at -O2 in Release). Optional LIBRARIES are linked
# PRIVATE (e.g. Distortion_optimization::TetGen, guarded by if(TARGET ...)).
# Binaries land at fixed paths, whatever the generator or the calling directory:
#   tests       <build>/test/Distortion_optimization/NAME
#   examples    <build>/examples/Distortion_optimization/NAME
#   benchmarks  <build>/benchmark/Distortion_optimization/NAME
#   tools       <build>/bin/NAME

include_guard(GLOBAL)

# Links `name` to the package (and to TBB, with its define), with the package's warnings; `scope`
# is PRIVATE for a program, PUBLIC for a library whose users must see the same types.
function(_distortion_link_package name scope)
  target_link_libraries(${name} ${scope} CGAL::Distortion_optimization)
  if(TARGET CGAL::TBB_support)
    target_link_libraries(${name} ${scope} CGAL::TBB_support)
    target_compile_definitions(${name} ${scope} DISTORTION_OPTIMIZATION_HAS_TBB)
  endif()
  if(TARGET Distortion_optimization::CHOLMOD_support AND NOT name MATCHES "_without_cholmod$")
    target_link_libraries(${name} ${scope} Distortion_optimization::CHOLMOD_support)
  endif()
  target_compile_options(${name} PRIVATE
    "$<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-Wall;-Wextra;-Wno-maybe-uninitialized>")
endfunction()

function(_distortion_setup_target name output_subdir)
  _distortion_link_package(${name} PRIVATE)
  target_compile_definitions(${name} PRIVATE
    "DISTORTION_OPTIMIZATION_DATA_DIR=\"${DISTORTION_OPTIMIZATION_DATA_DIR}\"")
  # The "$<0:>" generator expression stops multi-config generators from appending a
  # per-configuration subdirectory, so the binary path is the same everywhere.
  set_target_properties(${name} PROPERTIES
    RUNTIME_OUTPUT_DIRECTORY "${PROJECT_BINARY_DIR}/${output_subdir}$<0:>")
endfunction()

# The body of the functions below: the executable NAME from the sources, set up for `subdir`.
function(_distortion_add_executable name subdir)
  cmake_parse_arguments(PARSE_ARGV 2 ARG "" "" "LIBRARIES")
  if(NOT ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${name}: no source files")
  endif()
  add_executable(${name} ${ARG_UNPARSED_ARGUMENTS})
  _distortion_setup_target(${name} ${subdir})
  target_link_libraries(${name} PRIVATE ${ARG_LIBRARIES})
endfunction()

# Tests and examples spend their run time in the shared instantiations and the static libraries,
# compiled at the build type's level (-O3 in Release); their own files compile about a fifth faster
# at -O2.
function(_distortion_optimize_less name)
  target_compile_options(${name} PRIVATE
    "$<$<AND:$<CONFIG:Release>,$<CXX_COMPILER_ID:GNU,Clang,AppleClang>>:-O2>")
endfunction()

function(distortion_add_test name)
  _distortion_add_executable(${name} test/Distortion_optimization ${ARGN})
  _distortion_optimize_less(${name})
  target_link_libraries(${name} PRIVATE GTest::gtest_main)
  # The GoogleTest tests share the temporary folder (and some check what is left in it): one at a
  # time, while `ctest -j` runs the others (the installed-package build, the examples) beside them.
  gtest_discover_tests(${name}
    WORKING_DIRECTORY "${PROJECT_BINARY_DIR}/test/Distortion_optimization"
    DISCOVERY_TIMEOUT 60
    PROPERTIES RESOURCE_LOCK distortion_temporary_folder
               # CHOLMOD's BLAS threads spin while they wait: beside the other tests of `ctest -j`
               # they would slow every factorization down.
               ENVIRONMENT OPENBLAS_NUM_THREADS=1)
endfunction()

function(distortion_add_example name)
  _distortion_add_executable(${name} examples/Distortion_optimization ${ARGN})
  _distortion_optimize_less(${name})
endfunction()

function(distortion_add_benchmark name)
  _distortion_add_executable(${name} benchmark/Distortion_optimization ${ARGN})
  target_link_libraries(${name} PRIVATE benchmark::benchmark)
endfunction()

function(distortion_add_tool name)
  _distortion_add_executable(${name} bin ${ARGN})
endfunction()

# A static library of compiled templates for the programs above: linked to the package (and TBB,
# with its define, PUBLIC: the programs that link it must see the same types).
function(distortion_add_library name)
  add_library(${name} STATIC ${ARGN})
  _distortion_link_package(${name} PUBLIC)
endfunction()
