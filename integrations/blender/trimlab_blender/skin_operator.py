"""Skin from Mesh Cache: a mesh animation — an OBJ (or PLY, OFF, STL) sequence folder, or
the active object's shape keys — fitted by trimlab.skin with rigid joints, and built as
an armature (one bone per joint), a skinned mesh in the fit's rest pose with one vertex
group per bone, and an action keying every bone at every pose (frame 1 is pose 0)."""

import bpy
import numpy as np
from mathutils import Matrix

from .mesh_arrays import mesh_triangles, new_mesh, shape_key_poses
from .operator_run import run_reporting
from .table_properties import int_property
from .vertex_groups import add_armature_weights


def _bone_heads(rest, labels, count):
    """Each bone's head at the centroid of the vertices it starts from."""
    heads = np.zeros((count, 3))
    for b in range(count):
        members = rest[labels == b]
        heads[b] = members.mean(axis=0) if len(members) else rest.mean(axis=0)
    return heads


def build_armature(context, name, rest, labels, count, matrix):
    data = bpy.data.armatures.new(name)
    armature = bpy.data.objects.new(name, data)
    context.collection.objects.link(armature)
    armature.matrix_world = matrix
    size = float(np.linalg.norm(rest.max(axis=0) - rest.min(axis=0))) * 0.05 or 0.1
    previous = context.view_layer.objects.active
    context.view_layer.objects.active = armature
    bpy.ops.object.mode_set(mode="EDIT")
    for b, head in enumerate(_bone_heads(rest, labels, count)):
        bone = data.edit_bones.new(f"Bone.{b:03d}")
        bone.head = head
        bone.tail = head + np.array([0.0, 0.0, size])
    bpy.ops.object.mode_set(mode="OBJECT")
    context.view_layer.objects.active = previous
    return armature


def _fcurves(action, bone, path, values, frames):
    """One F-curve per component of `values` (k, c), keyed at `frames`."""
    for index in range(values.shape[1]):
        curve = action.fcurves.new(f'pose.bones["{bone}"].{path}', index=index, action_group=bone)
        curve.keyframe_points.add(len(frames))
        curve.keyframe_points.foreach_set("co", np.column_stack([frames, values[:, index]]).ravel())
        curve.update()


def build_action(armature, transforms):
    """Pose t, bone b: basis = R⁻¹ M R, so that the bone moves its rest pose by M (t, b)."""
    action = bpy.data.actions.new(f"{armature.name} action")
    armature.animation_data_create().action = action
    frames = np.arange(1, len(transforms) + 1, dtype=np.float64)
    for b, bone in enumerate(armature.data.bones):
        rest = bone.matrix_local
        inverse = rest.inverted()
        locations, rotations, scales = [], [], []
        for t in range(len(transforms)):
            basis = inverse @ Matrix(transforms[t, b].tolist()) @ rest
            location, rotation, scale = basis.decompose()
            if rotations and np.dot(rotations[-1], rotation) < 0:
                rotation.negate()  # the shorter way between keys
            locations.append(tuple(location))
            rotations.append(tuple(rotation))
            scales.append(tuple(scale))
        _fcurves(action, bone.name, "location", np.array(locations), frames)
        _fcurves(action, bone.name, "rotation_quaternion", np.array(rotations), frames)
        _fcurves(action, bone.name, "scale", np.array(scales), frames)
    return action


class TRIMLAB_OT_skin_from_cache(bpy.types.Operator):
    """Fit a skinned animation (armature, weights, action) to a mesh cache"""

    bl_idname = "object.trimlab_skin_from_cache"
    bl_label = "Skin from Mesh Cache"
    bl_options = {"REGISTER", "UNDO"}

    source: bpy.props.EnumProperty(
        name="Source",
        items=[("FOLDER", "Sequence folder", "A folder of OBJ (PLY, OFF, STL) poses, one file per frame"),
               ("SHAPE_KEYS", "Shape keys", "The active object's shape keys, the basis as the rest pose")],
        default="FOLDER",
    )
    directory: bpy.props.StringProperty(name="Folder", subtype="DIR_PATH", default="")
    bones: int_property("skin", "bones", "Bones", 8)

    def invoke(self, context, event):
        return context.window_manager.invoke_props_dialog(self)

    def poses(self, context, trimlab):
        if self.source == "FOLDER":
            folder = bpy.path.abspath(self.directory)
            return (*trimlab.load_animation(folder), folder.rstrip("/").split("/")[-1] or "animation",
                    Matrix.Identity(4))
        obj = context.active_object
        if obj is None or obj.type != "MESH" or obj.data.shape_keys is None:
            raise ValueError("the active object has no shape keys")
        return shape_key_poses(obj.data), mesh_triangles(obj.data), obj.name, obj.matrix_world.copy()

    def execute(self, context):
        def work(trimlab, progress):
            poses, F, name, matrix = self.poses(context, trimlab)
            return poses, F, name, matrix, trimlab.skin(poses, F, bones=self.bones, name=name, progress=progress)

        result = run_reporting(self, context, work)
        if result is None:
            return {"CANCELLED"}
        poses, F, name, matrix, fit = result
        rest = fit.rest_positions
        armature = build_armature(context, f"{name} rig", rest, fit.labels, fit.bone_count, matrix)
        obj = bpy.data.objects.new(f"{name} skinned", new_mesh(f"{name} skinned", rest, F))
        context.collection.objects.link(obj)
        obj.matrix_world = matrix
        add_armature_weights(obj, armature, fit.weights, [bone.name for bone in armature.data.bones],
                             "TrimLab Armature")
        build_action(armature, fit.transforms)
        context.scene.frame_start, context.scene.frame_end = 1, len(poses)
        obj["trimlab_e_rms"] = fit.error["e_rms"]
        self.report({"INFO"}, f"TrimLab: {fit.bone_count} bones, E_RMS {fit.error['e_rms']:.4f}")
        return {"FINISHED"}
