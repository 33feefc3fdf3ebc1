"""TrimLab from Python: self-trimming of self-intersecting surfaces by winding numbers.

Meshes travel as NumPy arrays: vertices V (n, 3) float64, triangles F (m, 3) int32
(counter-clockwise seen from outside), animations as poses (k, n, 3) float64. Every
function runs the same core code as the `trimlab` command line and the GUI panels:

    load, load_scene, save, info, winding_numbers, demos     meshes and their report
    close_holes                                             an open mesh closed for the trim rules
    trim, trim_poses, save_poses                            the exact trimmed solid (CSG too), pose by pose
    render                                                  CPU reference or OpenGL images
    load_animation, segment, skin                           mesh animations, skinning fits
    skeleton, fit_rig                                       curve skeleton, rig, weights; the rig fitted to motion
    parameters                                              the tables keywords take their ranges from

Long functions release the GIL and take progress=callable(stage, done, total); an
exception raised by the callback stops the work and reaches the caller, and a callback
that returns False stops it with trimlab.Cancelled. Errors derive
from trimlab.Error (see help(trimlab.Error) and the classes beside it).
"""

from ._trimlab import (
    Cancelled,
    Error,
    InputError,
    MeshLoadError,
    MeshSaveError,
    NotTrimmableError,
    ParameterError,
    RenderError,
    SegmentationInputError,
    SkeletonInputError,
    SkinningBonesError,
    SkinningFit,
    close_holes,
    demos,
    fit_rig,
    info,
    load,
    load_animation,
    load_scene,
    parameters,
    render,
    save,
    save_poses,
    segment,
    skeleton,
    skin,
    trim,
    trim_poses,
    winding_numbers,
)

__all__ = [
    "Cancelled",
    "Error",
    "InputError",
    "MeshLoadError",
    "MeshSaveError",
    "NotTrimmableError",
    "ParameterError",
    "RenderError",
    "SegmentationInputError",
    "SkeletonInputError",
    "SkinningBonesError",
    "SkinningFit",
    "close_holes",
    "demos",
    "fit_rig",
    "info",
    "load",
    "load_animation",
    "load_scene",
    "parameters",
    "render",
    "save",
    "save_poses",
    "segment",
    "skeleton",
    "skin",
    "trim",
    "trim_poses",
    "winding_numbers",
]
