"""A year of glare without pictures (simulator.study.annual.glare) and the host rays it stands on (rays.py).

Closed forms: a uniform sky overhead is one source of the whole hemisphere (E_v = πL, Σ L²ω/P² = 2πL²), a
sun in sight adds its disk's L²Ω/P² (docs/REFERENCES.md §Glare indices, §Annual glare); the host's rays pass
a pane as the kernels' shadow rays do (docs/REFERENCES.md §Thin slab).
"""

import math
from pathlib import Path

import numpy as np

from simulator.glare import indices as ix
from simulator.glare.sources import GlareSettings
from simulator.scene.model import Geometry, Scene, Sensor, SensorKind
from simulator.study.annual import glare as AG
from simulator.study.annual.rays import cast, ray_scene
from simulator.study.inputs import sky_patches as SP

ROOT = Path(__file__).resolve().parents[1]


def _open_view(settings: GlareSettings | None = None):
    """An eye in an empty stage looking straight up (+Z), its up +Y: every pixel sees the sky."""
    view = Sensor("up", SensorKind.GLARE, np.zeros(3), np.array([0.0, 0.0, 1.0]), up=np.array([0.0, 1.0, 0.0]),
                  resolution=(64, 64), glare=settings)  # fmt: skip
    rs = ray_scene(Scene(Geometry(), [], []))
    return view, rs, AG.view_sky(view, rs, [], [], SP.N_PATCHES + 1)


def test_a_uniform_sky_overhead_is_one_source_of_the_whole_hemisphere():
    """Every patch at L = 3000 cd/m² (above evalglare's 2000), the eye looking up: E_v = πL (the pixels'
    cosines at their centres: within 1e-4), one source of ω = 2π (the pixels tile the hemisphere exactly) at the
    line of sight (P = 1), so G = 2πL²; DGP is then the formula's value, 0.7573."""
    view, rs, vs = _open_view()
    L = 3000.0
    lum = np.zeros((1, SP.N_PATCHES + 1))
    lum[0, : SP.N_PATCHES] = L
    assert vs.n_regions == 1 and abs(vs.omega.sum() - 2 * math.pi) < 1e-9
    ev = float(lum[0] @ vs.a)
    assert abs(ev / (math.pi * L) - 1.0) < 1e-4
    sun = AG.sun_terms(vs, rs, np.array([[0.0, 0.0, -1.0]]), np.zeros(1))
    g = AG.glare_term(vs, lum, sun)[0]
    assert abs(g / (2 * math.pi * L * L) - 1.0) < 1e-9
    d, _ = AG.dgp_hourly(np.array([ev]), np.array([g]))
    want = ix.DGP_C1 * math.pi * L + ix.DGP_C2 * math.log10(1 + 2 * math.pi * L * L / (math.pi * L) ** 1.87) + ix.DGP_C3
    assert abs(want - 0.7573) < 5e-5 and abs(d[0] - want) < 1e-4


def test_a_sun_in_sight_is_a_disk_source_of_its_own_or_joins_the_sky_without_peak_extraction():
    """The same sky (L = 3000) and a sun 30° off the line of sight, E_n = 80,000 lx: it adds E_n·cos 30° to E_v
    and, with peak extraction (evalglare's default), a source of luminance E_n/(π sin²α), α = 0.2665°, over
    Ω = 2π(1 − cos α) at its position index: G = 2πL² + L_s²Ω/P_s². With -x the sun joins the sky's source:
    G = S²/(W·P²), S = 2πL + L_sΩ, W = 2π + Ω, P at the direction of πL·ẑ + L_sΩ·s (the ω·L-weighted mean)."""
    L, en = 3000.0, 80000.0
    s = np.array([[math.sin(math.radians(30.0)), 0.0, math.cos(math.radians(30.0))]])
    lum = np.zeros((1, SP.N_PATCHES + 1))
    lum[0, : SP.N_PATCHES] = L
    a = AG.SUN_HALF_ANGLE_RAD
    ls, om = en / (math.pi * math.sin(a) ** 2), 2 * math.pi * (1 - math.cos(a))
    view, rs, vs = _open_view()
    sun = AG.sun_terms(vs, rs, s, np.array([en]))
    assert abs(sun.ev[0] - en * math.cos(math.radians(30))) < 1e-6 * en
    assert abs(sun.luminance[0] / ls - 1) < 1e-12 and abs(sun.omega / om - 1) < 1e-9
    p_s = float(ix.position_index(s, np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0]))[0])
    g = AG.glare_term(vs, lum, sun)[0]
    assert abs(g / (2 * math.pi * L * L + ls * ls * om / p_s**2) - 1) < 1e-9
    view, rs, vs = _open_view(GlareSettings(peak_extraction=False))
    sun = AG.sun_terms(vs, rs, s, np.array([en]))
    g = AG.glare_term(vs, lum, sun)[0]
    S, W = 2 * math.pi * L + ls * om, 2 * math.pi + om
    c = math.pi * L * np.array([0.0, 0.0, 1.0]) + ls * om * s[0]
    p = float(ix.position_index((c / np.linalg.norm(c))[None], np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0]))[0])
    assert abs(g / (S * S / (W * p * p)) - 1) < 1e-3  # the pixels' ω·d sums to πẑ within the grid's rounding


def test_dgp_and_dgps_of_the_hours_are_the_formulas():
    """dgp_hourly against indices.dgp (with and without the low-light correction, capped at 1) over E_v from 0
    to 20,000 lx; dgps_hourly against indices.dgps; the slope of DGP in E_v against a central difference."""
    ev = np.array([0.0, 50.0, 400.0, 999.0, 1000.0, 3000.0, 20000.0])
    g = np.array([0.0, 1e5, 1e7, 1e8, 1e6, 1e12, 1e3])
    for low in (False, True):
        d, slope = AG.dgp_hourly(ev, g, low)
        assert np.allclose(d, [ix.dgp(e, gg, low_light=low) for e, gg in zip(ev, g)], atol=1e-12)
        h = 1e-3
        num = (AG.dgp_hourly(ev + h, g, low)[0] - AG.dgp_hourly(ev - h, g, low)[0]) / (2 * h)
        ok = (ev > 1.0) & (d < 1.0) & (np.abs(ev - 1000.0) > 1.0)
        assert np.allclose(slope[ok], num[ok], rtol=1e-4, atol=1e-9)
    d, _ = AG.dgps_hourly(ev)
    assert np.allclose(d, [ix.dgps(e) for e in ev], atol=1e-15)


def test_glare_metrics_count_the_hours_and_the_en17037_level():
    """100 occupied hours: DGP 0.30 in 90, 0.38 in 4, 0.42 in 3, 0.50 in 3 (and 0.9 in an unoccupied one):
    glare autonomy (below 0.40) 94%; above 0.35/0.40/0.45: 10, 6, 3 hours; EN 17037: 10% > 5% above 0.35, 6%
    above 0.40, 3% ≤ 5% above 0.45 → the minimum level (1). With 0.38 in 2 of those hours instead, 4% above
    0.40 → medium (2)."""
    d = np.array([0.30] * 90 + [0.38] * 4 + [0.42] * 3 + [0.50] * 3 + [0.9])
    occ = np.array([True] * 100 + [False])
    m = AG.glare_metrics(d, occ, 0.40)
    assert m == {"GA": 94.0, "hours_above_0.35": 10.0, "hours_above_0.40": 6.0, "hours_above_0.45": 3.0, "EN17037_glare": 1.0}
    d[94:96] = 0.38
    assert AG.glare_metrics(d, occ, 0.40)["EN17037_glare"] == 2.0


def test_the_host_rays_pass_a_pane_as_the_kernels_shadow_rays_do():
    """The glazed office (a clear pane of ior 1.52 in the window): the direct sun at work-plane points through
    the pane, the host's E_n·cos·T(θ) against an ordinary direct-light run of a delta sun (4σ and 1e-4 relative),
    for 6 sun positions; behind the blind (opaque) nothing."""
    from simulator.scene.usd import load_stage
    from simulator.study.annual.sunlight import direct_sun
    from test_study_annual import host_sun_against_engine

    base = load_stage(ROOT / "stages" / "office.usda", light_units="photometric", radiometric_spectrum="E", variants={"window": "glazed"})
    sensors = [Sensor(f"s{i}", SensorKind.IRRADIANCE, np.array([x, y, 0.8]), np.array([0.0, 0.0, 1.0]))
               for i, (x, y) in enumerate((x, y) for x in (0.5, 1.5, 2.5, 3.5) for y in (1.0, 2.0, 3.0))]  # fmt: skip
    suns = [(250, 20), (270, 35), (290, 15), (230, 40), (270, 60), (260, 10)]
    dirs, lit = host_sun_against_engine(base, sensors, suns)
    assert lit > 10
    # through the pane the sun is T(θ) of what the open window passes
    from simulator.scene.surfaces import slab_rt

    rs = ray_scene(base)
    hit = cast(rs, np.array([1.0, 2.0, 1.0]), dirs[1])
    assert abs(hit.through - slab_rt(abs(dirs[1][0]), 1.52)[1]) < 1e-12
    down = load_stage(ROOT / "stages" / "office_shading.usda", light_units="photometric", radiometric_spectrum="E",
                      variants={"blinds": "down"})  # fmt: skip
    assert np.all(direct_sun(sensors, down, dirs, np.full(len(suns), 50000.0)) == 0.0)
