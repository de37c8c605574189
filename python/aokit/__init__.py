"""aokit: ambient occlusion for VTK render pipelines, from Python.

The kit's AO families as VTK render passes that take and give python3-vtk9's objects::

    import aokit
    ao = aokit.ObscurancePass(samples=8)   # any setting by keyword, or ao.SetSamples(8)
    renderer.SetPass(ao)
    window.Render()
    occlusion = aokit.read_ao(ao)          # float32 (height, width), -1 where no surface

Every setting comes from the family's one table (the C++ kit, the CLI and scene files read the
same one): ``help(aokit.ObscurancePass.SetSamples)`` gives its unit, range and default; a bad
value raises ValueError with the kit's one-line message.
"""
from vtkmodules import vtkRenderingOpenGL2 as _gl  # noqa: F401  (VTK's OpenGL classes, as the passes need)

from . import aokitVTK as _vtk
from ._passes import FieldPass, HybridPass, ObscurancePass, methods, new_pass
from ._props import set_casts_ao, set_receives_ao, set_static, casts_ao, receives_ao, is_static
from ._arrays import read_ao, reference, metrics
from ._scene import load_scene, builtin_scenes
from .offscreen import OffscreenWindow

__all__ = [
    "ObscurancePass", "HybridPass", "FieldPass", "methods", "new_pass",
    "set_casts_ao", "set_receives_ao", "set_static", "casts_ao", "receives_ao", "is_static",
    "read_ao", "reference", "metrics", "load_scene", "builtin_scenes", "OffscreenWindow",
]
