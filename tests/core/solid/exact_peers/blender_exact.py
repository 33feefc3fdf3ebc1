# One boolean of bench_exact through Blender's Exact solver (the Boolean modifier, as a
# user applies it), run as a whole process like `trimlab trim`. A benchmark-only peer:
#   blender -b --factory-startup --python blender_exact.py -- OUT.obj A.obj [B.obj]
# With B: A minus B. Without: A's self-union (the modifier's Self Intersection option
# with an empty operand collection), which keeps the points of nonzero winding. Prints
# one line: "blender volume V ms T triangles N" (T: the modifier applied, import and
# export excluded).
import sys
import time

import bmesh
import bpy


def import_obj(path):
    bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    return bpy.context.selected_objects[0]


def volume_and_triangles(obj):
    mesh = bmesh.new()
    mesh.from_mesh(obj.data)
    bmesh.ops.triangulate(mesh, faces=mesh.faces[:])
    result = mesh.calc_volume(signed=True), len(mesh.faces)
    mesh.free()
    return result


def main(arguments):
    output, inputs = arguments[0], arguments[1:]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    target = import_obj(inputs[0])
    modifier = target.modifiers.new("bench", "BOOLEAN")
    modifier.solver = "EXACT"
    if len(inputs) > 1:
        modifier.operation = "DIFFERENCE"
        modifier.object = import_obj(inputs[1])
    else:
        modifier.operation = "UNION"
        modifier.operand_type = "COLLECTION"
        modifier.collection = bpy.data.collections.new("nothing")
        modifier.use_self = True
    bpy.context.view_layer.objects.active = target
    start = time.perf_counter()
    bpy.ops.object.modifier_apply(modifier="bench")
    ms = (time.perf_counter() - start) * 1000
    volume, triangles = volume_and_triangles(target)
    bpy.ops.object.select_all(action="DESELECT")
    target.select_set(True)
    bpy.ops.wm.obj_export(filepath=output, export_selected_objects=True, forward_axis="Y", up_axis="Z",
                          export_materials=False, export_normals=False, export_uv=False)
    print(f"blender volume {volume!r} ms {ms:.1f} triangles {triangles}")


main(sys.argv[sys.argv.index("--") + 1:])
