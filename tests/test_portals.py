"""DomeLight portals (UsdLux PortalLight): the sampler and its pdf twin, and
readings through a window with and without a portal.

A portal only changes how the dome is sampled (``simulator/kernels/lights/dome.py``):
where it guides a receiver, directions are drawn uniformly in its spherical
rectangle and the pdf is Σ_k P_k/Ω_k over the portals a direction passes
through, 0 elsewhere (cosine directions cover the rest under MIS). So every
reading must equal the one without the portal, and, in a black room lit by a
uniform sky through an open window, Lambert's closed form
E = L·∫_window cosθ dω (``simulator.reference.closed_forms.polygon_irradiance``,
docs/REFERENCES.md §Lambert's polygon formula).

Statistical checks use fixed seeds and |x − truth| ≤ 4σ plus a relative
slack of 2e-4 where a closed form is the truth: float32 spherical-rectangle
sampling (the solid angle is a sum of four acos, each good to ~1e-7 rad)
leaves a bias of a few 1e-5 relative, which 65k-sample runs of a sensor
facing the window head-on resolve (2e-5 relative standard error).
"""

from __future__ import annotations

import dataclasses
import math
import zlib

import numpy as np
import pytest
import warp as wp
from scipy import stats

from simulator.engine.device import warp as _warp
from simulator.engine.driver import Engine
from simulator.io import latlong
from simulator.kernels.lights import SceneRec, pdf_light, sample_light
from simulator.reference import closed_forms as cf
from simulator.scene.model import Geometry, Light, LightKind, Portal, Scene, Sensor, SensorKind

wp.set_module_options({"enable_backward": False})

N = 1 << 18
ALPHA = 1e-3
#: relative slack against a closed form: float32 spherical-rectangle sampling (module docstring)
F32_SLACK = 2e-4

#: west-wall window of the test room: x = 0, y 0.5..1.5, z 0.5..1.5, passing light toward +X
WINDOW = Portal("/Room/Window", np.array([0.0, 1.0, 1.0]), np.column_stack([[0, -1, 0], [0, 0, 1], [-1, 0, 0]]), 1.0, 1.0)
#: skylight in the ceiling (z = 2, x 0.8..1.6, y 0.4..1.0), passing light down (−Z): local Z is world +Z
SKYLIGHT = Portal("/Room/Skylight", np.array([1.2, 0.7, 2.0]), np.eye(3), 0.8, 0.6)


# --------------------------------------------------------------------------- kernels


@wp.kernel
def k_sample_light(
    scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, seed: int,
    wi: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float), value: wp.array(dtype=wp.vec2), pdf_again: wp.array(dtype=float),
):  # fmt: skip
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    s = sample_light(scene, li, p, n, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))
    wi[i] = s.wi
    pdf[i] = s.pdf
    value[i] = s.value
    pdf_again[i] = pdf_light(scene, li, p, n, s.wi, s.dist, s.tri)


@wp.kernel
def k_pdf_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, wi: wp.array(dtype=wp.vec3), out: wp.array(dtype=float)):
    i = wp.tid()
    out[i] = pdf_light(scene, li, p, n, wi[i], 1.0e30, -1)


def _engine(lights, geometry=None) -> Engine:
    scene = Scene(geometry=geometry or Geometry(), lights=lights, sensors=[], path="<test>")
    return Engine(scene, [Sensor("s", SensorKind.IRRADIANCE, np.zeros(3), np.array([0.0, 0.0, 1.0]))], device="cpu", threads=1)


def _sample(eng, p, n, what):
    _warp()
    outs = [wp.empty(N, dtype=dt, device="cpu") for dt in (wp.vec3, float, wp.vec2, float)]
    seed = zlib.crc32(what.encode()) & 0x7FFFFFFF
    with wp.ScopedDevice("cpu"):
        wp.launch(k_sample_light, dim=N, inputs=[eng.scene_rec, 0, wp.vec3(*p), wp.vec3(*n), seed], outputs=outs)
    wi, pdf, value, again = (o.numpy() for o in outs)
    return wi.astype(np.float64), pdf.astype(np.float64), value.astype(np.float64), again.astype(np.float64)


def _pdf(eng, p, n, wi) -> np.ndarray:
    _warp()
    out = wp.empty(len(wi), dtype=float, device="cpu")
    with wp.ScopedDevice("cpu"):
        wp.launch(k_pdf_light, dim=len(wi), inputs=[eng.scene_rec, 0, wp.vec3(*p), wp.vec3(*n),
                                                   wp.array(wi.astype(np.float32), dtype=wp.vec3)], outputs=[out])  # fmt: skip
    return out.numpy().astype(np.float64)


def _dome(portals=(), texture_map=None) -> Light:
    return Light("/Sky", LightKind.DOME, np.zeros(3), np.eye(3), (2.0, 400.0), portals=portals, texture_map=texture_map)


def _chi_square(observed, expected) -> float:
    """p-value of Pearson's statistic, bins merged in order until each expects ≥ 5."""
    o_m, e_m, oa, ea = [], [], 0.0, 0.0
    for o, e in zip(np.ravel(observed).astype(float), np.ravel(expected).astype(float)):
        oa, ea = oa + o, ea + e
        if ea >= 5.0:
            o_m.append(oa), e_m.append(ea)
            oa = ea = 0.0
    if e_m:
        o_m[-1] += oa
        e_m[-1] += ea
    o_m, e_m = np.array(o_m), np.array(e_m)
    return float(stats.chi2.sf(np.sum((o_m - e_m) ** 2 / e_m), len(e_m) - 1))


def _portal_bins(eng, portal: Portal, p, n, edges: np.ndarray, order: int = 6) -> np.ndarray:
    """N·∫_bin pdf_light dω over the grid of bin ``edges`` (in [0, 1], the
    same along u and v) on the portal (u along X, v along Y), by order ×
    order Gauss–Legendre per bin: dω = cosθ_portal/d² dA. The pdf must be
    smooth inside each bin (edges placed on its jumps)."""
    x, w = np.polynomial.legendre.leggauss(order)
    lo, width = edges[:-1], np.diff(edges)
    nb = len(lo)
    cells = lo[:, None] + width[:, None] * 0.5 * (x[None, :] + 1)  # (nb, order)
    cw = width[:, None] * 0.5 * w[None, :]
    U = np.broadcast_to(cells[:, None, :, None], (nb, nb, order, order)).ravel()
    V = np.broadcast_to(cells[None, :, None, :], (nb, nb, order, order)).ravel()
    W = (cw[:, None, :, None] * cw[None, :, None, :]).ravel()
    corner = portal.corners()[0]
    q = corner + (U * portal.width)[:, None] * portal.frame[:, 0] + (V * portal.height)[:, None] * portal.frame[:, 1]
    d = q - p
    t2 = np.sum(d * d, axis=1)
    wi = d / np.sqrt(t2)[:, None]
    jac = portal.width * portal.height * np.abs(wi @ portal.frame[:, 2]) / t2
    return N * (_pdf(eng, p, n, wi) * jac * W).reshape(nb, nb, order * order).sum(axis=2)


def _through(portal: Portal, p, wi) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(inside, u, v): whether each direction from p crosses the portal rectangle, and where."""
    ez = portal.frame[:, 2]
    corner = portal.corners()[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((corner - p) @ ez) / (wi @ ez)
    q = p + t[:, None] * wi - corner
    u, v = q @ portal.frame[:, 0] / portal.width, q @ portal.frame[:, 1] / portal.height
    inside = (t > 0) & (u >= -1e-6) & (u <= 1 + 1e-6) & (v >= -1e-6) & (v <= 1 + 1e-6)
    return inside, np.clip(u, 0, 1 - 1e-12), np.clip(v, 0, 1 - 1e-12)


def _check_portal_sampler(eng, portals, p, n, what, radiance, edges=np.linspace(0.0, 1.0, 11)):
    """Samples against pdf_light: the pdf a sample carries is pdf_light's,
    its value is L(ω)·cos⁺θ/pdf, every sample passes through a portal, and
    the directions binned on each portal fit N·∫_bin pdf dω by chi-square; the
    expected counts sum to N (∫ pdf dω over the portals = 1)."""
    p, n = np.asarray(p, float), np.asarray(n, float)
    wi, pdf, value, again = _sample(eng, p, n, what)
    assert np.all(pdf > 0), f"{what}: a guided receiver always gets a sample"
    np.testing.assert_allclose(again, pdf, rtol=2e-5, err_msg=f"{what}: sample pdf vs pdf_light")
    # cosθ from the float32 direction is good to a few ε32 absolute: near the
    # horizon that is a large relative error, hence the absolute term (16× headroom)
    expect = radiance(wi) * np.maximum(wi @ n, 0.0) / pdf
    slack = 1e-4 * expect + radiance(wi) * 16 * 6e-8 / pdf
    assert np.all(np.abs(value[:, 0] - expect) <= slack), f"{what}: value is not L·cos⁺θ/pdf"
    counts, expected = [], []
    claimed = np.zeros(N, bool)
    for portal in portals:
        inside, u, v = _through(portal, p, wi)
        mine = inside & ~claimed  # non-overlapping portals: each direction crosses one
        claimed |= inside
        nb = len(edges) - 1
        iu = np.clip(np.searchsorted(edges, u[mine], side="right") - 1, 0, nb - 1)
        iv = np.clip(np.searchsorted(edges, v[mine], side="right") - 1, 0, nb - 1)
        counts.append(np.bincount(iu * nb + iv, minlength=nb * nb))
        expected.append(_portal_bins(eng, portal, p, n, edges).ravel())
    assert claimed.all(), f"{what}: a sample passes through no portal"
    expected = np.concatenate(expected)
    assert expected.sum() / N == pytest.approx(1.0, abs=2e-4), f"{what}: ∫ pdf dω = {expected.sum() / N}"
    assert _chi_square(np.concatenate(counts), expected) > ALPHA, what


def test_one_portal_sampler_matches_its_pdf():
    """A uniform dome with one window portal, seen from the floor (portal
    partly at grazing angles) and from the far wall: directions uniform in
    the window's spherical rectangle, pdf 1/Ω inside it, 0 outside."""
    eng = _engine([_dome((WINDOW,))])
    for p, n in [((1.0, 1.0, 0.3), (0.0, 0.0, 1.0)), ((1.99, 0.3, 1.8), (-1.0, 0.0, 0.0))]:
        _check_portal_sampler(eng, [WINDOW], p, n, f"window from {p}", lambda wi: 2.0)
    wi = np.array([[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])  # through the window; up, through no portal
    p = np.array([1.0, 1.0, 1.0])
    pdf = _pdf(eng, p, np.array([-1.0, 0.0, 0.0]), wi)
    omega = cf.polygon_solid_angle(WINDOW.corners(), p)
    np.testing.assert_allclose(pdf, [1.0 / omega, 0.0], rtol=1e-5)


def test_two_portals_are_picked_by_projected_solid_angle():
    """A window and a skylight seen from the floor: each is picked with
    probability Π_k/ΣΠ (Π the projected solid angle, Lambert's formula), so
    the share of samples through each matches, and the binned directions fit
    pdf_light on both portals."""
    eng = _engine([_dome((WINDOW, SKYLIGHT))])
    p, n = np.array([1.2, 1.0, 0.2]), np.array([0.0, 0.0, 1.0])
    _check_portal_sampler(eng, [WINDOW, SKYLIGHT], p, n, "window + skylight", lambda wi: 2.0)
    wi, _, _, _ = _sample(eng, p, n, "window + skylight")
    pi_w, pi_s = (cf.polygon_irradiance(1.0, q.corners(), p, n) for q in (WINDOW, SKYLIGHT))
    share = np.mean(_through(SKYLIGHT, p, wi)[0])
    expect = pi_s / (pi_w + pi_s)
    assert abs(share - expect) <= 4 * math.sqrt(expect * (1 - expect) / N)


def test_overlapping_portals_pdf_integrates_to_one():
    """Two portals one behind the other (the window, and a larger one 0.5 m
    outside it, covering it as seen from the receiver): directions through both count both, pdf = Σ P_k/Ω_k. Its
    integral over the sphere, by uniform directions (E[4π·pdf] = 1), is 1
    within 4σ, and samples binned on the large portal fit that pdf."""
    outer = Portal("/Outer", np.array([-0.5, 1.0, 1.0]), WINDOW.frame, 2.4, 2.4)
    eng = _engine([_dome((WINDOW, outer))])
    p, n = np.array([1.0, 1.2, 0.4]), np.array([-0.3, 0.0, 1.0]) / math.hypot(0.3, 1.0)
    rng = np.random.default_rng(7)
    d = rng.normal(size=(N, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    f = 4 * np.pi * _pdf(eng, p, n, d)
    assert abs(f.mean() - 1.0) <= 4 * f.std() / math.sqrt(N), f"∫ pdf dω = {f.mean():.4f} ± {f.std() / math.sqrt(N):.4f}"
    # bins on the outer portal, with edges where the window's outline falls
    # (seen from p the window projects onto u 0.229…0.854, v 0.3125…0.9375)
    edges = np.sort(np.r_[np.linspace(0.0, 1.0, 9), (2.2 - 1.65) / 2.4, (2.2 - 0.15) / 2.4, 0.75 / 2.4, 2.25 / 2.4])
    _check_portal_sampler(eng, [outer], p, n, "overlapping portals", lambda wi: 2.0, edges)


def test_textured_dome_through_a_portal():
    """A textured dome (a 16 × 8 map, one bright texel row) with a portal:
    directions are drawn through the portal as for a uniform dome, and each
    sample's value is L·map(ω)·cos⁺θ/pdf, the map looked up along ω (nearest texel)."""
    rng = np.random.default_rng(3)
    m = rng.uniform(0.2, 2.0, size=(8, 16))
    m[4] *= 5.0
    eng = _engine([_dome((WINDOW,), texture_map=m)])

    def radiance(wi):
        row, col = latlong.uv_to_texel(latlong.direction_to_latlong_uv(wi), 16, 8)
        return 2.0 * m[row, col]

    _check_portal_sampler(eng, [WINDOW], (1.0, 1.0, 0.3), (0.0, 0.0, 1.0), "textured dome", radiance)


@pytest.mark.parametrize("texture", [False, True])
def test_receiver_no_portal_guides_gets_the_plain_dome_sampler(texture):
    """Behind the window (outdoors, x < 0), or in front of it with the window
    below its horizon (a wall facing away from it), no portal guides the
    receiver: the dome is sampled as without portals (cosine lobe, or the
    map), so the same random numbers give the same samples, and the pdf of
    any direction is the portal-less one."""
    m = np.linspace(0.5, 3.0, 8 * 16).reshape(8, 16) if texture else None
    with_p, without = _engine([_dome((WINDOW,), m)]), _engine([_dome((), m)])
    for p, n in [((-1.0, 1.0, 0.5), (0.0, 0.0, 1.0)), ((1.0, 1.0, 1.0), (1.0, 0.0, 0.0))]:
        p, n = np.array(p), np.array(n)
        a, b = _sample(with_p, p, n, "behind"), _sample(without, p, n, "behind")
        for x, y in zip(a, b):
            np.testing.assert_allclose(x, y, rtol=1e-6, atol=0)
        d = np.random.default_rng(1).normal(size=(4096, 3))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        np.testing.assert_allclose(_pdf(with_p, p, n, d), _pdf(without, p, n, d), rtol=1e-6, atol=0)


# --------------------------------------------------------------------------- readings


def _quads(quads, albedo: float) -> Geometry:
    pts, tris = [], []
    for q in quads:
        b = len(pts)
        pts += list(q)
        tris += [(b, b + 1, b + 2), (b, b + 2, b + 3)]
    t = len(tris)
    return Geometry(np.array(pts, float), np.array(tris, np.int32), np.full(t, albedo), np.zeros((t, 2)),
                    np.zeros(t, bool), np.zeros(t, np.int32), ["room"])  # fmt: skip


def window_room(albedo: float) -> Geometry:
    """A closed 2 m cube with one opening, the 1 m × 1 m window of ``WINDOW``."""
    return _quads([
        [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], [(0, 0, 2), (0, 2, 2), (2, 2, 2), (2, 0, 2)],
        [(2, 0, 0), (2, 0, 2), (2, 2, 2), (2, 2, 0)], [(0, 0, 0), (0, 0, 2), (2, 0, 2), (2, 0, 0)],
        [(0, 2, 0), (2, 2, 0), (2, 2, 2), (0, 2, 2)],
        [(0, 0, 0), (0, 2, 0), (0, 2, 0.5), (0, 0, 0.5)], [(0, 0, 1.5), (0, 2, 1.5), (0, 2, 2), (0, 0, 2)],
        [(0, 0, 0.5), (0, 0.5, 0.5), (0, 0.5, 1.5), (0, 0, 1.5)], [(0, 1.5, 0.5), (0, 2, 0.5), (0, 2, 1.5), (0, 1.5, 1.5)],
    ], albedo)  # fmt: skip


ROOM_SENSORS = [
    Sensor(f"s{i}", SensorKind.IRRADIANCE, np.array(p, float), np.array(n, float) / np.linalg.norm(n))
    for i, (p, n) in enumerate([((1, 1, 0.3), (0, 0, 1)), ((1.5, 0.5, 0.3), (0, 0, 1)), ((1.99, 1, 1), (-1, 0, 0)),
                                ((0.5, 1.8, 1.2), (0, -1, 0)), ((0.7, 0.4, 1.0), (-1, 0.5, 0.3))])
]  # fmt: skip


def _read(geometry, dome, method, samples, seed, sensors=ROOM_SENSORS):
    eng = Engine(Scene(geometry=geometry, lights=[dome], sensors=[], path="<test>"), sensors, device="cpu")
    r = eng.run(method, samples=samples, seed=seed)
    return r.mean[:, 0], r.stderr[:, 0]


@pytest.mark.parametrize("method", ["light", "mis", "path"])
def test_black_room_window_matches_lambert_with_and_without_portal(method):
    """A uniform sky (L = 2 W m⁻² sr⁻¹) through an open window into a black
    room: E = L·Π, Π the window's projected solid angle (Lambert's formula,
    clipped to each receiver's horizon), with the portal and without it. The
    portal must also cut the noise: it puts every light sample in the window,
    where without it most cosine directions hit the black walls."""
    g = window_room(0.0)
    truth = np.array([cf.polygon_irradiance(2.0, WINDOW.corners(), s.position, s.normal) for s in ROOM_SENSORS])
    errs = {}
    for portals in [(WINDOW,), ()]:
        x, se = _read(g, _dome(portals), method, 16384, 11)
        bad = np.abs(x - truth) > 4 * se + F32_SLACK * truth
        assert not bad.any(), f"{method} portals={len(portals)}: {x[bad]} vs {truth[bad]} ± {se[bad]}"
        errs[len(portals)] = se
    assert np.all(errs[1] < 0.5 * errs[0]), f"{method}: portal stderr {errs[1]} vs {errs[0]} without"


def test_reflecting_room_path_with_and_without_portal_agree():
    """Walls of albedo 0.5: interreflected sky light, no closed form; the
    portal changes sampling only, so the two path readings agree within 4σ
    of their difference."""
    g = window_room(0.5)
    a, sa = _read(g, _dome((WINDOW,)), "path", 8192, 21)
    b, sb = _read(g, _dome(()), "path", 8192, 22)
    assert np.all(np.abs(a - b) <= 4 * np.hypot(sa, sb)), f"{a} vs {b}"


@pytest.mark.parametrize("method", ["light", "mis"])
def test_textured_sky_window_with_and_without_portal_agree(method):
    """A textured sky (a 32 × 16 map with a bright band) through the window of
    a black room: the reading with the portal equals the one without, within
    4σ of the difference (the map is sampled by texel without the portal, by
    the window's solid angle with it)."""
    m = np.ones((16, 32))
    m[6:9] = 6.0
    m[:, 10:14] *= 0.3
    g = window_room(0.0)
    a, sa = _read(g, _dome((WINDOW,), m), method, 16384, 31)
    b, sb = _read(g, _dome((), m), method, 16384, 32)
    assert np.all(np.abs(a - b) <= 4 * np.hypot(sa, sb)), f"{a} vs {b} ± {np.hypot(sa, sb)}"


def test_receivers_outside_read_the_sky_with_a_portal():
    """Receivers outside the room (behind the window portal, and on the roof
    with the window below its horizon): no portal guides them, the dome is
    sampled as without portals, and ``light`` still counts the whole sky
    they see: on the roof, facing up, E = π·L exactly (the cosine lobe's
    estimate has zero variance there)."""
    g = window_room(0.0)
    sensors = [Sensor("ground", SensorKind.IRRADIANCE, np.array([-1.0, 1.0, 0.2]), np.array([0.0, 0.0, 1.0])),
               Sensor("roof", SensorKind.IRRADIANCE, np.array([1.0, 1.0, 2.001]), np.array([0.0, 0.0, 1.0]))]  # fmt: skip
    a, sa = _read(g, _dome((WINDOW,)), "light", 4096, 41, sensors)
    b, sb = _read(g, _dome(()), "light", 4096, 41, sensors)
    np.testing.assert_allclose(a, b, rtol=1e-6)
    assert a[1] == pytest.approx(2.0 * math.pi, rel=1e-5)


def test_office_readings_with_and_without_the_window_portal_agree():
    """stages/office.usda's sky portal fills its window: it changes sampling
    only, so path readings on a subset of the benchmark's sensors (every
    61st work-plane sensor and the north wall) agree with the same readings
    with the portal removed, within 4σ of their difference (so the stored
    reference, configs/references/office_bench.csv, made without the
    portal, stays valid); the portal is read onto the dome."""
    from pathlib import Path

    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, load_scene

    cfg = load_config(Path(__file__).resolve().parent.parent / "configs" / "office_bench.toml")
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    subset = sensors[::61] + [s for s in sensors if s.grid == "north_wall"][::4]
    sky = next(l for l in scene.lights if l.kind == LightKind.DOME)
    assert [p.name for p in sky.portals] == ["/Office/WindowPortal"]
    bare = dataclasses.replace(scene, lights=[dataclasses.replace(l, portals=()) for l in scene.lights])
    a = Engine(scene, subset, device="cpu").run("path", samples=512, seed=5)
    b = Engine(bare, subset, device="cpu").run("path", samples=512, seed=6)
    diff = np.abs(a.mean[:, 1] - b.mean[:, 1])
    assert np.all(diff <= 4 * np.hypot(a.stderr[:, 1], b.stderr[:, 1])), f"{a.mean[:, 1]} vs {b.mean[:, 1]}"
