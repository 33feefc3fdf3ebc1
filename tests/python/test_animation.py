"""load_animation, segment, skin: the pipelines the verbs run, their results as arrays,
and refusals in the command line's words (the same message for the same input)."""

import numpy as np
import pytest

import trimlab


@pytest.fixture(scope="module")
def bar(data):
    path = str(data / "animations" / "bar")
    poses, F = trimlab.load_animation(path)
    return path, poses, F


def cli_error(stderr):
    line = stderr.strip().splitlines()[-1]
    return line.removeprefix("trimlab: ").removeprefix("error: ")


def test_load_animation_gives_poses_and_triangles(bar):
    _, poses, F = bar
    assert poses.dtype == np.float64 and poses.ndim == 3 and poses.shape[2] == 3
    assert F.dtype == np.int32 and F.max() < poses.shape[1]


def test_a_broken_animation_raises_mesh_load_error(data):
    with pytest.raises(trimlab.MeshLoadError):
        trimlab.load_animation(str(data / "animations" / "mismatched_vertices"))


def test_segment_labels_every_vertex(bar):
    _, poses, F = bar
    result = trimlab.segment(poses, F, clusters=2)
    assert result["labels"].shape == (poses.shape[1],)
    assert 1 <= result["count"] <= poses.shape[1] and result["labels"].max() < result["count"]


def test_segment_refuses_one_pose_in_the_command_lines_words(bar):
    _, poses, F = bar
    with pytest.raises(trimlab.SegmentationInputError, match="walk: .*1 pose"):
        trimlab.segment(poses[:1], F, name="walk")


def test_skin_fits_weights_transforms_and_errors(bar, out):
    _, poses, F = bar
    fit = trimlab.skin(poses, F, bones=2, reconstruct=True)
    n, k = poses.shape[1], poses.shape[0]
    assert fit.bone_count == 2
    assert fit.weights.shape == (n, 2) and np.allclose(fit.weights.sum(axis=1), 1.0)
    assert fit.transforms.shape == (k, 2, 4, 4) and np.allclose(fit.transforms[:, :, 3], [0, 0, 0, 1])
    assert fit.approximation.shape == poses.shape
    assert fit.error["e_rms"] >= 0 and len(fit.error["per_pose"]) == k
    exported = fit.save_gltf(str(out / "bar.glb"))
    assert exported["joints"] == 2 and (out / "bar.glb").stat().st_size > 0
    reloaded, _ = trimlab.load_animation(str(out / "bar.glb"))
    assert reloaded.shape == poses.shape


def test_skin_matches_the_command_lines_error_on_the_same_input(bar, run_cli, out):
    path, poses, F = bar
    too_many = str(poses.shape[1] + 1)
    code, _, stderr = run_cli("skin", path, "--bones", too_many, "-o", str(out / "x.glb"))
    assert code == 1
    with pytest.raises(trimlab.SkinningBonesError) as caught:
        trimlab.skin(poses, F, bones=int(too_many), name=path)
    assert str(caught.value) == cli_error(stderr)


@pytest.mark.parametrize("keywords, arguments", [
    ({"bones": 0}, ["--bones", "0"]),
    ({"bones": 2, "method": "sad"}, ["--bones", "2", "--method", "sad"]),
    ({"bones": 2, "chain": "pose-to-pose"}, ["--bones", "2", "--chain", "pose-to-pose"]),
    ({"bones": 2, "influences": 9}, ["--bones", "2", "--influences", "9"]),
])
def test_skin_parameter_errors_are_the_command_lines(bar, run_cli, out, keywords, arguments):
    path, poses, F = bar
    code, _, stderr = run_cli("skin", path, *arguments, "-o", str(out / "x.glb"))
    assert code == 2
    with pytest.raises(trimlab.ParameterError) as caught:
        trimlab.skin(poses, F, **keywords)
    assert isinstance(caught.value, ValueError)
    assert str(caught.value) == cli_error(stderr).replace("--", "")


def test_skin_can_be_cancelled(bar):
    _, poses, F = bar

    def cancel(stage, done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        trimlab.skin(poses, F, bones=2, progress=cancel)


def test_load_animation_can_close_the_holes_of_every_pose(bar):
    path, poses, F = bar
    closed_poses, closed_F = trimlab.load_animation(path, close_holes=True)
    # The strip's one boundary loop of 10 edges: one centre per pose, ten fan triangles.
    assert closed_poses.shape == (poses.shape[0], poses.shape[1] + 1, 3)
    assert closed_F.shape == (len(F) + 10, 3)
    for pose, closed in zip(poses, closed_poses):
        assert np.array_equal(closed[:-1], pose)
        assert trimlab.info(closed, closed_F)["closed"]
    with pytest.raises(trimlab.ParameterError):
        trimlab.load_animation(path, close_holes="sometimes")
