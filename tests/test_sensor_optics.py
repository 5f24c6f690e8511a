"""A sensor model's angular response at the sensor's own vertex (kernels.optics, the hook in
vertex_estimate): closed forms, the sampler against its pdf, and its table files.

A head of response r reads ∫ L(ω) r(ω) dω (docs/REFERENCES.md §Sensor models): 2π·L/(n + 1) for
cosⁿ θ under a uniform sky, E·r(θ, φ) under a distant light of normal irradiance E, and L·∫r dω for
a table under a uniform sky, that integral taken here by scipy's adaptive quadrature of the table's
linear interpolation (no code shared with the engine). Statistical readings pass within 4 standard
errors plus float32 slack, at fixed seeds; the sampler passes a chi-square test (p > 1e-3).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import warp as wp
from scipy import integrate, stats

from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.kernels.lights import LightRec, light_record
from simulator.kernels.lights.rect import field_window
from simulator.kernels.optics import OpticsRec, optics_record, pdf_optics, sample_optics
from simulator.reference import closed_forms as cf
from simulator.scene.model import Geometry, Light, LightKind, Scene, Sensor, SensorKind
from simulator.sensor_models.angular import cos_power, half_power, read_table, table_from_arrays

wp.config.quiet = True

FLOAT32_SLACK = 2e-6  # relative: float32 arithmetic in the kernels
CHI2_P_MIN = 1e-3

UP = np.array([0.0, 0.0, 1.0])
#: a symmetric table and one with azimuth columns (0°, 90°, 200°), r(0) = 1
SYMMETRIC = table_from_arrays("sym", [0, 20, 45, 70, 85], [1.0, 0.95, 0.55, 0.2, 0.02])
ASYMMETRIC = table_from_arrays("asym", [0, 30, 60, 90], [[1.0, 0.9, 0.4, 0.0], [1.0, 0.6, 0.1, 0.0],
                                                         [1.0, 0.95, 0.8, 0.3]], [0.0, 90.0, 200.0])


def _table_integral(resp) -> float:
    """∫ r dω of a table head by scipy's dblquad of its bilinear interpolation (independent of
    AngularResponse.integral_sr)."""
    th, ph, v = resp.theta_deg, resp.phi_deg, resp.values

    def r(theta, phi):
        d = math.degrees(theta)
        if d > th[-1]:
            return 0.0
        cols = [np.interp(d, th, row) for row in v]
        if len(ph) == 1:
            return cols[0]
        knots = list(ph) + [ph[0] + 360.0]
        cols.append(cols[0])
        p = math.degrees(phi)
        p = p + 360.0 if p < ph[0] else p
        i = max(k for k in range(len(knots) - 1) if knots[k] <= p)
        f = (p - knots[i]) / (knots[i + 1] - knots[i])
        return cols[i] + f * (cols[i + 1] - cols[i])

    val, _ = integrate.dblquad(lambda t, p: r(t, p) * math.sin(t), 0.0, 2 * math.pi, 0.0, math.pi / 2,
                               epsabs=1e-10, epsrel=1e-10)
    return val


def _dome_scene(radiance: float) -> Scene:
    return Scene(Geometry(), [Light("/Sky", LightKind.DOME, np.zeros(3), np.eye(3), (radiance, 100.0 * radiance))], [])


def _modelled(name, resp, normal=UP, ref=(1.0, 0.0, 0.0)) -> Sensor:
    return Sensor(name, SensorKind.IRRADIANCE, np.zeros(3), np.asarray(normal, float), optics=resp,
                  azimuth_ref=np.asarray(ref, float))


@pytest.mark.parametrize("method", ["mis", "bsdf", "light"])
def test_cos_power_head_under_a_dome_reads_its_closed_form(method):
    """A head r = cosⁿ θ under a uniform sky (L = 2 W m⁻² sr⁻¹) reads 2π·L/(n + 1) (docs/REFERENCES.md
    §Sensor models): n = 1 (π·L, as the ideal sensor beside it), 3, 0.5, and a half-power angle of 10°
    (n = ln ½ / ln cos 10° = 45.3), by light samples weighed by r/cosθ, by directions drawn by r, and by
    both under MIS. Drawn by r the estimate is the constant 2π/(n + 1)·L, so only float32 rounding is left."""
    L = 2.0
    heads = [cos_power(1.0), cos_power(3.0), cos_power(0.5), half_power(10.0)]
    sensors = [Sensor("ideal", SensorKind.IRRADIANCE, np.zeros(3), UP)] + [_modelled(f"h{i}", h) for i, h in enumerate(heads)]
    res = Engine(_dome_scene(L), sensors).run(method, samples=1 << 14, seed=3)
    assert heads[3].exponent == pytest.approx(float(cf.half_power_exponent(10.0)), rel=1e-12)
    for i, s in enumerate(sensors):
        n = 1.0 if s.optics is None else s.optics.exponent
        for ch, scale in ((0, 1.0), (1, 100.0)):
            truth = float(cf.cos_power_dome_reading(L * scale, n))
            assert abs(res.mean[i, ch] - truth) <= 4 * res.stderr[i, ch] + FLOAT32_SLACK * truth, (method, s.name, ch, res.mean[i], truth)
        if method == "bsdf" and s.optics is not None:
            assert res.stderr[i, 0] <= 1e-6 * res.mean[i, 0]


@pytest.mark.parametrize("method", ["mis", "bsdf", "light"])
def test_table_head_under_a_dome_reads_its_integral(method):
    """A tabulated head under a uniform sky reads L·∫r dω; ∫r dω by scipy's dblquad of the table's
    interpolation (symmetric: 0–85° in five rows; three azimuth columns at 0°, 90°, 200°), and
    AngularResponse.integral_sr (exact for a piecewise-linear r) agrees with it to 1e-8."""
    L = 1.5
    sensors = [_modelled("sym", SYMMETRIC), _modelled("asym", ASYMMETRIC, ref=(0.6, 0.8, 0.0)),
               _modelled("tilted", ASYMMETRIC, normal=(0.0, 0.6, 0.8), ref=(1.0, 0.0, 0.0))]
    res = Engine(_dome_scene(L), sensors[:2]).run(method, samples=1 << 14, seed=5)
    for i, resp in enumerate((SYMMETRIC, ASYMMETRIC)):
        exact = _table_integral(resp)
        assert resp.integral_sr() == pytest.approx(exact, rel=1e-8)
        truth = L * exact
        assert abs(res.mean[i, 0] - truth) <= 4 * res.stderr[i, 0] + FLOAT32_SLACK * truth, (method, i, res.mean[i], truth)


def _distant(theta_deg: float, phi_deg: float, e: float) -> Light:
    """A delta distant light of normal irradiance ``e`` arriving from (θ, φ) about +Z, φ from +X toward +Y."""
    t, p = math.radians(theta_deg), math.radians(phi_deg)
    toward = np.array([math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)])
    ez = toward
    ex = np.cross([0.0, 1.0, 0.0] if abs(toward[1]) < 0.9 else [1.0, 0.0, 0.0], ez)
    ex /= np.linalg.norm(ex)
    return Light("/Sun", LightKind.DISTANT, np.zeros(3), np.column_stack([ex, np.cross(ez, ex), ez]), (e, 100.0 * e))


@pytest.mark.parametrize("theta, phi", [(0.0, 0.0), (12.5, 30.0), (45.0, 90.0), (63.0, 150.0), (80.0, 260.0), (88.0, 10.0)])
def test_table_head_under_a_distant_light_reads_E_r(theta, phi):
    """Under a distant light of normal irradiance E = 1000 W/m² at incidence θ and azimuth φ a head
    reads E·r(θ, φ) exactly (docs/REFERENCES.md §Sensor models): light sampling of a delta light has
    no variance, so the reading is E·r up to float32 rounding (relative 1e-5), r here by numpy's
    interpolation of the table (the symmetric head; the asymmetric one with its azimuth reference +X)."""
    e = 1000.0
    scene = Scene(Geometry(), [_distant(theta, phi, e)], [])
    sensors = [_modelled("sym", SYMMETRIC), _modelled("asym", ASYMMETRIC), _modelled("cos3", cos_power(3.0))]
    res = Engine(scene, sensors).run("light", samples=64, seed=1)
    for i, resp in enumerate((SYMMETRIC, ASYMMETRIC, cos_power(3.0))):
        if resp.kind == "power":
            r = math.cos(math.radians(theta)) ** 3
        elif resp.symmetric:
            r = float(np.interp(theta, resp.theta_deg, resp.values[0])) if theta <= resp.theta_deg[-1] else 0.0
        else:
            r = float(resp.response(theta, phi))
        assert res.mean[i, 0] == pytest.approx(e * r, rel=1e-5, abs=1e-4), (i, theta, phi, res.mean[i, 0], e * r)
        assert res.stderr[i, 0] <= 1e-5 * e


def test_furnace_head_reads_L_integral_through_bounces():
    """In the furnace (stages/furnace.usda, ρ = 0.5, L_e = 1 W m⁻² sr⁻¹) the radiance is L_e/(1 − ρ) = 2
    in every direction (docs/REFERENCES.md §Furnace), so a head reads 2·∫r dω whatever it faces: paths
    leave the head by r and carry (r/p)/π into the bounces. Path tracing, 4σ."""
    import dataclasses
    from pathlib import Path

    from simulator.config.loader import load_config
    from simulator.pipeline import load_scene

    root = Path(__file__).resolve().parents[1]
    cfg = dataclasses.replace(load_config(root / "configs" / "furnace.toml"), variants={"reflectance": "rho_0_5"})
    scene = load_scene(cfg)
    p = np.array([0.3, -0.2, 1.1])
    sensors = [Sensor("cos3", SensorKind.IRRADIANCE, p, UP, optics=cos_power(3.0)),
               Sensor("sym", SensorKind.IRRADIANCE, p, np.array([1.0, 0.0, 0.0]), optics=SYMMETRIC),
               Sensor("asym", SensorKind.IRRADIANCE, p, np.array([0.0, -0.6, -0.8]), optics=ASYMMETRIC,
                      azimuth_ref=np.array([1.0, 0.0, 0.0]))]
    res = Engine(scene, sensors).run("path", samples=1 << 13, seed=2)
    for i, s in enumerate(sensors):
        truth = float(cf.furnace_radiance(1.0, 0.5)) * s.optics.integral_sr()
        assert abs(res.mean[i, 0] - truth) <= 4 * res.stderr[i, 0] + FLOAT32_SLACK * truth, (s.name, res.mean[i], truth)


# ----------------------------------------------------------------------------- patches: a head's area average


def _patch(name, resp, up=(0.0, 1.0, 0.0), size=(2.0, 1.0)) -> Sensor:
    """A patch at the origin facing +Z (width axis cross(up, normal): +X for up = +Y), read through ``resp``."""
    return Sensor(name, SensorKind.PATCH, np.zeros(3), UP.copy(), up=np.asarray(up, float), size=size, optics=resp)


@pytest.mark.parametrize("method", ["mis", "bsdf", "light"])
def test_cos_power_patch_under_a_dome_reads_its_closed_form_at_every_point(method):
    """A patch read through a head r = cosⁿ θ (a photometer head's area average: the same hook at every
    point drawn on it) under a uniform sky (L = 2 W m⁻² sr⁻¹) reads 2π·L/(n + 1) (docs/REFERENCES.md
    §Sensor models), n = 3 and a 10° half-power head (n = 45.3), by every estimator, within 4σ. Drawn by
    r (bsdf) every sample, wherever on the patch its point falls, is that value up to float32
    rounding: the standard error is under 1e-6 of it, so every point reads the closed form."""
    L = 2.0
    heads = [cos_power(3.0), half_power(10.0)]
    sensors = [_patch(f"p{i}", h) for i, h in enumerate(heads)]
    res = Engine(_dome_scene(L), sensors).run(method, samples=1 << 14, seed=4)
    for i, h in enumerate(heads):
        for ch, scale in ((0, 1.0), (1, 100.0)):
            truth = float(cf.cos_power_dome_reading(L * scale, h.exponent))
            assert abs(res.mean[i, ch] - truth) <= 4 * res.stderr[i, ch] + FLOAT32_SLACK * truth, (method, i, ch, res.mean[i], truth)
        if method == "bsdf":
            assert res.stderr[i, 0] <= 1e-6 * res.mean[i, 0], res.stderr[i]


def test_patch_head_across_a_shadow_edge_reads_E_r_times_its_lit_share():
    """A patch (2 m × 1 m at the origin, facing +Z) under a delta distant light of normal irradiance
    E = 1000 W/m² at θ = 35° from +Z, its azimuth along +X, with a black opaque sheet at z = h = 0.4 m
    over x ≥ 0.3 m: a point (x, y, 0) is in shadow where x + h·tan θ ≥ 0.3, so the lit share of the patch
    is (x_b − x_min)/(x_max − x_min), x_b = 0.3 − h·tan θ. Read through the asymmetric table head, each
    point reads E·r(θ, φ) or 0, φ from the patch's width axis: the patch with up +Y (width +X, spanning
    x ∈ [−1, 1]) reads E·r(35°, 0°)·(x_b + 1)/2; with up +X (width −Y, spanning x ∈ [−0.5, 0.5]) the light
    lies at φ = 90° and it reads E·r(35°, 90°)·(x_b + 0.5); a plain cosine patch E·cos θ·(x_b + 1)/2.
    Each sample is a Bernoulli draw of the lit share: 4σ, 2^15 samples."""
    e, theta, h, edge = 1000.0, 35.0, 0.4, 0.3
    a, b, c, d = [edge, -20.0, h], [20.0, -20.0, h], [20.0, 20.0, h], [edge, 20.0, h]
    tris = np.array([[a, b, c], [a, c, d]], float)
    g = Geometry(points=tris.reshape(-1, 3), triangles=np.arange(6, dtype=np.int32).reshape(2, 3), albedo=np.zeros(2),
                 emission=np.zeros((2, 2)), two_sided=np.zeros(2, bool), prim=np.zeros(2, np.int32), prim_names=["/Sheet"])
    scene = Scene(g, [_distant(theta, 0.0, e)], [])
    x_b = edge - h * math.tan(math.radians(theta))
    sensors = [_patch("along", ASYMMETRIC), _patch("across", ASYMMETRIC, up=(1.0, 0.0, 0.0)),
               Sensor("cosine", SensorKind.PATCH, np.zeros(3), UP.copy(), up=np.array([0.0, 1.0, 0.0]), size=(2.0, 1.0))]
    truths = [e * float(ASYMMETRIC.response(theta, 0.0)) * (x_b + 1.0) / 2.0,
              e * float(ASYMMETRIC.response(theta, 90.0)) * (x_b + 0.5),
              e * math.cos(math.radians(theta)) * (x_b + 1.0) / 2.0]
    res = Engine(scene, sensors).run("light", samples=1 << 15, seed=6)
    for i, truth in enumerate(truths):
        assert abs(res.mean[i, 0] - truth) <= 4 * res.stderr[i, 0] + FLOAT32_SLACK * truth, (sensors[i].name, res.mean[i], truth)


# ----------------------------------------------------------------------------- the sampler


@wp.kernel
def _draw(o: OpticsRec, seed: int, local: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float),
          twin: wp.array(dtype=float), weight: wp.array(dtype=float)):
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    s = sample_optics(o, wp.vec2(wp.randf(rng), wp.randf(rng)))
    local[i] = s.local
    pdf[i] = s.pdf
    twin[i] = pdf_optics(o, s.local)
    weight[i] = s.weight


@wp.kernel
def _pdf_at(o: OpticsRec, local: wp.array(dtype=wp.vec3), out: wp.array(dtype=float)):
    i = wp.tid()
    out[i] = pdf_optics(o, local[i])


def _pdf_grid(rec, mu: np.ndarray, phi: np.ndarray) -> np.ndarray:
    s = np.sqrt(np.maximum(0.0, 1.0 - mu * mu))
    d = np.stack([s * np.cos(phi), s * np.sin(phi), mu], -1).reshape(-1, 3).astype(np.float32)
    out = wp.empty(len(d), dtype=float, device="cpu")
    wp.launch(_pdf_at, dim=len(d), inputs=[rec, wp.array(d, dtype=wp.vec3, device="cpu"), out], device="cpu")
    return out.numpy().reshape(mu.shape)


@pytest.mark.parametrize("resp", [SYMMETRIC, ASYMMETRIC, cos_power(4.0), half_power(10.0)], ids=lambda r: r.name)
def test_optics_sampler_follows_its_pdf(resp):
    """sample_optics draws directions with the density pdf_optics gives: chi-square over bins in
    (1 − μ, φ) with expected counts N·∫_bin pdf dω, the code's pdf integrated by Gauss–Legendre (8 × 8
    nodes per bin, never rescaled); the pdf integrates to 1 over the hemisphere (within 1e-3); the
    returned pdf equals its twin (rel. 1e-4) but for float32 rounding at a θ-bin edge (where the twin may
    find the neighbouring bin: under 1e-4 of the draws, each within 1e-4 rad of an edge), and the
    weight equals r/pdf with r from numpy."""
    keep: list = []
    with wp.ScopedDevice("cpu"):
        rec = optics_record(resp, keep)
    n = 1 << 18
    out = [wp.empty(n, dtype=t, device="cpu") for t in (wp.vec3, float, float, float)]
    wp.launch(_draw, dim=n, inputs=[rec, 17, *out], device="cpu")
    local, pdf, twin, weight = (o.numpy() for o in out)
    assert np.all(local[:, 2] >= 0) and np.all(pdf > 0)
    theta = np.degrees(np.arctan2(np.hypot(local[:, 0], local[:, 1]), local[:, 2]))
    off = np.abs(twin - pdf) > 1e-4 * pdf
    assert off.mean() < 1e-4, off.mean()
    if resp.kind == "table" and off.any():
        d_theta = resp.theta_deg[-1] / 256
        to_edge = np.abs(theta[off] / d_theta - np.round(theta[off] / d_theta)) * math.radians(d_theta)
        assert np.all(to_edge < 1e-4), to_edge
    else:
        assert not off.any()
    phi = np.degrees(np.mod(np.arctan2(local[:, 1], local[:, 0]), 2 * np.pi))
    r = resp.response(theta, phi)
    np.testing.assert_allclose(weight, r / pdf, rtol=2e-4, atol=1e-6)
    # bins: 1 − μ on a square-root scale (narrow heads), φ in 8 sectors
    top = 1.0 - math.cos(math.radians(resp.theta_deg[-1] if resp.kind == "table" else 90.0))
    edges = top * np.linspace(0.0, 1.0, 25) ** 2
    pe = np.linspace(0.0, 2 * np.pi, 9)
    x, w = np.polynomial.legendre.leggauss(8)
    expected = np.zeros((24, 8))
    for a in range(24):
        m = edges[a] + (edges[a + 1] - edges[a]) * (x + 1) / 2
        wm = w * (edges[a + 1] - edges[a]) / 2
        for b in range(8):
            ph = pe[b] + (pe[b + 1] - pe[b]) * (x + 1) / 2
            wph = w * (pe[b + 1] - pe[b]) / 2
            grid = _pdf_grid(rec, 1.0 - m[:, None] + 0 * ph[None, :], ph[None, :] + 0 * m[:, None])
            expected[a, b] = n * float(wm @ grid @ wph)
    assert abs(expected.sum() / n - 1.0) < 1e-3, expected.sum() / n
    ia = np.clip(np.searchsorted(edges, 1.0 - local[:, 2], side="right") - 1, 0, 23)
    ib = np.clip((np.radians(phi) / (2 * np.pi) * 8).astype(int), 0, 7)
    counts = np.zeros((24, 8))
    np.add.at(counts, (ia, ib), 1)
    e, c = expected.reshape(-1), counts.reshape(-1)
    order = np.argsort(e)  # merge bins under 5 expected into their neighbours
    e, c = e[order], c[order]
    ce, cc = np.cumsum(e), np.cumsum(c)
    cut = np.searchsorted(ce, 5.0)
    e = np.concatenate([[ce[cut]], e[cut + 1:]])
    c = np.concatenate([[cc[cut]], c[cut + 1:]])
    chi2 = stats.chisquare(c, e * c.sum() / e.sum())
    assert chi2.pvalue > CHI2_P_MIN, chi2


# ----------------------------------------------------------------------------- light samples in the field


@wp.kernel
def _window(l: LightRec, p: wp.vec3, a: wp.vec3, cos_f: float, out: wp.array(dtype=wp.vec4)):
    out[0] = field_window(l, p, a, cos_f)


def _rect(centre, width, height, spin_deg=0.0, tilt_deg=0.0) -> Light:
    """A RectLight facing down (its −ez), spun about Z and tilted about its own X."""
    s, t = math.radians(spin_deg), math.radians(tilt_deg)
    rz = np.array([[math.cos(s), -math.sin(s), 0.0], [math.sin(s), math.cos(s), 0.0], [0.0, 0.0, 1.0]])
    rx = np.array([[1.0, 0.0, 0.0], [0.0, math.cos(t), -math.sin(t)], [0.0, math.sin(t), math.cos(t)]])
    return Light("/R", LightKind.RECT, np.asarray(centre, float), rz @ rx, (4000.0, 4000.0), width=width, height=height)


def _window_brute(light: Light, p, a, alpha_deg: float) -> np.ndarray:
    """(u0, u1, v0, v1): 200,000 directions on the cone's rim met with the light's plane, their extent
    along ex and ey from the corner, clipped to the light (numpy, float64)."""
    a = np.asarray(a, float) / np.linalg.norm(a)
    t1 = np.cross(a, [1.0, 0.0, 0.0] if abs(a[0]) < 0.9 else [0.0, 1.0, 0.0])
    t1 /= np.linalg.norm(t1)
    t2 = np.cross(a, t1)
    phi = np.linspace(0.0, 2 * np.pi, 200_000, endpoint=False)
    al = math.radians(alpha_deg)
    d = math.cos(al) * a + math.sin(al) * (np.cos(phi)[:, None] * t1 + np.sin(phi)[:, None] * t2)
    ex, ey, ez = light.frame.T
    corner = light.position - 0.5 * light.width * ex - 0.5 * light.height * ey
    s = ((corner - p) @ ez) / (d @ ez)
    x = p + s[:, None] * d - corner
    u, v = x @ ex, x @ ey
    return np.array([max(0.0, u.min()), min(light.width, u.max()), max(0.0, v.min()), min(light.height, v.max())])


@pytest.mark.parametrize("case", ["straight", "tilted", "spun_and_tilted_light", "clipped_one_side"])
def test_field_window_bounds_the_cone_on_the_light(case):
    """field_window (the dual conic's tangent lines, docs/REFERENCES.md §Light samples in a narrow field)
    gives the bounding box of the ellipse a head's field cone cuts in a RectLight's plane, clipped to the
    light: the same box, within 1e-4 m (float32), as 200,000 rays of the cone's rim met with that plane by
    numpy (their spacing, 3e-5 rad, leaves under 1e-6 m at these distances)."""
    p = np.array([0.1, -0.2, 0.0])
    light, a, alpha = {
        "straight": (_rect((0.3, -0.1, 2.0), 3.0, 2.0), (0.0, 0.0, 1.0), 10.5),
        "tilted": (_rect((0.6, 0.2, 2.5), 4.0, 3.0), (0.2, 0.1, 1.0), 20.0),
        "spun_and_tilted_light": (_rect((0.0, 0.5, 1.8), 3.0, 2.5, spin_deg=30.0, tilt_deg=15.0), (-0.1, 0.25, 1.0), 12.0),
        "clipped_one_side": (_rect((0.5, -0.2, 2.0), 1.2, 0.3), (0.0, 0.0, 1.0), 10.5),
    }[case]
    keep: list = []
    with wp.ScopedDevice("cpu"):
        rec = light_record(light, keep)
        out = wp.zeros(1, dtype=wp.vec4)
        a_n = np.asarray(a, float) / np.linalg.norm(a)
        wp.launch(_window, dim=1, inputs=[rec, wp.vec3(*p), wp.vec3(*a_n), math.cos(math.radians(alpha)), out])
    got = out.numpy()[0]
    want = _window_brute(light, p, a_n, alpha)
    np.testing.assert_allclose(got, want, atol=1e-4)
    assert want[1] - want[0] < light.width or want[3] - want[2] < light.height  # the window is a part of the light


def test_field_window_whole_light_where_the_cone_is_unbounded_and_empty_where_it_misses():
    """A field whose cone reaches the light plane's horizon (axis 80° from the light's normal, α = 20°)
    cuts no ellipse: the window is the whole light. A light 2 m aside of a 10° field straight up lies
    wholly outside it: the window is empty (u0 ≥ u1), so the head draws no light sample there."""
    keep: list = []
    with wp.ScopedDevice("cpu"):
        out = wp.zeros(1, dtype=wp.vec4)
        light = _rect((0.0, 0.0, 2.0), 1.2, 0.3)
        rec = light_record(light, keep)
        a = np.array([math.sin(math.radians(80.0)), 0.0, math.cos(math.radians(80.0))])
        wp.launch(_window, dim=1, inputs=[rec, wp.vec3(0.0, 0.0, 0.0), wp.vec3(*a), math.cos(math.radians(20.0)), out])
        np.testing.assert_allclose(out.numpy()[0], [0.0, 1.2, 0.0, 0.3], atol=1e-6)
        rec = light_record(_rect((2.0, 0.0, 2.0), 1.2, 0.3), keep)
        wp.launch(_window, dim=1, inputs=[rec, wp.vec3(0.0, 0.0, 0.0), wp.vec3(0.0, 0.0, 1.0), math.cos(math.radians(10.5)), out])
        w = out.numpy()[0]
        assert w[0] >= w[1], w


CONE = table_from_arrays("cone", [0.0, 10.0, 10.5], [1.0, 1.0, 0.0])


def _arc_inside(rho: float, x0: float, x1: float, y0: float, y1: float) -> float:
    """Angle (radians) of the circle of radius ρ about the origin that lies in [x0, x1] × [y0, y1]: its
    crossings with the four edge lines sorted, each arc between two tested at its middle."""
    cuts = [0.0, 2 * math.pi]
    for c, on_x in ((x0, True), (x1, True), (y0, False), (y1, False)):
        if abs(c) < rho:
            t = math.acos(c / rho) if on_x else math.asin(c / rho)
            cuts += [t % (2 * math.pi), (-t if on_x else math.pi - t) % (2 * math.pi)]
    cuts.sort()
    total = 0.0
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        m = 0.5 * (lo + hi)
        if x0 <= rho * math.cos(m) <= x1 and y0 <= rho * math.sin(m) <= y1:
            total += hi - lo
    return total


def _rect_reading(light: Light, resp, power: float = 1.0, whole: bool = False) -> float:
    """∫ L·r(θ) dω over a RectLight facing down at height h above a head at the origin looking up, in
    polar coordinates about the point straight above: L·∫ r(θ)·(h/d)/d²·ρ·arc(ρ) dρ (cosθ = cosθ_l = h/d,
    d² = h² + ρ², arc(ρ) the angle of the circle ρ on the light, exact), by scipy's quad broken at the
    table's knots and where the circle meets the light's edges and corners; r by numpy's interpolation
    of the table, or cosⁿ (no code shared with the engine). ``power``: ∫ L·rᵖ dω; ``whole``: r = 1 (L·Ω)."""
    h = light.position[2]
    x0, x1 = light.position[0] - light.width / 2, light.position[0] + light.width / 2
    y0, y1 = light.position[1] - light.height / 2, light.position[1] + light.height / 2

    def r_of(th_deg):
        if whole:
            return 1.0
        if resp.kind == "power":
            return math.cos(math.radians(th_deg)) ** (resp.exponent * power)
        return float(np.interp(th_deg, resp.theta_deg, resp.values[0], right=0.0)) ** power

    def f(rho):
        d2 = h * h + rho * rho
        return r_of(math.degrees(math.atan2(rho, h))) * h / d2**1.5 * rho * _arc_inside(rho, x0, x1, y0, y1)

    top = math.hypot(max(abs(x0), abs(x1)), max(abs(y0), abs(y1)))
    if resp.kind == "table" and not whole:
        top = min(top, h * math.tan(math.radians(resp.theta_deg[-1])))
    breaks = sorted({abs(x0), abs(x1), abs(y0), abs(y1), *(math.hypot(x, y) for x in (x0, x1) for y in (y0, y1)),
                     *(h * math.tan(math.radians(t)) for t in (resp.theta_deg if resp.kind == "table" else ()))})
    edges = [0.0] + [b for b in breaks if 0.0 < b < top] + [top]
    val = sum(integrate.quad(f, lo, hi, epsabs=1e-14, epsrel=1e-11, limit=200)[0] for lo, hi in zip(edges[:-1], edges[1:]))
    return light.emission[0] * val


@pytest.mark.parametrize("resp", [CONE, half_power(10.0)], ids=["cone", "half_power"])
@pytest.mark.parametrize("method", ["light", "mis", "bsdf"])
def test_narrow_head_under_a_rect_light_partly_in_its_field(resp, method):
    """A 10° head looking up at a 1.2 m × 0.3 m RectLight (4000 cd/m², 2 m up, its centre 0.25 m and
    0.1 m aside, so its field holds part of it) reads L·∫ r dω over the light
    (docs/REFERENCES.md §Sensor models; by quadrature in _rect_reading: 196.0 W/m² for the cone, 175.5
    W/m² for the half-power head):
    by light samples drawn toward r in the field (light; for the cosⁿ head over the whole light, which has
    no edge outside which r is 0), by those and the directions drawn by r under MIS (mis: the cosⁿ head's
    window where r ≥ 0.01, the rest the directions'), and by the directions alone (bsdf). Within 4
    standard errors plus float32 slack."""
    light = _rect((0.25, 0.1, 2.0), 1.2, 0.3)
    truth = _rect_reading(light, resp)
    res = Engine(Scene(Geometry(), [light], []), [_modelled("h", resp)]).run(method, samples=1 << 14, seed=11)
    assert abs(res.mean[0, 0] - truth) <= 4 * res.stderr[0, 0] + FLOAT32_SLACK * truth, (res.mean[0], res.stderr[0], truth)


def test_cone_head_light_samples_beat_the_plain_light_sample():
    """The cone head of the test above under ``light``: a plain light sample, uniform in the light's
    solid angle Ω, would estimate L·r(ω)·Ω, of relative variance per sample Ω·∫r² dω/(∫r dω)² − 1
    (quadrature: 0.70 here, most of the light lying outside the field; the tree before this sampler
    measured 0.72). Drawn within the field's window and resampled toward r (16 candidates,
    kernels.lights.rect.sample_field), one sample's relative variance is at most a tenth of that
    (measured 0.005 at this seed: what is left is the spread of the candidates' mean of r over the
    window, whose corners lie outside the cone's ellipse)."""
    light = _rect((0.25, 0.1, 2.0), 1.2, 0.3)
    mean, second = _rect_reading(light, CONE), _rect_reading(light, CONE, power=2.0)
    omega = _rect_reading(light, CONE, whole=True) / light.emission[0]
    plain = omega * light.emission[0] * second / mean**2 - 1.0
    res = Engine(Scene(Geometry(), [light], []), [_modelled("h", CONE)]).run("light", samples=1 << 14, seed=11)
    v = res.samples[0] * res.stderr[0, 0] ** 2 / res.mean[0, 0] ** 2
    assert plain > 0.5, plain
    assert v <= 0.1 * plain, (v, plain)


# ----------------------------------------------------------------------------- the files


def _write(tmp_path, text: str):
    p = tmp_path / "head.csv"
    p.write_text(text)
    return p


def test_angular_table_reads_and_normalises(tmp_path):
    """A datasheet table is read as written and normalised to 1 at 0°; azimuth columns too; a table that
    ends before 90° with a response left is noted (read as 0 beyond)."""
    r = read_table(_write(tmp_path, "# a head\nangle_deg,response\n0,80\n40,60\n80,8\n"))
    assert r.values[0].tolist() == pytest.approx([1.0, 0.75, 0.1])
    assert r.response(20.0) == pytest.approx(0.875) and r.response(85.0) == 0.0
    assert any("ends at 80" in n for n in r.notes)
    a = read_table(_write(tmp_path, "angle_deg,response_0,response_180\n0,1,1\n90,0,0.5\n"))
    assert a.response(90.0, 90.0) == pytest.approx(0.25) and not a.symmetric


@pytest.mark.parametrize("text, message", [
    ("angle_deg,response\n0,1\n30,-0.2\n", "head.csv:3: response -0.2 is negative"),
    ("angle_deg,response\n0,1\n95,0.1\n", "head.csv:3: angle 95° is outside 0–90°"),
    ("angle_deg,response\n0,1\n40,0.5\n30,0.6\n", "head.csv:4: angle 30° is not above the previous row's (40°)"),
    ("angle_deg,response\n0,0\n30,0.6\n", "head.csv:2: the response at normal incidence is 0"),
    ("angle_deg,response\n5,1\n30,0.6\n", "head.csv:2: the first angle must be 0°"),
    ("angle,response\n0,1\n", "head.csv:1: angular response header"),
    ("angle_deg,response\n0,1\n", "needs at least 2 rows"),
    ("angle_deg,response_0,response_400\n0,1,1\n", "head.csv:1: column 'response_400': the azimuth must be in [0, 360)"),
    ("angle_deg,response\n0,1\n30,x\n", "head.csv:3: not a number"),
])
def test_angular_table_errors_name_file_and_row(tmp_path, text, message):
    """Each bad table is one UserError line naming the file and its row."""
    with pytest.raises(UserError) as e:
        read_table(_write(tmp_path, text))
    assert message in str(e.value) and "\n" not in str(e.value), str(e.value)
