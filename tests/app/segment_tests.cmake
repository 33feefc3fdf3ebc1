# The `trimlab segment` verb as scripts call it: exit codes, one-line errors, outputs.
trimlab_add_test(app segment_verb LIBS trimlab_cli_test_support)
