#!/usr/bin/env python3
"""Writes the glTF animation test files of tests/data/animations/ (Python 3, standard
library only, deterministic). Rerun after changing it and commit its output:

    python3 tests/data/make_animation_files.py

Every file is a .gltf with one embedded (base64 data URI) buffer. The motions are chosen
so that the sampled poses can be written down by hand (tests/core/animation/tst_animation_gltf.cpp).
"""
import base64
import json
import math
import os
import struct

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "animations")
FLOAT, UBYTE, USHORT = 5126, 5121, 5123


class Asset:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def add(self, fmt, values, count, gltf_type, component, extra=None):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        self.data += struct.pack("<" + fmt * len(values), *values)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset})
        accessor = {"bufferView": len(self.views) - 1, "componentType": component, "count": count, "type": gltf_type}
        accessor.update(extra or {})
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def floats(self, values, gltf_type, per_element):
        return self.add("f", values, len(values) // per_element, gltf_type, FLOAT)

    def positions(self, points):
        flat = [c for p in points for c in p]
        bounds = {"min": [min(p[i] for p in points) for i in range(3)], "max": [max(p[i] for p in points) for i in range(3)]}
        return self.add("f", flat, len(points), "VEC3", FLOAT, bounds)

    def document(self, body):
        body["asset"] = {"version": "2.0", "generator": "tests/data/make_animation_files.py"}
        body["buffers"] = [{"byteLength": len(self.data),
                            "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode()}]
        body["bufferViews"] = self.views
        body["accessors"] = self.accessors
        return json.dumps(body, indent=1, sort_keys=True) + "\n"


def morph_square():
    """Unit square in z = 0 (vertices 0..3 counter-clockwise from the origin), one morph
    target lifting vertex 2 by (0, 0, 1). Animation 0 'lift' (LINEAR): weight 0, 1, 0.5 at
    t = 0, 1, 2 s. Animation 1 'steps' (STEP): weight 0.2, 0.8 at t = 0, 1 s."""
    a = Asset()
    position = a.positions([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)])
    indices = a.add("H", [0, 1, 2, 0, 2, 3], 6, "SCALAR", USHORT)
    target = a.positions([(0, 0, 0), (0, 0, 0), (0, 0, 1), (0, 0, 0)])
    lift_times = a.floats([0.0, 1.0, 2.0], "SCALAR", 1)
    lift_weights = a.floats([0.0, 1.0, 0.5], "SCALAR", 1)
    step_times = a.floats([0.0, 1.0], "SCALAR", 1)
    step_weights = a.floats([0.2, 0.8], "SCALAR", 1)
    return a.document({
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "square"}],
        "meshes": [{"weights": [0.0], "primitives": [{"attributes": {"POSITION": position}, "indices": indices,
                                                       "targets": [{"POSITION": target}]}]}],
        "animations": [
            {"name": "lift", "samplers": [{"input": lift_times, "output": lift_weights, "interpolation": "LINEAR"}],
             "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}]},
            {"name": "steps", "samplers": [{"input": step_times, "output": step_weights, "interpolation": "STEP"}],
             "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}]},
        ],
    })


def skinned_bar():
    """A 2 x 1 strip (vertices 0-2 at y = 0, x = 0, 1, 2; vertices 3-5 at y = 1) skinned to
    joint j0 (node 1, at the origin) and its child j1 (node 2, at x = 1): x = 0 follows j0,
    x = 2 follows j1, x = 1 half each. Inverse bind matrices: identity and a translation by
    (-1, 0, 0). The mesh node itself is moved to x = +5, which glTF ignores for skinned
    meshes. Animation 'bend' (LINEAR): j1 turns from identity to 90 degrees about +z
    between t = 0 and t = 1 s."""
    a = Asset()
    position = a.positions([(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0)])
    indices = a.add("H", [0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4], 12, "SCALAR", USHORT)
    joints = a.add("B", [0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0] * 2, 6, "VEC4", UBYTE)
    weights = a.floats([1, 0, 0, 0, 0.5, 0.5, 0, 0, 1, 0, 0, 0] * 2, "VEC4", 4)
    identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
    shifted = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1]  # column-major translate(-1, 0, 0)
    inverse_bind = a.floats(identity + shifted, "MAT4", 16)
    times = a.floats([0.0, 1.0], "SCALAR", 1)
    s = math.sin(math.pi / 4)
    rotations = a.floats([0, 0, 0, 1, 0, 0, s, s], "VEC4", 4)
    return a.document({
        "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "skin": 0, "translation": [5, 0, 0], "name": "bar"},
                  {"name": "j0", "children": [2]},
                  {"name": "j1", "translation": [1, 0, 0]}],
        "skins": [{"joints": [1, 2], "inverseBindMatrices": inverse_bind}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": position, "JOINTS_0": joints, "WEIGHTS_0": weights},
                                    "indices": indices}]}],
        "animations": [{"name": "bend", "samplers": [{"input": times, "output": rotations, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]}],
    })


def main():
    os.makedirs(HERE, exist_ok=True)
    for name, text in (("morph_square.gltf", morph_square()), ("skinned_bar.gltf", skinned_bar())):
        with open(os.path.join(HERE, name), "w", newline="\n") as f:
            f.write(text)


if __name__ == "__main__":
    main()
