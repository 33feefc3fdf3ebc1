target_sources(trimlab_core PRIVATE
  io/pfm_image.cpp
  io/gltf_builder.cpp
)
