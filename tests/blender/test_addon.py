"""The TrimLab add-on in Debian's Blender, headless: installs it from a zip, enables it,
runs every operator on a small mesh and checks the result against the trimlab module —
the trimmed volume to 1e-9, the skinned mesh against the fit's reconstruction, the
skeleton's bones and its rest pose, and an error as the operator's report — and opens the
rig `trimlab skeleton` exports with Blender's glTF importer, in its rest position.

    blender -b --factory-startup --python test_addon.py -- MODULE_DIR ADDON_DIR DATA_DIR OUT_DIR \
        SHARED_DATA_DIR TRIMLAB_EXECUTABLE

SHARED_DATA_DIR holds the Dem Bones sample, whose skin must play in Blender with the RMSE
that `trimlab skin` (TRIMLAB_EXECUTABLE) prints for it.

Exits non-zero (--python-exit-code) on the first failed check."""

import os
import re
import subprocess
import sys
import traceback
import zipfile

import bpy
import numpy as np

module_dir, addon_dir, data_dir, out_dir, shared_dir, trimlab_exe = sys.argv[sys.argv.index("--") + 1:][:6]
os.environ["TRIMLAB_PYTHONPATH"] = module_dir
sys.path[:0] = [module_dir]
os.makedirs(out_dir, exist_ok=True)

import addon_utils  # noqa: E402
import trimlab  # noqa: E402


def install_from_zip():
    """Installs the add-on as users do, from a zip of its folder, into the user scripts
    folder BLENDER_USER_SCRIPTS names (the test's own), and enables it."""
    scripts = os.environ.get("BLENDER_USER_SCRIPTS", "")
    check(scripts.startswith(out_dir), "BLENDER_USER_SCRIPTS must point into the test's output folder")
    archive = os.path.join(out_dir, "trimlab_blender.zip")
    with zipfile.ZipFile(archive, "w") as zipped:
        folder = os.path.join(addon_dir, "trimlab_blender")
        for name in sorted(os.listdir(folder)):
            if name.endswith(".py"):
                zipped.write(os.path.join(folder, name), f"trimlab_blender/{name}")
    bpy.ops.preferences.addon_install(filepath=archive, overwrite=True)
    addon_utils.enable("trimlab_blender", default_set=True, handle_error=None)
    check("trimlab_blender" in bpy.context.preferences.addons, "the zip's add-on is not enabled")


def check(condition, message):
    if not condition:
        raise AssertionError(message)


install_from_zip()
from trimlab_blender.mesh_arrays import mesh_triangles, mesh_vertices  # noqa: E402


def clear_scene():
    for collection in (bpy.data.objects, bpy.data.meshes, bpy.data.armatures, bpy.data.actions):
        for block in list(collection):
            collection.remove(block)


def object_from_arrays(name, V, F, location=(0.0, 0.0, 0.0)):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(V.tolist(), [], F.tolist())
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    obj.location = location
    bpy.context.view_layer.update()
    return obj


def activate(*objects):
    for o in bpy.context.view_layer.objects:
        o.select_set(False)
    for o in objects:
        o.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]


def volume(obj, world=False):
    V = mesh_vertices(obj.data, obj.matrix_world if world else None)
    return trimlab.info(V, mesh_triangles(obj.data))["signed_volume"]


def evaluated_vertices(obj):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    V = mesh_vertices(mesh)
    evaluated.to_mesh_clear()
    return V


def test_self_trim_replace_and_duplicate():
    V, F = trimlab.load("demo:pushed-sphere")
    expected = trimlab.info(*trimlab.trim(V, F, rule="parity"))["signed_volume"]
    for mode in ("REPLACE", "DUPLICATE"):
        clear_scene()
        obj = object_from_arrays("pushed", V, F)
        activate(obj)
        check(bpy.ops.object.trimlab_self_trim(rule="parity", mode=mode) == {"FINISHED"}, "self-trim did not finish")
        result = bpy.context.view_layer.objects.active
        check((result == obj) == (mode == "REPLACE"), f"{mode}: wrong object holds the result")
        got = volume(result)
        check(abs(got - expected) <= 1e-9 * abs(expected), f"{mode}: volume {got} != trimlab's {expected}")
        if mode == "DUPLICATE":
            check(len(obj.data.vertices) == len(V), "duplicate changed the source mesh")


def test_boolean_of_selected():
    clear_scene()
    V, F = trimlab.load(os.path.join(data_dir, "meshes", "cube.obj"))
    size = V.max(axis=0) - V.min(axis=0)
    a = object_from_arrays("A", V, F)
    b = object_from_arrays("B", V, F, location=tuple(size * 0.5))
    activate(a, b)
    check(bpy.ops.object.trimlab_boolean(expression="0 - 1") == {"FINISHED"}, "boolean did not finish")
    result = bpy.context.view_layer.objects.active
    expected = trimlab.info(*trimlab.trim([(V, F), (V + size * 0.5, F)], csg="0 - 1", rule="nonzero"))
    got = volume(result, world=True)
    check(abs(got - expected["signed_volume"]) <= 1e-9 * expected["signed_volume"],
          f"boolean volume {got} != trimlab's {expected['signed_volume']}")
    cube = trimlab.info(V, F)["signed_volume"]
    check(abs(got - cube * 7 / 8) <= 1e-9 * cube, f"boolean volume {got} is not 7/8 of the cube's {cube}")


def test_self_trim_error_is_a_report():
    clear_scene()
    V, F = trimlab.load(os.path.join(data_dir, "meshes", "open_square.obj"))
    activate(object_from_arrays("open", V, F))
    try:
        bpy.ops.object.trimlab_self_trim()
    except RuntimeError as error:  # Blender raises an operator's ERROR report
        check("closed surface" in str(error), f"unexpected report: {error}")
        return
    raise AssertionError("self-trim of an open mesh did not report an error")


def check_skinned(poses, F, name):
    fit = trimlab.skin(poses, F, bones=2, reconstruct=True, name=name)
    arm = next(o for o in bpy.data.objects if o.type == "ARMATURE")
    skinned = next(o for o in bpy.data.objects if o.name.endswith("skinned"))
    check(len(arm.data.bones) == fit.bone_count == 2, f"{len(arm.data.bones)} bones, expected 2")
    check(len(skinned.vertex_groups) == 2, "one vertex group per bone")
    scale = np.linalg.norm(poses.max(axis=(0, 1)) - poses.min(axis=(0, 1)))
    for t in range(len(poses)):
        bpy.context.scene.frame_set(t + 1)
        got = evaluated_vertices(skinned)
        error = np.abs(got - fit.approximation[t]).max() / scale
        check(error < 1e-4, f"{name} pose {t}: Blender's skinned mesh is {error:.2e} off the fit")


def test_skin_from_sequence_folder():
    clear_scene()
    folder = os.path.join(data_dir, "animations", "bar")
    result = bpy.ops.object.trimlab_skin_from_cache(source="FOLDER", directory=folder, bones=2)
    check(result == {"FINISHED"}, "skin from a folder did not finish")
    poses, F = trimlab.load_animation(folder)
    check_skinned(poses, F, "bar")


def test_skin_from_shape_keys():
    clear_scene()
    poses, F = trimlab.load_animation(os.path.join(data_dir, "animations", "bar"))
    obj = object_from_arrays("bar keys", poses[0], F)
    obj.shape_key_add(name="Basis")
    for t in range(1, len(poses)):
        key = obj.shape_key_add(name=f"pose {t}")
        key.data.foreach_set("co", poses[t].astype(np.float32).ravel())
    activate(obj)
    check(bpy.ops.object.trimlab_skin_from_cache(source="SHAPE_KEYS", bones=2) == {"FINISHED"},
          "skin from shape keys did not finish")
    check_skinned(poses.astype(np.float32).astype(np.float64), F, "bar keys")


def cli_exported_rmse(folder, bones):
    """The "RMSE exported" line of `trimlab skin FOLDER --bones N` (Dem Bones' measure)."""
    out = os.path.join(out_dir, "dem-bones.glb")
    run = subprocess.run([trimlab_exe, "skin", folder, "--bones", str(bones), "-o", out],
                         capture_output=True, text=True)
    check(run.returncode == 0, f"trimlab skin failed: {run.stderr}")
    found = re.search(r"RMSE exported: (\S+)", run.stdout)
    check(found is not None, f"no RMSE line in: {run.stdout}")
    return float(found.group(1))


# The Dem Bones sample (754 vertices, 400 frames) skinned with 5 bones by the operator plays
# in Blender, frame by frame, with the RMSE the command line prints for the same fit: the
# skin Blender evaluates is the one the command line exports.
def test_skin_dem_bones_plays_with_the_cli_rmse():
    clear_scene()
    folder = os.path.join(shared_dir, "anim", "dem-bones", "frames")
    expected = cli_exported_rmse(folder, 5)
    result = bpy.ops.object.trimlab_skin_from_cache(source="FOLDER", directory=folder, bones=5)
    check(result == {"FINISHED"}, "skin of the Dem Bones sample did not finish")
    poses, F = trimlab.load_animation(folder)
    skinned = next(o for o in bpy.data.objects if o.name.endswith("skinned"))
    squared = 0.0
    for t in range(len(poses)):
        bpy.context.scene.frame_set(t + 1)
        squared += float(((evaluated_vertices(skinned) - poses[t]) ** 2).sum())
    played = np.sqrt(squared / (poses.shape[0] * poses.shape[1]))
    print(f"Dem Bones, 5 bones: RMSE played in Blender {played:.6g}, printed by trimlab skin {expected:.6g}")
    # Both measure float32 skins (Blender's deform, the exported file's joints): they agree to
    # a few 1e-5 of the error; a different fit or a mis-bound group is off by far more.
    check(abs(played - expected) <= 2e-4 * expected,
          f"Blender plays RMSE {played:.6g}, trimlab skin printed {expected:.6g}")


def test_skin_error_is_a_report():
    clear_scene()
    folder = os.path.join(data_dir, "animations", "bar")
    poses, F = trimlab.load_animation(folder)
    try:
        bpy.ops.object.trimlab_skin_from_cache(source="FOLDER", directory=folder, bones=poses.shape[1] + 1)
    except RuntimeError as error:
        check("segments" in str(error) or "bones" in str(error), f"unexpected report: {error}")
        return
    raise AssertionError("skinning with more bones than vertices did not report an error")


def test_extract_skeleton():
    clear_scene()
    V, F = trimlab.load("demo:nurbs-torus")
    obj = object_from_arrays("torus", V, F)
    activate(obj)
    check(bpy.ops.object.trimlab_extract_skeleton(nodes=8) == {"FINISHED"}, "skeleton did not finish")
    arm = next(o for o in bpy.data.objects if o.type == "ARMATURE")
    expected = trimlab.skeleton(V, F, nodes=8)
    check(len(expected["bones"]) >= 2, "the torus's rig has several bones")
    roots = [b for b in arm.data.bones if b.parent is None]
    check(len(roots) == 1, f"{len(roots)} root bones, expected one")
    check(len(arm.data.bones) == len(expected["bones"]) + 1, "one bone per rig bone and the root")
    rest = evaluated_vertices(obj)
    check(np.abs(rest - mesh_vertices(obj.data)).max() < 1e-6, "the rest pose moves the mesh")
    for bone in arm.pose.bones[1:]:
        bone.rotation_quaternion = (0.9, 0.3, 0.0, 0.0)
    bpy.context.view_layer.update()
    check(np.abs(evaluated_vertices(obj) - rest).max() > 1e-4, "posing the bones does not move the mesh")
    groups = {g.name for g in obj.vertex_groups}
    check(all(b.name in groups for b in arm.data.bones if b.parent is not None), "a bone without its vertex group")
    for b in arm.pose.bones:
        b.matrix_basis.identity()
    bpy.context.view_layer.update()
    check(np.abs(evaluated_vertices(obj) - rest).max() < 1e-6, "the cleared pose leaves an offset")


def import_gltf(path):
    """Blender's own glTF importer. Debian 12's Blender still names numpy's removed
    np.bool in it; the alias (numpy's own bool) lets the real importer run."""
    if "bool" not in np.__dict__:
        np.bool = bool
    check(bpy.ops.import_scene.gltf(filepath=path) == {"FINISHED"}, f"Blender did not import {path}")


# The rig `trimlab skeleton` writes opens in Blender in its rest position: one root bone, no
# pose on any bone, and clearing the pose leaves every vertex where the file's mesh is
# (before, the root's translation became a pose on 4 root bones and Clear Pose moved the
# cat by 29 % of its size).
def test_cli_rig_opens_in_rest_pose():
    clear_scene()
    mesh = os.path.join(shared_dir, "static", "odedstein-cat-low-resolution.obj.gz")
    out = os.path.join(out_dir, "cat-rig.glb")
    run = subprocess.run([trimlab_exe, "skeleton", mesh, "-o", out], capture_output=True, text=True)
    check(run.returncode == 0, f"trimlab skeleton failed: {run.stderr}")
    bones = int(re.search(r"(\d+) bones", run.stdout).group(1))
    import_gltf(out)
    arm = next(o for o in bpy.data.objects if o.type == "ARMATURE")
    obj = next(o for o in bpy.data.objects if o.type == "MESH")
    roots = [b.name for b in arm.data.bones if b.parent is None]
    check(roots == ["root"], f"root bones {roots}, expected one named root")
    check(len(arm.data.bones) == bones + 1, f"{len(arm.data.bones)} Blender bones for {bones} rig bones and the root")
    posed = [b.name for b in arm.pose.bones if np.abs(np.array(b.matrix_basis) - np.eye(4)).max() > 1e-5]
    check(not posed, f"bones imported with a pose: {posed[:5]}")
    V, _ = trimlab.load(mesh)
    file_mesh = V[:, [0, 2, 1]] * np.array([1.0, -1.0, 1.0])  # glTF's +Y up as Blender's +Z up
    world = np.array(obj.matrix_world)
    rest = evaluated_vertices(obj) @ world[:3, :3].T + world[:3, 3]
    diagonal = np.linalg.norm(file_mesh.max(axis=0) - file_mesh.min(axis=0))
    check(np.abs(rest - file_mesh).max() < 1e-5 * diagonal, "the imported rest pose moves the mesh")
    for b in arm.pose.bones:
        b.matrix_basis.identity()
    bpy.context.view_layer.update()
    cleared = evaluated_vertices(obj) @ world[:3, :3].T + world[:3, 3]
    check(np.abs(cleared - file_mesh).max() < 1e-5 * diagonal, "clearing the pose moves the mesh")
    names = {b.name for b in arm.pose.bones}
    check("spine_1" in names and not any(n.startswith("bone_") for n in names),
          f"bones named by body part, not number: {sorted(names)}")
    arm.pose.bones["spine_1"].rotation_quaternion = (0.9, 0.3, 0.0, 0.0)
    bpy.context.view_layer.update()
    check(np.abs(evaluated_vertices(obj) - rest).max() > 1e-3 * diagonal, "posing a bone does not move the mesh")


# An animation trimmed pose by pose as one glTF (`trimlab trim ANIM --poses A:B -o x.glb`)
# plays in Blender: one object per pose, and at frame k (pose k at k/24 s, Blender's
# 24 fps) pose k alone has scale 1, with the volume the command line printed for it.
def test_cli_trimmed_poses_play_in_blender():
    clear_scene()
    source = os.path.join(data_dir, "animations", "folding_box")
    out = os.path.join(out_dir, "folding-box-poses.glb")
    run = subprocess.run([trimlab_exe, "trim", source, "--poses", "0:2", "-o", out], capture_output=True, text=True)
    check(run.returncode == 0, f"trimlab trim --poses failed: {run.stderr}")
    volumes = [float(v) for v in re.findall(r"pose \d+ -> .*volume (\S+)", run.stdout)]
    check(len(volumes) == 3, f"no volume per pose in: {run.stdout}")
    import_gltf(out)
    poses = sorted((o for o in bpy.data.objects if o.type == "MESH"), key=lambda o: o.name)
    check([o.name for o in poses] == ["pose_0000", "pose_0001", "pose_0002"], f"objects {[o.name for o in poses]}")
    scene = bpy.context.scene
    check(scene.render.fps == 24, f"scene fps {scene.render.fps}")
    for frame in range(3):
        scene.frame_set(frame)
        shown = [round(o.matrix_world.to_scale().x, 6) for o in poses]
        check(shown == [1.0 if k == frame else 0.0 for k in range(3)], f"frame {frame}: scales {shown}")
        obj = poses[frame]
        V = mesh_vertices(obj.data, obj.matrix_world)
        measured = trimlab.info(V, mesh_triangles(obj.data))["signed_volume"]
        check(abs(measured - volumes[frame]) <= 1e-5 * abs(volumes[frame]),
              f"pose {frame}: volume {measured} in Blender, {volumes[frame]} printed")


def main():
    check(hasattr(bpy.types, "TRIMLAB_MT_object"), "the TrimLab menu is not registered")
    tests = [value for key, value in sorted(globals().items()) if key.startswith("test_")]
    failed = 0
    for test in tests:
        try:
            test()
            print(f"PASS {test.__name__}")
        except Exception:
            failed += 1
            print(f"FAIL {test.__name__}")
            traceback.print_exc()
    addon_utils.disable("trimlab_blender", default_set=True)
    check(not hasattr(bpy.types, "TRIMLAB_MT_object"), "disabling leaves the menu registered")
    print(f"{len(tests) - failed} of {len(tests)} add-on tests passed")
    if failed:
        sys.exit(1)


main()
