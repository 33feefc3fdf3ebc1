# `trimlab bench` run as users run it (a child process), on a small demo scene.
trimlab_add_test(app bench_verb LIBS trimlab_cli_test_support)
