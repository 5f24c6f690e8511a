"""Direct light computed, not sampled: :func:`simulator.engine.exact.exact_direct` against closed
forms for every emitter it reads, the occluder cull against a scan of every triangle, and the hybrid
(``exact+path``, ``exact+guided``: direct light computed, the rest sampled) against the closed form
of a furnace and against the all-sampled reading of furnished rooms, within 4 standard errors.

The closed forms are :mod:`simulator.reference.closed_forms` (Lambert's polygon formula, the disk on
its axis, the furnace), which share no code with the engine (docs/REFERENCES.md
§Lambert's polygon formula, §Uniform disk, §Furnace, §Visible part of an emitter).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from simulator.engine.exact import exact_direct
from simulator.engine.occluders import OccluderIndex, cull_clustered, pyramid_planes
from simulator.reference import closed_forms as cf
from simulator.scene.model import Geometry, Light, LightKind, Scene, Sensor, SensorKind

ROOT = Path(__file__).resolve().parents[1]
L = 1000.0  # cd/m²


def _quad(x0, x1, y0, y1, z, up=True):
    """Two triangles of the rectangle [x0, x1] × [y0, y1] at height z, facing +Z (or −Z)."""
    a, b, c, d = [x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]
    t = np.array([[a, b, c], [a, c, d]], float)
    return t if up else t[:, ::-1]


def _box(x0, x1, y0, y1, z0, z1, hole=None):
    """The six faces of a box, facing in; the top with a rectangular hole ``(hx0, hx1, hy0, hy1)``."""
    f = [_quad(x0, x1, y0, y1, z0, up=True)]
    if hole is None:
        f.append(_quad(x0, x1, y0, y1, z1, up=False))
    else:
        hx0, hx1, hy0, hy1 = hole
        f += [_quad(x0, hx0, y0, y1, z1, False), _quad(hx1, x1, y0, y1, z1, False),
              _quad(hx0, hx1, y0, hy0, z1, False), _quad(hx0, hx1, hy1, y1, z1, False)]  # fmt: skip
    for axis, v, sign in ((0, x0, 1), (0, x1, -1), (1, y0, 1), (1, y1, -1)):
        other = (y0, y1) if axis == 0 else (x0, x1)
        a, b = other
        if axis == 0:
            q = np.array([[v, a, z0], [v, b, z0], [v, b, z1], [v, a, z1]], float)
        else:
            q = np.array([[a, v, z0], [b, v, z0], [b, v, z1], [a, v, z1]], float)
        t = np.array([[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        n = np.cross(t[0, 1] - t[0, 0], t[0, 2] - t[0, 0])
        inward = np.zeros(3)
        inward[axis] = sign
        f.append(t if n @ inward > 0 else t[:, ::-1])
    return np.concatenate(f)


def _scene(tris, albedo=0.0, emission=None, two_sided=False, lights=()):
    tris = np.asarray(tris, float).reshape(-1, 3, 3)
    T = len(tris)
    em = np.zeros((T, 2)) if emission is None else np.broadcast_to(np.asarray(emission, float), (T, 2)).copy()
    g = Geometry(points=tris.reshape(-1, 3), triangles=np.arange(3 * T, dtype=np.int32).reshape(T, 3),
                 albedo=np.full(T, float(albedo)), emission=em, two_sided=np.full(T, bool(two_sided)),
                 prim=np.zeros(T, np.int32), prim_names=["/Mesh"])  # fmt: skip
    return Scene(g, list(lights), [])


def _sensors(P, N=(0, 0, 1)):
    N = np.broadcast_to(np.asarray(N, float), np.shape(P))
    return [Sensor(f"s{i}", SensorKind.IRRADIANCE, np.asarray(p, float), np.asarray(n, float) / np.linalg.norm(n))
            for i, (p, n) in enumerate(zip(P, N))]  # fmt: skip


def _floor(n, half, z=0.0, seed=1):
    rng = np.random.default_rng(seed)
    return np.c_[rng.uniform(-half, half, (n, 2)), np.full(n, z)]


def test_emissive_quad_equals_lambert_and_is_one_sided():
    """A 1 m × 2 m emissive quad (two triangles, merged into one polygon) at z = 2 facing down: on
    the floor below, E = L·∫cos θ dω by Lambert's formula (``polygon_irradiance``); above it, where
    its back faces, 0; two-sided, the same above as below at the mirror point."""
    quad = _quad(-0.5, 0.5, -1.0, 1.0, 2.0, up=False)
    scene = _scene(quad, emission=(L, L))
    P = _floor(60, 2.0)
    ex = exact_direct(scene, _sensors(P), np.arange(60))
    verts = np.array([[-0.5, -1, 2], [0.5, -1, 2], [0.5, 1, 2], [-0.5, 1, 2]], float)
    ref = np.array([cf.polygon_irradiance(L, verts, p, [0, 0, 1]) for p in P])
    np.testing.assert_allclose(ex.mean[:, 1], ref, rtol=1e-11)
    assert np.all(ex.bound[:, 1] <= 1e-9 * ref) and np.all(ex.covered[:, 0])
    above = _sensors(P + [0, 0, 4.0], (0, 0, -1))
    assert np.all(exact_direct(scene, above, np.arange(60)).mean == 0.0)
    both = _scene(quad, emission=(L, L), two_sided=True)
    np.testing.assert_allclose(exact_direct(both, above, np.arange(60)).mean[:, 1], ref, rtol=1e-11)


def test_emissive_quad_half_shaded():
    """A black shade x < 0 a gap g = 0.3 m below the emitter hides, seen from (px, py, 0), the part of
    it left of x_e = px·(1 − H/(H − g)) (H = 2 m): the visible part is a rectangle, read by the
    corner-rectangle closed form (``rect_irradiance_parallel``, docs/REFERENCES.md §Parallel rectangle)."""
    H, g = 2.0, 0.3
    emit = _quad(-0.5, 0.5, -1.0, 1.0, H, up=False)
    shade = _quad(-10.0, 0.0, -10.0, 10.0, H - g)
    scene = _scene(np.concatenate([emit, shade]), emission=None)
    scene.geometry.emission[:2] = (L, L)
    P = _floor(80, 1.5, seed=2)
    ex = exact_direct(scene, _sensors(P), np.arange(80))

    def rect(px, py, x0, x1):
        x0, x1 = max(x0, -0.5), min(x1, 0.5)
        return 0.0 if x0 >= x1 else float(cf.rect_irradiance_parallel(L, x0 - px, x1 - px, -1.0 - py, 1.0 - py, H))

    ref = np.array([rect(px, py, px * (1 - H / (H - g)), 0.5) for px, py, _ in P])
    np.testing.assert_allclose(ex.mean[:, 1], ref, rtol=1e-10, atol=1e-9)


def test_disk_polygon_bounds_hold_the_disk():
    """A DiskLight of radius 0.5 m facing down 1.5 m above receivers on its axis, facing up or tilted
    by 0.4 rad: the reading (the mean of its inscribed and circumscribed 256-gons' visible parts)
    lies within its reported bound of the disk's closed form (``disk_irradiance_on_axis``,
    docs/REFERENCES.md §Uniform disk), and the bound is at most 8·10⁻⁵ of the reading (π²/(2n²) = 7.5·10⁻⁵
    at n = 256)."""
    disk = Light("/Disk", LightKind.DISK, np.array([0.0, 0.0, 1.5]), np.eye(3), (L, L), radius=0.5)
    scene = _scene(np.zeros((0, 3, 3)), lights=[disk])
    tilt = 0.4
    sensors = _sensors([[0, 0, 0], [0, 0, 0]], [[0, 0, 1], [np.sin(tilt), 0, np.cos(tilt)]])
    ex = exact_direct(scene, sensors, np.arange(2))
    ref = [cf.disk_irradiance_on_axis(L, 0.5, 1.5), cf.disk_irradiance_on_axis(L, 0.5, 1.5, tilt)]
    for i in range(2):
        assert abs(ex.mean[i, 1] - ref[i]) <= ex.bound[i, 1]
        assert ex.bound[i, 1] <= 8e-5 * ex.mean[i, 1]
        assert ex.disk_bound[i, 1] > 0.0


def test_uniform_sky_whole_and_through_an_opening():
    """A uniform sky of radiance L: with nothing in the way every receiver, however tilted, reads
    π·L (the whole hemisphere, docs/REFERENCES.md §Uniform environment); inside a closed black box
    whose top has a 1 m × 0.6 m hole, only the sky seen through the hole reaches it, which is
    Lambert's formula on the hole's polygon (``polygon_irradiance``), for level and tilted receivers."""
    sky = Light("/Sky", LightKind.DOME, np.zeros(3), np.eye(3), (L, L))
    rng = np.random.default_rng(5)
    N = rng.normal(size=(12, 3))
    open_air = exact_direct(_scene(np.zeros((0, 3, 3)), lights=[sky]), _sensors(rng.normal(size=(12, 3)), N), np.arange(12))
    np.testing.assert_allclose(open_air.mean[:, 1], np.pi * L, rtol=1e-12)
    hole = (-0.3, 0.7, -0.2, 0.4)
    scene = _scene(_box(-2, 2, -1.5, 1.5, 0, 2.5, hole), lights=[sky])
    P = np.c_[rng.uniform(-1.8, 1.8, 30), rng.uniform(-1.3, 1.3, 30), rng.uniform(0.2, 1.5, 30)]
    N = np.c_[rng.normal(size=(30, 2)) * 0.4, np.ones(30)]
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    ex = exact_direct(scene, _sensors(P, N), np.arange(30))
    hx0, hx1, hy0, hy1 = hole
    verts = np.array([[hx0, hy0, 2.5], [hx1, hy0, 2.5], [hx1, hy1, 2.5], [hx0, hy1, 2.5]])
    ref = np.array([cf.polygon_irradiance(L, verts, p, n) for p, n in zip(P, N)])
    np.testing.assert_allclose(ex.mean[:, 1], ref, rtol=1e-9, atol=1e-9 * L)


def test_cull_keeps_every_triangle_that_reaches_the_hull():
    """The box hierarchy's cull per receiver returns exactly the triangles a scan of every triangle
    keeps (those not wholly outside one of the receiver's planes, a superset of what can block), and
    the clustered cull, whichever receivers it groups, a subset of those that holds every triangle
    reaching into the receiver's hull: one it sets aside, clipped to that hull, leaves nothing."""
    from simulator.engine.occluders import reaching_pairs

    rng = np.random.default_rng(8)
    c = rng.uniform(-3, 3, (2000, 1, 3))
    tris = c + rng.normal(scale=0.2, size=(2000, 3, 3))
    idx = OccluderIndex(tris)
    P = _floor(70, 2.5, z=-0.5, seed=9)
    N = np.tile([0.0, 0.0, 1.0], (70, 1))
    poly = np.array([[-0.5, -1, 2.5], [0.5, -1, 2.5], [0.5, 1, 2.5], [-0.5, 1, 2.5]])[::-1]
    planes = pyramid_planes(P, N, np.broadcast_to(poly, (70, 4, 3)), np.full(70, 4))
    j, t = idx.cull(planes)
    h = np.einsum("jkd,tvd->jtkv", planes[..., :3], tris) - planes[..., 3][:, None, :, None]
    tol = 1e-9 * idx.scale * (1 + np.linalg.norm(planes[..., :3], axis=2))[:, None, :, None]
    scan = ~np.any(np.all(h < -tol, axis=3), axis=2)  # (J, T)
    assert set(zip(j.tolist(), t.tolist())) == set(zip(*np.nonzero(scan)))
    sj, st = np.nonzero(scan)
    reach = reaching_pairs(planes, sj, st, tris)
    want = set(zip(sj[reach].tolist(), st[reach].tolist()))
    assert len(want) > 100 and len(want) < scan.sum()  # some candidates reach, some only seem to
    every = set(zip(sj.tolist(), st.tolist()))
    for size in (1, 7, 16, 70):
        jc, tc = cull_clustered(idx, P, N, poly, 4, cluster=size)
        got = set(zip(jc.tolist(), tc.tolist()))
        assert want <= got <= every


# ---------------------------------------------------------------- the hybrid, sampled


def _engine(scene, sensors):
    from simulator.engine.driver import Engine

    return Engine(scene, sensors, threads=2)


def test_hybrid_furnace_reads_its_closed_form():
    """Irradiance sensors inside a closed box whose walls emit L and reflect ρ = 0.5: E = π·L/(1 − ρ)
    (docs/REFERENCES.md §Furnace). The hybrid computes the walls' direct light, πL exactly, and
    samples the reflected πLρ/(1 − ρ); its reading is within 4 standard errors of the closed form at
    every sensor, and its error is the sampled part's (below the all-sampled one's at equal samples)."""
    rho = 0.5
    scene = _scene(_box(-1, 1, -1, 1, 0, 2), albedo=rho, emission=(L, L))
    P = np.array([[0, 0, 1.0], [0.5, -0.3, 0.4], [-0.6, 0.6, 1.7], [0.2, 0.1, 0.05]])
    N = np.array([[0, 0, 1.0], [1, 0, 0], [0, -1, 1], [0, 0, 1]], float)
    sensors = _sensors(P, N)
    want = float(cf.furnace_irradiance(L, rho))
    eng = _engine(scene, sensors)
    r = eng.run("exact+path", samples=4096, seed=3)
    assert r.method == "exact+path" and eng.hybrid_pilot["computed"]
    z = (r.mean[:, 1] - want) / r.stderr[:, 1]
    assert np.all(np.abs(z) < 4.0), z
    plain = _engine(scene, sensors).run("path", samples=4096, seed=3)
    assert np.all(np.abs(plain.mean[:, 1] - want) < 4.0 * plain.stderr[:, 1])
    assert np.mean(r.stderr[:, 1]) < np.mean(plain.stderr[:, 1])


def _office(stage: str, every: int):
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, load_scene

    from dataclasses import replace

    cfg = replace(load_config(ROOT / "configs" / "office_bench.toml"), stage=ROOT / "stages" / stage)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)[::every]
    return scene, sensors


@pytest.mark.parametrize("stage, methods", [("office_emissive.usda", ("exact+guided", "guided")),
                                            ("office.usda", ("exact+path", "path"))])
def test_hybrid_equals_all_sampled_in_furnished_rooms(stage, methods):
    """The office lit by an emissive window and emissive diffusers, and the office lit by
    RectLights, a sky through its window and the sun (the sun stays sampled: only its reflected
    light and the others' direct light differ in how they are read): every 61st work-plane sensor
    read with the direct light computed and with everything sampled, on independent seeds, agrees
    within 4 combined standard errors at 2,048 samples per sensor, and the pooled difference is
    within 4 standard errors of 0."""
    from simulator.plan.planner import make_plan

    scene, sensors = _office(stage, 61)
    plan = make_plan(scene, sensors)
    hyb, base = methods
    out = []
    for m, seed in ((hyb, 11), (base, 12)):
        eng = _engine(scene, sensors)
        eng.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
        out.append(eng.run(m, samples=2048, seed=seed))
    (a, b) = out
    d = a.mean[:, 1] - b.mean[:, 1]
    s = np.sqrt(a.stderr[:, 1] ** 2 + b.stderr[:, 1] ** 2)
    assert np.all(np.abs(d) < 4.0 * s), d / s
    assert abs(d.sum()) < 4.0 * np.sqrt(np.sum(s**2))


def test_hybrid_leaves_a_pane_and_the_sun_sampled():
    """The glazed room of the walkthrough: its sky reaches the desk through a pane, which the computed
    part cannot pass, so for those sensors the sky stays sampled (the plan says so) while the lamp is
    computed; the readings agree with all-sampled ones within 4 combined standard errors."""
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, load_scene
    from simulator.plan.planner import make_plan

    cfg = load_config(ROOT / "configs" / "walkthrough.toml")
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind == SensorKind.IRRADIANCE][::3]
    plan = make_plan(scene, sensors)
    hyb = [sp for sp in plan.sensors if sp.method == "exact+guided"]
    assert hyb and all("pane or a cut-out" in sp.reason for sp in hyb if "/Room/Sky" not in sp.computed)
    out = []
    for m, seed in (("exact+guided", 21), ("guided", 22)):
        eng = _engine(scene, sensors)
        eng.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
        eng.set_computed(plan.computed_mask([l.name for l in scene.lights]))
        out.append(eng.run(m, samples=2048, seed=seed))
    a, b = out
    s = np.sqrt(a.stderr[:, 1] ** 2 + b.stderr[:, 1] ** 2)
    assert np.all(np.abs(a.mean[:, 1] - b.mean[:, 1]) < 4.0 * s)
