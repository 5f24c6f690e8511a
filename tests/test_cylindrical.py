"""Cylindrical and semi-cylindrical sensors: closed forms against numeric quadrature, the sampler and
the engine's closed form against them, config and stage reading."""

import math

import numpy as np
import pytest

from simulator.reference import closed_forms as cf


def _normals(axis, facing, phis):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    f = np.asarray(facing, float) - np.dot(facing, a) * a
    f /= np.linalg.norm(f)
    g = np.cross(a, f)
    return np.cos(phis)[:, None] * f + np.sin(phis)[:, None] * g


def _mean_irradiance(intensity, src, p, normals):
    w = np.asarray(src, float) - np.asarray(p, float)
    d2 = w @ w
    return float(np.mean(intensity * np.maximum(normals @ (w / math.sqrt(d2)), 0.0) / d2))


@pytest.mark.parametrize("src, p, axis, facing", [
    ((0, 0, 3), (1.0, 0.5, 1.0), (0, 0, 1), (-1, 0, 0)),
    ((0, 0, 3), (1.0, 0.5, 1.0), (0, 0, 1), (1, 0, 0)),
    ((0.2, -1.0, 2.5), (1.5, 0.0, 1.0), (0, 0, 1), (0, 1, 0.5)),
    ((0, 0, 3), (1.0, 0.0, 1.0), (0, 0.6, 0.8), (1, 0, 0)),
])  # fmt: skip
def test_point_closed_forms_match_quadrature_over_the_surface(src, p, axis, facing):
    """Midpoint quadrature of E(n) = I·max(0, n·ŵ)/d² over the (half) cylinder's normals, 200,000 points,
    against I·sinθ/(πd²) and I·sinθ(1 + cos φ)/(πd²) (docs/REFERENCES.md §Cylindrical illuminance)."""
    k = 200_000
    whole = (np.arange(k) + 0.5) * (2 * np.pi / k)
    half = -0.5 * np.pi + (np.arange(k) + 0.5) * (np.pi / k)
    ez = _mean_irradiance(100.0, src, p, _normals(axis, facing, whole))
    esc = _mean_irradiance(100.0, src, p, _normals(axis, facing, half))
    assert cf.cylindrical_point_irradiance(100.0, src, p, axis) == pytest.approx(ez, rel=1e-6)
    assert cf.semicylindrical_point_irradiance(100.0, src, p, facing, axis) == pytest.approx(esc, rel=1e-6)


def test_sphere_integrals_of_uniform_fields():
    """(1/π)∫L·sinθ dω: πL over the whole sphere, πL/2 over the upper hemisphere; with (1 + cos φ) the same
    (scipy dblquad over θ and φ)."""
    from scipy.integrate import dblquad

    def integral(weight, th_max):
        v, _ = dblquad(lambda th, ph: weight(th, ph) * math.sin(th), 0.0, 2 * math.pi, 0.0, th_max, epsabs=1e-11)
        return v / math.pi

    cyl = lambda th, ph: math.sin(th)  # noqa: E731
    semi = lambda th, ph: math.sin(th) * (1.0 + math.cos(ph))  # noqa: E731
    assert integral(cyl, math.pi) == pytest.approx(math.pi, rel=1e-9)
    assert integral(semi, math.pi) == pytest.approx(math.pi, rel=1e-9)
    assert integral(cyl, 0.5 * math.pi) == pytest.approx(float(cf.dome_cylindrical_irradiance(1.0)), rel=1e-9)
    assert integral(semi, 0.5 * math.pi) == pytest.approx(float(cf.dome_cylindrical_irradiance(1.0)), rel=1e-9)


def _run(text, tmp_path, method=None):
    from simulator.config.loader import load_config
    from simulator.engine.driver import Engine
    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan
    from simulator.scene.usd import load_stage

    p = tmp_path / "c.toml"
    p.write_text(text)
    cfg = load_config(p)
    scene = load_stage(cfg.stage, light_units=cfg.light_units)
    sensors = cfg.sensors
    import dataclasses

    sim = cfg.simulation if method is None else dataclasses.replace(cfg.simulation, method=method)
    res = run_plan(Engine(scene, sensors), make_plan(scene, sensors, sim.method, sim.component), sim)
    return sensors, res, scene


_POINT = """
stage = "{root}/stages/point.usda"
[simulation]
samples = 8192
seed = 3
[[sensor]]
name = "cyl"
kind = "cylindrical"
position = [1.0, 0.5, 1.0]
[[sensor]]
name = "semi"
kind = "semicylindrical"
position = [1.0, 0.5, 1.0]
facing = [-1, 0, 0.3]
[[sensor]]
name = "tilted"
kind = "cylindrical"
position = [1.0, 0.0, 1.0]
axis = [0, 0.6, 0.8]
"""


def _root():
    from pathlib import Path

    return Path(__file__).resolve().parent.parent.as_posix()


@pytest.mark.parametrize("method", ["light", "path", None])
def test_engine_reads_the_closed_form_under_a_point_light(tmp_path, method):
    """Sampled (light, path: within 4 standard errors) and planned (the analytic closed form, float32) readings."""
    sensors, res, scene = _run(_POINT.format(root=_root()), tmp_path, method)
    (l,) = scene.lights
    want = [cf.cylindrical_point_irradiance(l.emission[1], l.position, sensors[0].position, sensors[0].up),
            cf.semicylindrical_point_irradiance(l.emission[1], l.position, sensors[1].position, sensors[1].normal, sensors[1].up),
            cf.cylindrical_point_irradiance(l.emission[1], l.position, sensors[2].position, sensors[2].up)]  # fmt: skip
    for i, w in enumerate(want):
        if method is None:
            assert res.methods[i] == "analytic" and res.stderr[i, 1] == 0
            assert res.mean[i, 1] == pytest.approx(w, rel=1e-5)
        else:
            assert res.stderr[i, 1] > 0 and abs(res.mean[i, 1] - w) <= 4 * res.stderr[i, 1]


def test_engine_reads_pi_l_over_2_under_a_uniform_sky(tmp_path):
    text = f"""
stage = "{_root()}/stages/dome.usda"
[simulation]
samples = 32768
seed = 2
method = "mis"
[[sensor]]
name = "cyl"
kind = "cylindrical"
position = [0, 0, 1]
[[sensor]]
name = "semi"
kind = "semicylindrical"
position = [0, 0, 1]
facing = [0, -1, 0]
"""
    sensors, res, scene = _run(text, tmp_path)
    want = float(cf.dome_cylindrical_irradiance(scene.lights[0].emission[1]))
    for i in range(2):
        assert abs(res.mean[i, 1] - want) <= 4 * res.stderr[i, 1] and res.stderr[i, 1] < 0.01 * want


def test_csv_columns_only_when_a_run_has_one(tmp_path):
    """Runs without a cylindrical sensor keep their header; one with both kinds writes their columns after it."""
    from simulator.io.results import COLUMNS, _csv_text, readings_from

    sensors, res, _ = _run(_POINT.format(root=_root()), tmp_path)
    assert not any("cylindrical" in c for c in COLUMNS)
    rows = readings_from(sensors, res.mean, res.stderr, res.samples, res.seconds, res.methods, None)
    head = _csv_text(rows).splitlines()[0].split(",")
    assert head[: len(COLUMNS)] == list(COLUMNS)
    assert head[len(COLUMNS) :] == ["cylindrical_irradiance_W_m2", "cylindrical_irradiance_stderr_W_m2", "cylindrical_illuminance_lx",
                                    "cylindrical_illuminance_stderr_lx", "semicylindrical_irradiance_W_m2",
                                    "semicylindrical_irradiance_stderr_W_m2", "semicylindrical_illuminance_lx",
                                    "semicylindrical_illuminance_stderr_lx"]  # fmt: skip


@pytest.mark.parametrize("extra, message", [
    ('kind = "semicylindrical"\nposition = [0, 0, 1]\nfacing = [0, 0, 2]', "sensor[0].facing: parallel to sensor[0].axis"),
    ('kind = "cylindrical"\nposition = [0, 0, 1]\nfacing = [1, 0, 0]', "facing: not valid for kind 'cylindrical'"),
    ('kind = "semicylindrical"\nposition = [0, 0, 1]', "facing"),
])  # fmt: skip
def test_config_mistakes_are_one_line(tmp_path, capsys, extra, message):
    from simulator.commands.cli import main

    p = tmp_path / "bad.toml"
    p.write_text(f'stage = "{_root()}/stages/point.usda"\n[[sensor]]\nname = "s"\n{extra}\n[output]\ncsv = "{tmp_path.as_posix()}/o.csv"\n')
    assert main(["run", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and message in err, err
    assert not (tmp_path / "o.csv").exists()


def test_a_stage_authored_cylindrical_sensor(tmp_path):
    """A prim with probesim:sensor:kind = "cylindrical": its axis is the prim's +Y (a camera's up), so a
    prim turned 90° about X stands the axis along +Z; it reads the point light's closed form."""
    from simulator.scene.usd import load_stage

    stage = tmp_path / "s.usda"
    stage.write_text('''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def SphereLight "Point"
{
    float inputs:intensity = 400
    bool inputs:normalize = 1
    float inputs:radius = 0.05
    bool treatAsPoint = 1
    double3 xformOp:translate = (0, 0, 3)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Xform "Ez"
{
    token probesim:sensor:kind = "cylindrical"
    double3 xformOp:translate = (1, 0.5, 1)
    float3 xformOp:rotateXYZ = (90, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
}
''')
    scene = load_stage(stage, light_units="photometric")
    (s,) = scene.sensors
    assert s.spec.name == "cylindrical" and np.allclose(s.up, [0, 0, 1], atol=1e-9)
    from simulator.engine.driver import Engine

    r = Engine(scene, [s]).run("analytic", samples=0, seed=0)
    (l,) = scene.lights
    assert r.mean[0, 1] == pytest.approx(float(cf.cylindrical_point_irradiance(l.emission[1], l.position, s.position)), rel=1e-5)
