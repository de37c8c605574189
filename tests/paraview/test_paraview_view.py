"""The AOKit view inside pvbatch (one process) against the kit's own CLI on the same scene and
camera, read back as float AO. This process runs Debian's VTK (it exports the scene with aokit);
pvbatch runs ParaView's VTK in its own process: the two never share one."""
import json
import os
import subprocess

import numpy as np
import pytest

import aokit

W, H = 512, 384
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PVBATCH = os.path.join(ROOT, "scripts", "pvbatch.sh")


def read_f32(path):
    raw = open(path, "rb").read()
    header = raw.index(b"\n")
    magic, w, h = raw[:header].split()
    assert magic == b"AOKITF32"
    return np.frombuffer(raw[header + 1:], dtype=np.float32).reshape(int(h), int(w))


def export_scene(tmp_path, window):
    """sphere-plane's meshes in world space as .vtp, its camera, R and falloff."""
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    win, renderer = window
    scene = aokit.load_scene("sphere-plane", renderer)
    win.Render()
    meshes = []
    actors = renderer.GetActors()
    actors.InitTraversal()
    for i in range(actors.GetNumberOfItems()):
        actor = actors.GetNextActor()
        t = vtkTransform()
        t.SetMatrix(actor.GetMatrix())
        move = vtkTransformPolyDataFilter()
        move.SetInputData(actor.GetMapper().GetInput())
        move.SetTransform(t)
        path = str(tmp_path / ("mesh%d.vtp" % i))
        writer = vtkXMLPolyDataWriter()
        writer.SetInputConnection(move.GetOutputPort())
        writer.SetFileName(path)
        assert writer.Write() == 1
        meshes.append(path)
    cam = renderer.GetActiveCamera()
    return {"size": [W, H], "meshes": meshes, "radius": scene.GetAORadius(), "falloff": scene.GetFalloff(),
            "camera": {"position": list(cam.GetPosition()), "focal_point": list(cam.GetFocalPoint()),
                       "view_up": list(cam.GetViewUp()), "view_angle": cam.GetViewAngle()}}


def cli_ao(cli, method, tmp_path):
    out = tmp_path / ("cli-" + method + ".f32")
    subprocess.run([cli, "render", "sphere-plane", "-m", method, "--size", "%dx%d" % (W, H),
                    "--ao-float", str(out), "-o", str(tmp_path / ("cli-" + method + ".png"))],
                   check=True, capture_output=True, timeout=180)
    return read_f32(out)


@pytest.fixture(scope="module", params=["separate", "grouped"])
def rendered(tmp_path_factory, request):
    """pvbatch's AO of every family: the meshes as representations of their own, or as the blocks
    of one vtkMultiBlockDataSet (ParaView's GroupDatasets) drawn by one composite mapper."""
    from conftest import cli, window_pair
    tmp = tmp_path_factory.mktemp("pv-" + request.param)
    with window_pair() as window:
        job = export_scene(tmp, window)
    job["grouped"] = request.param == "grouped"
    job["outputs"] = {f: str(tmp / ("pv-" + f + ".f32")) for f in ("obscurance", "field", "hybrid")}
    (tmp / "job.json").write_text(json.dumps(job))
    run = subprocess.run([PVBATCH, os.path.join(os.path.dirname(__file__), "pv_render_families.py"),
                          str(tmp / "job.json")], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    return tmp, job, cli(), run


# The target: each family within RMSE 0.01 of the CLI's AO on the same camera.
@pytest.mark.parametrize("family", ["obscurance", "field", "hybrid"])
def test_view_ao_matches_the_cli(rendered, family):
    tmp, job, cli, run = rendered
    pv = read_f32(job["outputs"][family])
    ref = cli_ao(cli, family, tmp)
    assert pv.shape == ref.shape == (H, W)
    both = (pv >= 0) & (ref >= 0)
    assert both.sum() > 0.99 * (ref >= 0).sum()  # the same surfaces covered
    rmse = float(np.sqrt(np.mean((pv[both] - ref[both]) ** 2)))
    print("%s %s: RMSE %.5f max %.4f over %d px" % ("grouped" if job["grouped"] else "separate", family, rmse, np.abs(pv[both] - ref[both]).max(), both.sum()))
    assert rmse <= 0.01
    assert ref[both].max() > 0.3 and pv[both].max() > 0.3  # the contact is dark on both sides


def test_a_bad_setting_is_one_error_line(tmp_path):
    script = tmp_path / "bad.py"
    script.write_text("from paraview.simple import CreateView\n"
                      "v = CreateView('AOKitRenderView')\n"
                      "v.ObscuranceSamples = -3\nv.AOMethod = 7\n"
                      "print('samples', v.GetProperty('ObscuranceSamples').GetElement(0))\n")
    run = subprocess.run([PVBATCH, str(script)], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-2000:]
    out = run.stdout + run.stderr
    lines = [l for l in out.splitlines() if "aokit:" in l]
    assert len(lines) == 2, out
    assert "samples must be an integer in 1..64, got '-3'" in lines[0]
    assert "AOMethod must be 0 (none), 1 (obscurance), 2 (field) or 3 (hybrid), got 7" in lines[1]
