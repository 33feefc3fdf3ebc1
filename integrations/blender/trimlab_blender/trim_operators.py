"""Self-Trim and Boolean: the exact trimmed solid (trimlab.trim) of the active mesh, or
of the selected meshes combined by a CSG expression, as a new closed mesh."""

import bpy

from .mesh_arrays import mesh_triangles, mesh_vertices, new_mesh
from .operator_run import run_reporting

# The static rules by their command-line names (trimlab trim --rule).
RULES = [
    ("alternating-border", "Alternating border", "In where ceil(w/2) is odd: w mod 4 in {1, 2}"),
    ("parity", "Parity", "In where the winding number is odd"),
    ("positive-index", "Positive index", "In where w >= 1"),
    ("nonzero", "Nonzero", "In where w != 0 (Blender's exact self-union keeps these)"),
    ("negative", "Negative", "In where w < 0"),
]


def _link_like(context, source, name, mesh, matrix):
    obj = bpy.data.objects.new(name, mesh)
    for collection in (source.users_collection if source else [context.collection]):
        collection.objects.link(obj)
    obj.matrix_world = matrix
    return obj


class TRIMLAB_OT_self_trim(bpy.types.Operator):
    """Replace (or duplicate) the active mesh with its exact trimmed solid under a rule"""

    bl_idname = "object.trimlab_self_trim"
    bl_label = "Self-Trim"
    bl_options = {"REGISTER", "UNDO"}

    rule: bpy.props.EnumProperty(name="Rule", items=RULES, default="alternating-border")
    mode: bpy.props.EnumProperty(
        name="Result",
        items=[("REPLACE", "Replace", "Give the active object the trimmed mesh"),
               ("DUPLICATE", "Duplicate", "Add a new object with the trimmed mesh")],
        default="REPLACE",
    )

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"

    def execute(self, context):
        obj = context.active_object
        V, F = mesh_vertices(obj.data), mesh_triangles(obj.data)
        result = run_reporting(self, context, lambda t, progress: t.trim(V, F, rule=self.rule, progress=progress))
        if result is None:
            return {"CANCELLED"}
        mesh = new_mesh(f"{obj.data.name} trimmed", *result)
        if self.mode == "REPLACE":
            obj.data = mesh
        else:
            duplicate = _link_like(context, obj, f"{obj.name} trimmed", mesh, obj.matrix_world.copy())
            context.view_layer.objects.active = duplicate
        self.report({"INFO"}, f"TrimLab: {len(result[1])} triangles, {self.rule}")
        return {"FINISHED"}


class TRIMLAB_OT_boolean(bpy.types.Operator):
    """Combine the selected meshes by a CSG expression over their ids (the active object is 0, the
    others follow by name), each classified by the rule; the exact result as a new object"""

    bl_idname = "object.trimlab_boolean"
    bl_label = "Boolean of Selected"
    bl_options = {"REGISTER", "UNDO"}

    expression: bpy.props.StringProperty(
        name="Expression", default="0 - 1",
        description="Object ids with | (union), & (intersection), - (difference) and parentheses")
    rule: bpy.props.EnumProperty(name="Rule", items=RULES, default="nonzero")

    @classmethod
    def poll(cls, context):
        return sum(1 for o in context.selected_objects if o.type == "MESH") >= 2

    @staticmethod
    def operands(context):
        """The selected meshes in id order: the active one, then the others by name."""
        active = context.active_object
        others = sorted((o for o in context.selected_objects if o.type == "MESH" and o != active),
                        key=lambda o: o.name)
        return ([active] if active and active.type == "MESH" and active.select_get() else []) + others

    def execute(self, context):
        objects = self.operands(context)
        meshes = [(mesh_vertices(o.data, o.matrix_world), mesh_triangles(o.data)) for o in objects]
        result = run_reporting(self, context, lambda t, progress: t.trim(
            meshes, csg=self.expression, rule=self.rule, progress=progress))
        if result is None:
            return {"CANCELLED"}
        from mathutils import Matrix

        mesh = new_mesh("TrimLab Boolean", *result)
        obj = _link_like(context, objects[0], "TrimLab Boolean", mesh, Matrix.Identity(4))
        context.view_layer.objects.active = obj
        self.report({"INFO"}, f"TrimLab: {self.expression} of {len(objects)} objects, {len(result[1])} triangles")
        return {"FINISHED"}
