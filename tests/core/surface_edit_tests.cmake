# Editable surfaces as documents (core/surface/editable_surface, control_edit,
# control_brush; thesis 8.2): control edits as timeline frames, project files, scenes.
trimlab_add_test(core surface_edit LIBS trimlab::core)
trimlab_add_test(core surface_project LIBS trimlab::core)
