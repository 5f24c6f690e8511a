"""The surface guide of guided paths: the patch sampler and its pdf, and
``guided`` readings against closed forms and against ``path``.

Sampler tests (simulator/scene/patches.py, the kernels' ``patch_index`` /
``patch_point`` / ``sample_guide`` / ``pdf_guide``):

- the sub-triangle index of a point drawn on sub-triangle k is k (round
  trip), on the device and in the numpy twin;
- ``sample_guide`` draws patch j with probability P_j and points uniform on
  it: chi-square over the 4m × 4m grid (each patch of the m × m grid holds 16
  congruent cells of the finer grid, so each cell expects N·P_j/16);
- ``pdf_guide`` at a drawn point is the density the sampler reports, P_j/A_j.

Estimator tests: a guided reading is unbiased, so it must equal the closed
form within 4 standard errors (+ 2e-6 relative for float32), as ``path``
does (tests/test_enclosures.py states the closed forms and their sources).
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
import warp as wp
from scipy import stats

from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.kernels.guide import SceneRec, patch_index, patch_point, pdf_guide, sample_guide
from simulator.pipeline import collect_sensors, load_scene
from simulator.reference import closed_forms as cf
from simulator.scene.model import Geometry, Scene, Sensor, SensorKind
from simulator.scene.patches import patch_distribution_rows, patch_index_np, patch_layout

wp.set_module_options({"enable_backward": False})

CONFIGS = Path(__file__).resolve().parents[1] / "configs"
FLOAT32_SLACK = 2e-6
ALPHA = 1e-3


@wp.kernel
def _roundtrip_kernel(m: wp.array(dtype=wp.int32), k: wp.array(dtype=wp.int32), u: wp.array(dtype=wp.vec2),
                      st: wp.array(dtype=wp.vec2), back: wp.array(dtype=wp.int32)):  # fmt: skip
    i = wp.tid()
    p = patch_point(k[i], m[i], u[i])
    st[i] = p
    back[i] = patch_index(p[0], p[1], m[i])


@wp.kernel
def _sample_guide_kernel(scene: SceneRec, row: int, seed: int, y: wp.array(dtype=wp.vec3), face: wp.array(dtype=wp.int32),
                         density: wp.array(dtype=float), pdf: wp.array(dtype=float)):  # fmt: skip
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    g = sample_guide(scene, row, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))
    y[i] = g.y
    face[i] = g.face
    density[i] = g.density
    pdf[i] = pdf_guide(scene, row, g.face, g.y)


def _st(points: np.ndarray, tri: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(s, t) of points q on triangles (a, b, c): q = a + s(b − a) + t(c − a)."""
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    e1, e2, d = b - a, c - a, points - a
    d00, d01, d11 = (e1 * e1).sum(1), (e1 * e2).sum(1), (e2 * e2).sum(1)
    d20, d21 = (d * e1).sum(1), (d * e2).sum(1)
    den = d00 * d11 - d01 * d01
    return (d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den


def test_patch_index_and_point_round_trip():
    """patch_point(k, m, u) lies in sub-triangle k: patch_index gives k back,
    for every k of m = 1, 2, 3, 7, 64 and u away from the cell's edges
    (u ∈ [0.01, 0.99]², so float32 rounding cannot move the point across
    one). The numpy twin patch_index_np agrees, and every (s, t) lies on the
    triangle (s, t ≥ 0, s + t ≤ 1)."""
    rng = np.random.default_rng(3)
    ms, ks = [], []
    for m in (1, 2, 3, 7, 64):
        ms.append(np.full(m * m, m))
        ks.append(np.arange(m * m))
    m = np.concatenate(ms).astype(np.int32)
    k = np.concatenate(ks).astype(np.int32)
    u = rng.uniform(0.01, 0.99, (len(k), 2)).astype(np.float32)
    st = wp.empty(len(k), dtype=wp.vec2, device="cpu")
    back = wp.empty(len(k), dtype=wp.int32, device="cpu")
    wp.launch(_roundtrip_kernel, dim=len(k), inputs=[wp.array(m, dtype=wp.int32, device="cpu"), wp.array(k, dtype=wp.int32, device="cpu"),
              wp.array(u, dtype=wp.vec2, device="cpu"), st, back], device="cpu")  # fmt: skip
    st, back = st.numpy().astype(np.float64), back.numpy()
    np.testing.assert_array_equal(back, k)
    np.testing.assert_array_equal(patch_index_np(st[:, 0], st[:, 1], m), k)
    assert np.all(st >= 0) and np.all(st.sum(1) <= 1 + 1e-6)


def test_layout_counts_and_areas():
    """Each triangle of longest edge L gets m = ⌈L/h⌉ (h = 0.25 m), m²
    patches of area A/m² each, so a triangle's patch areas sum to its area;
    past the cap the patch size grows until the total fits; more triangles
    than the cap: no guide."""
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [10, 0, 0], [10, 3, 0], [13, 0, 0]], float)
    tris = np.array([[0, 1, 2], [3, 4, 5]])
    lay = patch_layout(pts, tris, target_m=0.25, cap=100000)
    assert list(lay.m) == [math.ceil(math.sqrt(2) / 0.25), math.ceil(3 * math.sqrt(2) / 0.25)]
    assert lay.n_patches == int(np.sum(lay.m.astype(int) ** 2))
    for t, area in enumerate((0.5, 4.5)):
        assert lay.patch_area_m2[lay.patch_tri == t].sum() == pytest.approx(area, rel=1e-12)
    small = patch_layout(pts, tris, target_m=0.25, cap=100)
    assert small.n_patches <= 100 and small.patch_size_m > 0.25 and "cap" in small.reason
    none = patch_layout(pts, tris, cap=1)
    assert not none.usable and "no guide" in none.reason


def _guide_engine(tally_fn):
    """An engine on three triangles (one tilted, one far and large) with the
    guide set from per-patch tallies ``tally_fn(layout) -> (rows, N)``."""
    pts = np.array([
        [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.6, 0.0],
        [2.0, 0.0, 0.0], [2.0, 1.0, 0.5], [2.5, 0.2, 1.0],
        [-5.0, -5.0, 3.0], [5.0, -5.0, 3.0], [0.0, 5.0, 3.0],
    ])  # fmt: skip
    tris = np.array([[0, 1, 2], [3, 4, 5], [6, 7, 8]], np.int32)
    geo = Geometry(points=pts, triangles=tris, albedo=np.full(3, 0.5), emission=np.zeros((3, 2)),
                   two_sided=np.zeros(3, bool), prim=np.array([0, 1, 2], np.int32), prim_names=["/A", "/B", "/C"])  # fmt: skip
    scene = Scene(geometry=geo, lights=[], sensors=[], path="<test>")
    sensor = Sensor(name="s", kind=SensorKind.IRRADIANCE, position=np.array([0.2, 0.2, 1.0]), normal=np.array([0.0, 0.0, -1.0]))
    eng = Engine(scene, [sensor], device="cpu", threads=1)
    dev = eng._dev
    lay = dev.layout
    tally = tally_fn(lay, dev.guide_rows)
    ids, cdf, row_start, density = patch_distribution_rows(tally, lay)
    dev.set_guide(ids, cdf, row_start, density)
    return eng, dev, pts[tris], tally


def test_guide_sampler_draws_patches_with_their_probability_and_points_uniformly():
    """The surfaces' table of the guide draws patch j with P_j = tally_j/Σ tally (here
    random tallies, a fifth of the patches 0, on three triangles of
    different size and tilt) and a point uniform on it. Binned on the grid
    of 4m per edge, whose cells are congruent and nest 16 to a patch, each
    cell expects N·P_j/16 (cells of zero-tally patches get at most 1e-5·N
    samples: float32 points rounded onto a shared edge); chi-square
    p > 1e-3. The density the sampler reports, and pdf_guide at
    the drawn point, are P_j/A_j (P_j within float32 rounding, 2.5e-7)."""
    rng = np.random.default_rng(11)

    def tally_fn(lay, rows):
        t = np.zeros((rows, lay.n_patches))
        t[rows - 1] = rng.gamma(0.7, 1.0, lay.n_patches) * (rng.uniform(size=lay.n_patches) > 0.2)
        return t

    eng, dev, tri_pts, tally = _guide_engine(tally_fn)
    lay = dev.layout
    n = 1 << 19
    y = wp.empty(n, dtype=wp.vec3, device="cpu")
    face = wp.empty(n, dtype=wp.int32, device="cpu")
    dens = wp.empty(n, dtype=float, device="cpu")
    pdf = wp.empty(n, dtype=float, device="cpu")
    row = dev.guide_rows - 1  # the surfaces' table
    wp.launch(_sample_guide_kernel, dim=n, inputs=[dev.rec, row, 1234, y, face, dens, pdf], device="cpu")
    y, face, dens, pdf = y.numpy().astype(np.float64), face.numpy(), dens.numpy(), pdf.numpy()
    p_j = tally[row] / tally[row].sum()
    s, t = _st(y, tri_pts[face])
    m = lay.m[face].astype(np.int64)
    patch = lay.offset[face] + patch_index_np(s, t, m)
    fine = patch_index_np(s, t, 4 * m)  # the 4m grid's cell within the triangle
    # global fine-cell index and its expected count
    fine_off = np.cumsum(16 * lay.m.astype(np.int64) ** 2) - 16 * lay.m.astype(np.int64) ** 2
    observed = np.bincount(fine_off[face] + fine, minlength=int(16 * np.sum(lay.m.astype(np.int64) ** 2)))
    expected = np.zeros_like(observed, dtype=float)
    for tri in range(3):
        mm = int(lay.m[tri])
        # the coarse patch of each fine cell: its centroid's coarse index
        k = np.arange(16 * mm * mm)
        sc, tc = _cell_centroids(k, 4 * mm)
        coarse = lay.offset[tri] + patch_index_np(sc, tc, np.full(len(k), mm))
        expected[fine_off[tri] + k] = n * p_j[coarse] / 16.0
    assert observed[expected == 0].sum() <= 1e-5 * n  # float32 rounding onto a shared edge, no more
    live = expected > 0
    stat = float(np.sum((observed[live] - expected[live]) ** 2 / expected[live]))
    dof = int(live.sum()) - 1
    assert stats.chi2.sf(stat, dof) > ALPHA, (stat, dof)
    # the twins agree at the drawn points, but for points that float32
    # rounding put on an edge shared with another patch: at most 1e-5·N
    assert np.sum(np.abs(pdf - dens) > 1e-6 * dens) <= 1e-5 * n
    # P_j as the float32 CDF holds it is within 2·2⁻²⁴ of the exact share
    # (the density is formed from it); re-binned edge points aside
    off = np.abs(dens * lay.patch_area_m2[patch] - p_j[patch]) > 2.5e-7 + 1e-6 * p_j[patch]
    assert off.sum() <= 1e-5 * n, off.sum()


def _cell_centroids(k: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray]:
    """(s, t) of the centroid of sub-triangle k on a triangle cut m × m."""
    j = np.floor(m - np.sqrt(np.maximum(m * m - k, 0))).astype(np.int64)
    j = np.where(j * (2 * m - j) > k, j - 1, j)
    j = np.where((j + 1) * (2 * m - j - 1) <= k, j + 1, j)
    r = k - j * (2 * m - j)
    i, upper = r // 2, r % 2
    s = np.where(upper == 1, i + 2.0 / 3.0, i + 1.0 / 3.0)
    t = np.where(upper == 1, j + 2.0 / 3.0, j + 1.0 / 3.0)
    return s / m, t / m


# --------------------------------------------------------------------------- guided readings


def _setup(config: str, variant: str | None = None, sensors: list[str] | None = None):
    cfg = load_config(CONFIGS / config)
    if variant is not None:
        cfg = dataclasses.replace(cfg, variants={"reflectance": variant})
    scene = load_scene(cfg)
    found = [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE]
    if sensors is not None:
        found = [s for s in found if s.name in sensors]
    return cfg, scene, found, Engine(scene, found)


def _check(name: str, est: float, se: float, truth: float, extra: float = 0.0, max_rel_se: float = 0.005):
    """|est − truth| ≤ 4·se + float32 slack (+ a stated model bound); se < max_rel_se·truth."""
    bound = 4.0 * se + FLOAT32_SLACK * abs(truth) + extra
    assert abs(est - truth) <= bound, f"{name}: {est:.6g} vs {truth:.6g} (± {se:.3g}, bound {bound:.3g})"
    assert se < max_rel_se * abs(truth), f"{name}: stderr {se / truth:.3%} ≥ {max_rel_se:.2%}"


@pytest.fixture
def forced_guide(monkeypatch):
    """The guide used whatever its concentration (the enclosures' light is
    spread evenly, so a run would otherwise leave it out)."""
    from simulator.engine import guide as G

    monkeypatch.setattr(G, "MIN_CONCENTRATION", 0.0)
    return G


def test_guided_furnace_with_the_guide_on(forced_guide):
    """Furnace at ρ = 0.5 (configs/furnace.toml, variant rho_0_5): every wall
    emits L_e = 1 W m⁻² sr⁻¹, so every irradiance sensor reads π·L_e/(1 − ρ)
    = 2π W/m² and the radiance meter L_e/(1 − ρ) = 2 (cf.furnace_irradiance /
    furnace_radiance; docs/REFERENCES.md §Furnace), both channels. The guide
    is forced on (it would be dropped: concentration ≈ 1.5 < 4), so guided
    steps, their mixture weights and the (1 − c) share of the cosine
    strategy in the MIS weights are all exercised. Measured relative variance
    per sample 0.02–0.13 → 8192 samples give a stderr ≤ 0.4%."""
    cfg, scene, sensors, engine = _setup("furnace.toml", "rho_0_5")
    rho = float(scene.geometry.albedo[0])
    res = engine.run("guided", samples=8192, seed=21)
    assert engine.guide.sampled > 0 and "used" in engine.guide.reason
    for ch in (0, 1):
        le = float(scene.geometry.emission[0, ch])
        for i, s in enumerate(sensors):
            truth = cf.furnace_radiance(le, rho) if s.kind == SensorKind.RADIANCE else cf.furnace_irradiance(le, rho)
            _check(f"{s.name}[{ch}]", res.mean[i, ch], res.stderr[i, ch], truth)


def test_guided_bounce_cap_truncates(forced_guide):
    """Furnace ρ = 0.5, one upward sensor, at most k = 2 bounces: the path
    sums the Neumann series to order 2, E_2 = π·L_e·(1 − ρ³)/(1 − ρ) =
    5.498 W/m² (docs/REFERENCES.md §Truncated paths); a guided step counts
    as a bounce like a cosine one, and the guide is not drawn at the last
    vertex (the next would add nothing). 16384 samples."""
    _, scene, sensors, engine = _setup("furnace.toml", "rho_0_5", sensors=["centre_up"])
    rho, le = float(scene.geometry.albedo[0]), float(scene.geometry.emission[0, 0])
    truth = cf.furnace_irradiance(le, rho) * (1.0 - rho**3)
    res = engine.run("guided", samples=16384, seed=5, max_depth=2)
    _check("max_depth 2", res.mean[0, 0], res.stderr[0, 0], truth)


def test_guided_furnace_drops_an_even_guide():
    """Furnace at ρ = 0.9 (the config's variant): the pilot's light is spread
    evenly over the walls (concentration < MIN_CONCENTRATION), so the guide
    is left out and the reading is a plain path's, 10π W/m² (closed form as
    above): a stage with no bright patch is still read right. 8192 samples,
    relative variance per sample ≤ 0.05 → stderr ≤ 0.25%."""
    cfg, scene, sensors, engine = _setup("furnace.toml", "rho_0_9")
    res = engine.run("guided", samples=8192, seed=3)
    assert engine.guide.sampled == 0 and "not used" in engine.guide.reason
    rho, le = float(scene.geometry.albedo[0]), float(scene.geometry.emission[0, 0])
    for i, s in enumerate(sensors):
        truth = cf.furnace_radiance(le, rho) if s.kind == SensorKind.RADIANCE else cf.furnace_irradiance(le, rho)
        _check(s.name, res.mean[i, 0], res.stderr[i, 0], truth)


def test_guided_cie171_5_8_indirect_component(forced_guide):
    """CIE 171:2006 case 5.8 at ρ = 0.5 (configs/cie171_5_8.toml, component
    indirect): a 4 m cube, a 10,000 lm isotropic point source at its centre;
    mean indirect illuminance over the surfaces ρΦ/((1 − ρ)·S_T) = 104.17 lx
    (cf.cie171_indirect_illuminance;
    docs/REFERENCES.md §CIE 171:2006 case 5.8), read by six patches on the six faces (their mean is the surface
    mean, its stderr √Σse²/6). The indirect component leaves out the light
    reaching a patch straight from the source but follows the paths from
    it; here with the guide forced on. Measured relative variance per sample
    ≈ 0.1 → 8192 samples: stderr ≈ 0.35% per patch, 0.14% for the mean."""
    cfg, scene, sensors, engine = _setup("cie171_5_8.toml", "rho_0_5")
    assert cfg.simulation.component == "indirect"
    g = scene.geometry
    p = g.points[g.triangles]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum()
    (light,) = scene.lights
    res = engine.run("guided", samples=8192, seed=9, component="indirect")
    assert engine.guide.sampled > 0
    for ch in (0, 1):
        flux = 4.0 * math.pi * light.emission[ch]
        truth = cf.cie171_indirect_illuminance(flux, 0.5, area)
        mean = float(res.mean[:, ch].mean())
        se = float(np.sqrt(np.sum(res.stderr[:, ch] ** 2)) / len(sensors))
        _check(f"mean[{ch}]", mean, se, truth, max_rel_se=0.0025)


def test_guided_integrating_sphere_without_a_layout():
    """Integrating sphere (configs/integrating_sphere.toml): its 512 × 256 UV
    wall has more triangles than the patch cap, so there is no guide and a
    guided path is a plain one (with the weight window applied after each
    vertex's next-event estimate). A sensor facing away from the centre
    reads only reflected light, E_r = Φ/(4πR²)·ρ/(1 − ρ) = 400 lx at ρ = 0.8,
    I = 100 cd (cf.integrating_sphere_reflected; docs/REFERENCES.md
    §Integrating sphere), here at the centre facing +z; the tessellation's
    bound 2.1e-4 (see tests/test_enclosures.py) is added. 4096 samples,
    relative variance per sample ≈ 0.01 → stderr ≈ 0.16%."""
    cfg, scene, _, _ = _setup("integrating_sphere.toml")
    sensor = Sensor(name="away", kind=SensorKind.IRRADIANCE, position=np.array([0.0, 0.0, 0.3]), normal=np.array([0.0, 0.0, 1.0]))
    engine = Engine(scene, [sensor])
    (light,) = scene.lights
    res = engine.run("guided", samples=4096, seed=13, component="indirect")
    # no layout (and a run of 4,096 samples, under the guide's pilot, builds no guide either)
    assert not engine._dev.layout.usable and engine.guide is None
    for ch in (0, 1):
        flux = 4.0 * math.pi * light.emission[ch]
        truth = cf.integrating_sphere_reflected(flux, 1.0, 0.8)
        _check(f"away[{ch}]", res.mean[0, ch], res.stderr[0, ch], truth, extra=2.1e-4 * truth)


def test_guided_office_covers_the_reference(office_guided):
    """The office (configs/office_bench.toml, the auto plan's light mask):
    guided readings of all 1,464 sensors, 512 samples each, fixed seed,
    against the stored reference (configs/references/office_bench.csv,
    pooled path runs, 0.64% RMS stderr). Both are unbiased and independent,
    so z = (x − r)/√(se_x² + se_r²) should lie within ±1.96 for 95% of the
    sensors: binomial spread √(0.95·0.05/1464) = 0.57%, so 4σ gives
    [92.7%, 97.3%]; the guide's mixture weights put heavier tails on a
    reading's samples than on path's, which show as coverage under 95% at
    small budgets (measured 93.6% at 256 samples for path, 94.4% for guided;
    this test's seed gives 94.1% at 512), and the band's lower end is not
    widened for them. The guide must be used here
    (concentration ≫ 4), and the mean reading within 1% of the reference's.
    The run is tests/conftest.py's ``office_guided``, which tests/test_split.py
    and tests/test_patch_pick.py check too."""
    run = office_guided
    r, sr = run.reference_lx, run.reference_stderr_lx
    res = run.result
    assert run.guide_sampled > 0 and run.guide_concentration > 4
    z = (res.mean[:, 1] - r) / np.sqrt(res.stderr[:, 1] ** 2 + sr**2)
    cover = float(np.mean(np.abs(z) < 1.96))
    assert 0.927 <= cover <= 0.973, cover
    assert abs(res.mean[:, 1].sum() / r.sum() - 1.0) < 0.01


def test_a_run_too_small_for_the_guides_pilot_reads_plain_paths():
    """One desk sensor of the office at 256 samples: the guide's pilot alone would draw
    guide.PILOT_MIN_TOTAL = 16,384 samples, 64 times the run, so the guided run builds no guide and
    says why (``Engine.guide_skipped``); a guided trace without a guide is a plain path trace, so its
    reading is ``path``'s, bit for bit (same seed). 64 such sensors (16,384 samples) build it."""
    from simulator.engine import guide as G
    from simulator.scene.usd import load_stage

    scene = load_stage(CONFIGS.parent / "stages" / "office.usda", light_units="photometric")
    desk = Sensor("desk", SensorKind.IRRADIANCE, np.array([2.0, 2.0, 0.8]), np.array([0.0, 0.0, 1.0]))
    eng = Engine(scene, [desk])
    guided = eng.run("guided", samples=256, seed=3)
    assert eng.guide is None and eng.guide_skipped and f"{G.PILOT_MIN_TOTAL:,}" in eng.guide_skipped
    plain = Engine(scene, [desk]).run("path", samples=256, seed=3)
    np.testing.assert_array_equal(guided.mean, plain.mean)
    np.testing.assert_array_equal(guided.stderr, plain.stderr)
    many = Engine(scene, [desk] * (G.PILOT_MIN_TOTAL // 256))
    many.run("guided", samples=256, seed=3)
    assert many.guide is not None and many.guide_skipped is None
