"""Runs inside pvbatch (ParaView's VTK 9.2, never Debian's): shows the meshes of a job file in the
AOKit view (one representation each, or with "grouped" one multiblock of them all), with the job's
camera, R and falloff, and writes each family's AO as the CLI's .f32.

  scripts/pvbatch.sh pv_render_families.py job.json
"""
import json
import sys

from paraview.simple import (CreateView, GroupDatasets, Render, Show, XMLPolyDataReader,
                             _DisableFirstRenderCameraReset)

FAMILIES = {"obscurance": 1, "field": 2, "hybrid": 3}

job = json.load(open(sys.argv[1]))
_DisableFirstRenderCameraReset()
view = CreateView("AOKitRenderView")
view.ViewSize = job["size"]
view.OrientationAxesVisibility = 0
readers = [XMLPolyDataReader(FileName=[mesh]) for mesh in job["meshes"]]
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
print("pv_render_families: wrote", ", ".join(job["outputs"]))
