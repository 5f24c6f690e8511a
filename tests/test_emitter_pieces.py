"""Emissive geometry in pieces (simulator.scene.emitters, kernels/lights/emissive.py).

The cut of large emitting triangles keeps the surface and its emission, the
pieces' triangle shares are a distribution per piece, and the piece pick
(an estimate × a learned factor, with a uniform share) leaves every reading
unbiased: against Lambert's formula per triangle (the analytic method) on a
stage with nothing to block, and against the same emitters as RectLights on
the office.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from simulator.config import load_config
from simulator.engine.driver import Engine
from simulator.plan.planner import make_plan
from simulator.scene.emitters import MAX_PIECES, emitter_pieces, split_emitters
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage
from simulator.scene.vectors import cross3

ROOT = Path(__file__).resolve().parents[1]

#: a 5 m × 3 m emitting quad facing down (cut into pieces) and a small tilted
#: two-sided one beside it (its own prim); black, and placed so that neither
#: hides the other from the receivers below (the analytic sum sees no occluder)
TWO_EMITTERS = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def Mesh "Big" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 3, 2, 1]
        point3f[] points = [(-2.5, -1.5, 2), (2.5, -1.5, 2), (2.5, 1.5, 2), (-2.5, 1.5, 2)]
        uniform bool doubleSided = 0
        rel material:binding = </World/Looks/Glow>
    }
    def Mesh "Small" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 3, 2, 1]
        point3f[] points = [(3.3, -0.2, 1.2), (3.7, -0.2, 1.0), (3.7, 0.2, 1.0), (3.3, 0.2, 1.2)]
        uniform bool doubleSided = 1
        rel material:binding = </World/Looks/Bright>
    }
    def Scope "Looks"
    {
        def Material "Glow"
        {
            token outputs:surface.connect = </World/Looks/Glow/Surface.outputs:surface>
            def Shader "Surface"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0, 0, 0)
                color3f inputs:emissiveColor = (50, 50, 50)
                token outputs:surface
            }
        }
        def Material "Bright"
        {
            token outputs:surface.connect = </World/Looks/Bright/Surface.outputs:surface>
            def Shader "Surface"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0, 0, 0)
                color3f inputs:emissiveColor = (900, 900, 900)
                token outputs:surface
            }
        }
    }
}
"""


def _areas(points, tris):
    p = points[tris]
    cr = cross3(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    return 0.5 * np.linalg.norm(cr, axis=1), cr


def test_cut_keeps_the_surface_and_its_emission(tmp_path):
    """Each emitting triangle longer than 1 m becomes m² sub-triangles of
    equal area summing to its own, facing the same way, with its emission,
    albedo and prim; triangles that do not emit are left as they are."""
    path = tmp_path / "two.usda"
    path.write_text(TWO_EMITTERS)
    g = load_stage(path).geometry
    s, orig = split_emitters(g)
    assert s.n_triangles > g.n_triangles and len(orig) == s.n_triangles
    a0, n0 = _areas(g.points, g.triangles)
    a1, n1 = _areas(s.points, s.triangles)
    np.testing.assert_allclose(np.bincount(orig, a1, minlength=g.n_triangles), a0, rtol=1e-12)
    unit0 = n0 / np.linalg.norm(n0, axis=1, keepdims=True)
    unit1 = n1 / np.linalg.norm(n1, axis=1, keepdims=True)
    np.testing.assert_allclose(unit1, unit0[orig], atol=1e-12)
    for name in ("emission", "albedo", "two_sided", "prim"):
        np.testing.assert_array_equal(getattr(s, name), getattr(g, name)[orig])
    edge = np.max(np.linalg.norm(s.points[s.triangles] - np.roll(s.points[s.triangles], 1, axis=1), axis=2), axis=1)
    assert edge.max() <= 1.0 + 1e-9


def test_pieces_are_compact_and_their_shares_distributions(tmp_path):
    """At most MAX_PIECES pieces, each of one prim here, its triangles' shares
    summing to 1 and ∝ their power; every emitting triangle in exactly one."""
    path = tmp_path / "two.usda"
    path.write_text(TWO_EMITTERS)
    s, _ = split_emitters(load_stage(path).geometry)
    pc = emitter_pieces(s)
    assert 2 < pc.n <= MAX_PIECES
    assert sorted(pc.tris.tolist()) == np.flatnonzero(np.any(s.emission > 0, axis=1)).tolist()
    for k in range(pc.n):
        sl = slice(pc.first[k], pc.first[k] + pc.count[k])
        assert pc.prob[sl].sum() == pytest.approx(1.0, abs=1e-12)
        assert len(np.unique(s.prim[pc.tris[sl]])) == 1
        a, _ = _areas(s.points, s.triangles[pc.tris[sl]])
        np.testing.assert_allclose(pc.prob[sl], a / a.sum(), rtol=1e-9)  # uniform emission: ∝ area
    assert emitter_pieces(s, cap=1).n == 1  # capped at one: every triangle ∝ its power, as before pieces


@pytest.mark.parametrize("method", ["light", "mis", "path"])
def test_piece_pick_reads_lamberts_formula(tmp_path, method):
    """Receivers under and beside the two emitters (one facing away from the
    small one, one tilted so the big one straddles its horizon) read the
    analytic sum of Lambert's formula per triangle within 4 standard errors
    with the pieces picked (their factors learnt by the pilot first)."""
    path = tmp_path / "two.usda"
    path.write_text(TWO_EMITTERS)
    scene = load_stage(path)
    spots = [((0, 0, 0), (0, 0, 1)), ((2, 0.5, 0.3), (0, 0, 1)), ((3.5, 0, 0.5), (0, 0, 1)),
             ((-2, -1, 1.0), (0.7, 0, 0.714)), ((3.0, 0, 1.6), (0, 0, -1)), ((3.5, 1, 1.5), (-0.6, 0, 0.8))]
    sensors = [Sensor(name=f"s{i}", kind=SensorKind.IRRADIANCE, position=np.array(p, float),
                      normal=np.array(n, float) / np.linalg.norm(n)) for i, (p, n) in enumerate(spots)]  # fmt: skip
    eng = Engine(scene, sensors)
    eng.emitter_pieces = True  # the pieces' pick itself, whatever the pilot would choose
    truth = eng.run("analytic", samples=0, seed=0).mean
    res = eng.run(method, samples=1 << 13, seed=7)
    assert eng._dev.pieces.n > 2 and eng.piece_factors is not None
    assert (truth[:, 0] > 0).sum() >= 5
    err = np.abs(res.mean - truth)
    assert np.all(err <= 4 * res.stderr + 2e-6 * np.abs(truth)), (res.mean, truth, res.stderr)


def test_office_window_emitter_is_sampled_where_the_room_sees_it(monkeypatch):
    """On stages/office_emissive.usda (a 5 m × 3 m window emitter behind a
    2.8 m × 1.4 m opening, six emissive diffusers) the pieces, picked by
    their estimate × learned visibility, read the direct light of 12
    work-plane sensors with less than half the relative variance per sample
    of one piece (each triangle ∝ its power, which sends most samples to the
    window, most of it hidden); both equal the same emitters as RectLights
    (office_rect_twin.usda) within 4 combined standard errors."""
    from simulator.scene import emitters

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    sensors = list(cfg.sensors)[::122]
    em = load_stage(ROOT / "stages" / "office_emissive.usda")
    tw = load_stage(ROOT / "stages" / "office_rect_twin.usda")
    eng = Engine(em, sensors)
    r_em = eng.run("light", samples=4096, seed=2)
    assert eng._dev.pieces.n > 6 and eng.piece_factors is not None
    monkeypatch.setattr(emitters, "MAX_PIECES", 1)
    one = Engine(em, sensors)
    r_one = one.run("light", samples=4096, seed=2)
    assert one._dev.pieces.n == 1
    r_tw = Engine(tw, sensors).run("light", samples=4096, seed=2)

    def relvar(r):
        return np.mean(r.stderr[:, 1] ** 2 * r.samples / r.mean[:, 1] ** 2)

    assert relvar(r_one) > 2 * relvar(r_em), (relvar(r_one), relvar(r_em))
    for r in (r_em, r_one):
        se = np.hypot(r.stderr, r_tw.stderr)
        assert np.all(np.abs(r.mean - r_tw.mean) <= 4 * se + 1e-6 * np.abs(r_tw.mean)), (r.mean, r_tw.mean, se)


@pytest.mark.parametrize("seed", [7, 8])
def test_furnace_cuts_its_walls_without_cutting_its_triangles_and_reads_its_closed_form(seed):
    """The furnace (configs/furnace.toml, ρ = 0.95: every wall emits L_e = 1 W m⁻² sr⁻¹ and is seen
    whole from everywhere inside): its 12 emitting triangles are cut into 264 elements in up to
    MAX_PIECES pieces, but only for sampling: the device keeps the stage's 12 triangles, so the cut
    adds nothing to the hierarchy every ray traverses (it did, when the triangles themselves were cut:
    2× the CPU per sample). Whichever the pieces' choice, every irradiance sensor reads π·L_e/(1 − ρ) =
    20π W/m² (closed_forms.furnace_irradiance; docs/REFERENCES.md §Furnace) and the radiance meter
    L_e/(1 − ρ), within 4 standard errors (+ float32 slack)."""
    from simulator.pipeline import collect_sensors, load_scene
    from simulator.reference import closed_forms as cf

    cfg = load_config(ROOT / "configs" / "furnace.toml")
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind in (SensorKind.IRRADIANCE, SensorKind.RADIANCE)]
    eng = Engine(scene, sensors)
    res = eng.run("path", samples=4096, seed=seed)
    pilot = eng.pieces_pilot
    assert pilot is not None and pilot["pieces"] > 1 and pilot["elements"] == 264, pilot
    assert eng._dev.rec.tris.shape[0] == 3 * scene.geometry.n_triangles
    assert (eng._dev.pieces.n > 1) == pilot["kept"]
    rho = float(scene.geometry.albedo[0])
    for ch in (0, 1):
        le = float(scene.geometry.emission[0, ch])
        for i, s in enumerate(sensors):
            truth = cf.furnace_radiance(le, rho) if s.kind == SensorKind.RADIANCE else cf.furnace_irradiance(le, rho)
            bound = 4 * res.stderr[i, ch] + 2e-6 * truth
            assert abs(res.mean[i, ch] - truth) <= bound, (s.name, ch, res.mean[i], truth)


def test_office_keeps_its_pieces_and_reads_its_twin():
    """The emissive office (a window emitter its wall mostly hides, six diffusers) keeps its pieces
    under path tracing: the pilot predicts one piece would have at least PIECES_MIN_GAIN times their
    relative variance (measured 2.2; 3.0 in a run). Its path readings of 12 work-plane sensors equal
    the same emitters as RectLights (office_rect_twin.usda) within 4 combined standard errors."""
    from simulator.scene import emitters

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    sensors = list(cfg.sensors)[::122]
    eng = Engine(load_stage(ROOT / "stages" / "office_emissive.usda"), sensors)
    r_em = eng.run("path", samples=512, seed=3)
    pilot = eng.pieces_pilot
    assert pilot is not None and pilot["kept"] and pilot["predicted_gain"] >= emitters.PIECES_MIN_GAIN, pilot
    assert eng._dev.pieces.n > 6
    r_tw = Engine(load_stage(ROOT / "stages" / "office_rect_twin.usda"), sensors).run("path", samples=512, seed=3)
    se = np.hypot(r_em.stderr, r_tw.stderr)
    assert np.all(np.abs(r_em.mean - r_tw.mean) <= 4 * se + 1e-6 * np.abs(r_tw.mean)), (r_em.mean, r_tw.mean, se)


def test_plan_names_the_pieces(tmp_path):
    """``probesim plan``'s light-sampling line says how emissive geometry is sampled."""
    path = tmp_path / "two.usda"
    path.write_text(TWO_EMITTERS)
    scene = load_stage(path)
    s = Sensor(name="a", kind=SensorKind.IRRADIANCE, position=np.zeros(3), normal=np.array([0.0, 0, 1]))
    plan = make_plan(scene, [s], "mis", "total")
    line = plan.light_sampling["mis"]
    assert "emissive geometry" in line and "pieces" in line and "visibility a pilot learns" in line


def test_split_emitters_keeps_every_per_triangle_array_aligned():
    """Every per-triangle array of the geometry follows the cut: an array of length T before the split
    has the split's length after it, holding the value of the triangle each piece came from (a surface
    row or solid side left at the old length sent the kernels past the end of the array)."""
    from dataclasses import fields

    from simulator.scene.emitters import split_emitters
    from simulator.scene.model import Geometry

    pts = np.array([[0, 0, 0], [4, 0, 0], [0, 3, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1]], float)
    tris = np.array([[0, 1, 2], [3, 4, 5]], np.int32)
    g = Geometry(points=pts, triangles=tris, albedo=np.array([0.5, 0.3]), emission=np.array([[1.0, 1.0], [0.0, 0.0]]),
                 two_sided=np.array([False, True]), prim=np.array([0, 1], np.int32), prim_names=["a", "b"],
                 albedo_rgb=np.array([[0.5] * 3, [0.3] * 3]), reflectance_id=np.array([-1, -1], np.int32),
                 emission_rgb=np.ones((2, 3)), surface_id=np.array([0, -1], np.int32),
                 solid_side=np.array([1, 0], np.int8))
    split, orig = split_emitters(g, 1.0)
    assert split.n_triangles > g.n_triangles
    for f in fields(Geometry):
        a = getattr(g, f.name)
        if f.name in ("points", "triangles") or not isinstance(a, np.ndarray) or len(a) != g.n_triangles:
            continue
        b = getattr(split, f.name)
        assert b is not None and len(b) == split.n_triangles, f.name
        np.testing.assert_array_equal(b, a[orig], err_msg=f.name)
