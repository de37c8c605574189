"""The AOKit view under MPI (issue 18 item 3): every mesh split across the ranks by ParaView's
RedistributeDataSet, each family's AO read back from rank 0 (every rank holds the same composited AO)
against the same view in one process. Targets: RMSE at most 0.01, and no seam: along the pieces'
boundaries (where the rank holding the surface changes, from a frame coloured by ProcessId) the
largest difference at most 0.05. Without the kit's exchanges (parallel/RankExchange.h) the contact
shadow between a sphere on one rank and a plane on another is missing altogether."""
import json
import os
import subprocess

import numpy as np
import pytest

from test_paraview_view import PVBATCH, export_scene, read_f32

FAMILIES = ("obscurance", "field", "hybrid")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def read_png(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    rgb = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(int)
    return rgb  # bottom row first, as the .f32 files


def run_job(tmp, job, ranks):
    job = dict(job, outputs={f: str(tmp / ("n%d-%s.f32" % (ranks, f))) for f in FAMILIES},
               ranks_png=str(tmp / ("n%d-ranks.png" % ranks)))
    path = tmp / ("job%d.json" % ranks)
    path.write_text(json.dumps(job))
    script = os.path.join(os.path.dirname(__file__), "pv_render_families.py")
    command = [PVBATCH, script, str(path)]
    if ranks > 1:
        command = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + command
    # ParaView 5.11's first IceT frame under OpenMPI with more ranks than cores (4 on this machine's
    # 2) now and then never returns: rank 0 in IceT's MPI_Comm_dup, the others already waiting for
    # the next command. The plain Render View does it too (3 of 12 runs), so a run that outlives
    # its time is run once more; a failure is a failure.
    for attempt in range(2):
        try:
            run = subprocess.run(command, capture_output=True, text=True, timeout=90 if ranks > 2 else 300, env=ENV)
            break
        except subprocess.TimeoutExpired:
            subprocess.run(["pkill", "-9", "-x", "pvbatch"])
            if attempt == 1:
                raise
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert "ranks:" not in run.stdout + run.stderr  # no warning that ranks do not share occluders
    return {f: read_f32(job["outputs"][f]) for f in FAMILIES}, read_png(job["ranks_png"]), run


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    from conftest import window_pair
    tmp = tmp_path_factory.mktemp("pv-mpi")
    with window_pair() as window:
        job = export_scene(tmp, window)
    job["redistribute"] = True
    return {n: run_job(tmp, job, n) for n in (1, 2, 4)}


def seam(ranks_rgb):
    """Pixels whose right or upper neighbour shows a surface of another rank (both covered; the
    background is black, each rank's cells a colour of their own, unlit)."""
    covered = ranks_rgb.sum(axis=2) > 120  # not the silhouettes' blends of rank 0's blue (sum 143) into black
    diff = np.abs(ranks_rgb[:, 1:] - ranks_rgb[:, :-1]).sum(axis=2) > 40
    right = np.zeros(covered.shape, bool)
    right[:, :-1] = diff & covered[:, 1:] & covered[:, :-1]
    diff = np.abs(ranks_rgb[1:] - ranks_rgb[:-1]).sum(axis=2) > 40
    up = np.zeros(covered.shape, bool)
    up[:-1] = diff & covered[1:] & covered[:-1]
    edge = right | up
    grown = edge.copy()  # both sides of the boundary
    grown[:, 1:] |= edge[:, :-1]
    grown[1:] |= edge[:-1]
    return grown


@pytest.mark.parametrize("ranks", [2, 4])
def test_the_data_is_split_across_the_ranks(runs, ranks):
    assert seam(runs[1][1]).sum() == 0  # one process: every cell on rank 0
    assert seam(runs[ranks][1]).sum() > 500  # the pieces meet inside the picture


@pytest.mark.parametrize("ranks", [2, 4])
@pytest.mark.parametrize("family", FAMILIES)
def test_ranks_give_the_one_process_ao(runs, ranks, family):
    one, many = runs[1][0][family], runs[ranks][0][family]
    assert one.shape == many.shape
    both = (one >= 0) & (many >= 0)
    assert both.sum() > 0.99 * (one >= 0).sum() and (many >= 0).sum() <= 1.01 * (one >= 0).sum()
    d = np.abs(one - many)
    rmse = float(np.sqrt(np.mean(d[both] ** 2)))
    on_seam = seam(runs[ranks][1]) & both
    worst = float(d[on_seam].max())
    print("-n %d %s: RMSE %.5f max %.4f; seam %d px, max %.4f" % (ranks, family, rmse, d[both].max(), on_seam.sum(), worst))
    assert rmse <= 0.01
    assert worst <= 0.05
    assert one[both].max() > 0.3 and many[both].max() > 0.3  # the contact is dark on both sides
