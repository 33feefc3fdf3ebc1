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
