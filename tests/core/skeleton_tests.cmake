# Skeleton extraction by mesh contraction, stages A–D (core/skeleton/: contraction,
# simplification, refinement, selection; Berenguer & Moreno III.A–D) on generated meshes.
trimlab_add_test(core skeleton_contraction LIBS trimlab::core Eigen3::Eigen)
target_sources(tst_core_skeleton_contraction PRIVATE skeleton_shapes.cpp)
trimlab_add_test(core skeleton_extraction LIBS trimlab::core)
target_sources(tst_core_skeleton_extraction PRIVATE skeleton_shapes.cpp)
# The timing benchmark (not a test; run by hand, see its file comment).
add_executable(bench_skeleton bench_skeleton.cpp)
target_link_libraries(bench_skeleton PRIVATE trimlab::core Qt6::Core)
trimlab_set_warnings(bench_skeleton)
