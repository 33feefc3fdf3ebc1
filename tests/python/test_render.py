"""render: the CPU reference backend always, the OpenGL backend where a context can be
had (a display: the suite runs under xvfb-run), and both agreeing on what is shown."""

import os
import subprocess
import sys

import numpy as np
import pytest

import trimlab


@pytest.fixture(scope="module")
def pushed():
    return trimlab.load("demo:pushed-sphere")


def test_reference_render_gives_color_depth_and_ids(pushed):
    image = trimlab.render(*pushed, width=64, height=48)
    assert image["color"].shape == (48, 64, 3) and image["color"].dtype == np.uint8
    assert image["depth"].shape == (48, 64) and image["ids"].dtype == np.int32
    covered = image["ids"] >= 0
    assert covered.any() and not covered.all()
    assert np.isinf(image["depth"][~covered]).all() and np.isfinite(image["depth"][covered]).all()


def test_a_fixed_camera_and_the_untrimmed_surface(pushed):
    camera = [0, 0, 5, 0, 0, 0, 0, 1, 0, 45]
    trimmed = trimlab.render(*pushed, width=32, height=32, camera=camera)
    plain = trimlab.render(*pushed, width=32, height=32, camera=",".join(map(str, camera)), trim=False)
    assert (plain["ids"] >= 0).sum() >= (trimmed["ids"] >= 0).sum()


def test_render_refusals(pushed):
    with pytest.raises(trimlab.InputError, match="backend"):
        trimlab.render(*pushed, backend="vulkan")
    with pytest.raises(trimlab.InputError, match="camera"):
        trimlab.render(*pushed, camera="1,2,3")
    with pytest.raises(trimlab.InputError, match="width and height"):
        trimlab.render(*pushed, width=0)


def test_opengl_agrees_with_the_reference(pushed):
    if not os.environ.get("DISPLAY"):
        if os.environ.get("TRIMLAB_REQUIRE_GL") == "1":
            pytest.fail("TRIMLAB_REQUIRE_GL=1 but there is no display (run under xvfb-run -a)")
        pytest.skip("the OpenGL backend needs a display (xvfb-run)")
    size = dict(width=64, height=48)
    gl = trimlab.render(*pushed, backend="opengl", **size)
    cpu = trimlab.render(*pushed, **size)
    assert gl["color"].shape == cpu["color"].shape
    agree = (gl["ids"] == cpu["ids"]).mean()
    assert agree > 0.98


def test_opengl_without_display_is_a_render_error():
    # In a process of its own: Qt keeps the first display it connected to.
    code = ("import trimlab\n"
            "V, F = trimlab.load('demo:sphere')\n"
            "try:\n"
            "    trimlab.render(V, F, backend='opengl', width=8, height=8)\n"
            "except trimlab.RenderError as e:\n"
            "    print('RenderError:', e)\n")
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM")}
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=60)
    assert "RenderError: the OpenGL backend needs a display" in done.stdout, done.stderr
