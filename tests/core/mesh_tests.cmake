# Mesh loading, triangulation, validation and the OpenMesh bridge (core/mesh/).
trimlab_add_test(core mesh_io LIBS trimlab::core)
trimlab_add_test(core mesh_triangulation LIBS trimlab::core)
trimlab_add_test(core mesh_validation LIBS trimlab::core)
trimlab_add_test(core openmesh_adapter LIBS trimlab::core OpenMeshCore)
