# view/: the orbit camera of the viewport.
trimlab_add_test(core orbit_controller LIBS trimlab::core)
