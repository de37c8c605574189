"""numpy: the AO of a pass's last frame, the Embree reference of the same view, the bench's metrics."""
import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand, vtkFloatArray

from . import aokitVTK as _vtk


def _image(array, size):
    return numpy_support.vtk_to_numpy(array).reshape(size[1], size[0]).astype(np.float32, copy=True)


def read_ao(ao_pass, renderer=None):
    """The AO of the pass's last frame of `renderer` (default: the renderer it drew last) as a
    float32 array (height, width): occlusion in [0, 1], -1 where no surface, bottom row first
    (rows as the CLI's .f32)."""
    array, size = vtkFloatArray(), [0, 0]
    if not ao_pass.ReadAO(None, renderer, array, size):
        raise RuntimeError(ao_pass.GetLastError())
    return _image(array, size)


def reference(renderer, samples=256, radius=None, falloff=None, seed=1, progress=None):
    """The Embree reference of what `renderer` shows: float32 (height, width) as read_ao.

    radius and falloff default to those the renderer's aokit pass used in its last frame.
    progress: a callable taking the fraction done."""
    ao_pass = renderer.GetPass()
    if radius is None or falloff is None:
        if not isinstance(ao_pass, _vtk.vtkAOKitPass) or ao_pass.GetFrameRadius() <= 0.0:
            raise ValueError("reference: give radius and falloff, or render once with an aokit pass on the renderer")
        radius = ao_pass.GetFrameRadius() if radius is None else radius
        falloff = ao_pass.GetFrameFalloff() if falloff is None else falloff
    ref = _vtk.vtkAOKitReference()
    ref.SetSamples(int(samples))
    ref.SetRadius(float(radius))
    ref.SetFalloff(str(falloff))
    ref.SetSeed(int(seed))
    if progress is not None:
        ref.AddObserver(vtkCommand.ProgressEvent, _progress_observer(progress))
    array, size = vtkFloatArray(), [0, 0]
    if not ref.Compute(renderer, array, size):
        raise ValueError(ref.GetLastError())
    return _image(array, size)


def _progress_observer(progress):
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_DOUBLE

    @calldata_type(VTK_DOUBLE)
    def observe(obj, event, fraction):
        progress(fraction)

    return observe


def metrics(ao, ref):
    """The bench's metrics of `ao` against `ref` (same shape, -1 = no surface) over the pixels both
    cover: dict with rmse, mae, p99, ssim (of 1 - AO) and pixels."""
    ao, ref = np.asarray(ao, dtype=np.float32), np.asarray(ref, dtype=np.float32)
    if ao.ndim != 2 or ao.shape != ref.shape:
        raise ValueError("metrics: both images must be 2-D and of one shape, got %s and %s" % (ao.shape, ref.shape))
    h, w = ao.shape
    out = [0.0] * 5
    ok = _vtk.vtkAOKitReference().Compare(numpy_support.numpy_to_vtk(ao.ravel(), deep=1),
                                          numpy_support.numpy_to_vtk(ref.ravel(), deep=1), w, h, out)
    if not ok:
        raise ValueError("metrics: no pixel covered in both images, or malformed input")
    return {"rmse": out[0], "mae": out[1], "p99": out[2], "ssim": out[3], "pixels": int(out[4])}
