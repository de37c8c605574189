"""A 512x384 VTK window (offscreen buffers) with one renderer on the X display, for the Python
suite and the ParaView suite's scene export (Debian's VTK)."""
import contextlib
import os

import pytest


@contextlib.contextmanager
def offscreen_window(width=512, height=384):
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    if not os.environ.get("DISPLAY"):
        pytest.skip("no X display (run through ctest, which starts Xvfb)")
    renderer, win = vtkRenderer(), vtkRenderWindow()
    win.AddRenderer(renderer)
    win.SetSize(width, height)
    win.SetOffScreenRendering(1)
    try:
        yield win, renderer
    finally:
        renderer.SetPass(None)
        win.Finalize()
