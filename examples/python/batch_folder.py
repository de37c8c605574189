"""Renders every mesh of a folder with AO into PNGs, with a progress bar.

    PYTHONPATH=build/lib/python3.11/dist-packages python3 examples/python/batch_folder.py DIR OUT [WxH]

    python3 -m aokit.headless examples/python/batch_folder.py DIR OUT [WxH]   # no X server: OSMesa

One window and one pass serve every mesh (a new window per mesh would rebuild every program).
Under X (Xvfb will do) it draws into offscreen buffers of an ordinary window; started through
aokit.headless, into aokit.OffscreenWindow. Prints the process's resident memory after each mesh.
"""
import os
import sys

from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter

import aokit
from aokit.offscreen import bound


def rss_mb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


folder, out = sys.argv[1], sys.argv[2]
w, h = (int(v) for v in (sys.argv[3] if len(sys.argv) > 3 else "1024x768").split("x"))
meshes = sorted(f for f in os.listdir(folder) if f.lower().endswith((".off", ".obj", ".ply", ".stl", ".vtp", ".vtk")))
if not meshes:
    sys.exit("batch: no mesh files in " + folder)
os.makedirs(out, exist_ok=True)
if bound():
    window = aokit.OffscreenWindow(w, h)
    renderer = window.GetRenderers().GetFirstRenderer()
else:
    window = vtkRenderWindow()
    window.SetSize(w, h)
    window.SetOffScreenRendering(1)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
renderer.SetBackground(1, 1, 1)
ao = aokit.ObscurancePass()
renderer.SetPass(ao)
grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetInputConnection(grab.GetOutputPort())
for i, name in enumerate(meshes):
    try:
        scene = aokit.load_scene(os.path.join(folder, name), renderer)   # camera and R from its bounds
    except ValueError as e:
        print("\nbatch: skipped %s: %s" % (name, e))
        continue
    ao.set_scene_radius(scene.GetAORadius())
    window.Render()
    grab.Modified()
    writer.SetFileName(os.path.join(out, os.path.splitext(name)[0] + ".png"))
    writer.Write()
    del scene  # its actors leave the renderer
    done = (i + 1) / len(meshes)
    bar = "#" * int(30 * done)
    sys.stdout.write("\r[%-30s] %d/%d %s  RSS %.1f MB" % (bar, i + 1, len(meshes), name[:24], rss_mb()))
    sys.stdout.flush()
print()
