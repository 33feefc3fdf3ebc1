# NURBS surfaces (core/surface/nurbs_*): basis functions, exact rational primitives and
# evaluation, watertight tessellation with sparse re-evaluation, JSON and OBJ.
trimlab_add_test(core nurbs_basis LIBS trimlab::core)
trimlab_add_test(core nurbs_surface LIBS trimlab::core)
trimlab_add_test(core nurbs_tessellation LIBS trimlab::core)
# The timing benchmark (not a test; run by hand, see its file comment).
add_executable(bench_nurbs bench_nurbs.cpp)
target_link_libraries(bench_nurbs PRIVATE trimlab::core)
trimlab_set_warnings(bench_nurbs)
