# scene/: world-space geometry of scene objects, procedural shapes and demo scenes.
target_sources(trimlab_core PRIVATE
  scene/world_geometry.cpp
  scene/shape_generators.cpp
  scene/demo_shapes.cpp
  scene/demo_scenes.cpp
  scene/scene_source.cpp
  scene/object_transform.cpp
)
