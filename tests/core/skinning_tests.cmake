# Skinning of mesh animations (core/animation/skinning_*; thesis 2.3 and chapter 4).
trimlab_add_test(core skinning_nnls LIBS trimlab::core)
trimlab_add_test(core skinning_fit LIBS trimlab::core)
trimlab_add_test(core skinning_corrections LIBS trimlab::core)
trimlab_add_test(core skinning_propagation LIBS trimlab::core)
trimlab_add_test(core skinning_rig LIBS trimlab::core)
trimlab_add_test(core skinning_gltf LIBS trimlab::core)
target_compile_definitions(tst_core_skinning_gltf PRIVATE TRIMLAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
trimlab_add_test(core segment_count_search LIBS trimlab::core)
