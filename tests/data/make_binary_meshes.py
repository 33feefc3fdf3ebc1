#!/usr/bin/env python3
"""Writes the binary (and generated) test meshes of tests/data/: binary PLY and STL,
glTF/GLB assets with their buffers, the gzip variants, and the broken binary files.

Standard library only. The output is deterministic (gzip mtime 0, a fixed pseudo-random
generator), so running it again reproduces the committed files byte for byte:

    python3 tests/data/make_binary_meshes.py

Hand-written text files (OBJ, OFF, ASCII PLY/STL, broken text files) are inputs here,
not outputs; see tests/data/README.md for what every file holds.
"""

import base64
import gzip
import json
import struct
from pathlib import Path

HERE = Path(__file__).resolve().parent
GOOD = HERE / "meshes"
BROKEN = HERE / "broken"

# The unit cube [0,1]^3: 8 vertices, 12 triangles counter-clockwise seen from outside
# (the quads of meshes/cube.obj split along their first diagonal).
CUBE_POSITIONS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                  (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_TRIANGLES = [(0, 3, 2), (0, 2, 1), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
                  (2, 3, 7), (2, 7, 6), (0, 4, 7), (0, 7, 3), (1, 2, 6), (1, 6, 5)]

NAN = float("nan")


def write(path, data):
    path.write_bytes(data)


def gz(data):
    return gzip.compress(data, compresslevel=9, mtime=0)


def garbage(count, seed):
    """Deterministic pseudo-random bytes (a linear congruential generator)."""
    out = bytearray()
    state = seed
    for _ in range(count):
        state = (state * 1103515245 + 12345) & 0x7FFFFFFF
        out.append((state >> 16) & 0xFF)
    return bytes(out)


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = sum(x * x for x in n) ** 0.5
    return tuple(x / length for x in n) if length else (0.0, 0.0, 0.0)


# ---------------------------------------------------------------- PLY

def ply_header(encoding, lines):
    return ("ply\nformat %s 1.0\n" % encoding + "".join(l + "\n" for l in lines) + "end_header\n").encode()


def cube_ply_le(positions=CUBE_POSITIONS):
    """Little endian, float coordinates, with elements and properties the reader skips:
    a leading 'blob' element with a short list and a double, normals and colours per
    vertex, a texcoord list before and an int after the index list per face."""
    header = ply_header("binary_little_endian", [
        "comment unit cube, binary little endian",
        "element blob 2",
        "property list uchar short samples",
        "property double weight",
        "element vertex %d" % len(positions),
        "property float x", "property float y", "property float z",
        "property float nx", "property float ny", "property float nz",
        "property uchar red", "property uchar green", "property uchar blue",
        "element face %d" % len(CUBE_TRIANGLES),
        "property list uchar float texcoord",
        "property list uchar int vertex_indices",
        "property int flags",
    ])
    body = bytearray()
    body += struct.pack("<B3hd", 3, -1, 2, 300, 0.25)
    body += struct.pack("<Bd", 0, 1.5)
    for i, p in enumerate(positions):
        body += struct.pack("<3f3f3B", *p, 0.0, 0.0, 1.0, 10 * i, 255, 0)
    for f, t in enumerate(CUBE_TRIANGLES):
        texcoords = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0] if f == 0 else []
        body += struct.pack("<B%df" % len(texcoords), len(texcoords), *texcoords)
        body += struct.pack("<B3i", 3, *t)
        body += struct.pack("<i", f)
    return header + bytes(body)


def cube_ply_be():
    """Big endian, double coordinates, 'vertex_index' with ushort counts and uint indices,
    an int8 property and a uchar list per vertex, and a trailing 'edge' element."""
    header = ply_header("binary_big_endian", [
        "comment unit cube, binary big endian",
        "element vertex 8",
        "property char flag",
        "property double x", "property double y", "property double z",
        "property list uchar uchar misc",
        "element face 12",
        "property list ushort uint vertex_index",
        "element edge 2",
        "property int vertex1", "property int vertex2", "property uchar red",
    ])
    body = bytearray()
    for i, p in enumerate(CUBE_POSITIONS):
        body += struct.pack(">b3d", -i, *p)
        body += struct.pack(">B%dB" % (i % 3), i % 3, *range(i % 3))
    for t in CUBE_TRIANGLES:
        body += struct.pack(">H3I", 3, *t)
    body += struct.pack(">iiB", 0, 1, 255) + struct.pack(">iiB", 2, 3, 128)
    return header + bytes(body)


def triangle_ply_le(vertex_count_declared, face_list):
    header = ply_header("binary_little_endian", [
        "element vertex %d" % vertex_count_declared,
        "property float x", "property float y", "property float z",
        "element face 1",
        "property list uint int vertex_indices",
    ])
    body = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + face_list
    return header + body


def negative_index_ply_be():
    header = ply_header("binary_big_endian", [
        "element vertex 3",
        "property float x", "property float y", "property float z",
        "element face 1",
        "property list uchar int vertex_indices",
    ])
    return header + struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack(">B3i", 3, 0, -5, 2)


# ---------------------------------------------------------------- STL

def stl_binary(header_text, triangles, declared=None):
    header = header_text.encode().ljust(80, b" ")
    body = bytearray(struct.pack("<I", len(triangles) if declared is None else declared))
    for a, b, c in triangles:
        body += struct.pack("<3f", *normal(a, b, c))
        body += struct.pack("<9f", *a, *b, *c)
        body += struct.pack("<H", 0)
    return header + bytes(body)


def cube_triangles(positions=CUBE_POSITIONS):
    return [tuple(positions[i] for i in t) for t in CUBE_TRIANGLES]


# ---------------------------------------------------------------- glTF

class BufferBuilder:
    """Packs binary chunks into one buffer with 4-byte alignment and records views."""

    def __init__(self):
        self.data = bytearray()
        self.views = []

    def add(self, payload, target=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if target:
            view["target"] = target
        self.views.append(view)
        self.data += payload
        return len(self.views) - 1


def position_accessor(view, positions, **extra):
    accessor = {"bufferView": view, "componentType": 5126, "count": len(positions), "type": "VEC3",
                "min": [min(p[i] for p in positions) for i in range(3)],
                "max": [max(p[i] for p in positions) for i in range(3)]}
    accessor.update(extra)
    return accessor


def floats(positions):
    return b"".join(struct.pack("<3f", *p) for p in positions)


def cube_gltf_parts(positions=CUBE_POSITIONS, triangles=CUBE_TRIANGLES, uint_indices=False):
    """A buffer with positions and unsigned short (or int) triangle indices, and the two
    accessors (0: POSITION, 1: indices) reading it."""
    buffer = BufferBuilder()
    pos_view = buffer.add(floats(positions), 34962)
    index_format, component = ("<3I", 5125) if uint_indices else ("<3H", 5123)
    idx_view = buffer.add(b"".join(struct.pack(index_format, *t) for t in triangles), 34963)
    accessors = [position_accessor(pos_view, positions),
                 {"bufferView": idx_view, "componentType": component, "count": 3 * len(triangles), "type": "SCALAR"}]
    return buffer, accessors


def two_nodes_json(buffer, accessors, uri):
    """Scene 1 (the default) holds node 0, the cube scaled by 2, rotated 90 degrees about
    z and moved to x = +5 (TRS), and node 2, a parent moved to x = -5 by a column-major
    matrix, whose child node 1
    mirrors the cube in x (scale -1, 1, 1). Scene 0 holds node 3, a decoy far away that a
    loader ignoring the default scene would pick."""
    half = 0.5 ** 0.5
    gltf = {
        "asset": {"version": "2.0", "generator": "tests/data/make_binary_meshes.py"},
        "scene": 1,
        "scenes": [{"nodes": [3]}, {"nodes": [0, 2]}],
        "nodes": [
            {"mesh": 0, "translation": [5, 0, 0], "rotation": [0, 0, half, half], "scale": [2, 2, 2]},
            {"mesh": 0, "scale": [-1, 1, 1]},
            {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -5, 0, 0, 1], "children": [1]},
            {"mesh": 0, "translation": [100, 0, 0]},
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "accessors": accessors,
        "bufferViews": buffer.views,
        "buffers": [{"byteLength": len(buffer.data)}],
    }
    if uri:
        gltf["buffers"][0]["uri"] = uri
    return gltf


def json_bytes(gltf):
    return json.dumps(gltf, indent=1, sort_keys=True).encode() + b"\n"


def glb(gltf, binary):
    chunk = json.dumps(gltf, separators=(",", ":"), sort_keys=True).encode()
    chunk += b" " * (-len(chunk) % 4)
    out = struct.pack("<II", len(chunk), 0x4E4F534A) + chunk
    if binary:
        payload = bytes(binary) + b"\0" * (-len(binary) % 4)
        out += struct.pack("<II", len(payload), 0x004E4942) + payload
    return b"glTF" + struct.pack("<II", 2, 12 + len(out)) + out


def data_uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(bytes(data)).decode()


def embedded_gltf(buffer, accessors, meshes, nodes, scenes=None, extra=None):
    gltf = {"asset": {"version": "2.0"}, "meshes": meshes, "nodes": nodes, "accessors": accessors,
            "bufferViews": buffer.views,
            "buffers": [{"byteLength": len(buffer.data), "uri": data_uri(buffer.data)}]}
    if scenes is not None:
        gltf["scenes"] = scenes
        gltf["scene"] = 0
    if extra:
        gltf.update(extra)
    return json_bytes(gltf)


def strip_fan_gltf():
    """No scenes (so every root node counts). Mesh 0: a unit square as a TRIANGLE_STRIP
    with unsigned byte indices and a 5-vertex TRIANGLE_FAN with unsigned short indices;
    mesh 1: a non-indexed TRIANGLES primitive whose third vertex comes from a sparse
    accessor, and a POINTS primitive that must be skipped. 12 vertices, 6 triangles, all
    facing +z. Two images that cannot be decoded check that textures are ignored."""
    buffer = BufferBuilder()
    square = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]
    fan = [(2.5, 0.5, 0), (2, 0, 0), (3, 0, 0), (3, 1, 0), (2, 1, 0)]
    loose = [(4, 0, 0), (5, 0, 0), (9, 9, 9)]  # vertex 2 replaced by (4, 1, 0) through sparse
    views = [buffer.add(floats(square)), buffer.add(bytes([0, 1, 2, 3])), buffer.add(floats(fan)),
             buffer.add(struct.pack("<5H", 0, 1, 2, 3, 4)), buffer.add(floats(loose)),
             buffer.add(struct.pack("<B", 2)), buffer.add(struct.pack("<3f", 4, 1, 0))]
    accessors = [
        position_accessor(views[0], square),
        {"bufferView": views[1], "componentType": 5121, "count": 4, "type": "SCALAR"},
        position_accessor(views[2], fan),
        {"bufferView": views[3], "componentType": 5123, "count": 5, "type": "SCALAR"},
        position_accessor(views[4], loose, sparse={
            "count": 1, "indices": {"bufferView": views[5], "componentType": 5121},
            "values": {"bufferView": views[6]}}),
    ]
    meshes = [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 5},
                              {"attributes": {"POSITION": 2}, "indices": 3, "mode": 6}]},
              {"primitives": [{"attributes": {"POSITION": 4}},
                              {"attributes": {"POSITION": 0}, "mode": 0}]}]
    # Textures must never be read or decoded: one missing external image, one embedded
    # image whose bytes are not an image at all.
    images = {"images": [{"uri": "texture_that_does_not_exist.png"},
                         {"uri": "data:image/png;base64," + base64.b64encode(b"not a png").decode()}],
              "textures": [{"source": 0}, {"source": 1}]}
    return embedded_gltf(buffer, accessors, meshes, [{"mesh": 0}, {"mesh": 1}], extra=images)


def split_vertices_cube_gltf():
    """The unit cube as exporters write it: every triangle pair (cube face) has its own
    four vertices (as if normals differed per face), 24 vertices in all, and the faces
    are split over two primitives of two nodes. Loaders must weld the bit-identical
    positions back into 8 vertices for the cube to be closed."""
    buffer = BufferBuilder()
    accessors = []
    primitives = []
    for half in (CUBE_TRIANGLES[:6], CUBE_TRIANGLES[6:]):
        positions, triangles = [], []
        for a, b, c in half:
            base = len(positions)
            positions += [CUBE_POSITIONS[a], CUBE_POSITIONS[b], CUBE_POSITIONS[c]]
            triangles.append((base, base + 1, base + 2))
        pos_view = buffer.add(floats(positions))
        idx_view = buffer.add(b"".join(struct.pack("<3H", *t) for t in triangles))
        accessors += [position_accessor(pos_view, positions),
                      {"bufferView": idx_view, "componentType": 5123, "count": 3 * len(triangles), "type": "SCALAR"}]
        primitives.append({"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1})
    meshes = [{"primitives": [p]} for p in primitives]
    return embedded_gltf(buffer, accessors, meshes, [{"mesh": 0}, {"mesh": 1}], scenes=[{"nodes": [0, 1]}])


def broken_gltfs():
    """name -> bytes for the broken glTF files built on the embedded cube."""
    out = {}

    def cube_variant(mutate, positions=CUBE_POSITIONS, triangles=CUBE_TRIANGLES):
        buffer, accessors = cube_gltf_parts(positions, triangles)
        meshes = [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}]
        nodes = [{"mesh": 0}]
        scenes = [{"nodes": [0]}]
        extra = {}
        mutate(accessors, meshes, nodes, scenes, extra)
        return embedded_gltf(buffer, accessors, meshes, nodes, scenes, extra)

    def points_only(accessors, meshes, nodes, scenes, extra):
        meshes[0]["primitives"] = [{"attributes": {"POSITION": 0}, "mode": 0},
                                   {"attributes": {"POSITION": 0}, "indices": 1, "mode": 1}]

    def out_of_bounds(accessors, meshes, nodes, scenes, extra):
        accessors[0]["count"] = 100

    def huge_count(accessors, meshes, nodes, scenes, extra):
        accessors[0]["count"] = 2000000000

    def missing_position(accessors, meshes, nodes, scenes, extra):
        meshes[0]["primitives"][0]["attributes"] = {"NORMAL": 0}

    def node_cycle(accessors, meshes, nodes, scenes, extra):
        nodes[:] = [{"mesh": 0, "children": [1]}, {"children": [0]}]

    def bad_node(accessors, meshes, nodes, scenes, extra):
        scenes[0]["nodes"] = [7]

    def draco(accessors, meshes, nodes, scenes, extra):
        extra["extensionsUsed"] = ["KHR_draco_mesh_compression"]
        extra["extensionsRequired"] = ["KHR_draco_mesh_compression"]

    def bad_triangle_count(accessors, meshes, nodes, scenes, extra):
        accessors[1]["count"] = 34

    out["points_only.gltf"] = cube_variant(points_only)
    out["accessor_out_of_bounds.gltf"] = cube_variant(out_of_bounds)
    out["huge_count.gltf"] = cube_variant(huge_count)
    out["missing_position.gltf"] = cube_variant(missing_position)
    out["node_cycle.gltf"] = cube_variant(node_cycle)
    out["bad_node_reference.gltf"] = cube_variant(bad_node)
    out["draco_required.gltf"] = cube_variant(draco)
    out["bad_triangle_count.gltf"] = cube_variant(bad_triangle_count)
    out["index_out_of_range.gltf"] = cube_variant(lambda *args: None,
                                                  triangles=CUBE_TRIANGLES[:-1] + [(1, 6, 8)])
    nan_positions = list(CUBE_POSITIONS)
    nan_positions[5] = (1, NAN, 1)
    out["nan.gltf"] = cube_variant(lambda *args: None, positions=nan_positions)
    buffer, accessors = cube_gltf_parts()
    missing = two_nodes_json(buffer, accessors, "missing.bin")
    out["missing_bin.gltf"] = json_bytes(missing)
    return out


# ---------------------------------------------------------------- main

def main():
    GOOD.mkdir(exist_ok=True)
    BROKEN.mkdir(exist_ok=True)

    # Good binary files.
    ply_le = cube_ply_le()
    write(GOOD / "cube_binary_le.ply", ply_le)
    write(GOOD / "cube_binary_be.ply", cube_ply_be())
    stl = stl_binary("binary unit cube", cube_triangles())
    write(GOOD / "cube_binary.stl", stl)
    write(GOOD / "cube_binary_solid_header.stl",
          stl_binary("solid cube, binary despite its header (as some exporters write)", cube_triangles()))
    buffer, accessors = cube_gltf_parts()
    write(GOOD / "two_nodes.bin", bytes(buffer.data))
    write(GOOD / "two_nodes.gltf", json_bytes(two_nodes_json(buffer, accessors, "two_nodes.bin")))
    two_nodes_glb = glb(two_nodes_json(buffer, accessors, None), buffer.data)
    write(GOOD / "two_nodes.glb", two_nodes_glb)
    write(GOOD / "strip_fan.gltf", strip_fan_gltf())
    write(GOOD / "cube_split_vertices.gltf", split_vertices_cube_gltf())
    tetra = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    tetra_buffer, tetra_accessors = cube_gltf_parts(tetra, [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)],
                                                    uint_indices=True)
    tetra_json = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
                  "accessors": tetra_accessors, "bufferViews": tetra_buffer.views,
                  "buffers": [{"byteLength": len(tetra_buffer.data)}]}
    write(GOOD / "tetrahedron.glb", glb(tetra_json, tetra_buffer.data))

    # Gzip variants of good files.
    for name in ["cube.obj", "cube.off", "cube_ascii.ply", "cube_binary_le.ply", "cube_ascii.stl",
                 "cube_binary.stl", "two_nodes.glb", "two_nodes.gltf", "strip_fan.gltf"]:
        write(GOOD / (name + ".gz"), gz((GOOD / name).read_bytes()))
    cube_obj = (GOOD / "cube.obj").read_bytes()
    write(GOOD / "cube_gzip_magic.obj", gz(cube_obj))
    half = len(cube_obj) // 2
    write(GOOD / "cube_multimember.obj.gz", gz(cube_obj[:half]) + gz(cube_obj[half:]))

    # Broken files: empty, garbage.
    for ext in ["obj", "off", "ply", "stl", "gltf", "glb"]:
        write(BROKEN / ("empty." + ext), b"")
    for i, ext in enumerate(["obj", "off", "ply", "stl", "gltf", "glb"]):
        data = garbage(300, 1000 + i)
        assert b"\0" in data and not data.startswith(b"solid")
        write(BROKEN / ("garbage." + ext), data)

    # Broken binary PLY.
    cut = len(ply_le) - 100
    write(BROKEN / "truncated_binary.ply", ply_le[:cut])
    nan_positions = list(CUBE_POSITIONS)
    nan_positions[5] = (1, NAN, 1)
    write(BROKEN / "nan_binary.ply", cube_ply_le(nan_positions))
    write(BROKEN / "huge_count_binary.ply", triangle_ply_le(2000000000, struct.pack("<I3i", 3, 0, 1, 2)))
    write(BROKEN / "huge_list.ply", triangle_ply_le(3, struct.pack("<I3i", 4000000000, 0, 1, 2)))
    write(BROKEN / "negative_index_binary.ply", negative_index_ply_be())

    # Broken binary STL.
    write(BROKEN / "truncated_binary.stl", stl[:84 + 50 * 5 + 20])
    write(BROKEN / "nan_binary.stl", stl_binary("nan", cube_triangles(nan_positions)))
    write(BROKEN / "huge_count.stl", stl_binary("huge", cube_triangles()[:1], declared=2000000000))
    write(BROKEN / "zero_facets.stl", stl_binary("no facets", []))

    # Broken glTF / GLB.
    for name, data in broken_gltfs().items():
        write(BROKEN / name, data)
    write(BROKEN / "wrong_magic.glb", b"glTX" + two_nodes_glb[4:])
    write(BROKEN / "version1.glb", two_nodes_glb[:4] + struct.pack("<I", 1) + two_nodes_glb[8:])
    write(BROKEN / "truncated.glb", two_nodes_glb[:100])

    # Broken gzip.
    cube_off = (GOOD / "cube.off").read_bytes()
    compressed_obj = gz(cube_obj)
    write(BROKEN / "truncated.obj.gz", compressed_obj[:len(compressed_obj) // 2])
    corrupt = bytearray(gz(cube_off))
    for i in range(20, 40):
        corrupt[i] ^= 0xFF
    write(BROKEN / "corrupt.off.gz", bytes(corrupt))
    write(BROKEN / "not_gzip.obj.gz", cube_obj)
    write(BROKEN / "empty.stl.gz", b"")
    write(BROKEN / "empty_content.obj.gz", gz(b""))
    write(BROKEN / "trailing_garbage.ply.gz", gz((GOOD / "cube_ascii.ply").read_bytes()) + b"garbage!")


if __name__ == "__main__":
    main()
