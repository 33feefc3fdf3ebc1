"""Extract Skeleton: trimlab.skeleton of the active mesh as an armature with one root
bone (at the rig's root joint; every bone of the rig hangs below it), one bone per rig
bone from its head joint to its tail joint, named by body part as trimlab names them
(spine_1, leg_L_2, ...), and the bone-heat weights as vertex groups
with an armature modifier. The bones' rest pose is the mesh as it is: with the pose
cleared the mesh does not move."""

import bpy
import numpy as np

from .mesh_arrays import mesh_triangles, mesh_vertices
from .operator_run import run_reporting
from .table_properties import int_property
from .vertex_groups import add_armature_weights

ROOT_BONE = "Root"


def build_rig(context, obj, result):
    joints, bones, parents = result["joints"], result["bones"], result["bone_parents"]
    data = bpy.data.armatures.new(f"{obj.name} skeleton")
    armature = bpy.data.objects.new(f"{obj.name} skeleton", data)
    for collection in obj.users_collection:
        collection.objects.link(armature)
    armature.matrix_world = obj.matrix_world.copy()
    size = float(np.linalg.norm(joints.max(axis=0) - joints.min(axis=0))) * 0.05 or 0.05
    previous = context.view_layer.objects.active
    context.view_layer.objects.active = armature
    bpy.ops.object.mode_set(mode="EDIT")
    root = data.edit_bones.new(ROOT_BONE)
    root.head = joints[result["root"]]
    root.tail = joints[result["root"]] + np.array([0.0, 0.0, size])
    edit = []
    for (head, tail), name in zip(bones, result["bone_names"]):
        bone = data.edit_bones.new(name)
        bone.head, bone.tail = joints[head], joints[tail]
        edit.append(bone)
    for b, parent in enumerate(parents):
        edit[b].parent = edit[parent] if parent >= 0 else root
        edit[b].use_connect = False
    bpy.ops.object.mode_set(mode="OBJECT")
    context.view_layer.objects.active = previous
    return armature


class TRIMLAB_OT_extract_skeleton(bpy.types.Operator):
    """Extract a skeleton from the active closed mesh: an armature with bone-heat weights"""

    bl_idname = "object.trimlab_extract_skeleton"
    bl_label = "Extract Skeleton"
    bl_options = {"REGISTER", "UNDO"}

    nodes: int_property("skeleton", "nodes", "Joints", 30)

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"

    def execute(self, context):
        obj = context.active_object
        V, F = mesh_vertices(obj.data), mesh_triangles(obj.data)
        result = run_reporting(self, context, lambda t, progress: t.skeleton(V, F, nodes=self.nodes, progress=progress))
        if result is None:
            return {"CANCELLED"}
        armature = build_rig(context, obj, result)
        weights = result["weights"]
        add_armature_weights(obj, armature, weights, list(result["bone_names"]),
                             "TrimLab Skeleton")
        self.report({"INFO"}, f"TrimLab: {len(result['bones'])} bones below one root")
        return {"FINISHED"}
