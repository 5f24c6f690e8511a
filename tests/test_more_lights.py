"""Textured DomeLights, CylinderLights and MeshLightAPI geometry lights.

Reference values come from formulas evaluated in numpy, independently of the
kernels: exact texel integrals of n·ω over a lat-long map, a fine surface
quadrature over a cylinder's side, Lambert's polygon formula
(``simulator.reference.closed_forms``). A statistical reading passes when
|estimate − truth| ≤ 4·stderr + float32 slack (+ the stated quadrature error
bound where the reference is a quadrature), with fixed seeds. Samplers get
chi-square tests against their pdf.

EXR maps are written by the tests (``simulator.io.exr``) into tmp_path.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import warp as wp
from scipy import stats

from simulator.reference import closed_forms as cf
from simulator.io import exr, latlong
from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.kernels import distributions as D
from simulator.scene.model import LightKind, Sensor, SensorKind
from simulator.scene.usd import load_stage
from simulator.units import emission_pair, luminance_grey, luminous_efficacy

FLOAT32_SLACK = 2e-6  # relative: float32 arithmetic in the kernels
CHI2_P_MIN = 1e-3  # a correct sampler fails with probability 1e-3 (fixed seed: deterministic)

wp.config.quiet = True


# ----------------------------------------------------------------------------- helpers


def write_stage(tmp_path: Path, body: str, up: str = "Z") -> Path:
    path = tmp_path / "s.usda"
    path.write_text(f'#usda 1.0\n(\n    upAxis = "{up}"\n    metersPerUnit = 1\n)\n\n{body}')
    return path


def write_map(path: Path, grey: np.ndarray, rgb_scale=(1.0, 1.0, 1.0)) -> Path:
    """A lat-long EXR whose BT.709 luminance is ``grey`` (R, G, B = grey × scale / Y(scale))."""
    y = luminance_grey(rgb_scale)
    exr.write_channels(path, {c: grey * s / y for c, s in zip("RGB", rgb_scale)})
    return path


def dome_body(file: str = "sky.exr", intensity: float = 1.0, extra: str = "", typ: str = "DomeLight",
              name: str = "Sky", fmt: str | None = "latlong") -> str:
    fmt_line = f'    token inputs:texture:format = "{fmt}"\n' if fmt else ""
    return (f'def {typ} "{name}"\n{{\n    float inputs:intensity = {intensity}\n'
            f"    asset inputs:texture:file = @./{file}@\n{fmt_line}{extra}}}\n")


def irradiance(name, p, n):
    n = np.asarray(n, float)
    return Sensor(name, SensorKind.IRRADIANCE, np.asarray(p, float), n / np.linalg.norm(n))


def radiance(name, p, d, half_angle_deg):
    d = np.asarray(d, float)
    return Sensor(name, SensorKind.RADIANCE, np.asarray(p, float), d / np.linalg.norm(d),
                  half_angle=math.radians(half_angle_deg))


def check(res, i, ch, truth, extra=0.0, label=""):
    est, se = res.mean[i, ch], res.stderr[i, ch]
    bound = 4.0 * se + FLOAT32_SLACK * abs(truth) + extra + 1e-12
    assert abs(est - truth) <= bound, f"{label}[{ch}]: {est} vs {truth} ± {se} (bound {bound})"


def rotation(seed: int) -> np.ndarray:
    """A random proper rotation (QR of a Gaussian matrix)."""
    q, r = np.linalg.qr(np.random.default_rng(seed).normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


def texel_cos_integral(n_local, width, height, rows, cols):
    """Exact ∫ n·ω dω over texels (rows, cols) of a lat-long map, in the map frame.

    With ω = (sinθ sinφ, cosθ, sinθ cosφ) (φ = longitude) and dω = sinθ dθ dφ:
    ∫∫ n·ω dω = n_x·S·(cos φ0 − cos φ1) + n_y·(sin²θ1 − sin²θ0)/2·(φ1 − φ0) + n_z·S·(sin φ1 − sin φ0),
    S = ∫ sin²θ dθ = [θ/2 − sin 2θ/4] over the row. Valid where n·ω ≥ 0 on the whole texel.
    """
    rows = np.asarray(rows)
    cols = np.asarray(cols)
    t0, t1 = np.pi * rows / height, np.pi * (rows + 1) / height
    phi1 = np.pi * (1 - 2 * cols / width)  # u = i/W is the texel's upper longitude
    phi0 = np.pi * (1 - 2 * (cols + 1) / width)
    s = (t1 - t0) / 2 - (np.sin(2 * t1) - np.sin(2 * t0)) / 4
    return (n_local[0] * s * (np.cos(phi0) - np.cos(phi1))
            + n_local[1] * (np.sin(t1) ** 2 - np.sin(t0) ** 2) / 2 * (phi1 - phi0)
            + n_local[2] * s * (np.sin(phi1) - np.sin(phi0)))


# ----------------------------------------------------------------------------- test kernels


@wp.kernel
def _draw_piecewise_2d(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int, seed: int,
                       out_uv: wp.array(dtype=wp.vec2), out_pdf: wp.array(dtype=float),
                       out_pdf_twin: wp.array(dtype=float), out_texel: wp.array(dtype=int)):
    t = wp.tid()
    rng = wp.rand_init(seed, t)
    s = D.sample_piecewise_2d(marg, cond, w, h, wp.vec2(wp.randf(rng), wp.randf(rng)))
    out_uv[t] = s.uv
    out_pdf[t] = s.pdf
    out_pdf_twin[t] = D.pdf_piecewise_2d(marg, cond, w, h, s.uv)
    out_texel[t] = s.texel


@wp.kernel
def _draw_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,
                  ex: wp.vec3, ey: wp.vec3, ez: wp.vec3, seed: int,
                  out_dir: wp.array(dtype=wp.vec3), out_pdf: wp.array(dtype=float),
                  out_pdf_twin: wp.array(dtype=float)):
    t = wp.tid()
    rng = wp.rand_init(seed, t)
    s = D.sample_latlong(marg, cond, w, h, ex, ey, ez, wp.vec2(wp.randf(rng), wp.randf(rng)))
    out_dir[t] = s.wi
    out_pdf[t] = s.pdf
    out_pdf_twin[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, s.wi)


@wp.kernel
def _eval_latlong(marg: wp.array(dtype=float), cond: wp.array(dtype=float), w: int, h: int,
                  ex: wp.vec3, ey: wp.vec3, ez: wp.vec3, dirs: wp.array(dtype=wp.vec3), uvs: wp.array(dtype=wp.vec2),
                  out_pdf: wp.array(dtype=float), out_uv: wp.array(dtype=wp.vec2), out_dir: wp.array(dtype=wp.vec3)):
    t = wp.tid()
    out_pdf[t] = D.pdf_latlong(marg, cond, w, h, ex, ey, ez, dirs[t])
    out_uv[t] = D.direction_to_latlong_uv(dirs[t], ex, ey, ez)
    out_dir[t] = D.latlong_uv_to_direction(uvs[t], ex, ey, ez)


def _tables(weights):
    marg, cond = latlong.build_distribution(weights)
    return (wp.array(marg.astype(np.float32), dtype=float, device="cpu"),
            wp.array(cond.astype(np.float32).ravel(), dtype=float, device="cpu"), marg, cond)


def _frame_args(frame):
    return [wp.vec3(*map(float, frame[:, k])) for k in range(3)]


# ----------------------------------------------------------------------------- lat-long convention


def test_latlong_convention_matches_openexr_axes():
    """The OpenEXR/UsdLux axes: north pole (lat +π/2, v = 0) is +Y; (lat 0, lon 0) is +Z,
    the image centre (u, v) = (½, ½); (lat 0, lon +π/2) is +X at u = ¼; u = 0 is lon +π (−Z).
    Our texel-centre longitude π − 2π(i+½)/W agrees with OpenEXR's LatLongMap pixel formula
    π − 2π·i/(W−1) at the centre of the image (i = (W−1)/2 → lon 0). The two maps invert each other."""
    cases = {(0.5, 0.0): (0, 1, 0), (0.5, 0.5): (0, 0, 1), (0.25, 0.5): (1, 0, 0), (0.75, 0.5): (-1, 0, 0),
             (0.0, 0.5): (0, 0, -1), (0.5, 1.0): (0, -1, 0)}
    for uv, d in cases.items():
        np.testing.assert_allclose(latlong.latlong_uv_to_direction(uv), d, atol=1e-12)
    # lat 30°, lon 60° (u = (1 − lon/π)/2 = 1/3, v = (½ − lat/π) = 1/3)
    lat, lon = math.radians(30), math.radians(60)
    d = [math.cos(lat) * math.sin(lon), math.sin(lat), math.cos(lat) * math.cos(lon)]
    np.testing.assert_allclose(latlong.direction_to_latlong_uv(d), [1 / 3, 1 / 3], atol=1e-12)
    uv = np.random.default_rng(1).uniform(0.001, 0.999, size=(1000, 2))
    frame = rotation(2)
    np.testing.assert_allclose(latlong.direction_to_latlong_uv(latlong.latlong_uv_to_direction(uv, frame), frame),
                               uv, atol=1e-12)
    w = 64  # centre column i = 31.5 in OpenEXR's pixel formula: lon 0 in both conventions
    assert math.pi - 2 * math.pi * ((w - 1) / 2 + 0.5) / w == pytest.approx(0.0, abs=1e-15)
    # texel solid angles are exact: they tile the sphere
    assert latlong.texel_solid_angles(64, 32).sum() * 64 == pytest.approx(4 * math.pi, rel=1e-13)


def test_latlong_kernel_twins_match_numpy():
    """The @wp.func twins of direction_to_latlong_uv / latlong_uv_to_direction agree with the
    numpy convention to float32 precision in a rotated frame."""
    rng = np.random.default_rng(3)
    frame = rotation(4)
    d = rng.normal(size=(4096, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    uv = rng.uniform(0.0, 1.0, size=(4096, 2))
    marg, cond, _, _ = _tables(np.ones((4, 8)))
    out_pdf = wp.empty(len(d), dtype=float, device="cpu")
    out_uv = wp.empty(len(d), dtype=wp.vec2, device="cpu")
    out_dir = wp.empty(len(d), dtype=wp.vec3, device="cpu")
    wp.launch(_eval_latlong, dim=len(d), device="cpu",
              inputs=[marg, cond, 8, 4, *_frame_args(frame), wp.array(d.astype(np.float32), dtype=wp.vec3, device="cpu"),
                      wp.array(uv.astype(np.float32), dtype=wp.vec2, device="cpu"), out_pdf, out_uv, out_dir])
    got_uv = out_uv.numpy()
    ref_uv = latlong.direction_to_latlong_uv(d, frame)
    du = np.abs(got_uv[:, 0] - ref_uv[:, 0])
    du = np.minimum(du, 1 - du)  # u = 0 and u = 1 are the same meridian
    assert du.max() < 2e-6 and np.abs(got_uv[:, 1] - ref_uv[:, 1]).max() < 2e-6
    np.testing.assert_allclose(out_dir.numpy(), latlong.latlong_uv_to_direction(uv, frame), atol=2e-6)
    # uniform weights: the solid-angle pdf is 1/(4π) up to the row's sinθ vs its mean
    assert np.all(out_pdf.numpy() > 0)


# ----------------------------------------------------------------------------- the 2-D sampler


def test_piecewise_2d_sampler_chi_square():
    """Samples of sample_piecewise_2d follow the tabulated distribution: chi-square over
    texels split 2 × 2 (within a texel the density is uniform), expected counts
    N·P(texel)/4 with P(texel) = weight/Σweight; p > 1e-3. Zero-weight texels (and a
    zero row) get no samples; the returned pdf equals P(texel)·W·H and its twin
    pdf_piecewise_2d."""
    rng = np.random.default_rng(5)
    h, w = 6, 8
    weights = rng.uniform(0.2, 1.0, size=(h, w)) ** 3
    weights[2, :] = 0.0
    weights[4, [1, 5, 6]] = 0.0
    marg, cond, marg64, cond64 = _tables(weights)
    n = 400_000
    out = [wp.empty(n, dtype=t, device="cpu") for t in (wp.vec2, float, float, int)]
    wp.launch(_draw_piecewise_2d, dim=n, inputs=[marg, cond, w, h, 11, *out], device="cpu")
    uv, pdf, twin, texel = (o.numpy() for o in out)
    p_texel = weights / weights.sum()
    np.testing.assert_allclose(latlong.texel_probabilities(marg64, cond64), p_texel, rtol=1e-12)
    assert np.all((uv >= 0) & (uv < 1))
    row, col = latlong.uv_to_texel(uv, w, h)
    assert np.array_equal(row * w + col, texel)
    assert np.all(p_texel[row, col] > 0)
    np.testing.assert_allclose(pdf, p_texel[row, col] * w * h, rtol=2e-5)
    np.testing.assert_allclose(twin, pdf, rtol=1e-6)
    sub = np.floor(uv * [2 * w, 2 * h]).astype(int)  # 2 × 2 cells per texel
    counts = np.zeros((2 * h, 2 * w))
    np.add.at(counts, (sub[:, 1], sub[:, 0]), 1)
    expected = np.repeat(np.repeat(p_texel, 2, axis=0), 2, axis=1) / 4 * n
    keep = expected > 0
    assert counts[~keep].sum() == 0
    chi2 = stats.chisquare(counts[keep], expected[keep])
    assert chi2.pvalue > CHI2_P_MIN, chi2


def test_latlong_pdf_is_a_density_on_the_sphere():
    """pdf_latlong (per steradian) integrates to 1 over the sphere: ∫∫ pdf(ω) sinθ dθ dφ by the
    midpoint rule on 8 × 4 sub-cells per texel, directions built here from the OpenEXR formula
    in a rotated frame. Within a texel pdf·sinθ is constant (pdf = pdf_uv / (2π² sinθ)), so the
    rule is exact and only float32 rounding remains (< 1e-5). And sample_latlong's pdf equals
    pdf_latlong at the direction it drew (the twin MIS needs)."""
    rng = np.random.default_rng(6)
    h, w = 16, 32
    values = rng.uniform(0.0, 1.0, size=(h, w)) ** 4
    frame = rotation(7)
    marg, cond, _, _ = _tables(latlong.sampling_weights(values))
    kt, kp = 8, 4
    theta = np.pi * (np.arange(h * kt) + 0.5) / (h * kt)
    phi = np.pi - 2 * np.pi * (np.arange(w * kp) + 0.5) / (w * kp)  # longitudes
    tt, pp = np.meshgrid(theta, phi, indexing="ij")
    st = np.sin(tt)
    local = np.stack([st * np.sin(pp), np.cos(tt), st * np.cos(pp)], axis=-1).reshape(-1, 3)
    dirs = local @ frame.T
    m = len(dirs)
    out_pdf = wp.empty(m, dtype=float, device="cpu")
    wp.launch(_eval_latlong, dim=m, device="cpu",
              inputs=[marg, cond, w, h, *_frame_args(frame), wp.array(dirs.astype(np.float32), dtype=wp.vec3, device="cpu"),
                      wp.zeros(m, dtype=wp.vec2, device="cpu"), out_pdf, wp.empty(m, dtype=wp.vec2, device="cpu"),
                      wp.empty(m, dtype=wp.vec3, device="cpu")])
    total = float(np.sum(out_pdf.numpy().reshape(tt.shape) * st) * (np.pi / (h * kt)) * (2 * np.pi / (w * kp)))
    assert total == pytest.approx(1.0, abs=1e-5)
    n = 20_000
    outs = [wp.empty(n, dtype=t, device="cpu") for t in (wp.vec3, float, float)]
    wp.launch(_draw_latlong, dim=n, inputs=[marg, cond, w, h, *_frame_args(frame), 3, *outs], device="cpu")
    d, pdf, twin = (o.numpy() for o in outs)
    np.testing.assert_allclose(np.linalg.norm(d, axis=1), 1.0, atol=1e-5)
    ok = pdf > 0
    assert ok.mean() > 0.999
    np.testing.assert_allclose(twin[ok], pdf[ok], rtol=1e-3)


# ----------------------------------------------------------------------------- textured domes


@pytest.mark.parametrize("units", ["photometric", "radiometric"])
def test_constant_map_dome_reads_pi_L(tmp_path, units):
    """A constant map c under intensity I is a uniform sky of radiance L = c·I·2^exposure:
    with no geometry every receiver reads E = πL (dome_irradiance at tilt 0), whatever the
    dome's rotation. light and mis within 4 stderr; bsdf exactly (every escape reads L)."""
    write_map(tmp_path / "sky.exr", np.full((16, 32), 0.75))
    body = dome_body(intensity=2.0, extra='    float inputs:exposure = 1\n'
                     '    float3 xformOp:rotateXYZ = (30, 40, 50)\n    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]\n')
    scene = load_stage(write_stage(tmp_path, body), light_units=units)
    (light,) = scene.lights
    spectrum = "D65" if units == "photometric" else "E"
    np.testing.assert_allclose(light.emission, emission_pair(4.0, units, spectrum), rtol=1e-12)
    sensors = [irradiance("up", (0, 0, 0), (0, 0, 1)), irradiance("tilted", (1, 2, 3), (1, -2, 0.5))]
    engine = Engine(scene, sensors)
    for method in ("light", "mis", "bsdf"):
        res = engine.run(method, samples=1 << 15, seed=1)
        for i in range(len(sensors)):
            for ch in (0, 1):
                truth = cf.dome_irradiance(0.75 * light.emission[ch], 0.0)
                check(res, i, ch, truth, label=f"{method}/{sensors[i].name}")
                if method == "bsdf":
                    assert res.stderr[i, ch] == pytest.approx(0.0, abs=1e-6 * truth)


def _patch_scene(tmp_path, units="photometric"):
    h, w = 16, 32
    rows, cols = np.meshgrid(np.arange(3, 6), np.arange(10, 14), indexing="ij")
    values = np.zeros((h, w))
    values[rows, cols] = np.random.default_rng(8).uniform(0.5, 2.0, size=rows.shape)
    write_map(tmp_path / "sky.exr", values, rgb_scale=(1.0, 0.8, 0.6))
    body = dome_body(intensity=3.0, extra='    float3 xformOp:rotateXYZ = (90, 0, 30)\n'
                                          '    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]\n')
    scene = load_stage(write_stage(tmp_path, body), light_units=units)
    return scene, values, rows.ravel(), cols.ravel()


@pytest.mark.parametrize("method", ["light", "bsdf", "mis"])
def test_patch_map_matches_exact_texel_integration(tmp_path, method):
    """A map that is zero except a 3 × 4-texel patch of values v_ij: E = L·Σ v_ij·∫_texel n·ω dω,
    with the exact texel integral (texel_cos_integral) for receivers that see the whole patch
    above their horizon (checked on a 16 × 16 sub-grid of every texel). This is the
    sum over texels of L·cosθ·ΔΩ with cosθ integrated exactly over each texel instead of taken
    at its centre. A receiver facing away from every texel reads exactly 0. 4 stderr."""
    scene, values, rows, cols = _patch_scene(tmp_path)
    (light,) = scene.lights
    assert any("/Sky" in w_ for w_ in scene.warnings)  # the coloured map was reduced to grey
    h, w = values.shape
    frame = light.frame
    centre = latlong.latlong_uv_to_direction([(11.5 + 0.5) / w, (4 + 0.5) / h], frame)
    tilt_axis = np.cross(centre, [0.0, 0.0, 1.0])
    tilt_axis /= np.linalg.norm(tilt_axis)
    tilted = centre * math.cos(0.6) + np.cross(tilt_axis, centre) * math.sin(0.6)
    normals = {"facing": centre, "tilted": tilted, "pole": frame[:, 1] + 0.3 * centre}
    sub = (np.arange(16) + 0.5) / 16
    sensors, truths = [], []
    for name, n in normals.items():
        n = n / np.linalg.norm(n)
        uv = np.stack(np.meshgrid((cols[:, None] + sub) / w, (rows[:, None] + sub) / h), -1).reshape(-1, 2)
        assert (latlong.latlong_uv_to_direction(uv, frame) @ n).min() > 0.02, name  # patch above the horizon
        integral = texel_cos_integral(frame.T @ n, w, h, rows, cols)
        sensors.append(irradiance(name, (0, 0, 0), n))
        truths.append(float(np.sum(values[rows, cols] * integral)))
    sensors.append(irradiance("away", (0, 0, 0), -centre))
    truths.append(0.0)
    samples = {"light": 1 << 14, "bsdf": 1 << 17, "mis": 1 << 15}[method]
    res = Engine(scene, sensors).run(method, samples=samples, seed=2)
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            check(res, i, ch, light.emission[ch] * truths[i], label=f"{method}/{s.name}")
    assert res.mean[-1, 0] == 0.0 and res.mean[-1, 1] == 0.0
    assert res.stderr[0, 1] < 0.02 * res.mean[0, 1]


@pytest.mark.parametrize("typ, pole_axis, up, local_to_world", [
    ("DomeLight", None, "Z", np.eye(3)),  # the prim frame: pole +Y, lon 0 toward +Z
    ("DomeLight_1", "Z", "Z", np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]])),  # pole +Z, lon 0 toward −Y
    ("DomeLight", None, "Y", np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]])),  # Y-up stage: its +Y is world +Z
])
def test_map_orientation_pins_latlong_convention(tmp_path, typ, pole_axis, up, local_to_world):
    """One bright texel (36 × 18 map, row 4, column 5: centre at lat 45°, lon 125°, OpenEXR:
    d = (cos lat sin lon, sin lat, cos lat cos lon) in the dome frame) is seen where that
    formula says: a 1° radiance meter aimed at d reads its radiance exactly; meters aimed at
    its mirror images (lon → −lon, lat → −lat, lon → lon − 180°) read 0; an irradiance sensor
    facing d reads > 0 and one facing −d reads exactly 0 (light sampling)."""
    h, w = 18, 36
    values = np.zeros((h, w))
    values[4, 5] = 5.0
    write_map(tmp_path / "sky.exr", values)
    extra = f'    uniform token poleAxis = "{pole_axis}"\n' if pole_axis else ""
    scene = load_stage(write_stage(tmp_path, dome_body(typ=typ, intensity=2.0, extra=extra), up=up))
    (light,) = scene.lights

    def world(lat_deg, lon_deg):
        lat, lon = math.radians(lat_deg), math.radians(lon_deg)
        return local_to_world @ [math.cos(lat) * math.sin(lon), math.sin(lat), math.cos(lat) * math.cos(lon)]

    d = world(45, 125)
    sensors = [radiance("at", (0, 0, 0), d, 1.0), radiance("lon-", (0, 0, 0), world(45, -125), 1.0),
               radiance("lat-", (0, 0, 0), world(-45, 125), 1.0), radiance("lon180", (0, 0, 0), world(45, -55), 1.0),
               irradiance("facing", (0, 0, 0), d), irradiance("away", (0, 0, 0), -d)]
    res = Engine(scene, sensors).run("light", samples=1024, seed=1)
    np.testing.assert_allclose(res.mean[0], 5.0 * np.asarray(light.emission), rtol=1e-6)
    assert np.all(res.mean[1:4] == 0.0)
    assert np.all(res.mean[4] > 0.0) and np.all(res.mean[5] == 0.0)


def test_several_textured_domes_add(tmp_path):
    """Two textured domes and an untextured one are three skies: E = π(L1 + L2 + L3) with
    L_k = c_k·I_k (constant maps), for light and mis within 4 stderr."""
    write_map(tmp_path / "a.exr", np.full((8, 16), 0.5))
    write_map(tmp_path / "b.exr", np.full((4, 8), 2.0))
    body = (dome_body("a.exr", 1.0, name="A") + dome_body("b.exr", 3.0, name="B", fmt="automatic")
            + 'def DomeLight "C"\n{\n    float inputs:intensity = 0.25\n}\n')
    scene = load_stage(write_stage(tmp_path, body))
    assert [l.texture_map is not None for l in scene.lights] == [True, True, False]
    sensors = [irradiance("up", (0, 0, 0), (0, 0, 1)), irradiance("side", (0, 0, 0), (0, 1, 0))]
    for method in ("light", "mis"):
        res = Engine(scene, sensors).run(method, samples=1 << 14, seed=4)
        for i in range(2):
            check(res, i, 1, math.pi * (0.5 + 6.0 + 0.25), label=method)


def test_dome_texture_errors(tmp_path):
    """A missing texture, an unsupported texture:format, a file that is not an EXR, a
    Radiance .hdr with no pixels, and negative texels are UserErrors naming the stage, the
    prim and the file."""
    stage = write_stage(tmp_path, dome_body("missing.exr"))
    with pytest.raises(UserError, match=r"s\.usda: /Sky: texture:file .*missing\.exr"):
        load_stage(stage)
    write_map(tmp_path / "sky.exr", np.ones((4, 8)))
    stage = write_stage(tmp_path, dome_body("sky.exr", fmt="mirroredBall"))
    with pytest.raises(UserError, match=r"s\.usda: /Sky: texture:format 'mirroredBall' of texture:file .*sky\.exr"):
        load_stage(stage)
    (tmp_path / "junk.exr").write_text("not an image")
    with pytest.raises(UserError, match=r"s\.usda: /Sky: texture:file .*junk\.exr: not an OpenEXR file"):
        load_stage(write_stage(tmp_path, dome_body("junk.exr")))
    (tmp_path / "sky.hdr").write_text("#?RADIANCE\n")
    with pytest.raises(UserError, match=r"s\.usda: /Sky: texture:file .*sky\.hdr: not a readable Radiance picture"):
        load_stage(write_stage(tmp_path, dome_body("sky.hdr", fmt="automatic")))
    exr.write_channels(tmp_path / "neg.exr", {"Y": -np.ones((4, 8))})
    with pytest.raises(UserError, match=r"/Sky: texture:file .*neg\.exr: 32 texel\(s\) are negative"):
        load_stage(write_stage(tmp_path, dome_body("neg.exr")))


# ----------------------------------------------------------------------------- EXR module


def test_exr_roundtrip_grey_and_errors(tmp_path):
    """write_channels stores float32 channels, string metadata and the envmap attribute
    atomically (no temp file left); read_rgb returns (H, W, 3) float32 and replicates a grey
    Y channel; read_channels returns every channel by name; a file without R, G, B or Y is a
    UserError naming it."""
    a = np.random.default_rng(9).uniform(0, 10, size=(5, 7))
    exr.write_channels(tmp_path / "m.exr", {"R": a, "G": 2 * a, "B": 3 * a}, {"probesim:units": "W/m2"})
    rgb = exr.read_rgb(tmp_path / "m.exr")
    assert rgb.dtype == np.float32 and rgb.shape == (5, 7, 3)
    np.testing.assert_array_equal(rgb, np.stack([a, 2 * a, 3 * a], -1).astype(np.float32))
    assert exr.read_header(tmp_path / "m.exr")["probesim:units"] == "W/m2"
    exr.write_channels(tmp_path / "m.exr", {"Y": a})  # replaces the file
    np.testing.assert_array_equal(exr.read_rgb(tmp_path / "m.exr"), np.repeat(a[..., None], 3, -1).astype(np.float32))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.exr"]
    exr.write_channels(tmp_path / "m.exr", {"R": a, "R.stderr": a / 10}, envmap="latlong")
    assert "LATLONG" in str(exr.read_header(tmp_path / "m.exr")["envmap"]).upper()
    assert sorted(exr.read_channels(tmp_path / "m.exr")) == ["R", "R.stderr"]
    exr.write_channels(tmp_path / "z.exr", {"Z": a})
    with pytest.raises(UserError, match=r"z\.exr: needs channels R, G, B \(or Y\), found Z"):
        exr.read_rgb(tmp_path / "z.exr")
    with pytest.raises(ValueError, match="reserved"):
        exr.write_channels(tmp_path / "x.exr", {"Y": a}, {"channels": "x"})
    assert not (tmp_path / "x.exr").exists()


# ----------------------------------------------------------------------------- cylinder lights


def cylinder_quadrature(L, centre, axis, e2, e3, radius, length, p, n, nx, nphi):
    """∫_side L·max(0, cosθr)·max(0, cosθl)/d² dA by the midpoint rule on an nx × nphi grid."""
    x = (np.arange(nx) + 0.5) / nx * length - length / 2
    phi = (np.arange(nphi) + 0.5) / nphi * 2 * np.pi
    normal = np.cos(phi)[:, None] * e2 + np.sin(phi)[:, None] * e3  # (nphi, 3)
    total = 0.0
    for xs in np.array_split(x, max(1, nx // 128)):
        q = centre + xs[:, None, None] * axis + radius * normal[None]  # (k, nphi, 3)
        d = q - p
        d2 = np.einsum("...i,...i", d, d)
        cos_r = np.einsum("...i,i", d, n) / np.sqrt(d2)
        cos_l = -np.einsum("...i,...i", d, normal[None]) / np.sqrt(d2)
        total += np.sum(np.maximum(cos_r, 0) * np.maximum(cos_l, 0) / d2)
    return L * total * (length / nx) * (radius * 2 * np.pi / nphi)


CYLINDER_BODY = """def CylinderLight "Tube"
{
    float inputs:intensity = 4
    float inputs:radius = 0.15
    float inputs:length = 1.2
    double3 xformOp:translate = (0.1, -0.2, 1.0)
    float3 xformOp:rotateXYZ = (0, 20, 35)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
}
"""


@pytest.fixture(scope="module")
def cylinder_case(tmp_path_factory):
    """The tube stage, its receivers, and quadrature references (computed once)."""
    scene = load_stage(write_stage(tmp_path_factory.mktemp("cyl"), CYLINDER_BODY))
    (light,) = scene.lights
    axis, e2, e3 = light.frame[:, 0], light.frame[:, 1], light.frame[:, 2]
    c = light.position
    sensors = [irradiance("broadside", c - 0.8 * e3, e3), irradiance("tilted", c - 0.5 * e2 + 0.2 * axis, e2 + 1.2 * axis),
               irradiance("beyond_end", c + 1.0 * axis + 0.3 * e2, -axis - 0.2 * e2),
               irradiance("inside", c + 0.05 * e2, e2)]
    truths, bounds = [], []
    for s in sensors:
        args = (1.0, c, axis, e2, e3, light.radius, light.length, s.position, s.normal)
        fine = cylinder_quadrature(*args, 1200, 2400)
        coarse = cylinder_quadrature(*args, 600, 1200)
        truths.append(fine)
        bounds.append(abs(fine - coarse))
    return scene, sensors, truths, bounds


@pytest.mark.parametrize("method", ["light", "bsdf", "mis"])
def test_cylinder_light_matches_surface_integration(cylinder_case, method):
    """CylinderLight (UsdLux: side emits outward, no caps, axis = local X) against a midpoint
    quadrature of L·cosθr·cosθl/d² over its side (1200 × 2400 points). Quadrature error bound:
    the midpoint rule is O(h²), so the error of the fine sum is about |fine − coarse| / 3
    (coarse: half the points per axis); the bound adds |fine − coarse|, under 1e-3 of the
    value. Receivers: broadside, tilted so the horizon cuts the tube, beyond one end (sees
    the side obliquely), and inside the tube (sees only the back of the side: 0).
    4 stderr + the bound."""
    scene, sensors, truths, bounds = cylinder_case
    (light,) = scene.lights
    assert light.kind == LightKind.CYLINDER
    assert truths[3] == 0.0 and min(truths[:3]) > 0.01
    assert max(b / t for b, t in zip(bounds[:3], truths[:3])) < 1e-3
    samples = {"light": 1 << 15, "bsdf": 1 << 16, "mis": 1 << 15}[method]
    res = Engine(scene, sensors).run(method, samples=samples, seed=5)
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            check(res, i, ch, light.emission[ch] * truths[i], extra=light.emission[ch] * bounds[i],
                  label=f"{method}/{s.name}")
    assert res.stderr[0, 1] < 0.02 * res.mean[0, 1]


def test_cylinder_light_radiance_side_not_caps(tmp_path):
    """A radiance meter aimed at the side reads the cylinder's radiance L; one looking in along
    the axis through a cap reads 0 (caps do not emit, and through them only the back of the
    side is seen)."""
    scene = load_stage(write_stage(tmp_path, CYLINDER_BODY))
    (light,) = scene.lights
    axis, e3, c = light.frame[:, 0], light.frame[:, 2], light.position
    sensors = [radiance("side", c - 0.8 * e3, e3, 2.0), radiance("cap", c + 2.0 * axis, -axis, 2.0)]
    res = Engine(scene, sensors).run("mis", samples=256, seed=1)
    np.testing.assert_allclose(res.mean[0], light.emission, rtol=1e-6)
    assert np.all(res.mean[1] == 0.0)


# ----------------------------------------------------------------------------- MeshLightAPI


def mesh_light_body(normalize: bool, double_sided: bool = False, material: str = "") -> str:
    # wound clockwise seen from above: the front face (cross(p1 − p0, p2 − p0)) points down, −Z
    return f"""def Mesh "Panel" (
    prepend apiSchemas = ["MeshLightAPI"{', "MaterialBindingAPI"' if material else ""}]
)
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 3, 2, 1]
    point3f[] points = [(-0.25, -0.2, 1), (0.25, -0.2, 1), (0.25, 0.2, 1), (-0.25, 0.2, 1)]
    uniform bool doubleSided = {int(double_sided)}
    float inputs:intensity = 3
    float inputs:exposure = 1
    color3f inputs:color = (1, 0.5, 0.25)
    bool inputs:normalize = {int(normalize)}
    {f"rel material:binding = <{material}>" if material else ""}
}}
"""


@pytest.mark.parametrize("units", ["photometric", "radiometric"])
@pytest.mark.parametrize("normalize", [False, True])
def test_mesh_light_quad_matches_polygon_irradiance(tmp_path, units, normalize):
    """A 0.5 × 0.4 m MeshLightAPI quad at z = 1, front face down, emits
    L = 3·2¹·grey(1, 0.5, 0.25) (÷ 0.2 m² with normalize) from its front face, with the
    spectrum of other lights (D65 photometric; E radiometric: twin L·K(E)). Receivers below
    read Lambert's polygon formula; one above (behind the front face) reads 0. 4 stderr."""
    scene = load_stage(write_stage(tmp_path, mesh_light_body(normalize)), light_units=units)
    assert not scene.lights and scene.geometry.n_triangles == 2
    value = 3.0 * 2.0 * luminance_grey((1, 0.5, 0.25)) / (0.2 if normalize else 1.0)
    k = luminous_efficacy("D65" if units == "photometric" else "E")
    pair = (value / k, value) if units == "photometric" else (value, value * k)
    np.testing.assert_allclose(scene.geometry.emission, [pair, pair], rtol=1e-6)  # area from point3f (float32) points
    assert np.all(scene.geometry.albedo == 0.0)  # no material bound: no reflection
    verts = np.array([(-0.25, -0.2, 1), (0.25, -0.2, 1), (0.25, 0.2, 1), (-0.25, 0.2, 1)], float)
    sensors = [irradiance("below", (0, 0, 0), (0, 0, 1)), irradiance("offset", (0.4, 0.3, 0.3), (-0.3, -0.2, 1)),
               irradiance("above", (0, 0, 1.5), (0, 0, -1))]
    res = Engine(scene, sensors).run("light", samples=1 << 14, seed=6)
    for i, s in enumerate(sensors):
        for ch in (0, 1):
            truth = cf.polygon_irradiance(pair[ch], verts, s.position, s.normal, one_sided_normal=(0, 0, -1))
            check(res, i, ch, float(truth), label=f"{s.name}")
    assert res.mean[2, 0] == 0.0


def test_mesh_light_is_geometry(tmp_path):
    """A MeshLightAPI prim is geometry: a panel (intensity 0 here) between an angle-0 sun of
    1000 lx straight above and a receiver leaves the receiver in shadow (exactly 0), while a
    receiver in the open reads 1000 lx exactly. Its albedo is the bound UsdPreviewSurface's
    diffuseColor (0.5), and 0 with light:materialSyncMode noMaterialResponse."""
    looks = """def Material "Grey"
{
    token outputs:surface.connect = </Grey/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0.5, 0.5, 0.5)
        token outputs:surface
    }
}
"""
    sun = 'def DistantLight "Sun"\n{\n    float inputs:intensity = 1000\n    float inputs:angle = 0\n}\n'  # shines down −Z
    body = mesh_light_body(False, material="/Grey").replace("float inputs:intensity = 3", "float inputs:intensity = 0")
    scene = load_stage(write_stage(tmp_path, body + looks + sun))
    assert np.all(scene.geometry.albedo == 0.5)
    res = Engine(scene, [irradiance("under", (0, 0, 0), (0, 0, 1)), irradiance("open", (2, 0, 0), (0, 0, 1))]).run(
        "light", samples=64, seed=1)
    assert np.all(res.mean[0] == 0.0)  # shadowed by the panel, which itself emits 0 here
    np.testing.assert_allclose(res.mean[1, 1], 1000.0, rtol=1e-6)
    silent = body.replace("bool inputs:normalize = 0", 'bool inputs:normalize = 0\n    token light:materialSyncMode = "noMaterialResponse"')
    assert np.all(load_stage(write_stage(tmp_path, silent + looks)).geometry.albedo == 0.0)
