# The method controls, the Frame statistics dock and "Measure all methods", driven in the
# real main window with a real OpenGL 4.3 context.
trimlab_add_test(ui method_panel LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 300)
# GPU resets in the real window: the context is re-created and the same frame shown; a
# second reset in a row falls back to a leaner method.
trimlab_add_test(ui context_loss LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
