# The designer's deformation history (core/timeline/; thesis 8.1.1–8.2): the Timeline
# model, .trimlab project files, stroke scripts and their replay, frame exports.
find_package(nlohmann_json 3 REQUIRED)
target_sources(trimlab_core PRIVATE
  timeline/atomic_write.cpp
  timeline/base64.cpp
  timeline/binary_array.cpp
  timeline/file_bytes.cpp
  timeline/frame_chain.cpp
  timeline/frame_export.cpp
  timeline/json_fields.cpp
  timeline/morph_gltf.cpp
  timeline/project_file.cpp
  timeline/stale_temporaries.cpp
  timeline/stroke_json.cpp
  timeline/stroke_replay.cpp
  timeline/stroke_script.cpp
  timeline/stroke_validation.cpp
  timeline/surface_json.cpp
  timeline/timeline.cpp
)
target_link_libraries(trimlab_core PRIVATE nlohmann_json::nlohmann_json)
