# The designer workflow in the main window: brush drags, undo/redo, sets and rules, the
# dynamic rules in the viewport, the homogeneous confluent refusal and project files,
# driven in the real window with a real OpenGL 4.3 context.
trimlab_add_test(ui design_workflow LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 300)
# The drag-latency benchmark (not a test; run by hand, see its file comment).
add_executable(bench_design_drag bench_design_drag.cpp)
target_link_libraries(bench_design_drag PRIVATE trimlab::ui trimlab_test_support Qt6::Test)
set_target_properties(bench_design_drag PROPERTIES AUTOMOC ON)
trimlab_set_warnings(bench_design_drag)
# Autosave of the design session and the offer to recover a crashed one.
trimlab_add_test(ui session_recovery LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 120)
# The GUI load paths (open, open animation, replay) on the whole malformed-file corpus.
trimlab_add_test(ui gui_broken_files LIBS trimlab::ui trimlab_gl_test_support TIMEOUT 300)
