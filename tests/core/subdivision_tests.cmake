# Subdivision surfaces (core/surface/subdivision_*, cage_*): the stencil-table surface
# against OpenSubdiv's own patch evaluation and limit masks, edits and supports, sharp
# features, cage validation; the polygon-keeping cage OBJ reader.
trimlab_add_test(core subdivision_surface LIBS trimlab::core OpenSubdiv::osdCPU)
target_sources(tst_core_subdivision_surface PRIVATE uniform_refinement.cpp)
trimlab_add_test(core cage_obj LIBS trimlab::core)
# The timing benchmark (not a test; run by hand, see its file comment).
add_executable(bench_subdivision bench_subdivision.cpp uniform_refinement.cpp)
target_link_libraries(bench_subdivision PRIVATE trimlab::core OpenSubdiv::osdCPU Qt6::Core)
trimlab_set_warnings(bench_subdivision)
