"""Blender properties from trimlab's parameter tables (trimlab.parameters), so that a
field's range, default and tooltip are the command line's. Without the module at
registration the field is unbounded and the module refuses bad values when it runs."""

import bpy

from .module_path import import_trimlab


def _row(operation, name):
    try:
        for row in import_trimlab().parameters(operation):
            if row["name"] == name:
                return row
    except ImportError:
        pass
    return None


def int_property(operation, name, label, fallback):
    row = _row(operation, name)
    if row is None:
        return bpy.props.IntProperty(name=label, default=fallback)
    return bpy.props.IntProperty(name=label, default=row["default"], min=int(row["min"]), max=int(row["max"]),
                                 description=row["help"])


def choice_property(operation, name, label, fallback):
    row = _row(operation, name)
    if row is None:
        return bpy.props.EnumProperty(name=label, items=[(fallback, fallback, "")], default=fallback)
    items = [(choice, text, "") for choice, text in row["choices"]]
    return bpy.props.EnumProperty(name=label, items=items, default=row["default"], description=row["help"])
