# `trimlab render` with the interior-inspection flags (--clip repeated, --cap, --csg,
# --object-rule, --highlight), run as a child process.
trimlab_add_test(app inspect_cli LIBS trimlab_gl_test_support)
target_compile_definitions(tst_app_inspect_cli PRIVATE TRIMLAB_EXECUTABLE="$<TARGET_FILE:trimlab>")
add_dependencies(tst_app_inspect_cli trimlab)
