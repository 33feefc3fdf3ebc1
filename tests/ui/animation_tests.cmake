# Mesh animations in the main window: the Timeline and the Segmentation panel, driven in
# the real window with a real OpenGL 4.3 context (core/animation/ underneath).
trimlab_add_test(ui animation_panel LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 180)
