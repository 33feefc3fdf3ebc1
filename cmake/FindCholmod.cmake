# CHOLMOD (SuiteSparse) and METIS for the sparse Cholesky factorizations of core/skeleton
# (mesh contraction and bone-heat weights), used through Eigen's CholmodSupport and
# MetisSupport. Debian 12's libsuitesparse-dev ships headers under include/suitesparse and
# no CMake package for CHOLMOD alone, so this module finds the shared libraries directly.
# Provides SuiteSparse::CHOLMOD and METIS::METIS.
find_path(Cholmod_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(Cholmod_LIBRARY cholmod)
find_library(Cholmod_SUITESPARSECONFIG_LIBRARY suitesparseconfig)
find_path(Metis_INCLUDE_DIR metis.h)
find_library(Metis_LIBRARY metis)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Cholmod REQUIRED_VARS Cholmod_LIBRARY Cholmod_INCLUDE_DIR
  Cholmod_SUITESPARSECONFIG_LIBRARY Metis_LIBRARY Metis_INCLUDE_DIR)

if(Cholmod_FOUND AND NOT TARGET SuiteSparse::CHOLMOD)
  add_library(SuiteSparse::CHOLMOD SHARED IMPORTED)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${Cholmod_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Cholmod_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${Cholmod_SUITESPARSECONFIG_LIBRARY}")
endif()
if(Cholmod_FOUND AND NOT TARGET METIS::METIS)
  add_library(METIS::METIS SHARED IMPORTED)
  set_target_properties(METIS::METIS PROPERTIES
    IMPORTED_LOCATION "${Metis_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Metis_INCLUDE_DIR}")
endif()
mark_as_advanced(Cholmod_INCLUDE_DIR Cholmod_LIBRARY Cholmod_SUITESPARSECONFIG_LIBRARY Metis_INCLUDE_DIR Metis_LIBRARY)
