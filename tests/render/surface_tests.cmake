# Control-point edits of editable surfaces rendered under static and dynamic rules
# (thesis Fig. 8.13 on a NURBS sphere; a subdivision-surface edit), against the reference.
trimlab_add_test(render surface_replays LIBS trimlab_gl_test_support)
