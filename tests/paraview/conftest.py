"""The plugin's suite runs on the X server CTest starts (AOKIT_XVFB_DISPLAY_FILE), or on DISPLAY:
pvbatch needs one even offscreen."""
import contextlib
import os

import pytest

_display_file = os.environ.get("AOKIT_XVFB_DISPLAY_FILE")
if _display_file and os.path.exists(_display_file):
    os.environ["DISPLAY"] = open(_display_file).read().strip()


def cli():
    path = os.environ.get("AOKIT_CLI")
    if not path:
        pytest.skip("AOKIT_CLI not set (run through ctest)")
    return path


@contextlib.contextmanager
def window_pair():
    """A 512x384 Debian-VTK window (offscreen buffers) with one renderer."""
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    if not os.environ.get("DISPLAY"):
        pytest.skip("no X display (run through ctest, which starts Xvfb)")
    renderer, win = vtkRenderer(), vtkRenderWindow()
    win.AddRenderer(renderer)
    win.SetSize(512, 384)
    win.SetOffScreenRendering(1)
    try:
        yield win, renderer
    finally:
        win.Finalize()
