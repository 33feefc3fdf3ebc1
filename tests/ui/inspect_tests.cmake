# Interior inspection: the Scene panel's model and the Render panel's clip, cap and
# highlight controls without OpenGL, then the real main window with a real OpenGL 4.3
# context — CSG built and typed through the Scene panel, Add Object, transforms with
# undo, a clipping box, caps and highlights — every frame checked against the CPU reference.
trimlab_add_test(ui inspect_scene LIBS trimlab::ui TIMEOUT 60)
trimlab_add_test(ui inspect_settings LIBS trimlab::ui TIMEOUT 60)
trimlab_add_test(ui inspect_csg LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
trimlab_add_test(ui inspect_clip LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
trimlab_add_test(ui inspect_transform LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
# X-ray: its choices through the store and the panel, and the viewport's colors against
# the CPU reference after switching it on through the widgets.
trimlab_add_test(ui inspect_xray LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
