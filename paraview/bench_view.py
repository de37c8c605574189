"""Frame cost of the AOKit view inside pvbatch: each method's AO time (its frame minus the plain
view's) over the plain Render View's frame, beside ParaView's built-in SSAO (Render View "Use
Ambient Occlusion"), on the same data and camera, timed as interleaved rounds (one frame of every
configuration per round), medians with the spread (min..max) of each.

  scripts/pvbatch.sh paraview/bench_view.py [--size 1024x768] [--rounds 15]
  mpiexec -n 2 scripts/pvbatch.sh paraview/bench_view.py     # the same across ranks

Under MPI ParaView's sources split the sphere between the ranks (the plane source is whole on
every rank); the times are rank 0's.
"""
import argparse
import statistics
import time

from paraview import servermanager
from paraview.simple import Contour, CreateView, Render, ResetCamera, Show, Sphere, Plane, Wavelet

parser = argparse.ArgumentParser()
parser.add_argument("--size", default="1024x768")
parser.add_argument("--rounds", type=int, default=15)
parser.add_argument("--scene", choices=["sphere-plane", "wavelet"], default="sphere-plane")
args = parser.parse_args()
size = [int(v) for v in args.size.split("x")]

if args.scene == "wavelet":
    data = [Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"], Isosurfaces=[157.0], ComputeNormals=1)]
else:
    data = [Sphere(Center=[0, 0.5, 0], Radius=0.5, ThetaResolution=128, PhiResolution=128),
            Plane(Origin=[-2, 0, -2], Point1=[2, 0, -2], Point2=[-2, 0, 2], XResolution=64, YResolution=64)]


def make(view_type, **props):
    v = CreateView(view_type)
    v.ViewSize = size
    v.OrientationAxesVisibility = 0
    for name, value in props.items():
        setattr(v, name, value)
    for d in data:
        Show(d, v).ColorArrayName = ["POINTS", ""]  # plain surfaces
    ResetCamera(v)
    v.CameraPosition = [0, 2.2, 3.6] if args.scene == "sphere-plane" else v.CameraPosition
    v.CameraFocalPoint = [0, 0.3, 0] if args.scene == "sphere-plane" else v.CameraFocalPoint
    return v


configs = {
    "plain": make("RenderView"),
    "paraview-ssao": make("RenderView", UseAmbientOcclusion=1),
    "obscurance": make("AOKitRenderView", AOMethod=1),
    "field": make("AOKitRenderView", AOMethod=2),
    "hybrid": make("AOKitRenderView", AOMethod=3),
}
times = {name: [] for name in configs}
for v in configs.values():  # warm-up: shaders, bakes, buffers
    Render(v)
    Render(v)
for _ in range(args.rounds):
    for name, v in configs.items():
        t0 = time.perf_counter()
        Render(v)
        times[name].append(1000.0 * (time.perf_counter() - t0))

plain = statistics.median(times["plain"])
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
print("scene %s %dx%d, %d interleaved rounds, pvbatch on %d rank(s)" % (args.scene, size[0], size[1], args.rounds, ranks))
print("%-14s %9s %17s %9s %12s" % ("config", "frame ms", "spread", "AO ms", "AO / plain"))
for name, t in times.items():
    med = statistics.median(t)
    print("%-14s %9.1f %8.1f..%-8.1f %9.1f %12.2f" % (name, med, min(t), max(t), med - plain, (med - plain) / plain))
