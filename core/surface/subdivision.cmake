# Subdivision surfaces (core/surface/subdivision_*, cage_*): OpenSubdiv refines the cage
# topology once; stencil tables re-evaluate the fixed-connectivity mesh per edit.
target_sources(trimlab_core PRIVATE
  surface/cage_obj.cpp
  surface/cage_refiner.cpp
  surface/subdivision_cage.cpp
  surface/subdivision_cages.cpp
  surface/subdivision_limit.cpp
  surface/subdivision_refinement.cpp
  surface/subdivision_surface.cpp
)
target_link_libraries(trimlab_core PRIVATE OpenSubdiv::osdCPU)
