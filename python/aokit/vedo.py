"""aokit's AO on a vedo Plotter (python3-vedo): every renderer of the plotter gets its own pass,
so multi-renderer plotters (Plotter(N=2), Plotter(shape=...)) work; translucent meshes and volumes
are drawn after the AO as VTK draws them. vedo's own add_ambient_occlusion sets vtkSSAOPass
(an absolute radius, opaque geometry only) on the current renderer alone.

    import aokit.vedo
    plt = vedo.Plotter(N=2)
    ...
    aokit.vedo.add_ao(plt, method="hybrid")   # R: a tenth of each renderer's visible bounds
    plt.show(...)
    aokit.vedo.remove_ao(plt)
"""
from . import aokitVTK as _vtk
from ._passes import new_pass


def add_ao(plotter, method="obscurance", radius=None, **settings):
    """Sets an aokit pass of `method` with `settings` on every renderer of the plotter (replacing
    an earlier one) and returns the passes, one per renderer. radius: R in world units; None, a
    tenth of the diagonal of each renderer's visible bounds, found every frame."""
    renderers = list(getattr(plotter, "renderers", []) or [])
    if not renderers:
        raise ValueError("aokit.vedo.add_ao: the plotter has no renderers")
    passes = []
    for r in renderers:
        p = new_pass(method, **settings)
        if radius is not None:
            p.set_scene_radius(radius)
        r.SetPass(p)
        passes.append(p)
    plotter._aokit_passes = passes  # the Python objects stay with the plotter
    return passes


def remove_ao(plotter):
    """Takes aokit's passes off every renderer of the plotter (other passes are left alone)."""
    for r in getattr(plotter, "renderers", []) or []:
        if isinstance(r.GetPass(), _vtk.vtkAOKitPass):
            r.SetPass(None)
    plotter._aokit_passes = []
