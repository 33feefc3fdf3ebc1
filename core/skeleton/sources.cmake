# Skeleton extraction by mesh contraction and automatic rigging (core/skeleton/;
# Berenguer & Moreno III.A–F). CHOLMOD and METIS solve the sparse normal equations.
target_sources(trimlab_core PRIVATE
  skeleton/bone_heat_terms.cpp
  skeleton/bone_heat_weights.cpp
  skeleton/collapse_complex.cpp
  skeleton/contraction_solver.cpp
  skeleton/cotangent_laplacian.cpp
  skeleton/meyer_laplacian.cpp
  skeleton/normal_equations.cpp
  skeleton/point_in_mesh.cpp
  skeleton/rig_hierarchy.cpp
  skeleton/rig_validation.cpp
  skeleton/rigged_gltf.cpp
  skeleton/skeleton_extraction.cpp
  skeleton/skeleton_input.cpp
  skeleton/skeleton_json.cpp
  skeleton/skeleton_pose.cpp
  skeleton/skeleton_refinement.cpp
  skeleton/skeleton_selection.cpp
  skeleton/skeleton_simplification.cpp
  skeleton/sparse_cholesky.cpp
)
target_link_libraries(trimlab_core PRIVATE SuiteSparse::CHOLMOD METIS::METIS)
