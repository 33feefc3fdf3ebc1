# The editable-surface UI (thesis 8.2): Create menu, Surface panel, control net overlay,
# picking and dragging control points with undo, the brush on control points — in the
# real main window with a real OpenGL 4.3 context; and the panel's settings and the
# picking rules without OpenGL.
trimlab_add_test(ui surface_editing LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
trimlab_add_test(ui surface_choices LIBS trimlab::ui TIMEOUT 60)
