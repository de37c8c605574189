"""A scientific viewer's pipeline (reader -> surface filter -> mapper -> actor) with AO added.

    PYTHONPATH=build/lib/python3.11/dist-packages python3 examples/python/reader_ao.py mesh.vtu [out.png]

The five lines marked "AO" are all aokit adds; without an output file it opens a window.
"""
import sys

from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOLegacy import vtkDataSetReader
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkDataSetMapper, vtkRenderer, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkWindowToImageFilter)
from vtkmodules.vtkIOImage import vtkPNGWriter
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import aokit                                   # AO

path = sys.argv[1]
reader = vtkDataSetReader() if path.endswith(".vtk") else vtkXMLGenericDataObjectReader()
reader.SetFileName(path)
surface = vtkDataSetSurfaceFilter()
surface.SetInputConnection(reader.GetOutputPort())
mapper = vtkDataSetMapper()
mapper.SetInputConnection(surface.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(1, 1, 1)
window = vtkRenderWindow()
window.AddRenderer(renderer)
window.SetSize(1024, 768)

ao = aokit.ObscurancePass(samples=8)          # AO: R from the visible bounds unless SetRadius
renderer.SetPass(ao)                           # AO

if len(sys.argv) > 2:
    window.SetOffScreenRendering(1)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(sys.argv[2])
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("%s: AO radius %.4g, AO stages %.1f ms" % (sys.argv[2], ao.GetFrameRadius(), ao.GetAOMilliseconds()))
else:
    ao.SetStageTiming(True)                    # AO (optional: the label's time)
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
