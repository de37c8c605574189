"""aokit.vedo on vedo's plotters: each subplot of Plotter(N=2) gets the AO of its single render."""
import numpy as np
import pytest

vedo = pytest.importorskip("vedo")
import aokit  # noqa: E402
import aokit.vedo  # noqa: E402


def objects():
    sphere = vedo.Sphere(r=0.5, res=48).pos(0, 0, 0.5)
    floor = vedo.Box(pos=(0, 0, -0.05), length=4, width=4, height=0.1)
    return sphere, floor


def camera(plotter):
    cam = plotter.renderer.GetActiveCamera()
    cam.SetPosition(0, -3.2, 2.0)
    cam.SetFocalPoint(0, 0, 0.3)
    cam.SetViewUp(0, 0, 1)
    cam.SetViewAngle(30)
    plotter.renderer.ResetCameraClippingRange()


def single(method):
    plt = vedo.Plotter(offscreen=True, size=(400, 300))
    plt.show(*objects(), interactive=False)
    camera(plt)
    (p,) = aokit.vedo.add_ao(plt, method=method, radius=0.6)
    plt.render()
    ao = aokit.read_ao(p)
    plt.close()
    return ao


@pytest.mark.parametrize("method", ["obscurance", "hybrid"])
def test_two_subplots_match_their_single_renders(window, method):
    alone = single(method)
    assert alone.max() > 0.3
    plt = vedo.Plotter(N=2, offscreen=True, size=(800, 300))
    for i in range(2):
        plt.at(i).show(*objects(), interactive=False)
        camera(plt)
    passes = aokit.vedo.add_ao(plt, method=method, radius=0.6)
    assert len(passes) == 2
    plt.render()
    for p, r in zip(passes, plt.renderers):
        ao = aokit.read_ao(p, r)
        assert ao.shape == alone.shape
        both = (ao >= 0) & (alone >= 0)
        assert both.sum() > 0.9 * (alone >= 0).sum()
        rmse = float(np.sqrt(np.mean((ao[both] - alone[both]) ** 2)))
        assert rmse <= 0.005, rmse
    aokit.vedo.remove_ao(plt)
    assert all(r.GetPass() is None for r in plt.renderers)
    plt.close()


def test_a_translucent_mesh_casts_nothing_and_is_drawn(window):
    plt = vedo.Plotter(offscreen=True, size=(400, 300))
    sphere, floor = objects()
    sphere.alpha(0.4)
    plt.show(sphere, floor, interactive=False)
    camera(plt)
    (p,) = aokit.vedo.add_ao(plt, radius=0.6)
    plt.render()
    ao = aokit.read_ao(p)
    # Only the floor is opaque: nothing above it within R, so no occlusion anywhere.
    assert ao[ao >= 0].max() < 0.02
    image = plt.screenshot(asarray=True)
    assert image.std() > 1.0  # the translucent sphere is still drawn over the floor
    plt.close()


def test_add_ao_needs_a_plotter_with_renderers():
    class Empty:
        renderers = []
    with pytest.raises(ValueError, match="no renderers"):
        aokit.vedo.add_ao(Empty())


def test_a_volume_is_drawn_over_the_ao_and_casts_nothing(window):
    # A vedo Volume floating over the background (nothing opaque behind it), beside the sphere on
    # its floor: with the pass it looks as without it, and the AO is the AO without the volume.
    def render(with_volume, with_ao):
        plt = vedo.Plotter(offscreen=True, size=(400, 300), bg="black")
        shown = list(objects())
        if with_volume:
            x, y, z = np.mgrid[-1:1:24j, -1:1:24j, -1:1:24j]
            blob = (255 * np.exp(-3.0 * (x * x + y * y + z * z))).astype(np.uint8)
            shown.append(vedo.Volume(blob, spacing=(0.025, 0.025, 0.025), origin=(-0.9, 0.0, 0.6)))
        plt.show(*shown, interactive=False)
        camera(plt)
        passes = aokit.vedo.add_ao(plt, radius=0.6) if with_ao else []
        plt.render()
        image = plt.screenshot(asarray=True).astype(np.int16)
        ao = aokit.read_ao(passes[0]) if passes else None
        plt.close()
        return image, ao

    plain, _ = render(with_volume=False, with_ao=False)
    vol_plain, _ = render(with_volume=True, with_ao=False)
    vol_ao, ao_with = render(with_volume=True, with_ao=True)
    _, ao_without = render(with_volume=False, with_ao=True)
    volume = np.abs(vol_plain - plain).max(axis=2) > 10  # where the volume shows
    assert volume.sum() > 200
    assert (plain[volume] == 0).all()  # ... over the black background only
    assert np.abs(vol_ao[volume] - vol_plain[volume]).max() <= 2  # drawn as without the pass
    assert np.array_equal(ao_with >= 0, ao_without >= 0)
    # The volume casts no AO; it only moves the near and far planes VTK fits to the visible
    # bounds, so a few containment tests flip at depth precision.
    diff = np.abs(ao_with - ao_without)[ao_without >= 0]
    print("volume: AO differs on %d of %d px, max %.4f, RMS %.6f" % ((diff > 0).sum(), diff.size, diff.max(),
                                                                     np.sqrt(np.mean(diff ** 2))))
    assert np.sqrt(np.mean(diff ** 2)) <= 0.001 and (diff > 0.02).sum() == 0
    assert ao_with.max() > 0.3
