"""Object ▸ TrimLab: the add-on's operators."""

import bpy


class TRIMLAB_MT_object(bpy.types.Menu):
    bl_idname = "TRIMLAB_MT_object"
    bl_label = "TrimLab"

    def draw(self, context):
        layout = self.layout
        layout.operator("object.trimlab_self_trim")
        layout.operator("object.trimlab_boolean")
        layout.separator()
        layout.operator("object.trimlab_skin_from_cache")
        layout.operator("object.trimlab_extract_skeleton")


def draw_object_menu(self, context):
    self.layout.menu(TRIMLAB_MT_object.bl_idname)
