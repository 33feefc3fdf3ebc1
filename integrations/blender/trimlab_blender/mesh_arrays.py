"""Blender meshes to NumPy arrays and back, without Python lists: vertices (n, 3)
float64, triangles (m, 3) int32 from the mesh's loop triangles."""

import numpy as np


def mesh_vertices(mesh, matrix=None):
    """(n, 3) float64 vertex positions, in object space or through `matrix` (4×4)."""
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    V = co.reshape(-1, 3).astype(np.float64)
    if matrix is not None:
        M = np.array(matrix, dtype=np.float64)
        V = V @ M[:3, :3].T + M[:3, 3]
    return V


def mesh_triangles(mesh):
    """(m, 3) int32 triangles of the mesh's faces (polygons fanned by Blender)."""
    mesh.calc_loop_triangles()
    F = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", F)
    return F.reshape(-1, 3)


def shape_key_poses(mesh):
    """(k, n, 3) float64: every shape key of the mesh, the basis first."""
    blocks = mesh.shape_keys.key_blocks
    poses = np.empty((len(blocks), len(mesh.vertices) * 3), dtype=np.float32)
    for k, block in enumerate(blocks):
        block.data.foreach_get("co", poses[k])
    return poses.reshape(len(blocks), -1, 3).astype(np.float64)


def new_mesh(name, V, F):
    """A new mesh datablock with vertices V (n, 3) and triangles F (m, 3)."""
    import bpy

    mesh = bpy.data.meshes.new(name)
    n, m = len(V), len(F)
    mesh.vertices.add(n)
    mesh.vertices.foreach_set("co", np.ascontiguousarray(V, dtype=np.float32).ravel())
    mesh.loops.add(3 * m)
    mesh.loops.foreach_set("vertex_index", np.ascontiguousarray(F, dtype=np.int32).ravel())
    mesh.polygons.add(m)
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * m, 3, dtype=np.int32))
    try:
        mesh.polygons.foreach_set("loop_total", np.full(m, 3, dtype=np.int32))
    except (AttributeError, TypeError):  # read-only where Blender derives it from loop_start
        pass
    mesh.update(calc_edges=True)
    return mesh
