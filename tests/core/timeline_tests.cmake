# The designer's deformation history (core/timeline/): model, project files, stroke
# scripts and their replay, frame exports (OBJ sequence, glTF morph animation).
trimlab_add_test(core timeline_model LIBS trimlab::core)
trimlab_add_test(core timeline_project LIBS trimlab::core)
trimlab_add_test(core timeline_script LIBS trimlab::core)
trimlab_add_test(core timeline_export LIBS trimlab::core)
# Runs scripts/gltf-validator (the Khronos glTF Validator, installed with npm on first
# use) on the exported file, so it needs the source tree's path.
trimlab_add_test(core timeline_gltf LIBS trimlab::core)
target_compile_definitions(tst_core_timeline_gltf PRIVATE TRIMLAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
