"""Next-event estimation by one picked light per vertex (kernels.light_pick).

The pick draws light li with probability P(li | x) = (1 − α)·w/Σw + α·c/Σc
and divides its sample by P; multiple importance sampling then uses the
strategy's density P(li | x)·pdf_light in the light sample's weight and in
the weight of a cosine direction that hits a light. So:

- the sampler and :func:`pick_probability` are twins: the drawn lights follow
  P (chi-square), P sums to one over the lights, delta lights are never
  picked (they are sampled at every vertex) and every light that can reach
  the vertex keeps P ≥ α/Σc whatever its learned factor;
- readings with the pick equal the closed forms within 4 standard errors
  for light, mis and path, on a stage with lights of every kind that has a
  closed form, on emissive triangles with lamps, and on the registry's
  two-light cases (hdr: a 1e5 W/m² sun and a 1 W/m² lamp; leak: lamps and an
  emissive quad in trays, truth 0), also with factors that starve a light;
- a wrong MIS density (pdf_light not multiplied by P in either weight) would
  bias mis against the closed form, which light, bsdf and mis agree on.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import warp as wp
from scipy import stats

from simulator.commands.verify import expected_values
from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.kernels.light_pick import PICK_UNIFORM, pick_light, pick_probability
from simulator.kernels.lights import SceneRec
from simulator.pipeline import collect_sensors, load_scene
from simulator.reference.cases import case
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

wp.set_module_options({"enable_backward": False})

FLOAT32_SLACK = 2e-6
CONFIGS = Path(__file__).resolve().parents[1] / "configs"

#: lights of every kind with a closed form (and a point light, which is never
#: picked), nothing that could block them: the analytic method's sum is the truth
MANY_LIGHTS = """
def Xform "World"
{
    def RectLight "Panel"
    {
        float inputs:intensity = 20
        bool inputs:normalize = 0
        float inputs:width = 1.2
        float inputs:height = 0.6
        double3 xformOp:translate = (0.3, 0.1, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Ball"
    {
        float inputs:intensity = 300
        bool inputs:normalize = 0
        float inputs:radius = 0.1
        double3 xformOp:translate = (-1, 0.5, 1.5)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def DiskLight "Disc"
    {
        float inputs:intensity = 100
        bool inputs:normalize = 0
        float inputs:radius = 0.25
        double3 xformOp:translate = (0.5, -1, 1.8)
        float3 xformOp:rotateXYZ = (20, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
    }
    def DistantLight "Sun"
    {
        float inputs:angle = 4
        float inputs:intensity = 50
        bool inputs:normalize = 1
        float3 xformOp:rotateXYZ = (0, 40, 0)
        uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
    }
    def DomeLight "Sky"
    {
        float inputs:intensity = 2
    }
    def SphereLight "Bulb"
    {
        float inputs:intensity = 40
        bool inputs:normalize = 1
        float inputs:radius = 0.05
        bool treatAsPoint = 1
        double3 xformOp:translate = (1, 1, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""

#: two emissive quads (front faces down) beside a rect lamp and a sphere; the
#: receivers below them cannot see one emitter past another
EMISSIVE = """
def Xform "World"
{
    def RectLight "Panel"
    {
        float inputs:intensity = 20
        bool inputs:normalize = 0
        float inputs:width = 0.5
        float inputs:height = 0.5
        double3 xformOp:translate = (-1, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Ball"
    {
        float inputs:intensity = 300
        bool inputs:normalize = 0
        float inputs:radius = 0.1
        double3 xformOp:translate = (0, -1.2, 1.5)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Mesh "Glow" (
        prepend apiSchemas = ["MeshLightAPI"]
    )
    {
        int[] faceVertexCounts = [4, 4]
        int[] faceVertexIndices = [0, 3, 2, 1, 4, 7, 6, 5]
        point3f[] points = [(0.5, -0.3, 2), (1.1, -0.3, 2), (1.1, 0.3, 2), (0.5, 0.3, 2),
                            (0.2, 0.8, 2.5), (0.4, 0.8, 2.5), (0.4, 1.4, 2.5), (0.2, 1.4, 2.5)]
        float inputs:intensity = 30
        bool inputs:normalize = 0
    }
}
"""


def _stage(tmp_path: Path, body: str) -> Path:
    path = tmp_path / "s.usda"
    path.write_text(f'#usda 1.0\n(\n    upAxis = "Z"\n    metersPerUnit = 1\n)\n\n{body}')
    return path


def _irr(name, p, n):
    n = np.asarray(n, float)
    return Sensor(name, SensorKind.IRRADIANCE, np.asarray(p, float), n / np.linalg.norm(n))


#: receivers facing up, tilted (some lights below their horizon), sideways and down
RECEIVERS = [
    ((0, 0, 0), (0, 0, 1)), ((0.2, -0.3, 0.4), (0.5, -0.2, 1)), ((-0.5, 0.2, 0.8), (-1, 0.3, 0.2)),
    ((0.3, 0.2, 1.2), (0.2, 0.1, -1)), ((0.6, 0.1, 0.3), (0, 1, 0.05)),
]  # fmt: skip


def _engine(tmp_path, body, pick="every"):
    scene = load_stage(_stage(tmp_path, body), light_units="radiometric")
    sensors = [_irr(f"r{i}", p, n) for i, (p, n) in enumerate(RECEIVERS)]
    eng = Engine(scene, sensors)
    eng.light_pick = pick
    return scene, sensors, eng


def _without(scene, drop):
    """A copy of the scene without the lights ``drop(light)`` is true for."""
    import dataclasses

    return dataclasses.replace(scene, lights=[l for l in scene.lights if not drop(l)])


def _closed_form(eng):
    """Every light's unoccluded closed form summed per receiver (the analytic
    method), except that a disk wholly below a receiver's horizon adds 0: the
    disk's contour integral holds only wholly above it, and the stages here
    have no receiver whose horizon a disk straddles."""
    import dataclasses

    from simulator.scene.model import LightKind

    disks = [l for l in eng.scene.lights if l.kind == LightKind.DISK]
    others = Engine(_without(eng.scene, lambda l: l.kind == LightKind.DISK), eng.sensors)
    total = others.run("analytic", samples=1, seed=1).mean
    for d in disks:
        part = Engine(dataclasses.replace(eng.scene, lights=[d]), eng.sensors).run("analytic", samples=1, seed=1).mean
        for i, s in enumerate(eng.sensors):
            ex, ey = d.frame[:, 0], d.frame[:, 1]
            h = (d.position - s.position) @ s.normal
            r = d.radius * np.hypot(ex @ s.normal, ey @ s.normal)
            assert h - r > 0 or h + r <= 0, f"{s.name}: a disk straddles the horizon"
            if h - r > 0:
                total[i] += part[i]
    return total


def _within(res, truth, k=4.0):
    bound = k * res.stderr + FLOAT32_SLACK * np.abs(truth) + 1e-9
    return np.abs(res.mean - truth) <= bound


# ----------------------------------------------------------------------------- the sampler and its pdf


@wp.kernel
def k_draw(scene: SceneRec, p: wp.vec3, n: wp.vec3, depth: int, seed: int, li: wp.array(dtype=int), prob: wp.array(dtype=float),
           twin: wp.array(dtype=float)):  # fmt: skip
    t = wp.tid()
    pk = pick_light(scene, p, n, -1, depth, wp.rand_init(seed, t))
    li[t] = pk.li
    prob[t] = pk.prob
    twin[t] = wp.where(pk.li >= 0, pick_probability(scene, pk, wp.max(pk.li, 0), p, n, -1, depth), -1.0)


@wp.kernel
def k_pdf(scene: SceneRec, p: wp.vec3, n: wp.vec3, depth: int, out: wp.array(dtype=float)):
    li = wp.tid()
    pk = pick_light(scene, p, n, -1, depth, wp.rand_init(1, 0))
    out[li] = pick_probability(scene, pk, li, p, n, -1, depth)


def _draws(eng, p, n, count=200_000, seed=5):
    rec = eng.scene_rec
    n_l = int(rec.n_lights)
    li, prob, twin, pdf = (wp.zeros(count, dtype=int), wp.zeros(count, dtype=float), wp.zeros(count, dtype=float),
                           wp.zeros(n_l, dtype=float))  # fmt: skip
    wp.launch(k_draw, dim=count, inputs=[rec, wp.vec3(*p), wp.vec3(*n), 1, seed], outputs=[li, prob, twin], device="cpu")
    wp.launch(k_pdf, dim=n_l, inputs=[rec, wp.vec3(*p), wp.vec3(*n), 1], outputs=[pdf], device="cpu")
    return li.numpy(), prob.numpy(), twin.numpy(), pdf.numpy().astype(np.float64)


@pytest.mark.parametrize("factors", ["ones", "skewed"])
def test_pick_sampler_and_pdf_are_twins(tmp_path, factors):
    """At a tilted vertex of the many-lights stage (rect, sphere, disk, cone
    sun, dome, point), 200,000 picks follow pick_probability: chi-square p >
    1e-3 over the lights with P > 0; each draw's own P equals the twin's to
    float32 precision; P sums to 1; the point light (delta) is never picked
    (its P reads 1: it is sampled at every vertex);
    and with skewed factors (one light's 0, another's 50) every light that can
    reach the vertex keeps P ≥ α/Σc — the uniform share that keeps a light a
    pilot saw blocked from being starved."""
    scene, _, eng = _engine(tmp_path, MANY_LIGHTS)
    n_l = len(scene.lights)
    if factors == "skewed":
        f = np.ones((1 + len(RECEIVERS), n_l))
        f[0, 0] = 0.0  # the rect: a pilot saw it blocked
        f[0, 1] = 50.0
        eng.fix_pick_factors(f)
    else:
        eng.fix_pick_factors(np.ones((1 + len(RECEIVERS), n_l)))
    p, n = (0.2, -0.3, 0.4), tuple(np.array((0.5, -0.2, 1.0)) / np.linalg.norm((0.5, -0.2, 1.0)))
    li, prob, twin, pdf = _draws(eng, p, n)
    assert np.all(li >= 0)
    point = [i for i, l in enumerate(scene.lights) if l.is_delta]
    assert point and np.all(pdf[point] == 1.0) and not np.isin(li, point).any()  # sampled at every vertex instead
    pdf[point] = 0.0
    assert pdf.sum() == pytest.approx(1.0, abs=1e-5)
    np.testing.assert_allclose(prob, twin, rtol=1e-5)
    np.testing.assert_allclose(prob, pdf[li], rtol=1e-5)
    can = pdf > 0
    assert can.sum() >= 4
    assert np.all(pdf[can] >= PICK_UNIFORM / can.sum() * (1 - 1e-5))
    counts = np.bincount(li, minlength=n_l)[can]
    chi = stats.chisquare(counts, pdf[can] / pdf[can].sum() * len(li))
    assert chi.pvalue > 1e-3, (counts, pdf)


# ----------------------------------------------------------------------------- readings equal closed forms


@pytest.mark.parametrize("method", ["light", "mis", "path"])
@pytest.mark.parametrize("body", ["many", "emissive"])
def test_picked_nee_matches_closed_forms(tmp_path, method, body):
    """With one picked light per vertex the readings of every receiver (both
    channels) equal the analytic sum of every light's closed form within 4
    standard errors (fixed seed): the many-lights stage (Lambert's polygon
    formula, spherical caps, the disk contour integral, πL for the dome,
    I·cosξ/d² for the point light) and two emissive quads with a rect lamp and
    a sphere (the quads by Lambert's formula per triangle). Nothing reflects,
    so path reads direct light too."""
    _, _, eng = _engine(tmp_path, MANY_LIGHTS if body == "many" else EMISSIVE)
    truth = _closed_form(eng)
    res = eng.run(method, samples=1 << 13, seed=3)
    assert eng.light_pick_mode(method) == "every"
    assert np.sum(truth[:, 0] > 0) >= 4  # the downward receiver sees no emitter on the emissive stage
    ok = _within(res, truth)
    assert ok.all(), (res.mean, truth, res.stderr)


def test_starved_light_still_reads_its_share(tmp_path):
    """Factors that give the rect and the dome weight 0 everywhere leave them
    only the uniform share α/Σc of the pick: light sampling is then noisier
    for them but still unbiased, the reading within 4σ of the closed form."""
    scene, sensors, eng = _engine(tmp_path, MANY_LIGHTS)
    names = [l.name.rsplit("/", 1)[-1] for l in scene.lights]
    f = np.ones((1 + len(sensors), len(names)))
    f[:, names.index("Panel")] = 0.0
    f[:, names.index("Sky")] = 0.0
    eng.fix_pick_factors(f)
    truth = _closed_form(eng)
    res = eng.run("light", samples=1 << 13, seed=4)
    assert _within(res, truth).all(), (res.mean, truth, res.stderr)


def test_light_bsdf_and_mis_agree_with_the_pick(tmp_path):
    """light (picked), bsdf (no light sampling) and mis (both, weighted by
    the power heuristic with the pick's density P·pdf_light) estimate the same
    irradiance: their weights sum to one only if both weights use the same
    density. Each agrees with the closed form within 4σ at the receivers that
    see the dome and the big rect, where a weight using pdf_light alone (P ≈
    0.2) would put mis ~10% off."""
    _, _, eng = _engine(tmp_path, MANY_LIGHTS)
    truth = _closed_form(eng)
    for m, seed in (("light", 7), ("bsdf", 8), ("mis", 9)):
        res = eng.run(m, samples=1 << 13, seed=seed)
        if m == "bsdf":  # blind to the point light: compare without it
            t = _closed_form(Engine(_without(eng.scene, lambda l: l.is_delta), eng.sensors))
        else:
            t = truth
        assert _within(res, t).all(), (m, res.mean, t, res.stderr)


def test_delta_light_reading_stays_exact(tmp_path):
    """A receiver that only the point light reaches (facing up above the
    rect lamp, which emits down, and above the sphere's top) reads
    I·cosξ/d² exactly, stderr 0, with the pick on: delta lights are sampled at
    every vertex, and no light with area is picked where none can reach. A
    receiver below sees all three (stderr > 0)."""
    body = """
def Xform "World"
{
    def RectLight "Panel"
    {
        float inputs:intensity = 20
        float inputs:width = 1
        float inputs:height = 1
        double3 xformOp:translate = (0, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Ball"
    {
        float inputs:intensity = 300
        float inputs:radius = 0.1
        double3 xformOp:translate = (-1, 0.5, 1.5)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Bulb"
    {
        float inputs:intensity = 40
        bool inputs:normalize = 1
        float inputs:radius = 0.05
        bool treatAsPoint = 1
        double3 xformOp:translate = (1, 1, 3)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""
    scene = load_stage(_stage(tmp_path, body), light_units="radiometric")
    s = [_irr("above", (0.8, 0.9, 2.5), (0.1, 0, 1)), _irr("up", (0, 0, 0), (0, 0, 1))]
    eng = Engine(scene, s)
    eng.light_pick = "every"
    res = eng.run("light", samples=256, seed=2)
    only_point = Engine(scene, s[:1])
    truth = only_point.run("analytic", samples=1, seed=1).mean[0]
    assert res.stderr[0, 0] == 0.0 and res.stderr[0, 1] == 0.0
    np.testing.assert_allclose(res.mean[0], truth, rtol=FLOAT32_SLACK)
    assert res.stderr[1, 0] > 0.0


@pytest.mark.parametrize("name", ["hdr", "leak"])
def test_registry_cases_with_the_pick(name):
    """The registry's two-light cases read their expected values within 4σ
    (and 1%) with the pick forced on: hdr (a 0.53° sun of 1e5 W/m² and a
    1 W/m² sphere lamp on receivers facing up, sideways and with the sun
    straddling the horizon) and leak (rect lamps and an emissive quad 1e-4 m
    above black trays, truth 0 under them)."""
    c = case(name)
    rows = expected_values(c)
    cfg = load_config(CONFIGS / c.config)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    eng = Engine(scene, sensors)
    eng.light_pick = "every"
    for method in ("light", "mis"):
        res = eng.run(method, samples=1 << 13, seed=12)
        for i, (s, ch, truth, _) in enumerate(rows):
            est, se = res.mean[i, ch], res.stderr[i, ch]
            assert abs(est - truth) <= 4 * se + FLOAT32_SLACK * abs(truth) + 1e-9, (method, s.name, est, truth, se)
            assert abs(est - truth) <= 0.01 * abs(truth) + 4 * se + 1e-9


def test_pilot_learns_blocked_lights(tmp_path):
    """The pilot's factor is Σ shadowed value / Σ estimate: a black plate
    between every receiver and the rect leaves the rect's factor at 0 at
    their first vertex, while the unblocked sphere's is 1 (its closed form is
    its unoccluded mean); the readings stay within 4σ of the closed form of
    the sphere alone (the rect is blocked everywhere)."""
    body = """
def Xform "World"
{
    def RectLight "Panel"
    {
        float inputs:intensity = 20
        bool inputs:normalize = 0
        float inputs:width = 0.5
        float inputs:height = 0.5
        double3 xformOp:translate = (0, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Ball"
    {
        float inputs:intensity = 300
        bool inputs:normalize = 0
        float inputs:radius = 0.1
        double3 xformOp:translate = (2, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Mesh "Plate"
    {
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(-5, -5, 1.5), (5, -5, 1.5), (5, 5, 1.5), (-5, 5, 1.5)]
    }
}
"""
    scene = load_stage(_stage(tmp_path, body), light_units="radiometric")
    sensors = [_irr("a", (0, 0, 0), (0, 0, 1)), _irr("b", (0.5, 0.3, 0.2), (0.3, 0, 1))]
    eng = Engine(scene, sensors)
    eng.light_pick = "every"
    res = eng.run("light", samples=1 << 12, seed=3)
    f = eng._dev.rec.pick_factor.numpy().reshape(1 + len(sensors), -1)
    names = [l.name.rsplit("/", 1)[-1] for l in scene.lights]
    assert np.all(f[1:, names.index("Panel")] == 0.0)
    np.testing.assert_allclose(f[1:, names.index("Ball")], 1.0, rtol=0.05)
    truth = Engine(_without(scene, lambda l: l.name.endswith("/Panel")), sensors).run("analytic", samples=1, seed=1).mean
    assert _within(res, truth).all(), (res.mean, truth, res.stderr)


#: a grey floor (ρ = 0.5) under the many-lights stage's receivers: paths
#: bounce, so the pick runs at the vertices past the sensor's
GREY_FLOOR = """
def Xform "Room"
{
    def Mesh "Floor" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(-4, -4, -0.5), (4, -4, -0.5), (4, 4, -0.5), (-4, 4, -0.5)]
        uniform bool doubleSided = 1
        rel material:binding = </Room/Grey>
    }
    def Material "Grey"
    {
        token outputs:surface.connect = </Room/Grey/Surface.outputs:surface>
        def Shader "Surface"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0.5, 0.5, 0.5)
            token outputs:surface
        }
    }
}
"""


@pytest.mark.parametrize("mode", ["after_first", "every"])
def test_paths_with_the_pick_agree_with_every_light(tmp_path, mode):
    """Over a grey floor (ρ = 0.5) the many-lights stage's receivers see
    reflected light (the downward one only that); path with the pick past the
    sensor's vertex (the rule's mode for path) and at every vertex reads what
    path sampling every light reads, within 4 combined standard errors
    (independent seeds): the pick, its MIS weights at the bounce vertices
    (lights hit, the dome escaped to) and the pilot's factors keep paths
    unbiased."""
    scene = load_stage(_stage(tmp_path, MANY_LIGHTS + GREY_FLOOR), light_units="radiometric")
    assert np.any(scene.geometry.albedo > 0.4)
    sensors = [_irr(f"r{i}", p, n) for i, (p, n) in enumerate(RECEIVERS)]
    ref, picked = Engine(scene, sensors), Engine(scene, sensors)
    ref.light_pick = "off"
    picked.light_pick = mode
    assert Engine(scene, sensors).light_pick_mode("path") == "after_first"  # the rule
    a = ref.run("path", samples=1 << 13, seed=21)
    b = picked.run("path", samples=1 << 13, seed=22)
    se = np.hypot(a.stderr, b.stderr)
    assert np.all(np.abs(a.mean - b.mean) <= 4 * se + FLOAT32_SLACK * np.abs(a.mean)), (a.mean, b.mean, se)


def test_plan_says_how_lights_are_sampled():
    """probesim plan names the light sampling of each method it uses and
    why: the office's paths (``exact+guided``, the plan's choice there: eight
    lights with area, the lamps' direct light computed) sample every light at the
    sensor and one picked light after it, with the roulette threshold of its
    albedo; the point stage's direct-light reads sample every light."""
    from simulator.plan.planner import format_plan, make_plan

    for name, method, words in (("office_bench", "exact+guided", "one light at each later vertex"),
                                ("hdr", "light", "every light at each vertex")):  # fmt: skip
        cfg = load_config(CONFIGS / ("stability/hdr.toml" if name == "hdr" else f"{name}.toml"))
        scene = load_scene(cfg)
        sensors = collect_sensors(cfg, scene)
        plan = make_plan(scene, sensors, method if name == "hdr" else "auto")
        assert words in plan.light_sampling[method]
        assert words in format_plan(plan) and plan.to_record()["light_sampling"] == plan.light_sampling
        if method == "exact+guided":  # ρ̄ = 0.23: min(0.1, 0.2·0.77)
            assert "Russian roulette below throughput 0.1:" in plan.light_sampling["exact+guided"]
            assert "the lights whose direct light is computed are left out" in plan.light_sampling["exact+guided"]
