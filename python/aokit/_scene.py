"""The kit's own scenes as VTK actors in a renderer (the same actors, camera and R the CLI uses)."""
from . import aokitVTK as _vtk


def builtin_scenes():
    return _vtk.vtkAOKitScene.GetBuiltinNames().split(",")


def load_scene(spec, renderer):
    """Puts a built-in scene (by name), a .json scene file or a mesh file into `renderer` with its
    camera. Returns the scene object (keep it: the actors leave when it goes); its GetAORadius() and
    GetFalloff() are the scene's R and falloff."""
    scene = _vtk.vtkAOKitScene()
    if not scene.Load(str(spec), renderer):
        raise ValueError(scene.GetLastError())
    return scene
