"""skeleton: the curve skeleton, the rig with one root and its bone-heat weights, and
the table's ranges for its keywords."""

import numpy as np
import pytest

import trimlab


@pytest.fixture(scope="module")
def torus():
    return trimlab.load("demo:nurbs-torus")


def test_skeleton_gives_a_rooted_rig_and_weights(torus):
    V, F = torus
    result = trimlab.skeleton(V, F, nodes=8)
    joints, parents, bones = result["joints"], result["parents"], result["bones"]
    assert len(bones) >= 2
    assert joints.shape[1] == 3 and len(parents) == len(joints)
    assert (parents == -1).sum() == 1 and parents[result["root"]] == -1
    assert bones.shape == (len(joints) - 1, 2)
    assert result["weights"].shape == (len(V), len(bones))
    assert np.allclose(result["weights"].sum(axis=1), 1.0, atol=1e-5)
    assert result["nodes"].shape[1] == 3 and result["edges"].shape[1] == 2
    names = result["bone_names"]
    assert len(names) == len(bones) and len(set(names)) == len(names) and "spine_1" in names


def test_skeleton_refuses_values_outside_the_table(torus):
    V, F = torus
    with pytest.raises(trimlab.ParameterError, match="nodes must be an integer from 2 to"):
        trimlab.skeleton(V, F, nodes=1)
    with pytest.raises(trimlab.ParameterError, match="root 5 is not one of the 4 joints"):
        trimlab.skeleton(V, F, nodes=4, root=5)
    with pytest.raises(trimlab.ParameterError, match="refine must be True or False"):
        trimlab.skeleton(V, F, refine="yes")


def test_skeleton_refuses_an_open_mesh(data):
    with pytest.raises(trimlab.SkeletonInputError):
        trimlab.skeleton(*trimlab.load(str(data / "meshes" / "open_square.obj")))
