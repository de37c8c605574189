"""Two viewports side by side in one window, each with its own AO family, one shared camera.

    PYTHONPATH=build/lib/python3.11/dist-packages python3 examples/python/two_viewports.py [out.png]
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkRenderWindowInteractor, vtkWindowToImageFilter
import vtkmodules.vtkInteractionStyle  # noqa: F401

import aokit

window = vtkRenderWindow()
window.SetSize(1600, 600)
scenes = []
camera = None
for i, method in enumerate(["obscurance", "hybrid"]):
    r = vtkRenderer()
    r.SetViewport(0.5 * i, 0, 0.5 * (i + 1), 1)
    window.AddRenderer(r)
    scenes.append(aokit.load_scene("bunny", r))      # the kit's scene: actors, camera, R
    ao = aokit.new_pass(method)
    ao.set_scene_radius(scenes[-1].GetAORadius())
    r.SetPass(ao)
    if camera is None:
        camera = r.GetActiveCamera()
    else:
        r.SetActiveCamera(camera)

if len(sys.argv) > 1:
    window.SetOffScreenRendering(1)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(sys.argv[1])
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
else:
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
