# The `trimlab skeleton` verb as scripts call it: exit codes, one-line errors, the Table III
# row, a rigged glTF that passes the Khronos validator and a skeleton JSON that loads back.
trimlab_add_test(app skeleton_verb LIBS trimlab::core trimlab_test_support)
target_compile_definitions(tst_app_skeleton_verb PRIVATE TRIMLAB_EXECUTABLE="$<TARGET_FILE:trimlab>")
add_dependencies(tst_app_skeleton_verb trimlab)
