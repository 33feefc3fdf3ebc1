# The method controls, the Frame statistics dock and "Measure all methods", driven in the
# real main window with a real OpenGL 4.3 context.
trimlab_add_test(ui method_panel LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 300)
