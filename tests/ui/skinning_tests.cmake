# The Skinning panel in the real main window: fit from the Segmentation panel's segments,
# the E_RMS chart and heat map, the approximation in the viewport (against the CPU
# reference), bone edits with undo, cancel, and the glTF export (core/animation/ skinning).
trimlab_add_test(ui skinning_panel LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 180)
