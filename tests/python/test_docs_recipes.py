"""The recipes of docs/python.md run as written: each ```python block is executed, in
order, in a folder holding meshes/ (closed and open test meshes) and walk/ (an OBJ
sequence), and leaves the files it promises."""

import os
import pathlib
import runpy
import shutil

import pytest

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"


def recipes():
    text = DOC.read_text()
    blocks = text.split("```python\n")[1:]
    return [block.split("```")[0] for block in blocks]


@pytest.fixture
def workspace(tmp_path, data):
    (tmp_path / "meshes").mkdir()
    for name in ("cube.obj", "tetrahedron.obj", "open_square.obj", "nonconvex.obj"):
        shutil.copy(data / "meshes" / name, tmp_path / "meshes" / name)
    shutil.copytree(data / "animations" / "bar", tmp_path / "walk")
    cwd = os.getcwd()
    os.chdir(tmp_path)
    yield tmp_path
    os.chdir(cwd)


def test_the_docs_have_four_recipes():
    assert len(recipes()) == 4


def test_the_recipes_run_as_written(workspace, capsys):
    for index, code in enumerate(recipes()):
        script = workspace / f"recipe_{index}.py"
        script.write_text(code)
        runpy.run_path(str(script), run_name="__main__")
    printed = capsys.readouterr().out
    assert "open_square.obj: skipped" in printed
    assert (workspace / "trimmed" / "cube.obj").exists()
    assert (workspace / "walk.glb").stat().st_size > 0
    assert "cube.obj" in printed and "E_RMS" in printed
    assert (workspace / "walk-trimmed" / "pose_0000.obj").exists() and "pose 0: " in printed
    assert (workspace / "walk-trimmed.glb").stat().st_size > 0
