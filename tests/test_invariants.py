"""Invariants of the whole pipeline on random small scenes.

A fixed-seed generator writes small stages (a sphere, a rect, a disk and a
point light, a distant light with a 1.5° disc, three black box occluders,
and stage-authored irradiance, patch and radiance sensors) into ``tmp_path``
as usda text, and the tests edit them the way a user would. Every stage goes
through the normal path: ``load_stage`` → ``Engine`` → ``run("light")``.

- Light is linear: scaling every light's intensity by k, or raising every
  exposure by e, scales every reading by k or 2^e. With the same seed the
  same random numbers are drawn, so this holds per sample up to float32
  rounding (2e-6 relative; exact for powers of two).
- Rigid motions: moving and turning the whole stage, sensors included,
  changes no reading beyond its statistical error (4 combined standard
  errors plus float32 slack; the directions drawn differ).
- Scale: a stage scaled by k (metersPerUnit, or a scale on the root prim)
  with normalized lights (fixed power) reads irradiance and radiance × 1/k².
- Sample count: the variance of a reading, across independent seeds, halves
  when the samples double (an F-test at 1e-3), and the reported standard
  errors follow (their mean squares halve, within 4 replicate standard errors).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from simulator.engine.driver import Engine
from simulator.scene.model import SensorKind
from simulator.scene.usd import load_stage

SAMPLES = 1 << 14
FLOAT32_SLACK = 2e-6


def _xform(translate, rotate=(0.0, 0.0, 0.0), scale=None) -> str:
    ops = [f"double3 xformOp:translate = ({translate[0]:.6f}, {translate[1]:.6f}, {translate[2]:.6f})",
           f"float3 xformOp:rotateXYZ = ({rotate[0]:.4f}, {rotate[1]:.4f}, {rotate[2]:.4f})"]  # fmt: skip
    order = ['"xformOp:translate"', '"xformOp:rotateXYZ"']
    if scale is not None:
        ops.append(f"float3 xformOp:scale = ({scale[0]:.6f}, {scale[1]:.6f}, {scale[2]:.6f})")
        order.append('"xformOp:scale"')
    return "\n        ".join(ops + [f"uniform token[] xformOpOrder = [{', '.join(order)}]"])


class RandomStage:
    """One random scene; :meth:`text` renders it with edits applied."""

    def __init__(self, seed: int, distant: bool = True):
        rng = np.random.default_rng(seed)
        u = rng.uniform
        self.distant = distant
        self.lights = [
            ("SphereLight", "Sphere", f"float inputs:radius = {u(0.15, 0.35):.4f}", u(200, 400), (u(-1, 1), u(-1, 1), u(2.6, 3.2)), (0, 0, 0)),
            ("RectLight", "Rect", f"float inputs:width = {u(0.5, 1.2):.4f}\n        float inputs:height = {u(0.3, 0.9):.4f}",
             u(300, 600), (u(-1, 1), u(-1, 1), u(2.8, 3.2)), (u(-25, 25), u(-25, 25), u(0, 90))),
            ("DiskLight", "Disk", f"float inputs:radius = {u(0.2, 0.4):.4f}", u(300, 600), (u(-1, 1), u(-1, 1), u(2.8, 3.2)), (u(-25, 25), u(-25, 25), 0)),
            ("SphereLight", "Point", "float inputs:radius = 0.05\n        bool treatAsPoint = 1", u(800, 1600), (u(-1, 1), u(-1, 1), u(2.5, 3.0)), (0, 0, 0)),
        ]  # fmt: skip
        self.sun_rotate = (u(-35, 35), u(-35, 35), 0.0)
        self.boxes = [((u(-1.2, 1.2), u(-1.2, 1.2), u(1.0, 2.0)), (u(0.3, 0.8), u(0.3, 0.8), 0.05)) for _ in range(3)]
        self.sensors = []
        for k in range(5):
            self.sensors.append(("irradiance", f"e{k}", (u(-1.5, 1.5), u(-1.5, 1.5), u(0.0, 0.5)), (180 + u(-40, 40), u(-40, 40), 0), ""))
        self.sensors.append(("patch", "patch", (u(-0.5, 0.5), u(-0.5, 0.5), 0.2), (180, 0, u(0, 90)), "float2 probesim:sensor:size = (0.5, 0.3)"))
        rect_pos = self.lights[1][4]
        self.sensors.append(("radiance", "meter", (rect_pos[0] + u(-1, 1), rect_pos[1] + u(-1, 1), 0.3), (180 + u(-15, 15), u(-15, 15), 0),
                             "float probesim:sensor:halfAngleDeg = 10"))  # fmt: skip

    def text(self, *, intensity_factor=1.0, exposure=0.0, root_translate=(0, 0, 0), root_rotate=(0, 0, 0),
             root_scale=None, meters_per_unit=1.0) -> str:  # fmt: skip
        body = []
        for typ, name, attrs, intensity, pos, rot in self.lights:
            body.append(f"""
    def {typ} "{name}"
    {{
        float inputs:intensity = {intensity * intensity_factor:.6f}
        float inputs:exposure = {exposure:.6f}
        bool inputs:normalize = 1
        {attrs}
        {_xform(pos, rot)}
    }}""")
        if self.distant:
            body.append(f"""
    def DistantLight "Sun"
    {{
        float inputs:angle = 1.5
        float inputs:intensity = {300.0 * intensity_factor:.6f}
        float inputs:exposure = {exposure:.6f}
        bool inputs:normalize = 1
        {_xform((0, 0, 0), self.sun_rotate)}
    }}""")
        for k, (pos, size) in enumerate(self.boxes):
            body.append(f"""
    def Cube "Box{k}" (prepend apiSchemas = ["MaterialBindingAPI"])
    {{
        double size = 1
        {_xform(pos, (0, 0, 0), size)}
        rel material:binding = </World/Black>
    }}""")
        for kind, name, pos, rot, extra in self.sensors:
            body.append(f"""
    def Xform "Sensor_{name}"
    {{
        token probesim:sensor:kind = "{kind}"
        string probesim:sensor:name = "{name}"
        {extra}
        {_xform(pos, rot)}
    }}""")
        body.append("""
    def Material "Black"
    {
        token outputs:surface.connect = </World/Black/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0, 0, 0)
            token outputs:surface
        }
    }""")
        root = _xform(root_translate, root_rotate, root_scale)
        return (f'#usda 1.0\n(\n    metersPerUnit = {meters_per_unit}\n    upAxis = "Z"\n    defaultPrim = "World"\n)\n\n'
                f'def Xform "World"\n{{\n    {root}\n' + "\n".join(body) + "\n}\n")  # fmt: skip


def readings(tmp_path, text: str, name: str, seed: int = 7, samples: int = SAMPLES):
    path = tmp_path / f"{name}.usda"
    path.write_text(text)
    scene = load_stage(path)
    sensors = scene.sensors
    res = Engine(scene, sensors).run("light", samples=samples, seed=seed)
    assert res.non_finite.sum() == 0
    return scene, sensors, res


STAGE_SEEDS = [11, 12]


@pytest.mark.parametrize("stage_seed", STAGE_SEEDS)
@pytest.mark.parametrize(
    "edit, factor",
    [
        pytest.param({"intensity_factor": 3.0}, 3.0, id="intensity_x3"),
        pytest.param({"exposure": 1.5}, 2.0**1.5, id="exposure_+1.5"),
    ],
)  # fmt: skip
def test_readings_scale_with_intensity_and_exposure(tmp_path, stage_seed, edit, factor):
    """Every reading × 3 when every intensity is × 3, and × 2^1.5 when every
    exposure is +1.5 (UsdLux: emission ∝ intensity·2^exposure): the same seed
    draws the same samples, so only float32 rounding (2e-6) separates them."""
    st = RandomStage(stage_seed)
    _, sensors, base = readings(tmp_path, st.text(), "base")
    assert np.all(base.mean[:, 1] > 0)  # every sensor sees some light
    _, _, res = readings(tmp_path, st.text(**edit), "edited")
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            want = factor * base.mean[i, ch]
            assert abs(res.mean[i, ch] - want) <= FLOAT32_SLACK * abs(want), f"{s.name}[{ch}] {edit}: {res.mean[i, ch]} vs {want}"
            assert res.stderr[i, ch] == pytest.approx(factor * base.stderr[i, ch], rel=1e-4, abs=1e-12)


def _agree(a, b, i, ch, what, rel_slack=FLOAT32_SLACK):
    se = math.hypot(a.stderr[i, ch], b.stderr[i, ch])
    diff = abs(a.mean[i, ch] - b.mean[i, ch])
    assert diff <= 4.0 * se + rel_slack * abs(a.mean[i, ch]) + 1e-12, f"{what}: {a.mean[i, ch]} vs {b.mean[i, ch]} (combined stderr {se})"


@pytest.mark.parametrize("stage_seed", STAGE_SEEDS)
def test_rigid_motion_of_the_whole_stage_changes_no_reading(tmp_path, stage_seed):
    """The root prim moved by (7.3, −4.1, 2.2) m and turned by (17°, −33°, 71°),
    lights, occluders and sensors with it: each reading agrees with the
    original within 4 combined standard errors (+ float32 slack: world
    coordinates near 10 m carry 1e-6 m of rounding, which moves a point
    light's reading by ~1e-6 relative)."""
    st = RandomStage(stage_seed)
    _, sensors, base = readings(tmp_path, st.text(), "base")
    _, moved_sensors, moved = readings(tmp_path, st.text(root_translate=(7.3, -4.1, 2.2), root_rotate=(17, -33, 71)), "moved")
    assert [s.name for s in moved_sensors] == [s.name for s in sensors]
    assert not np.allclose(moved_sensors[0].position, sensors[0].position)
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            _agree(base, moved, i, ch, f"{s.name}[{ch}]")


@pytest.mark.parametrize("how", ["metersPerUnit", "root_scale"])
def test_scaled_stage_with_normalized_lights_reads_inverse_square(tmp_path, how):
    """With normalize on, a light's power is fixed whatever its size; scaling
    every length by k then spreads it over k² the area: irradiance (and a
    patch's mean irradiance, and radiance) × 1/k². Scaled by metersPerUnit
    = 2.5 or by a root scale of 0.4 (no distant light here: its normal
    illuminance is not a length-dependent quantity)."""
    st = RandomStage(21, distant=False)
    _, sensors, base = readings(tmp_path, st.text(), "base")
    if how == "metersPerUnit":
        k, text = 2.5, st.text(meters_per_unit=2.5)
    else:
        k, text = 0.4, st.text(root_scale=(0.4, 0.4, 0.4))
    scene, scaled_sensors, scaled = readings(tmp_path, text, "scaled")
    assert scaled_sensors[0].position == pytest.approx(k * sensors[0].position)
    kinds = {s.kind for s in sensors}
    assert {SensorKind.IRRADIANCE, SensorKind.PATCH, SensorKind.RADIANCE} <= kinds
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            a = base.mean[i, ch] / k**2
            b = scaled.mean[i, ch]
            se = math.hypot(base.stderr[i, ch] / k**2, scaled.stderr[i, ch])
            assert abs(a - b) <= 4 * se + 1e-5 * abs(a) + 1e-12, f"{s.name}[{ch}] k={k}: {b} vs {a} ± {se}"


def test_doubling_the_samples_halves_the_variance(tmp_path):
    """Across R = 48 independent seeds, the sample variance of each reading
    at 2n samples is half that at n: under that hypothesis (and normal means,
    n = 2048 samples each) var(n)/(2·var(2n)) follows an F(R−1, R−1)
    distribution; the two-sided p-value must exceed 1e-3/(sensors) (Bonferroni).
    The reported stderr² follow: their means over seeds differ by a factor 2
    within 4 standard errors of that ratio (delta method over the replicates)."""
    st = RandomStage(31)
    path = tmp_path / "s.usda"
    path.write_text(st.text())
    scene = load_stage(path)
    sensors = scene.sensors
    eng = Engine(scene, sensors)
    R, n = 48, 2048
    runs = {m: [eng.run("light", samples=m, seed=1000 * m + r) for r in range(R)] for m in (n, 2 * n)}
    means = {m: np.array([res.mean[:, 1] for res in runs[m]]) for m in runs}  # (R, S)
    se2 = {m: np.array([res.stderr[:, 1] ** 2 for res in runs[m]]) for m in runs}
    noisy = se2[n].mean(axis=0) > 1e-12 * np.maximum(means[n].mean(axis=0) ** 2, 1e-300)
    assert noisy.sum() >= 4
    alpha = 1e-3 / noisy.sum()
    for i in np.flatnonzero(noisy):
        f = np.var(means[n][:, i], ddof=1) / (2.0 * np.var(means[2 * n][:, i], ddof=1))
        p = 2 * min(stats.f.cdf(f, R - 1, R - 1), stats.f.sf(f, R - 1, R - 1))
        assert p > alpha, f"{sensors[i].name}: var(n)/var(2n) = {2 * f:.3f}, p = {p:.2g}"
        a, b = se2[n][:, i], se2[2 * n][:, i]
        ratio = a.mean() / b.mean()
        # delta method: var(ā/b̄)/ratio² ≈ var(a)/(R ā²) + var(b)/(R b̄²) − 2 cov(a, b)/(R ā b̄)
        rel_var = (np.var(a, ddof=1) / a.mean() ** 2 + np.var(b, ddof=1) / b.mean() ** 2
                   - 2 * np.cov(a, b)[0, 1] / (a.mean() * b.mean())) / R  # fmt: skip
        assert abs(ratio - 2.0) <= 4.0 * ratio * math.sqrt(max(rel_var, 0.0)), f"{sensors[i].name}: stderr² ratio {ratio:.3f}"
