"""The plugin's suite runs on the X server CTest starts (AOKIT_XVFB_DISPLAY_FILE), or on DISPLAY:
pvbatch needs one even offscreen."""
import os
import sys

import pytest

_display_file = os.environ.get("AOKIT_XVFB_DISPLAY_FILE")
if _display_file and os.path.exists(_display_file):
    os.environ["DISPLAY"] = open(_display_file).read().strip()


def cli():
    path = os.environ.get("AOKIT_CLI")
    if not path:
        pytest.skip("AOKIT_CLI not set (run through ctest)")
    return path


def window_pair():
    """A 512x384 Debian-VTK window with one renderer (tests/python/vtk_window.py)."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python"))
    from vtk_window import offscreen_window
    return offscreen_window()
