# Mesh loading, validation and the OpenMesh bridge (core/mesh/). triangle_mesh.cpp is
# listed in core/CMakeLists.txt.
target_sources(trimlab_core PRIVATE
  mesh/gltf_accessor.cpp
  mesh/gltf_document.cpp
  mesh/gltf_reader.cpp
  mesh/gzip_input.cpp
  mesh/loop_subdivision.cpp
  mesh/obj_writer.cpp
  mesh/obj_line_parser.cpp
  mesh/mesh_io.cpp
  mesh/mesh_load_error.cpp
  mesh/mesh_validation.cpp
  mesh/mesh_validation_text.cpp
  mesh/obj_reader.cpp
  mesh/off_reader.cpp
  mesh/openmesh_adapter.cpp
  mesh/ply_header.cpp
  mesh/ply_reader.cpp
  mesh/ply_value_source.cpp
  mesh/polygon_triangulation.cpp
  mesh/reader_support.cpp
  mesh/stl_reader.cpp
  mesh/text_scanner.cpp
  mesh/vertex_welding.cpp
)
# Loop subdivision (mesh/loop_subdivision.cpp) refines through OpenSubdiv's Far API.
target_link_libraries(trimlab_core PRIVATE OpenSubdiv::osdCPU)
