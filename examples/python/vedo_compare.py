"""vedo's own add_ambient_occlusion (vtkSSAOPass) beside aokit.vedo.add_ao on one scene, both
against the Embree reference of the same pixels.

    PYTHONPATH=build/lib/python3.11/dist-packages python3 examples/python/vedo_compare.py [OUT_DIR]

Each method is drawn ambient-only in white (the pixel is 1 - AO), so vtkSSAOPass's AO, which VTK
only composites into the colour, is read back from the image the same way for every method.
Prints RMSE and MAE against a 256-ray reference and writes the three AO images as PNGs.
"""
import os
import sys

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


plt = plotter()
(p,) = aokit.vedo.add_ao(plt, method="obscurance", radius=R)
plt.render()
rows = {"aokit obscurance": aokit.read_ao(p)}
ref = aokit.reference(plt.renderer, samples=256, progress=lambda f: print("\rreference %3d%%" % (100 * f), end=""))
print()
covered = ref >= 0
aokit.vedo.remove_ao(plt)
(h,) = aokit.vedo.add_ao(plt, method="hybrid", radius=R)
plt.render()
rows["aokit hybrid"] = aokit.read_ao(h)
aokit.vedo.remove_ao(plt)
plt.close()

plt = plotter()
plt.add_ambient_occlusion(R)  # vedo: vtkSSAOPass, radius in world units
plt.render()
rows["vedo add_ambient_occlusion"] = ao_from_image(plt, covered)
plt.close()

save("reference", ref)
print("%-28s %8s %8s" % ("method (R = %.2f)" % R, "RMSE", "MAE"))
for name, ao in rows.items():
    m = aokit.metrics(ao, ref)
    print("%-28s %8.4f %8.4f" % (name, m["rmse"], m["mae"]))
    save(name.replace(" ", "-"), ao)
