# The `trimlab skin` verb as scripts call it: exit codes, one-line errors, the printed
# E_RMS and times, and a glTF that passes the Khronos validator and reloads.
trimlab_add_test(app skin_verb LIBS trimlab::core trimlab_cli_test_support)
