# The Skeleton panel in the real main window: skeleton extraction (core/skeleton/) run on a
# generated closed mesh, the stage views, posing by spin boxes and by dragging a bone,
# Reset pose, cancel, the refusal of an open mesh, the exports, and the settings.
trimlab_add_test(ui skeleton_panel LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
target_sources(tst_ui_skeleton_panel PRIVATE ${PROJECT_SOURCE_DIR}/tests/core/skeleton_shapes.cpp)
target_include_directories(tst_ui_skeleton_panel PRIVATE ${PROJECT_SOURCE_DIR}/tests/core)
