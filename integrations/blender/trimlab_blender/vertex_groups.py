"""Skinning weights on a Blender mesh: one vertex group per bone (the vertices it moves,
with their weights) and an armature modifier that plays them."""

import numpy as np


def add_armature_weights(obj, armature, weights, group_names, modifier_name):
    """weights: (#V, #groups); group_names: the bone of each column."""
    for b, name in enumerate(group_names):
        group = obj.vertex_groups.new(name=name)
        for j in np.nonzero(weights[:, b] > 0)[0]:
            group.add([int(j)], float(weights[j, b]), "REPLACE")
    modifier = obj.modifiers.new(modifier_name, "ARMATURE")
    modifier.object = armature
