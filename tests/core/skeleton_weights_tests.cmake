# Bone-heat weights, posing, the rigged glTF export and the skeleton JSON file
# (core/skeleton/bone_heat_*, skeleton_pose, rigged_gltf, skeleton_json; Berenguer &
# Moreno III.E–F), and the Loop subdivision the skeleton verb uses (core/mesh/).
trimlab_add_test(core skeleton_weights LIBS trimlab::core)
target_sources(tst_core_skeleton_weights PRIVATE skeleton_shapes.cpp) # axisCapsule
trimlab_add_test(core skeleton_pose LIBS trimlab::core)
target_sources(tst_core_skeleton_pose PRIVATE skeleton_shapes.cpp)
trimlab_add_test(core skeleton_export LIBS trimlab::core TinyGLTF::TinyGLTF)
trimlab_add_test(core loop_subdivision LIBS trimlab::core)
