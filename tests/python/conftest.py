"""The Python suite runs on the X server CTest starts (AOKIT_XVFB_DISPLAY_FILE), or on DISPLAY."""
import os

import pytest

_display_file = os.environ.get("AOKIT_XVFB_DISPLAY_FILE")
if _display_file and os.path.exists(_display_file):
    os.environ["DISPLAY"] = open(_display_file).read().strip()


@pytest.fixture
def window():
    """A 512x384 on-screen VTK window (offscreen buffers) with one renderer."""
    from vtk_window import offscreen_window
    with offscreen_window() as pair:
        yield pair


def cli():
    path = os.environ.get("AOKIT_CLI")
    if not path:
        pytest.skip("AOKIT_CLI not set (run through ctest)")
    return path
