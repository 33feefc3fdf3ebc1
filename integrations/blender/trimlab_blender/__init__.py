"""TrimLab in Blender: exact self-trimming and Booleans by winding numbers, skinning of
mesh caches and skeleton extraction, through the `trimlab` Python module.

Install by copying this folder (or a zip of it) into Blender's add-on folder and
enabling "TrimLab" in Preferences ▸ Add-ons. The add-on imports `trimlab` from Blender's
Python: install the module (`cmake --install build`), or name the folder that holds
it (build/python) in the add-on's preferences or in TRIMLAB_PYTHONPATH.
"""

bl_info = {
    "name": "TrimLab",
    "author": "TrimLab",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D ▸ Object ▸ TrimLab",
    "description": "Exact self-trimming and Booleans by winding numbers, skinning of mesh caches, skeletons",
    "category": "Mesh",
}

import bpy

from . import menu, module_path, skeleton_operator, skin_operator, trim_operators

classes = (
    module_path.TrimLabPreferences,
    trim_operators.TRIMLAB_OT_self_trim,
    trim_operators.TRIMLAB_OT_boolean,
    skin_operator.TRIMLAB_OT_skin_from_cache,
    skeleton_operator.TRIMLAB_OT_extract_skeleton,
    menu.TRIMLAB_MT_object,
)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.VIEW3D_MT_object.append(menu.draw_object_menu)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(menu.draw_object_menu)
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
