"""trim: the exact trimmed solid, identical to `trimlab trim` on the same input, CSG of
several objects, and its refusals; progress and cancellation through the callback."""

import numpy as np
import pytest

import trimlab


@pytest.fixture(scope="module")
def pushed():
    return trimlab.load("demo:pushed-sphere")


def test_trim_is_the_command_lines_mesh_vertex_for_vertex(pushed, run_cli, tmp_path_factory):
    path = tmp_path_factory.mktemp("trim") / "pushed.obj"
    code, stdout, stderr = run_cli("trim", "demo:pushed-sphere", "--rule", "alternating-border", "-o", str(path))
    assert code == 0, stderr
    V, F = trimlab.trim(*pushed, rule="alternating-border")
    Vc, Fc = trimlab.load(str(path))
    assert V.shape == Vc.shape and F.shape == Fc.shape
    assert np.array_equal(V, Vc) and np.array_equal(F, Fc)
    report = trimlab.info(V, F)
    assert report["closed"] and report["trimmable"]
    printed = float(stdout.split("volume ")[1].split()[0])
    assert report["signed_volume"] == pytest.approx(printed, rel=1e-7)


def test_rules_keep_different_solids(pushed):
    volumes = {rule: trimlab.info(*trimlab.trim(*pushed, rule=rule))["signed_volume"]
               for rule in ("parity", "nonzero", "alternating-border")}
    assert all(v > 0 for v in volumes.values())
    assert volumes["nonzero"] >= volumes["parity"] - 1e-9


def test_stats_report_a_closed_result(pushed):
    V, F, stats = trimlab.trim(*pushed, stats=True)
    assert stats["open_edges"] == 0 and stats["signed_volume"] > 0 and stats["kept_faces"] > 0


def test_csg_of_two_objects(data):
    V, F = trimlab.load(str(data / "meshes" / "cube.obj"))
    shifted = V + (V.max(axis=0) - V.min(axis=0)) * 0.5
    cube = trimlab.info(V, F)["signed_volume"]
    union = trimlab.info(*trimlab.trim([(V, F), (shifted, F)], csg="0 | 1"))["signed_volume"]
    difference = trimlab.info(*trimlab.trim([(V, F), (shifted, F)], csg="0 - 1", rules={1: "parity"}))
    assert union == pytest.approx(cube * (2 - 1 / 8))
    assert difference["signed_volume"] == pytest.approx(cube * 7 / 8)
    assert difference["closed"]


def test_refusals_name_the_problem(data, pushed):
    V, F = pushed
    with pytest.raises(trimlab.InputError, match="unknown rule 'odd'"):
        trimlab.trim(V, F, rule="odd")
    with pytest.raises(trimlab.InputError, match="csg refers to object 1, but the scene has 1 object"):
        trimlab.trim(V, F, csg="0 - 1")
    with pytest.raises(trimlab.InputError, match="csg '0 -': "):
        trimlab.trim([(V, F)], csg="0 -")
    with pytest.raises(trimlab.NotTrimmableError, match="closed surface"):
        trimlab.trim(*trimlab.load(str(data / "meshes" / "open_square.obj")))


def test_progress_is_reported_and_an_exception_from_it_cancels(pushed):
    stages = []
    trimlab.trim(*pushed, progress=lambda stage, done, total: stages.append(stage))
    assert stages

    class Stop(Exception):
        pass

    def stop(stage, done, total):
        raise Stop(stage)

    with pytest.raises(Stop):
        trimlab.trim(*pushed, progress=stop)

    with pytest.raises(trimlab.Cancelled):
        trimlab.trim(*pushed, progress=lambda stage, done, total: False)


def test_trim_with_clip_planes_cuts_and_caps():
    V, F = trimlab.load("demo:pushed-sphere")
    _, _, whole = trimlab.trim(V, F, stats=True)
    Vf, Ff, front = trimlab.trim(V, F, clip=[(0.3, 0.0, -1.0, 0.1)], stats=True)
    _, _, back = trimlab.trim(V, F, clip=[(-0.3, 0.0, 1.0, -0.1)], stats=True)
    assert front["open_edges"] == 0 and trimlab.info(Vf, Ff)["trimmable"]
    assert 0 < front["signed_volume"] < whole["signed_volume"]
    assert front["signed_volume"] + back["signed_volume"] == pytest.approx(whole["signed_volume"], rel=1e-5)
    with pytest.raises(trimlab.InputError):
        trimlab.trim(V, F, clip=[(0.0, 0.0, 0.0, 1.0)])
    with pytest.raises(trimlab.InputError):
        trimlab.trim(V, F, clip=[(1.0, 0.0, 0.0)])


@pytest.fixture(scope="module")
def folding(data):
    return trimlab.load_animation(str(data / "animations" / "folding_box"))


def test_trim_poses_is_the_command_lines_poses_vertex_for_vertex(folding, data, run_cli, tmp_path_factory):
    out = tmp_path_factory.mktemp("poses")
    source = str(data / "animations" / "folding_box")
    code, stdout, stderr = run_cli("trim", source, "--poses", "1:2", "--rule", "nonzero", "-o", str(out / "p_%04d.obj"))
    assert code == 0, stderr
    trimmed = trimlab.trim_poses(*folding, rule="nonzero", first=1)
    assert len(trimmed) == 2
    for pose, (V, F) in zip((1, 2), trimmed):
        Vc, Fc = trimlab.load(str(out / f"p_{pose:04d}.obj"))
        assert np.array_equal(V, Vc) and np.array_equal(F, Fc)


def test_each_pose_is_trimmed_on_its_own(folding):
    poses, F = folding
    trimmed = trimlab.trim_poses(poses, F, rule="parity", stats=True)
    assert len(trimmed) == len(poses)
    volumes = []
    for pose, (V, Ft, stats) in zip(poses, trimmed):
        Vs, Fs = trimlab.trim(pose, F, rule="parity")
        assert np.array_equal(V, Vs) and np.array_equal(Ft, Fs)
        assert stats["open_edges"] == 0
        volumes.append(stats["signed_volume"])
    assert len(set(volumes)) == len(volumes)  # the box folds: every pose keeps another solid


def test_trim_poses_cuts_every_pose_with_the_clip_planes(folding):
    poses, F = folding
    plane = [(0.0, 0.0, 1.0, 0.0)]
    for pose, (V, Ft, stats) in zip(poses, trimlab.trim_poses(poses, F, clip=plane, stats=True)):
        _, _, whole = trimlab.trim(pose, F, stats=True)
        _, _, cut = trimlab.trim(pose, F, clip=plane, stats=True)
        assert stats["signed_volume"] == pytest.approx(cut["signed_volume"], rel=1e-12)
        assert stats["open_edges"] == 0 and 0 < stats["signed_volume"] < whole["signed_volume"]


def test_trim_poses_refusals_name_the_problem(folding, data):
    poses, F = folding
    with pytest.raises(trimlab.InputError, match=r"poses 2 to 5: the animation has 3 poses \(0 to 2\)"):
        trimlab.trim_poses(poses, F, first=2, last=5)
    with pytest.raises(trimlab.InputError, match="poses 2 to 1"):
        trimlab.trim_poses(poses, F, first=2, last=1)
    with pytest.raises(trimlab.InputError, match="unknown rule 'confluent'"):
        trimlab.trim_poses(poses, F, rule="confluent")
    open_poses, open_F = trimlab.load_animation(str(data / "animations" / "bar"))
    with pytest.raises(trimlab.NotTrimmableError, match=r"pose 0 has no inside to trim: .*close_holes=True"):
        trimlab.trim_poses(open_poses, open_F)
    closed_poses, closed_F = trimlab.load_animation(str(data / "animations" / "bar"), close_holes=True)
    assert len(trimlab.trim_poses(closed_poses, closed_F)) == len(closed_poses)


def test_trim_poses_reports_every_pose_and_stops_when_asked(folding):
    reports = []
    trimlab.trim_poses(*folding, progress=lambda stage, done, total: reports.append((stage, done, total)))
    assert [r for r in reports if r[0] == "poses"] == [("poses", k, 3) for k in range(4)]
    with pytest.raises(trimlab.Cancelled):
        trimlab.trim_poses(*folding, progress=lambda stage, done, total: False)


def test_save_poses_writes_the_command_lines_sequence(folding, data, run_cli, tmp_path_factory):
    out = tmp_path_factory.mktemp("sequence")
    source = str(data / "animations" / "folding_box")
    code, _, stderr = run_cli("trim", source, "--poses", "1:2", "--fps", "12", "-o", str(out / "cli.glb"))
    assert code == 0, stderr
    trimmed = trimlab.trim_poses(*folding, first=1, stats=True)
    trimlab.save_poses(str(out / "module.glb"), trimmed, fps=12, first=1,
                       comment="folding_box trimmed by alternating-border")
    assert (out / "module.glb").read_bytes() == (out / "cli.glb").read_bytes()


def test_save_poses_refusals_name_the_problem(folding, out):
    trimmed = trimlab.trim_poses(*folding)
    with pytest.raises(trimlab.InputError, match="at least one pose"):
        trimlab.save_poses(str(out / "none.glb"), [])
    with pytest.raises(trimlab.InputError, match=r"poses\[1\] must be \(V, F\)"):
        trimlab.save_poses(str(out / "bad.glb"), [trimmed[0], trimmed[1][0]])
    with pytest.raises(trimlab.InputError, match="obj"):
        trimlab.save_poses(str(out / "poses.obj"), trimmed)
    with pytest.raises(trimlab.ParameterError, match="fps"):
        trimlab.save_poses(str(out / "slow.glb"), trimmed, fps=0)
    assert not list(out.iterdir())
    with pytest.raises(trimlab.MeshSaveError):
        trimlab.save_poses(str(out / "missing" / "poses.glb"), trimmed)
