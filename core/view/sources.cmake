# view/: the interactive orbit camera (the Camera type itself is in the base list).
target_sources(trimlab_core PRIVATE view/orbit_controller.cpp)
