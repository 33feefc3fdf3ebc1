# The `trimlab skin` verb as scripts call it: exit codes, one-line errors, the printed
# E_RMS and times, and a glTF that passes the Khronos validator and reloads.
trimlab_add_test(app skin_verb LIBS trimlab::core trimlab_test_support)
target_compile_definitions(tst_app_skin_verb PRIVATE TRIMLAB_EXECUTABLE="$<TARGET_FILE:trimlab>"
                                                     TRIMLAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(tst_app_skin_verb trimlab)
