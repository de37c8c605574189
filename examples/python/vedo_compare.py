"""vedo's own add_ambient_occlusion (vtkSSAOPass) beside aokit.vedo.add_ao on one scene, both
against the Embree reference of the same pixels.

    PYTHONPATH=build/lib/python3.11/dist-packages python3 examples/python/vedo_compare.py [OUT_DIR]

Each method is drawn ambient-only in white (the pixel is 1 - AO), so vtkSSAOPass's AO, which VTK
only composites into the colour, is read back from the image the same way for every method.
Prints RMSE, MAE and the median frame time (7 frames each) against a 256-ray reference, writes
the three AO images as PNGs and chart.png: each method's error against its frame time (matplotlib,
which python3-vedo brings).
"""
import os
import statistics
import sys
import time

import numpy as np
import vedo

import aokit
import aokit.vedo

out = sys.argv[1] if len(sys.argv) > 1 else "vedo-compare"
os.makedirs(out, exist_ok=True)
R = 0.6


def scene():
    sphere = vedo.Sphere(r=0.5, res=64).pos(0, 0, 0.5)
    torus = vedo.Torus(r1=0.35, r2=0.12).pos(0.95, 0.3, 0.12)
    floor = vedo.Box(pos=(0, 0, -0.05), length=4, width=4, height=0.1)
    for m in (sphere, torus, floor):
        m.color("white").lighting(ambient=1.0, diffuse=0.0, specular=0.0)
    return sphere, torus, floor


def plotter():
    plt = vedo.Plotter(offscreen=True, size=(800, 600), bg="black")
    plt.show(*scene(), interactive=False)
    cam = plt.renderer.GetActiveCamera()
    cam.SetPosition(0.3, -3.4, 2.1)
    cam.SetFocalPoint(0.2, 0, 0.3)
    cam.SetViewUp(0, 0, 1)
    plt.renderer.ResetCameraClippingRange()
    return plt


def ao_from_image(plt, covered):
    img = plt.screenshot(asarray=True)[::-1, :, 0].astype(np.float32) / 255.0  # bottom row first
    return np.where(covered, 1.0 - img, -1.0).astype(np.float32)


def save(name, ao):
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter
    vis = (np.where(ao >= 0, 1.0 - ao, 0.0) * 255).astype(np.uint8)  # bottom row first, as VTK's images
    image = vtkImageData()
    image.SetDimensions(ao.shape[1], ao.shape[0], 1)
    image.GetPointData().SetScalars(numpy_to_vtk(vis.ravel(), deep=1))
    writer = vtkPNGWriter()
    writer.SetFileName(os.path.join(out, name + ".png"))
    writer.SetInputData(image)
    writer.Write()


def frame_ms(plt, frames=7):
    ms = []
    for _ in range(frames):
        t0 = time.perf_counter()
        plt.render()
        ms.append(1000.0 * (time.perf_counter() - t0))
    return statistics.median(ms)


times = {}
plt = plotter()
times["no AO"] = frame_ms(plt)
(p,) = aokit.vedo.add_ao(plt, method="obscurance", radius=R)
plt.render()
rows = {"aokit obscurance": aokit.read_ao(p)}
times["aokit obscurance"] = frame_ms(plt)
ref = aokit.reference(plt.renderer, samples=256, progress=lambda f: print("\rreference %3d%%" % (100 * f), end=""))
print()
covered = ref >= 0
aokit.vedo.remove_ao(plt)
(h,) = aokit.vedo.add_ao(plt, method="hybrid", radius=R)
plt.render()
rows["aokit hybrid"] = aokit.read_ao(h)
times["aokit hybrid"] = frame_ms(plt)
aokit.vedo.remove_ao(plt)
plt.close()

plt = plotter()
plt.add_ambient_occlusion(R)  # vedo: vtkSSAOPass, radius in world units
plt.render()
rows["vedo add_ambient_occlusion"] = ao_from_image(plt, covered)
times["vedo add_ambient_occlusion"] = frame_ms(plt)
plt.close()

save("reference", ref)
print("%-28s %8s %8s %9s" % ("method (R = %.2f)" % R, "RMSE", "MAE", "frame ms"))
print("%-28s %8s %8s %9.1f" % ("no AO", "", "", times["no AO"]))
errors = {}
for name, ao in rows.items():
    m = aokit.metrics(ao, ref)
    errors[name] = m["rmse"]
    print("%-28s %8.4f %8.4f %9.1f" % (name, m["rmse"], m["mae"], times[name]))
    save(name.replace(" ", "-"), ao)

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as pyplot  # noqa: E402
fig, ax = pyplot.subplots(figsize=(6, 4))
for name, rmse in errors.items():
    ax.scatter(times[name], rmse)
    ax.annotate(name, (times[name], rmse), textcoords="offset points", xytext=(5, 5), fontsize=8)
ax.axvline(times["no AO"], color="grey", linestyle=":", label="frame without AO")
ax.set_xlabel("frame time, ms (median of 7)")
ax.set_ylabel("RMSE against the 256-ray reference")
ax.set_ylim(bottom=0)
ax.set_xlim(0, 1.35 * max(times.values()))  # room for the labels
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(out, "chart.png"), dpi=100)
print("wrote", os.path.join(out, "chart.png"))
