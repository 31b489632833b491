# Creates the imported target Distortion_optimization::CHOLMOD_support when SuiteSparse's CHOLMOD
# is found (Debian: libsuitesparse-dev, with libopenblas-dev as its BLAS and libmetis-dev for its
# ordering). A program linking it gets the define CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD:
# the package then factors the Newton systems of triangle maps, their harmonic and Tutte starts
# with CHOLMOD's supernodal Cholesky instead of Eigen's simplicial one (several times faster from
# some ten thousand vertices on). Every translation unit of a program must see the same choice.
include_guard(GLOBAL)

if(NOT TARGET Distortion_optimization::CHOLMOD_support)
  find_path(DISTORTION_OPTIMIZATION_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(DISTORTION_OPTIMIZATION_CHOLMOD_LIBRARY cholmod)
  find_library(DISTORTION_OPTIMIZATION_SUITESPARSECONFIG_LIBRARY suitesparseconfig)
  mark_as_advanced(DISTORTION_OPTIMIZATION_CHOLMOD_INCLUDE_DIR DISTORTION_OPTIMIZATION_CHOLMOD_LIBRARY
                   DISTORTION_OPTIMIZATION_SUITESPARSECONFIG_LIBRARY)
  if(DISTORTION_OPTIMIZATION_CHOLMOD_INCLUDE_DIR AND DISTORTION_OPTIMIZATION_CHOLMOD_LIBRARY
     AND DISTORTION_OPTIMIZATION_SUITESPARSECONFIG_LIBRARY)
    add_library(Distortion_optimization::CHOLMOD_support INTERFACE IMPORTED)
    set_target_properties(Distortion_optimization::CHOLMOD_support PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${DISTORTION_OPTIMIZATION_CHOLMOD_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES
        "${DISTORTION_OPTIMIZATION_CHOLMOD_LIBRARY};${DISTORTION_OPTIMIZATION_SUITESPARSECONFIG_LIBRARY}"
      INTERFACE_COMPILE_DEFINITIONS CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD)
  endif()
endif()
