# `trimlab bench` run as users run it (a child process), on a small demo scene.
trimlab_add_test(app bench_verb LIBS trimlab_test_support)
target_compile_definitions(tst_app_bench_verb PRIVATE TRIMLAB_EXECUTABLE="$<TARGET_FILE:trimlab>")
add_dependencies(tst_app_bench_verb trimlab)
