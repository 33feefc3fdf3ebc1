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


def test_fit_rig_follows_a_rigid_motion_of_the_mesh(torus):
    V, F = torus
    rig = trimlab.skeleton(V, F, nodes=8)
    turn = np.radians(25.0)
    R = np.array([[np.cos(turn), -np.sin(turn), 0.0], [np.sin(turn), np.cos(turn), 0.0], [0.0, 0.0, 1.0]])
    moved = V @ R.T + np.array([0.3, -0.1, 0.2])
    fit = trimlab.fit_rig(rig, np.stack([V, moved]))
    bones = len(rig["bones"])
    assert fit["rotations"].shape == (2, bones, 4) and fit["root_translations"].shape == (2, 3)
    assert fit["per_pose"][0] == 0.0
    # One rotation for every bone and the root's translation reproduce a rigid motion.
    assert fit["e_rms_diagonal"] < 1e-3, fit["e_rms_diagonal"]
    # Rotations are each bone's own, relative to its parent: the root's bones turn, the others stay.
    at_root = rig["bone_parents"] == -1
    z = np.abs(fit["rotations"][1, :, 3])
    assert np.allclose(z[at_root], np.sin(turn / 2), atol=1e-3) and np.allclose(z[~at_root], 0.0, atol=1e-3)


def test_fit_rig_refuses_poses_of_another_mesh(torus):
    V, F = torus
    rig = trimlab.skeleton(V, F, nodes=6)
    with pytest.raises(trimlab.InputError, match=f"pose 0 has 3 vertices, the weights {len(V)}"):
        trimlab.fit_rig(rig, np.stack([V[:3], V[:3]]))
    with pytest.raises(trimlab.ParameterError, match="rest_pose 2 is not one of the 1 poses"):
        trimlab.fit_rig(rig, V[np.newaxis], rest_pose=2)
    with pytest.raises(trimlab.InputError, match="no 'weights'"):
        trimlab.fit_rig({k: v for k, v in rig.items() if k != "weights"}, V[np.newaxis])
