"""Runs inside pvbatch (ParaView's VTK 9.2, never Debian's): shows the meshes of a job file in the
AOKit view (one representation each, or with "grouped" one multiblock of them all), with the job's
camera, R and falloff, and writes each family's AO as the CLI's .f32. With "redistribute" every mesh
is split across the ranks by ParaView's RedistributeDataSet (a no-op in one process), and with
"ranks_png" a last frame without AO shows each cell in a colour of the rank holding it.

  scripts/pvbatch.sh pv_render_families.py job.json
  mpiexec -n 2 scripts/pvbatch.sh pv_render_families.py job.json
"""
import json
import sys

from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, GroupDatasets, ProcessIdScalars,
                             RedistributeDataSet, Render, SaveScreenshot, Show, XMLPolyDataReader,
                             _DisableFirstRenderCameraReset)

FAMILIES = {"obscurance": 1, "field": 2, "hybrid": 3}

job = json.load(open(sys.argv[1]))
_DisableFirstRenderCameraReset()
view = CreateView("AOKitRenderView")
view.ViewSize = job["size"]
view.OrientationAxesVisibility = 0
readers = [XMLPolyDataReader(FileName=[mesh]) for mesh in job["meshes"]]
if job.get("redistribute"):
    readers = [RedistributeDataSet(Input=r) for r in readers]
if job.get("grouped"):  # one multiblock dataset, one representation: every mesh a block
    Show(GroupDatasets(Input=readers), view).Representation = "Surface"
else:
    for reader in readers:
        Show(reader, view).Representation = "Surface"
cam = job["camera"]
view.CameraPosition, view.CameraFocalPoint = cam["position"], cam["focal_point"]
view.CameraViewUp, view.CameraViewAngle = cam["view_up"], cam["view_angle"]
view.AORadius = job["radius"]
for family, out in job["outputs"].items():
    view.AOMethod = FAMILIES[family]
    setattr(view, family.capitalize() + "Falloff", job["falloff"])
    view.AOOutputFile = out
    Render(view)
    Render(view)  # a still frame: what is sent each frame once the meshes are gathered
    view.UpdatePropertyInformation()
    print("pv_render_families: %s sent %d bytes" % (family, view.GetPropertyValue("AOExchangedBytes")))
if job.get("ranks_png"):
    view.AOMethod, view.AOOutputFile = 0, ""
    view.UseColorPaletteForBackground, view.Background = 0, [0.0, 0.0, 0.0]
    lut = GetColorTransferFunction("ProcessId")
    lut.ApplyPreset("Jet", True)
    lut.RescaleTransferFunction(0.0, 3.0)
    for r in readers:
        rep = Show(ProcessIdScalars(Input=r, CellScalars=1), view)
        rep.Representation = "Surface"
        ColorBy(rep, ("CELLS", "ProcessId"))
        rep.Ambient, rep.Diffuse, rep.Specular = 1.0, 0.0, 0.0
    for r in readers:
        Show(r, view).Visibility = 0
    SaveScreenshot(job["ranks_png"], view, ImageResolution=job["size"])
print("pv_render_families: wrote", ", ".join(job["outputs"]))
