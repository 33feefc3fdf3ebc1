# Debian 12's OpenSubdivConfig.cmake references static archives (libosdCPU.a) that the
# libosd-dev package does not ship, so find_package(OpenSubdiv CONFIG) fails there.
# This module finds the shared libraries and headers directly and provides
# OpenSubdiv::osdCPU (Far: refinement, stencil tables) and OpenSubdiv::osdGPU (Osd's
# OpenGL evaluators, render/frame/gpu_subdivision.h). libosdGPU loads its GL functions
# itself, at run time, from libGL.so.1 through glXGetProcAddressARB: it links no GL library.
find_path(OpenSubdiv_INCLUDE_DIR opensubdiv/version.h)
find_library(OpenSubdiv_osdCPU_LIBRARY osdCPU)
find_library(OpenSubdiv_osdGPU_LIBRARY osdGPU)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenSubdiv
  REQUIRED_VARS OpenSubdiv_osdCPU_LIBRARY OpenSubdiv_osdGPU_LIBRARY OpenSubdiv_INCLUDE_DIR)

if(OpenSubdiv_FOUND AND NOT TARGET OpenSubdiv::osdCPU)
  add_library(OpenSubdiv::osdCPU SHARED IMPORTED)
  set_target_properties(OpenSubdiv::osdCPU PROPERTIES
    IMPORTED_LOCATION "${OpenSubdiv_osdCPU_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${OpenSubdiv_INCLUDE_DIR}")
endif()
if(OpenSubdiv_FOUND AND NOT TARGET OpenSubdiv::osdGPU)
  add_library(OpenSubdiv::osdGPU SHARED IMPORTED)
  set_target_properties(OpenSubdiv::osdGPU PROPERTIES
    IMPORTED_LOCATION "${OpenSubdiv_osdGPU_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${OpenSubdiv_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES OpenSubdiv::osdCPU)
endif()
mark_as_advanced(OpenSubdiv_INCLUDE_DIR OpenSubdiv_osdCPU_LIBRARY OpenSubdiv_osdGPU_LIBRARY)
