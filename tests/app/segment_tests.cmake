# The `trimlab segment` verb as scripts call it: exit codes, one-line errors, outputs.
trimlab_add_test(app segment_verb LIBS trimlab_test_support)
target_compile_definitions(tst_app_segment_verb PRIVATE TRIMLAB_EXECUTABLE="$<TARGET_FILE:trimlab>")
add_dependencies(tst_app_segment_verb trimlab)
