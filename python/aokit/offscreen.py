"""Python without an X server: a VTK render window on an OSMesa context (Mesa's llvmpipe).

    python3 -m aokit.headless script.py [args]      # runs script.py with OSMesa bound

    # in script.py
    window = aokit.OffscreenWindow(1024, 768)       # a vtkGenericOpenGLRenderWindow
    renderer = window.GetRenderers().GetFirstRenderer()

Why a launcher: python3-vtk9's libraries link glvnd's libOpenGL, whose gl* entry points dispatch
to nothing when only an OSMesa context is current, and GLEW looks its functions up through GLX.
`aokit.headless` starts the script in a python3 whose LD_PRELOAD puts libOSMesa first (the core
gl* symbols bind to Mesa's) and the kit's headless library second (its GLX shim answers GLEW from
OSMesaGetProcAddress), as the CLI's own link order does. Such a process is not meant to open X
windows.
"""
import ctypes
import os

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkGenericOpenGLRenderWindow

OSMESA = "libOSMesa.so.8"


def bound():
    """Whether this process was started by `python3 -m aokit.headless` (OSMesa and the GLX shim
    preloaded)."""
    return os.environ.get("AOKIT_HEADLESS") == "1" and OSMESA in os.environ.get("LD_PRELOAD", "")

# OSMesa's attribute names (GL/osmesa.h).
_FORMAT, _RGBA, _DEPTH_BITS, _STENCIL_BITS, _ACCUM_BITS = 0x22, 0x1908, 0x30, 0x31, 0x32
_PROFILE, _CORE_PROFILE, _MAJOR, _MINOR = 0x33, 0x34, 0x36, 0x37
_GL_UNSIGNED_BYTE = 0x1401
MAX_SIDE = 16384


class _Context:
    """An OSMesa core-profile 3.3 context with its own colour buffer of width x height."""

    def __init__(self, width, height):
        self.lib = ctypes.CDLL(OSMESA)
        self.lib.OSMesaCreateContextAttribs.restype = ctypes.c_void_p
        self.lib.OSMesaGetCurrentContext.restype = ctypes.c_void_p
        attribs = (ctypes.c_int * 15)(_FORMAT, _RGBA, _DEPTH_BITS, 24, _STENCIL_BITS, 0, _ACCUM_BITS, 0,
                                      _PROFILE, _CORE_PROFILE, _MAJOR, 3, _MINOR, 3, 0)
        self.handle = self.lib.OSMesaCreateContextAttribs(attribs, None)
        if not self.handle:
            raise RuntimeError("OffscreenWindow: could not create an OSMesa core-profile 3.3 context")
        self.width, self.height = width, height
        self.buffer = (ctypes.c_ubyte * (width * height * 4))()

    def make_current(self, *unused):
        if not self.lib.OSMesaMakeCurrent(ctypes.c_void_p(self.handle), self.buffer, _GL_UNSIGNED_BYTE,
                                          self.width, self.height):
            raise RuntimeError("OffscreenWindow: OSMesaMakeCurrent failed")

    def __del__(self):
        if getattr(self, "handle", None):
            self.lib.OSMesaDestroyContext(ctypes.c_void_p(self.handle))


def OffscreenWindow(width=1024, height=768):
    """A vtkGenericOpenGLRenderWindow of width x height with one renderer, drawing into an OSMesa
    context. Needs a process started by `python3 -m aokit.headless` (RuntimeError otherwise)."""
    if not bound():
        raise RuntimeError("OffscreenWindow: this python3 does not have OSMesa bound; run the script as "
                           "`python3 -m aokit.headless script.py` (see aokit.offscreen)")
    width, height = int(width), int(height)
    if not (1 <= width <= MAX_SIDE and 1 <= height <= MAX_SIDE):
        raise ValueError("OffscreenWindow: size %dx%d is out of range (1..%d per side)" % (width, height, MAX_SIDE))
    context = _Context(width, height)
    context.make_current()
    window = vtkGenericOpenGLRenderWindow()
    window.AddObserver(vtkCommand.WindowMakeCurrentEvent, context.make_current)
    window._aokit_context = context  # the context lives as long as the window's Python object
    window.SetOwnContext(0)
    window.SetReadyForRendering(True)
    window.SetIsCurrent(True)
    window.SetFrameBlitModeToNoBlit()  # the frame stays in VTK's framebuffer; VTK reads it from there
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    window.SetOffScreenRendering(1)
    window.AddRenderer(vtkRenderer())
    return window
