"""Python without an X server: `python3 -m aokit.headless` and aokit.OffscreenWindow (OSMesa)."""
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import aokit
from test_render import cli_ao, H, W

SCRIPT = textwrap.dedent("""
    import sys
    import numpy as np
    import aokit
    window = aokit.OffscreenWindow(%d, %d)
    renderer = window.GetRenderers().GetFirstRenderer()
    scene = aokit.load_scene("sphere-plane", renderer)
    for method in ("obscurance", "hybrid", "field"):
        p = aokit.new_pass(method)
        p.set_scene_radius(scene.GetAORadius())
        p.SetSceneFalloff(scene.GetFalloff())
        renderer.SetPass(p)
        window.Render()
        np.save(sys.argv[1] + "-" + method + ".npy", aokit.read_ao(p))
    renderer.SetPass(None)
    print("rendered without", "DISPLAY" if "DISPLAY" not in __import__("os").environ else "??")
""") % (W, H)


def test_headless_script_equals_the_cli_bit_for_bit(tmp_path):
    script = tmp_path / "render.py"
    script.write_text(SCRIPT)
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "AOKIT_XVFB_DISPLAY_FILE")}
    done = subprocess.run([sys.executable, "-m", "aokit.headless", str(script), str(tmp_path / "ao")],
                          capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "rendered without DISPLAY" in done.stdout
    assert "GLEW" not in done.stderr and "ERR" not in done.stderr, done.stderr
    for method in ("obscurance", "hybrid", "field"):
        ao = np.load(tmp_path / ("ao-" + method + ".npy"))
        assert ao.max() > 0.3
        assert np.array_equal(ao, cli_ao(method, tmp_path))


def test_offscreen_window_without_the_launcher_says_how():
    with pytest.raises(RuntimeError, match="python3 -m aokit.headless"):
        aokit.OffscreenWindow(64, 64)


def test_launcher_needs_a_script():
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    done = subprocess.run([sys.executable, "-m", "aokit.headless", "/no/such/script.py"],
                          capture_output=True, text=True, env=env, timeout=60)
    assert done.returncode != 0
    assert done.stderr.strip() == "aokit.headless: no such script: /no/such/script.py"
