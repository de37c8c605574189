"""`python3 -m aokit.headless script.py [args]`: runs a script with OSMesa bound (aokit.offscreen
says why), without an X server."""
import os
import runpy
import sys

from .offscreen import OSMESA, bound

_HERE = os.path.dirname(os.path.abspath(__file__))


def _headless_library():
    """The kit's headless library (its GLX shim), beside the package's own libraries."""
    from . import _paths
    for rel in _paths.HEADLESS_LIBRARIES:
        path = os.path.normpath(os.path.join(_HERE, rel))
        if os.path.exists(path):
            return path
    raise RuntimeError("aokit.headless: libaokit_headless not found (looked in %s)" % ", ".join(_paths.HEADLESS_LIBRARIES))


def main(argv):
    if len(argv) < 1:
        sys.exit("usage: python3 -m aokit.headless script.py [args]")
    if not bound():
        env = dict(os.environ)
        env["LD_PRELOAD"] = ":".join(p for p in [OSMESA, _headless_library(), env.get("LD_PRELOAD", "")] if p)
        env["AOKIT_HEADLESS"] = "1"
        env.pop("DISPLAY", None)
        os.execve(sys.executable, [sys.executable, "-m", "aokit.headless"] + argv, env)
    script = argv[0]
    if not os.path.exists(script):
        sys.exit("aokit.headless: no such script: %s" % script)
    sys.argv = argv
    runpy.run_path(script, run_name="__main__")


if __name__ == "__main__":
    main(sys.argv[1:])
