# The space-warp brush (core/deform/; thesis 8.2).
trimlab_add_test(core deform_parts LIBS trimlab::core)
trimlab_add_test(core deform_brush LIBS trimlab::core)
