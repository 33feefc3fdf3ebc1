# `trimlab render` with the interior-inspection flags (--clip repeated, --cap, --csg,
# --object-rule, --highlight), run as a child process.
trimlab_add_test(app inspect_cli LIBS trimlab_gl_test_support trimlab_cli_test_support)
