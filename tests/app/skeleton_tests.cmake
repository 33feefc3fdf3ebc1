# The `trimlab skeleton` verb as scripts call it: exit codes, one-line errors, the Table III
# row, a rigged glTF that passes the Khronos validator and a skeleton JSON that loads back.
trimlab_add_test(app skeleton_verb LIBS trimlab::core trimlab_cli_test_support)
