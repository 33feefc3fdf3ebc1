"""load, load_scene, save, info, winding_numbers, demos: arrays in and out, and the
errors of bad files and bad arrays."""

import numpy as np
import pytest

import trimlab


def test_load_gives_float64_vertices_and_int32_triangles(data):
    V, F = trimlab.load(str(data / "meshes" / "cube.obj"))
    assert V.dtype == np.float64 and V.shape == (8, 3)
    assert F.dtype == np.int32 and F.shape == (12, 3)
    assert F.min() == 0 and F.max() == 7


@pytest.mark.parametrize("name", ["cube.off", "cube_ascii.ply", "cube_binary.stl", "cube.obj.gz"])
def test_every_format_loads_the_same_cube(data, name):
    V, F = trimlab.load(str(data / "meshes" / name))
    assert trimlab.info(V, F)["signed_volume"] == pytest.approx(trimlab.info(*trimlab.load(str(data / "meshes" / "cube.obj")))["signed_volume"])


def test_a_demo_loads_and_is_listed():
    assert "demo:pushed-sphere" in trimlab.demos()
    V, F = trimlab.load("demo:pushed-sphere")
    assert len(V) > 100 and trimlab.info(V, F)["closed"]


def test_a_bad_file_raises_mesh_load_error_naming_file_line_and_reason(data, run_cli):
    path = data / "broken"
    broken = sorted(p for p in path.iterdir() if p.suffix == ".obj")[0]
    with pytest.raises(trimlab.MeshLoadError) as caught:
        trimlab.load(str(broken))
    error = caught.value
    assert isinstance(error, trimlab.Error)
    assert error.file == str(broken) and error.reason and str(error).startswith(str(broken))
    code, _, stderr = run_cli("info", str(broken))
    assert code == 1 and str(error) in stderr


def test_a_missing_file_and_an_unknown_demo():
    with pytest.raises(trimlab.MeshLoadError, match="nonexistent"):
        trimlab.load("/nonexistent/mesh.obj")
    with pytest.raises(trimlab.InputError, match="demo"):
        trimlab.load("demo:no-such-demo")


def test_load_scene_returns_every_object(data):
    objects = trimlab.load_scene(str(data / "meshes" / "cube.obj"))
    assert len(objects) == 1 and objects[0][0].shape == (8, 3)


@pytest.mark.parametrize("suffix", ["obj", "ply", "stl", "glb", "gltf"])
def test_save_writes_what_load_reads(data, out, suffix):
    V, F = trimlab.load(str(data / "meshes" / "cube.obj"))
    path = out / f"cube.{suffix}"
    trimlab.save(str(path), V, F)
    V2, F2 = trimlab.load(str(path))
    assert trimlab.info(V2, F2)["signed_volume"] == pytest.approx(trimlab.info(V, F)["signed_volume"])


def test_save_refuses_unknown_formats_and_unwritable_folders(data, out):
    V, F = trimlab.load(str(data / "meshes" / "cube.obj"))
    with pytest.raises(trimlab.InputError, match="unknown mesh format"):
        trimlab.save(str(out / "cube.xyz"), V, F)
    with pytest.raises(trimlab.MeshSaveError):
        trimlab.save("/nonexistent/folder/cube.obj", V, F)


def test_bad_arrays_are_refused_with_their_shape_or_element():
    V = np.zeros((4, 3))
    with pytest.raises(trimlab.InputError, match=r"V must be an \(n, 3\).*shape \(4, 2\)"):
        trimlab.save("x.obj", np.zeros((4, 2)), [[0, 1, 2]])
    with pytest.raises(trimlab.InputError, match=r"F must be an \(m, 3\) integer array.*float64"):
        trimlab.winding_numbers(V, np.zeros((1, 3)), np.zeros((1, 3)))
    with pytest.raises(trimlab.InputError, match=r"F\[1\] = \(0, 1, 9\): vertex 9 does not exist \(V has 4"):
        trimlab.winding_numbers(V, [[0, 1, 2], [0, 1, 9]], np.zeros((1, 3)))
    with pytest.raises(ValueError, match="negative"):
        trimlab.winding_numbers(V, [[0, 1, -1]], np.zeros((1, 3)))


def test_info_is_the_command_lines_report(data, run_cli):
    path = str(data / "meshes" / "open_square.obj")
    report = trimlab.info(*trimlab.load(path), name="open_square.obj")
    assert not report["trimmable"] and report["defects"]["boundary_edges"]["count"] > 0
    assert "closed surface" in report["trim_unavailable_reason"]
    code, stdout, _ = run_cli("info", path)
    assert code == 0 and report["text"].strip() in stdout


def test_info_counts_out_of_range_faces_instead_of_refusing():
    report = trimlab.info(np.zeros((3, 3)), [[0, 1, 7]])
    assert report["defects"]["out_of_range_faces"] == {"count": 1, "first": [0]}


def test_winding_numbers_inside_and_outside(data):
    V, F = trimlab.load(str(data / "meshes" / "cube.obj"))
    center = V.mean(axis=0)
    w = trimlab.winding_numbers(V, F, [center, center + 10.0])
    assert w.shape == (2,) and w.dtype == np.float64
    assert w == pytest.approx([1.0, 0.0], abs=1e-9)


def test_output_triangles_share_their_buffer_with_the_result(data):
    V, F = trimlab.load(str(data / "meshes" / "cube.obj"))
    assert F.base is not None and not F.flags.owndata


def test_close_holes_makes_an_open_mesh_trimmable():
    V, F = trimlab.load("demo:sphere")
    closed_volume = trimlab.info(V, F)["signed_volume"]
    open_F = F[1:]
    report = trimlab.info(V, open_F)
    assert not report["trimmable"] and "--close-holes" in report["trim_unavailable_reason"]
    V2, F2 = trimlab.close_holes(V, open_F)
    assert V2.shape == (len(V) + 1, 3) and F2.shape == (len(F) + 2, 3)
    assert np.array_equal(V2[: len(V)], V) and np.array_equal(F2[: len(open_F)], open_F)
    assert np.allclose(V2[-1], V[F[0]].mean(axis=0))
    closed = trimlab.info(V2, F2)
    assert closed["trimmable"] and closed["genus"] == 0
    # The fan of a hole of three edges lies in the plane of the missing triangle.
    assert closed["signed_volume"] == pytest.approx(closed_volume, rel=1e-6)
    same_V, same_F = trimlab.close_holes(V, F)
    assert np.array_equal(same_V, V) and np.array_equal(same_F, F)


def test_close_holes_refuses_a_boundary_that_is_no_loop():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]], dtype=float)
    F = np.array([[0, 1, 2], [3, 1, 2]], dtype=np.int32)
    with pytest.raises(trimlab.InputError):
        trimlab.close_holes(V, F)


def test_close_holes_warns_where_a_fan_crosses_the_surface():
    # An open tube around z with a small tetrahedron through its top opening: the top
    # loop's fan cuts the tetrahedron.
    sides = 8
    angles = 2 * np.pi * np.arange(sides) / sides
    ring = np.stack([np.cos(angles), np.sin(angles), np.zeros(sides)], axis=1)
    V = np.concatenate([ring, ring + [0, 0, 1],
                        [[0, 0, 0.8], [0.2, 0, 1.2], [-0.1, 0.17, 1.2], [-0.1, -0.17, 1.2]]])
    F = [[s, (s + 1) % sides, sides + (s + 1) % sides] for s in range(sides)]
    F += [[s, sides + (s + 1) % sides, sides + s] for s in range(sides)]
    F += [[16, 18, 17], [16, 19, 18], [16, 17, 19], [17, 18, 19]]
    with pytest.warns(RuntimeWarning, match="crosses triangle 1[6-9]"):
        V2, F2 = trimlab.close_holes(V, np.array(F, dtype=np.int32))
    assert trimlab.info(V2, F2)["closed"]
