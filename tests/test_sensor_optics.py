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
