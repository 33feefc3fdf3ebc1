"""Finding the trimlab module from Blender's Python: where it is installed, the folder
the add-on's preferences name, or TRIMLAB_PYTHONPATH."""

import os
import sys

import bpy

_ADDON = __package__


class TrimLabPreferences(bpy.types.AddonPreferences):
    bl_idname = _ADDON

    module_folder: bpy.props.StringProperty(
        name="trimlab module folder",
        description="The folder holding the trimlab package (e.g. build/python); empty: installed or "
        "TRIMLAB_PYTHONPATH",
        subtype="DIR_PATH",
        default="",
    )

    def draw(self, context):
        self.layout.prop(self, "module_folder")


def _folders(context):
    folders = []
    addon = context.preferences.addons.get(_ADDON) if context else None
    # While the add-on's modules import (its classes read trimlab's tables) the entry
    # exists but its preferences are not registered yet.
    preferences = getattr(addon, "preferences", None)
    if preferences is not None and preferences.module_folder:
        folders.append(bpy.path.abspath(preferences.module_folder))
    folders += [f for f in os.environ.get("TRIMLAB_PYTHONPATH", "").split(os.pathsep) if f]
    return folders


def import_trimlab(context=None):
    """The trimlab module; raises ImportError naming where it was looked for."""
    for folder in _folders(context or bpy.context):
        if folder not in sys.path:
            sys.path.insert(0, folder)
    try:
        import trimlab
    except ImportError as error:
        raise ImportError(
            "the trimlab module is not importable from Blender's Python "
            f"({sys.version.split()[0]}): install it with cmake --install, or set its folder in the "
            f"TrimLab add-on preferences or TRIMLAB_PYTHONPATH ({error})") from error
    return trimlab
