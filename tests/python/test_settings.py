"""Import, the settings table as Set/Get methods, and the one-line errors."""
import math
import subprocess
import sys

import pytest

import aokit

FAMILIES = [aokit.ObscurancePass, aokit.HybridPass, aokit.FieldPass]


def test_import_beside_vtkmodules_without_display():
    env = {"PYTHONPATH": ":".join(sys.path)}
    done = subprocess.run([sys.executable, "-c", "import aokit, vtkmodules; print(aokit.methods())"],
                          capture_output=True, text=True, env=env, timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "['obscurance', 'hybrid', 'field']"
    assert done.stderr == ""


@pytest.mark.parametrize("family", FAMILIES)
def test_every_setting_round_trips_its_default(family):
    p = family()
    assert p.GetNumberOfSettings() > 5
    for i in range(p.GetNumberOfSettings()):
        key, default = p.GetSettingKey(i), p.GetSettingDefault(i)
        cap = key[0].upper() + key[1:]
        setter, getter = getattr(p, "Set" + cap), getattr(p, "Get" + cap)
        assert key in setter.__doc__ and "default " + default in setter.__doc__
        value = getter()
        shown = "" if default == "empty" else default  # an empty text default reads "empty" in help
        assert p.GetSetting(key) == shown, key
        setter(value)  # the Python value goes back in unchanged
        assert p.GetSetting(key) == shown, key


@pytest.mark.parametrize("family", FAMILIES)
def test_every_choice_is_accepted_and_read_back(family):
    p = family()
    for i in range(p.GetNumberOfSettings()):
        if p.GetSettingKind(i) != "choice":
            continue
        key = p.GetSettingKey(i)
        words = p.GetSettingRange(i).replace("one of ", "").split(", ")
        for w in words:
            try:
                p.set(key, w)
            except ValueError as e:  # a rule between settings may refuse it ("combine=cone needs kind=cube")
                assert str(e).startswith(p.GetMethod() + ": ") and "\n" not in str(e)
                continue
            assert p.GetSetting(key) == w
        p.set(key, p.GetSettingDefault(i))


def test_values_by_kind_and_keyword_constructor():
    p = aokit.ObscurancePass(samples=8, filter=False, bias=0.05, interleave="rotations")
    assert p.GetSamples() == 8 and isinstance(p.GetSamples(), int)
    assert p.GetFilter() is False
    assert p.GetBias() == 0.05
    assert p.GetInterleave() == "rotations"
    assert p.settings()["samples"] == 8
    h = aokit.new_pass("hybrid", res=128)
    assert isinstance(h, aokit.HybridPass) and h.GetRes() == 128


@pytest.mark.parametrize("call, message", [
    (lambda: aokit.ObscurancePass().SetSamples(0), "obscurance: samples must be an integer in 1..64, got '0'"),
    (lambda: aokit.ObscurancePass().SetSamples("many"), "obscurance: samples must be an integer in 1..64, got 'many'"),
    (lambda: aokit.ObscurancePass().SetBias(math.nan), "obscurance: bias must be a number in 0..0.5, got 'nan'"),
    (lambda: aokit.ObscurancePass().SetScale(0.3), "obscurance: scale must be one of 1, 0.5, 0.25, got '0.3'"),
    (lambda: aokit.ObscurancePass(colour=1), "obscurance: unknown setting 'colour'"),
    (lambda: aokit.HybridPass().SetRes(100000), "hybrid: res must be"),
    (lambda: aokit.new_pass("ssao"), "unknown AO method 'ssao' (known: obscurance, hybrid, field)"),
    (lambda: aokit.ObscurancePass().set_scene_radius(-1), "obscurance: the scene radius must be"),
    (lambda: aokit.HybridPass().SetSceneRadius(float("inf")), "hybrid: the scene radius must be"),
    (lambda: aokit.FieldPass().SetSceneFalloff("gauss"), "unknown falloff"),
    (lambda: aokit.load_scene("no-such-scene", None), "scene: Load needs"),
])
def test_bad_values_raise_value_error_with_the_kits_line(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value).startswith(message)
    assert "\n" not in str(e.value)


def test_bad_value_keeps_the_old_one():
    p = aokit.ObscurancePass(samples=8)
    with pytest.raises(ValueError):
        p.SetSamples(65)
    assert p.GetSamples() == 8


def test_prop_marks():
    from vtkmodules.vtkRenderingCore import vtkActor
    a = vtkActor()
    assert aokit.casts_ao(a) and aokit.receives_ao(a) and not aokit.is_static(a)
    aokit.set_casts_ao(a, False)
    aokit.set_static(a)
    assert not aokit.casts_ao(a) and aokit.receives_ao(a) and aokit.is_static(a)
    aokit.set_receives_ao(a, False)
    aokit.set_casts_ao(a, True)
    assert aokit.casts_ao(a) and not aokit.receives_ao(a) and aokit.is_static(a)


@pytest.mark.parametrize("family", FAMILIES)
def test_the_cli_json_table_is_the_passes_table(family):
    # `aokit settings --json` is what the ParaView view's properties are generated from: it must
    # carry every setting of the family with the value a fresh pass holds.
    import json
    from conftest import cli
    p = family()
    table = json.loads(subprocess.run([cli(), "settings", p.GetMethod(), "--json"], check=True,
                                      capture_output=True, text=True, timeout=60).stdout)
    assert [m["name"] for m in table] == [p.GetMethod()]
    rows = table[0]["settings"]
    assert [r["key"] for r in rows] == [p.GetSettingKey(i) for i in range(p.GetNumberOfSettings())]
    for r in rows:
        assert r["default"] == p.GetSetting(r["key"]), r["key"]
        assert r["range_text"] and r["help"]
