"""Glossy and metal faces traced: the UsdPreviewSurface BSDF at path vertices, radiance meters and sensors.

Closed forms: a face of BSDF f under a uniform sky of luminance L reflects
toward wo the radiance L·A(wo), A(wo) = ∫ f(wi, wo) cosθ_i dω its
directional albedo (the quadrature of simulator.reference.microfacet, an
implementation independent of the kernels); a down-facing irradiance sensor
above it reads 2πL ∫₀¹ A(μ) μ dμ. A perfect mirror (metallic 1, roughness 0,
white) reflects the sky exactly. Monte Carlo readings within 4 standard
errors at fixed seeds (and 1%).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from simulator.reference.microfacet import directional_albedo, preview_lobes
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage
from tests.test_surfaces import DOME, L_DOME, material, quad, run, stage

GLOSSY = [  # (roughness, metallic, rho, clearcoat)
    (0.3, 1.0, 0.9, 0.0),
    (0.4, 0.0, 0.5, 0.0),
    (0.6, 0.0, 0.3, 1.0),
]


def _floor(rough, metal, rho, coat):
    extra = f"float inputs:roughness = {rough}\n        float inputs:metallic = {metal}"
    if coat:
        extra += f"\n        float inputs:clearcoat = {coat}\n        float inputs:clearcoatRoughness = 0.2"
    return material("F", extra, rho=rho) + quad("Floor", 0.0, "F", half=1e4) + DOME


def _lobes(rough, metal, rho, coat):
    return preview_lobes(rho, rough, metal, 1.5, None, coat, 0.2)


@pytest.mark.parametrize("case", GLOSSY, ids=["metal", "dielectric", "clearcoat"])
@pytest.mark.parametrize("zenith", [0.0, 60.0])
@pytest.mark.parametrize("method", ["path", "mis"])
def test_meter_sees_the_sky_reflected_by_the_bsdf(tmp_path, case, zenith, method):
    """A radiance meter looking down at a glossy floor at θ under a uniform sky: L·A(cos θ)."""
    t = math.radians(zenith)
    meter = [Sensor(name="m", kind=SensorKind.RADIANCE, position=np.array([0.0, 0.0, 1.0]),
                    normal=np.array([0.0, math.sin(t), -math.cos(t)]))]
    v, se = run(stage(tmp_path, _floor(*case)), meter, method, 20000)
    truth = L_DOME * directional_albedo(_lobes(*case), math.cos(t))
    assert abs(v[0] - truth) <= min(0.01 * truth, 4 * se[0] + 1e-6 * truth), (v, se, truth)


@pytest.mark.parametrize("case", GLOSSY, ids=["metal", "dielectric", "clearcoat"])
def test_sensor_above_a_glossy_floor(tmp_path, case):
    """A down-facing irradiance sensor 1 m above the floor (light sampling and BSDF directions at the
    floor's vertex, MIS): 2πL ∫ A(μ) μ dμ (Gauss–Legendre, 24 nodes)."""
    sensor = [Sensor(name="d", kind=SensorKind.IRRADIANCE, position=np.array([0.0, 0.0, 1.0]),
                     normal=np.array([0.0, 0.0, -1.0]))]
    v, se = run(stage(tmp_path, _floor(*case)), sensor, "path", 20000)
    x, w = np.polynomial.legendre.leggauss(24)
    mu, w = 0.5 * (x + 1), 0.5 * w
    truth = 2 * math.pi * L_DOME * sum(wk * mk * directional_albedo(_lobes(*case), mk, 256, 128)
                                       for mk, wk in zip(mu, w))
    assert abs(v[0] - truth) <= min(0.01 * truth, 4 * se[0] + 1e-6 * truth), (v, se, truth)


@pytest.mark.parametrize("zenith", [0.0, 45.0])
def test_perfect_mirror_reflects_the_sky_exactly(tmp_path, zenith):
    """metallic 1, roughness 0, white: a delta lobe of reflectance 1, so the meter reads L exactly."""
    t = math.radians(zenith)
    meter = [Sensor(name="m", kind=SensorKind.RADIANCE, position=np.array([0.0, 0.0, 1.0]),
                    normal=np.array([0.0, math.sin(t), -math.cos(t)]))]
    v, se = run(stage(tmp_path, _floor(0.0, 1.0, 1.0, 0.0)), meter, "path", 256)
    assert abs(v[0] - L_DOME) <= 2e-6 * L_DOME and se[0] == 0.0


def test_glossy_face_is_a_surface_row_and_the_plan_says_so(tmp_path):
    """roughness authored away from 0.5: the face gets the BSDF (a row), named in the plan; its inputs
    are no longer counted as ignored."""
    from simulator.plan.planner import make_plan

    scene = load_stage(stage(tmp_path, _floor(0.3, 1.0, 0.9, 0.0)))
    row = scene.geometry.surfaces[0]
    assert row.glossy and not row.pane and row.modelled
    assert not any("inputs:roughness" in w for w in scene.warnings)
    plan = make_plan(scene, [Sensor(name="d", kind=SensorKind.IRRADIANCE, position=np.array([0.0, 0.0, 1.0]),
                                    normal=np.array([0.0, 0.0, -1.0]))])
    assert any("GGX specular (roughness 0.3)" in l and "metallic 1" in l for l in plan.surfaces), plan.surfaces


POINT = 'def SphereLight "Lamp"\n{\n    float inputs:intensity = 100\n    float inputs:radius = 0.1\n    bool treatAsPoint = 1\n    float3 xformOp:translate = (0, 0, 2)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n'


def test_perfect_mirror_under_a_point_light_adds_its_image(tmp_path):
    """A white perfect mirror (metallic 1, roughness 0) 2 m below a point light of intensity I; a
    sensor 1 m above the mirror, 0.5 m aside, facing down: it sees only the image source 2 m below
    the mirror, E = I cos θ / d² exactly (the lamp itself is behind it). Light reflected on the way:
    the methods that follow bounces read it (``light`` reads direct light only), and the plan picks one."""
    from simulator.engine.driver import Engine
    from simulator.plan.planner import make_plan

    body = material("Mirror", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=1.0)
    body += quad("Floor", 0.0, "Mirror", half=50) + POINT
    scene = load_stage(stage(tmp_path, body))
    x = np.array([0.5, 0.0, 1.0])
    sensor = [Sensor(name="d", kind=SensorKind.IRRADIANCE, position=x, normal=np.array([0.0, 0.0, -1.0]))]
    method = make_plan(scene, sensor).sensors[0].method
    assert method == "path"
    res = Engine(scene, sensor).run(method, samples=64, seed=3)
    intensity = scene.lights[0].emission[1]  # cd, as read (π r² L for a point-treated sphere)
    image = np.array([0.0, 0.0, -2.0])
    d = x - image
    truth = intensity * (d[2] / np.linalg.norm(d)) / float(d @ d)
    assert abs(res.mean[0, 1] - truth) <= 2e-6 * truth, (res.mean[0, 1], truth)


def _wall_mirror(name: str, x: float) -> str:
    """A vertical square mirror in the plane x = const, bound to /Mirror."""
    return f"""
def Mesh "{name}"
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [({x}, -1, 0.5), ({x}, 1, 0.5), ({x}, 1, 2.5), ({x}, -1, 2.5)]
    rel material:binding = </Mirror>
}}
"""


def test_light_off_two_mirrors_is_named_not_silently_dropped(tmp_path):
    """The image-source connection reads a delta light one reflection deep. Two mirror planes facing
    each other (a floor mirror and a wall mirror) under a point light: the light reflected by both in
    turn is missing from every reading, so the summary names it; one mirror plane, or an area light
    (found through any number of mirrors by the paths' reflections), gives no such line."""
    mirror = material("Mirror", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=1.0)
    one = load_stage(stage(tmp_path, mirror + quad("Floor", 0.0, "Mirror", half=5) + POINT, "one.usda"))
    assert not any("two mirrors" in w for w in one.warnings), one.warnings
    two = load_stage(stage(tmp_path, mirror + quad("Floor", 0.0, "Mirror", half=5) + _wall_mirror("Wall", 1.5)
                           + POINT, "two.usda"))
    said = [w for w in two.warnings if "two mirrors" in w]
    assert len(said) == 1 and "/Lamp" in said[0] and "2 mirror planes" in said[0], two.warnings
    area = POINT.replace("bool treatAsPoint = 1", "bool treatAsPoint = 0")
    lit = load_stage(stage(tmp_path, mirror + quad("Floor", 0.0, "Mirror", half=5) + _wall_mirror("Wall", 1.5)
                           + area, "area.usda"))
    assert not any("two mirrors" in w for w in lit.warnings), lit.warnings


def test_office_window_variants():
    """stages/office.usda: ``window = open`` (the default) is all matte, as office_bench's stored
    reference reads it; ``glazed`` adds one clear pane in the opening and a semi-gloss floor."""
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    open_ = load_stage(root / "stages" / "office.usda", light_units="photometric")
    assert open_.geometry.surface_id is None
    glazed = load_stage(root / "stages" / "office.usda", light_units="photometric", variants={"window": "glazed"})
    g = glazed.geometry
    rows = {g.prim_names[g.prim[t]]: g.surfaces[g.surface_id[t]] for t in range(g.n_triangles) if g.surface_id[t] >= 0}
    assert set(rows) == {"/Office/Room/Pane", "/Office/Room/Floor"}
    assert rows["/Office/Room/Pane"].pane and rows["/Office/Room/Pane"].ior == pytest.approx(1.52)
    assert rows["/Office/Room/Floor"].glossy and rows["/Office/Room/Floor"].roughness == pytest.approx(0.4)
    assert g.n_triangles == open_.geometry.n_triangles + 2


def test_mirror_reflector_example_adds_the_lamps_image(tmp_path):
    """configs/mirror_reflector.toml: under the lamp the floor reads at least the direct I/h² plus the
    polished reflector's image 0.9·I/(2.5 m)² (interreflection only adds), within 4σ."""
    from pathlib import Path

    from simulator.engine.driver import Engine

    root = Path(__file__).resolve().parents[1]
    scene = load_stage(root / "stages" / "mirror_reflector.usda", light_units="photometric")
    s = [Sensor(name="u", kind=SensorKind.IRRADIANCE, position=np.zeros(3), normal=np.array([0.0, 0.0, 1.0]))]
    res = Engine(scene, s).run("path", samples=512, seed=2)
    intensity = scene.lights[0].emission[1]
    assert intensity == pytest.approx(1000.0, rel=1e-4)
    floor = intensity / 1.5 ** 2 + 0.9 * intensity / 2.5 ** 2
    assert res.mean[0, 1] >= floor - 4 * res.stderr[0, 1]
    # and the interreflection it adds is small: a 0.2 floor reflecting into a 1.2 m mirror
    assert res.mean[0, 1] <= 1.1 * floor
