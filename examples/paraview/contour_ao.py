"""A ParaView user's script: a dataset, an isosurface or its surface, shown in the AOKit view, and
a screenshot. Run with the kit's pvbatch wrapper (it puts ParaView's Python and the plugin in place):

  scripts/pvbatch.sh examples/paraview/contour_ao.py [DATA] [-o shot.png] [--method hybrid]

DATA: a VTK image file (.vti, .vtk) is contoured at the middle of its first point array's range;
a surface mesh (.vtp, .ply, .stl, .obj) is shown through ExtractSurface. Without DATA:
ParaView's Wavelet source, contoured. Under MPI (mpiexec -n 2 scripts/pvbatch.sh ...) each rank
reads and contours its own piece, and the AO is that of one process (the view's ranks share their
G-buffers and meshes; see the README).
"""
import argparse

from paraview.simple import (Contour, CreateView, ExtractSurface, OpenDataFile, Render,
                             ResetCamera, SaveScreenshot, Show, Wavelet)

METHODS = {"none": 0, "obscurance": 1, "field": 2, "hybrid": 3}

parser = argparse.ArgumentParser()
parser.add_argument("data", nargs="?", help="a .vti/.vtk image or a surface mesh (default: Wavelet)")
parser.add_argument("-o", "--output", default="contour_ao.png")
parser.add_argument("--method", choices=sorted(METHODS), default="obscurance")
args = parser.parse_args()

source = OpenDataFile(args.data) if args.data else Wavelet()
if source is None:
    raise SystemExit("contour_ao.py: ParaView has no reader for " + args.data)
source.UpdatePipeline()
point_arrays = source.PointData.keys()
if args.data is None or (args.data.endswith((".vti", ".vtk")) and point_arrays):
    array = point_arrays[0]
    lo, hi = source.PointData[array].GetRange()
    shown = Contour(Input=source, ContourBy=["POINTS", array], Isosurfaces=[0.5 * (lo + hi)],
                    ComputeNormals=1)
else:
    shown = ExtractSurface(Input=source)

view = CreateView("AOKitRenderView")
view.ViewSize = [1024, 768]
view.AOMethod = METHODS[args.method]  # R: a tenth of the data's diagonal unless view.AORadius sets it
Show(shown, view).ColorArrayName = ["POINTS", ""]  # a plain surface: the AO is what shades it
ResetCamera(view)
Render(view)
SaveScreenshot(args.output, view)
print("contour_ao.py: wrote", args.output)
