#!/usr/bin/env python3
"""Writes the broken project files (*.trimlab, version-1 mesh histories and version-2
surface histories), stroke scripts (script_*.json), animations (anim_*), NURBS files
(nurbs_*.nurbs.json) and skeleton files (skeleton_*.json) of tests/data/broken/, and the
valid version-2 project tests/data/projects/v2_cube_cage.trimlab the surface variants
start from (Python 3, standard library only, deterministic). Each broken file has one
defect; tests/core/io/tst_fuzz_regressions.cpp checks the exact error each must produce
(table in tests/data/README.md). The broken cages (cage_*.obj) are written by hand.
Rerun after changing it:

    python3 tests/data/broken/make_broken_documents.py
"""
import base64
import json
import os
import shutil
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ANIMATIONS = os.path.join(HERE, "..", "animations")
PROJECTS = os.path.join(HERE, "..", "projects")
PACKING = {"float32": "f", "float64": "d", "uint32": "I"}


def array(kind, values):
    data = struct.pack("<" + PACKING[kind] * len(values), *values)
    return {"base64": base64.b64encode(data).decode(), "count": len(values), "crc32": zlib.crc32(data), "type": kind}


def stroke(**extra):
    s = {"anchor": [0.0, 1.0, 0.0], "drag": [0.0, 0.0, 0.5], "profile": "smooth", "radius": 0.25,
         "smoothing": {"iterations": 2, "step": 0.5, "weights": "uniform"}, "strength": 1.0, "triangle": 0}
    s.update(extra)
    return s


def project():
    """docs/project-format.md's example: one triangle, one stroke lifting vertex 2 to z = 0.5."""
    return {
        "base_mesh": {"positions": array("float32", [0, 0, 0, 1, 0, 0, 0, 1, 0]),
                      "triangles": array("uint32", [0, 1, 2])},
        "format": "trimlab-project",
        "frames": [{"after": array("float32", [0, 1, 0.5]), "before": array("float32", [0, 1, 0]),
                    "stroke": stroke(), "vertices": array("uint32", [2])}],
        "generator": "TrimLab",
        "sets": [{"first_frame": 1, "frame_count": 1, "rule": "confluent"}],
        "static_rule": "alternating-border",
        "version": 1,
        "view": {"eye": [0.0, 0.0, 3.0], "fovy_degrees": 45.0, "target": [0.0, 0.0, 0.0], "up": [0.0, 1.0, 0.0]},
    }


def dump(document):
    return json.dumps(document, indent=1, sort_keys=True) + "\n"


def projects():
    out = {"project_empty.trimlab": "", "project_not_json.trimlab": "hello, world\n"}
    valid = dump(project())
    out["project_truncated.trimlab"] = valid[: len(valid) // 2]

    def variant(name, change):
        p = project()
        change(p)
        out[name] = dump(p)

    variant("project_wrong_format.trimlab", lambda p: p.update(format="trimlab-stroke-script"))
    variant("project_missing_format.trimlab", lambda p: p.pop("format"))
    variant("project_newer_version.trimlab", lambda p: p.update(version=7))
    variant("project_crc_mismatch.trimlab", lambda p: p["frames"][0]["after"].update(crc32=12345))
    variant("project_bad_base64.trimlab",
            lambda p: p["frames"][0]["after"].update(base64="AA#AAAAAgD8AAAA/"))
    variant("project_count_mismatch.trimlab", lambda p: p["base_mesh"]["positions"].update(count=12))
    variant("project_wrong_array_type.trimlab",
            lambda p: p["base_mesh"].update(positions=array("uint32", [0] * 9)))
    variant("project_unknown_rule.trimlab", lambda p: p["sets"][0].update(rule="sideways"))
    variant("project_sets_do_not_cover.trimlab", lambda p: p["sets"][0].update(frame_count=2))
    variant("project_before_mismatch.trimlab",
            lambda p: p["frames"][0].update(before=array("float32", [0, 1, 0.25])))
    variant("project_vertex_out_of_range.trimlab",
            lambda p: p["frames"][0].update(vertices=array("uint32", [3])))
    variant("project_triangle_out_of_range.trimlab",
            lambda p: p["base_mesh"].update(triangles=array("uint32", [0, 1, 7])))
    variant("project_radius_zero.trimlab", lambda p: p["frames"][0]["stroke"].update(radius=0.0))
    variant("project_nan_after.trimlab",
            lambda p: p["frames"][0].update(after=array("float32", [0, float("nan"), 0.5])))
    variant("project_huge_count.trimlab", lambda p: p["base_mesh"]["positions"].update(count=2000000000))
    variant("project_bad_fovy.trimlab", lambda p: p["view"].update(fovy_degrees=180.0))
    variant("project_missing_sets.trimlab", lambda p: p.pop("sets"))
    out["project_deep_nesting.trimlab"] = '{"format": "trimlab-project", "version": 1, "x": ' + "[" * 100 + "]" * 100 + "}\n"
    return out


def script(**extra):
    s = {"format": "trimlab-stroke-script", "version": 1,
         "sets": [{"rule": "additive", "strokes": [{"anchor": [0.5, 0.5, 0.0], "drag": [0.0, 0.0, 0.25]}]}]}
    s.update(extra)
    return s


def scripts():
    out = {"script_empty.json": "", "script_syntax_error.json": '{"format": "trimlab-stroke-script",, "version": 1}\n'}

    def variant(name, change):
        s = script()
        change(s)
        out[name] = json.dumps(s, indent=1) + "\n"

    first = lambda s: s["sets"][0]["strokes"][0]  # noqa: E731
    variant("script_wrong_format.json", lambda s: s.update(format="trimlab-project"))
    variant("script_newer_version.json", lambda s: s.update(version=2))
    variant("script_no_sets.json", lambda s: s.update(sets=[]))
    variant("script_unknown_field.json", lambda s: first(s).update(strenght=0.5))
    variant("script_negative_radius.json", lambda s: first(s).update(radius=-0.1))
    variant("script_unknown_profile.json", lambda s: first(s).update(profile="soft"))
    variant("script_step_out_of_range.json",
            lambda s: first(s).update(smoothing={"iterations": 2, "weights": "uniform", "step": 1.5}))
    variant("script_too_many_iterations.json",
            lambda s: first(s).update(smoothing={"iterations": 10001, "weights": "uniform", "step": 0.5}))
    variant("script_short_anchor.json", lambda s: first(s).update(anchor=[0.5, 0.5]))
    variant("script_missing_drag.json", lambda s: first(s).pop("drag"))
    variant("script_unknown_rule.json", lambda s: s["sets"][0].update(rule="sideways"))
    variant("script_strength_text.json", lambda s: first(s).update(strength="strong"))
    return out


def gltf(name):
    with open(os.path.join(ANIMATIONS, name)) as f:
        return json.load(f)


def buffer_of(document):
    uri = document["buffers"][0]["uri"]
    return bytearray(base64.b64decode(uri.split(",", 1)[1]))


def set_buffer(document, data):
    document["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bytes(data)).decode()
    document["buffers"][0]["byteLength"] = len(data)


def float_at(document, accessor, index, value):
    a = document["accessors"][accessor]
    view = document["bufferViews"][a["bufferView"]]
    data = buffer_of(document)
    struct.pack_into("<f", data, view.get("byteOffset", 0) + a.get("byteOffset", 0) + 4 * index, value)
    set_buffer(document, data)


def animations():
    out = {}

    def variant(name, source, change):
        d = gltf(source)
        change(d)
        out[name] = json.dumps(d, indent=1, sort_keys=True) + "\n"

    def lift_sampler(d):
        return d["animations"][0]["samplers"][0]

    variant("anim_no_animations.gltf", "morph_square.gltf", lambda d: d.pop("animations"))
    variant("anim_decreasing_times.gltf", "morph_square.gltf",
            lambda d: float_at(d, lift_sampler(d)["input"], 2, 0.5))
    variant("anim_nan_time.gltf", "morph_square.gltf",
            lambda d: float_at(d, lift_sampler(d)["input"], 1, float("nan")))
    variant("anim_weights_count.gltf", "morph_square.gltf",
            lambda d: d["accessors"][lift_sampler(d)["output"]].update(count=2))
    variant("anim_bad_channel_node.gltf", "morph_square.gltf",
            lambda d: d["animations"][0]["channels"][0]["target"].update(node=9))
    variant("anim_bad_interpolation.gltf", "morph_square.gltf",
            lambda d: lift_sampler(d).update(interpolation="CUBIC"))
    variant("anim_huge_keyframes.gltf", "morph_square.gltf",
            lambda d: d["accessors"][lift_sampler(d)["input"]].update(count=2000000000))

    def bad_joint(d):
        prim = d["meshes"][0]["primitives"][0]
        a = d["accessors"][prim["attributes"]["JOINTS_0"]]
        view = d["bufferViews"][a["bufferView"]]
        data = buffer_of(d)
        data[view.get("byteOffset", 0) + a.get("byteOffset", 0) + 1] = 5
        set_buffer(d, data)

    variant("anim_joint_out_of_range.gltf", "skinned_bar.gltf", bad_joint)
    variant("anim_missing_inverse_bind.gltf", "skinned_bar.gltf",
            lambda d: d["accessors"][d["skins"][0]["inverseBindMatrices"]].update(count=1))
    return out


def sequences():
    """Folders of OBJ poses; the first pose is the bar of tests/data/animations/bar."""
    with open(os.path.join(ANIMATIONS, "bar", "bar_1.obj")) as f:
        bar = f.read()
    lines = bar.splitlines(keepends=True)
    vertex_lines = [i for i, line in enumerate(lines) if line.startswith("v ")]
    return {
        "anim_seq_empty_pose": {"pose_0.obj": bar, "pose_1.obj": ""},
        "anim_seq_truncated_pose": {"pose_0.obj": bar, "pose_1.obj": "".join(lines[: vertex_lines[4]]) + "v 4 0\n"},
        "anim_seq_fewer_vertices": {"pose_0.obj": bar,
                                     "pose_1.obj": "".join(l for i, l in enumerate(lines) if i != vertex_lines[-1]
                                                           and not l.startswith("f "))
                                     + "f 1 2 7\n"},
        "anim_seq_out_of_range": {"pose_0.obj": bar, "pose_1.obj": bar + "f 1 2 99\n"},
    }


# The unit cube of tests/data/README.md as a Catmull-Clark cage: 8 vertices, 6 quads,
# counter-clockwise seen from outside.
CUBE_POSITIONS = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1]
CUBE_QUADS = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def surface_project():
    """A version-2 history (docs/project-format.md, "Editable surfaces"): the cube cage at
    level 0, whose tessellation is the cage itself with each quad (a, b, c, d) split into
    (a, b, c) and (a, c, d); one control-point edit lifts cage vertex 2 from (1, 1, 0) to
    (1, 1, 0.5), which moves mesh vertex 2 the same way."""
    triangles = [i for q in CUBE_QUADS for i in (q[0], q[1], q[2], q[0], q[2], q[3])]
    return {
        "base_mesh": {"positions": array("float32", CUBE_POSITIONS), "triangles": array("uint32", triangles)},
        "format": "trimlab-project",
        "frames": [{"after": array("float32", [1, 1, 0.5]), "before": array("float32", [1, 1, 0]),
                    "control_moves": {"after": array("float64", [1, 1, 0.5]),
                                      "before": array("float64", [1, 1, 0]),
                                      "indices": array("uint32", [2])},
                    "vertices": array("uint32", [2])}],
        "generator": "TrimLab",
        "sets": [{"first_frame": 1, "frame_count": 1, "rule": "confluent"}],
        "surface": {"boundary": "edges-only", "corners": [], "creases": [],
                    "face_indices": array("uint32", [i for q in CUBE_QUADS for i in q]),
                    "face_sizes": array("uint32", [4] * 6), "kind": "subdivision", "level": 0, "mode": "uniform",
                    "positions": array("float64", CUBE_POSITIONS), "scheme": "catmull-clark"},
        "version": 2,
    }


def surface_projects():
    out = {}

    def variant(name, change):
        p = surface_project()
        change(p)
        out[name] = dump(p)

    moves = lambda p: p["frames"][0]["control_moves"]  # noqa: E731
    # A ninth vertex no triangle uses: the stored base mesh is no longer the surface's
    # tessellation, so editing could not go on from it.
    variant("project_surface_base_mismatch.trimlab",
            lambda p: p["base_mesh"].update(positions=array("float32", CUBE_POSITIONS + [2, 2, 2])))
    variant("project_surface_control_out_of_range.trimlab",
            lambda p: moves(p).update(indices=array("uint32", [8])))
    variant("project_surface_before_differs.trimlab",
            lambda p: moves(p).update(before=array("float64", [1, 1, 0.25])))
    variant("project_surface_nan_after.trimlab",
            lambda p: moves(p).update(after=array("float64", [1, float("nan"), 0.5])))
    variant("project_surface_huge_count.trimlab",
            lambda p: p["surface"]["positions"].update(count=2000000000))
    variant("project_surface_level_too_deep.trimlab", lambda p: p["surface"].update(level=6))
    return out


def nurbs():
    """A valid trimlab-nurbs document (docs/nurbs-json.md): one biquadratic 5 × 3 patch in
    z = 0 with its three inner points of the middle row raised to z = 0.5, the centre one
    with weight 0.5."""
    points, weights = [], []
    for j in range(3):
        for i in range(5):
            points.append([float(i), float(j), 0.5 if j == 1 and 0 < i < 4 else 0.0])
            weights.append(0.5 if (i, j) == (2, 1) else 1.0)
    return {"format": "trimlab-nurbs", "version": 1, "generator": "TrimLab",
            "surfaces": [{"name": "patch", "degreeU": 2, "degreeV": 2, "countU": 5, "countV": 3,
                          "closedU": False, "closedV": False,
                          "knotsU": [0.0, 0.0, 0.0, 0.25, 0.5, 1.0, 1.0, 1.0],
                          "knotsV": [0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
                          "points": points, "weights": weights}]}


def nurbs_files():
    valid = json.dumps(nurbs(), indent=1) + "\n"
    out = {"nurbs_empty.nurbs.json": "", "nurbs_truncated.nurbs.json": valid[: len(valid) // 2]}

    def variant(name, change, text=lambda t: t):
        d = nurbs()
        change(d)
        out[name] = text(json.dumps(d, indent=1) + "\n")

    first = lambda d: d["surfaces"][0]  # noqa: E731
    # json.dumps writes NaN as the literal NaN, which JSON does not have.
    variant("nurbs_nan.nurbs.json", lambda d: first(d)["points"][6].__setitem__(1, float("nan")))
    # 1e999 is valid JSON syntax but overflows a double (Python would print Infinity).
    variant("nurbs_overflow.nurbs.json", lambda d: first(d)["weights"].__setitem__(3, 12345.5),
            lambda t: t.replace("12345.5", "1e999"))
    variant("nurbs_huge_count.nurbs.json", lambda d: first(d).update(countU=100000, countV=100000))
    variant("nurbs_points_count.nurbs.json", lambda d: first(d)["points"].pop())
    variant("nurbs_decreasing_knots.nurbs.json",
            lambda d: first(d).update(knotsU=[0.0, 0.0, 0.0, 0.5, 0.25, 1.0, 1.0, 1.0]))
    variant("nurbs_degree_out_of_range.nurbs.json", lambda d: first(d).update(degreeU=9))
    variant("nurbs_zero_weight.nurbs.json", lambda d: first(d)["weights"].__setitem__(7, 0.0))
    variant("nurbs_newer_version.nurbs.json", lambda d: d.update(version=2))
    variant("nurbs_count_text.nurbs.json", lambda d: first(d).update(countU="5"))
    return out


def skeleton():
    """A valid trimlab-skeleton document (docs/skeleton.md): a chain of 3 joints along x,
    2 bones, one mesh vertex per joint."""
    return {"format": "trimlab-skeleton", "version": 1, "generator": "TrimLab",
            "nodes": [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]], "root": 0, "parent": [-1, 0, 1],
            "edges": [[0, 1], [1, 2]],
            "bones": [{"head": 0, "tail": 1, "parent_bone": -1}, {"head": 1, "tail": 2, "parent_bone": 0}],
            "vertex_joint": [0, 1, 2]}


def skeleton_files():
    valid = json.dumps(skeleton(), indent=1) + "\n"
    out = {"skeleton_empty.json": "", "skeleton_truncated.json": valid[: len(valid) // 2]}

    def variant(name, change):
        d = skeleton()
        change(d)
        out[name] = json.dumps(d, indent=1) + "\n"

    variant("skeleton_newer_version.json", lambda d: d.update(version=2))
    variant("skeleton_parent_out_of_range.json", lambda d: d.update(parent=[-1, 0, 7]))
    variant("skeleton_negative_vertex_joint.json", lambda d: d.update(vertex_joint=[0, -1, 2]))
    variant("skeleton_edges_differ.json", lambda d: d["edges"].__setitem__(1, [2, 1]))
    return out


def main():
    with open(os.path.join(PROJECTS, "v2_cube_cage.trimlab"), "w", newline="\n") as f:
        f.write(dump(surface_project()))
    documents = {**projects(), **surface_projects(), **scripts(), **animations(), **nurbs_files(), **skeleton_files()}
    for name, text in documents.items():
        with open(os.path.join(HERE, name), "w", newline="\n") as f:
            f.write(text)
    for folder, files in sequences().items():
        path = os.path.join(HERE, folder)
        shutil.rmtree(path, ignore_errors=True)
        os.makedirs(path)
        for name, text in files.items():
            with open(os.path.join(path, name), "w", newline="\n") as f:
                f.write(text)


if __name__ == "__main__":
    main()
