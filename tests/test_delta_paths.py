"""Light of every kind reaching a sensor through a delta surface, against its image-source closed form.

One stage per case: a flat delta surface in the plane z = 0 (unbounded for
the purpose: ±10 km), a light above it at height h = 2 m facing down, and a
sensor at (0, 0, 1) facing down, so the light itself is behind the sensor
and all it reads is the light's mirror image, the light reflected in the
plane (its image at z = −h, distance D = 3 m from the sensor).

Delta surfaces and their reflectance F(μ) at incidence cosine μ:

- **mirror**: metallic 1, roughness 0, diffuseColor ρ = 0.9. UsdPreviewSurface's
  metallic Fresnel has F0 = F90 = ρ, so F = 0.9 at every angle;
- **coat**: a clearcoat of weight 1 at its fallback roughness 0.01 (the
  mirror limit) over a black metal base (metallic 1, diffuseColor 0: F0 =
  F90 = 0, so the base reflects nothing): F = F_c(μ) = 0.04 + 0.96(1 − μ)⁵,
  Schlick's approximation with the coat's fixed F0 = ((1 − 1.5)/(1 + 1.5))²;
- **pane**: a clear slab of ior 1.5 (the datasheet transmittance of a clear
  slab, 2n/(n² + 1)) over a black matte floor at z = −1 that stops what it
  passes: F = R(μ) of the plane-parallel slab, per polarisation and averaged
  (``tests.test_surfaces.slab``, Born & Wolf §1.5).

Image-source closed forms, on the axis (D = 3 m; the sensor's normal points
at the image, so cosθ at the sensor equals the incidence cosine on the
plane, μ):

- point (a sphere treated as a point), intensity I: E = F(1)·I/D²;
- sphere of radius r = 0.2 m and disk of radius 0.2 m, luminance L: both
  subtend a circular cone of half-angle α (sin α = r/D, tan α = r/D):
  E = 2πL ∫₀^α F(cos θ) cos θ sin θ dθ (πL sin²α for a constant F);
- rect 0.4 × 0.4 m, parallel to the plane: E = L ∫∫ F(D/ρ) D²/ρ⁴ dA over
  the image, ρ the distance to the image point;
- distant light of angle 0.53° at zenith 30° (normalised: intensity E⊥):
  E = L·π sin²θ_s·cos 30°·F(cos 30°), F taken at the cone's axis (its
  variation over the 0.27° cone is below 2·10⁻⁴ of F for the coat and the
  pane: the stated relative tolerance);
- dome of luminance L (a down-facing sensor over the plane): E = 2πL ∫₀¹ F(μ) μ dμ.

A radiance meter at the same point, its cone (0.1°) aimed at the image's
centre, reads F(μ)·L (μ = 1, the sun's 30°); a point light has no radiance
to read, so the point light is an irradiance case only.

The quadratures are Gauss–Legendre (64 nodes per dimension), exact to far
below the bounds. Bounds: 4 reported standard errors at a fixed seed plus a
relative 1e-4 (the float32 trace) or 2e-4 (the sun's Fresnel at its axis).

On the tree before the clearcoat's mirror limit, the sun's image source and
panes in the image-source table, 14 of these cases failed: all 11 clearcoat
ones (the coat at 0.01 reflected nothing), the sun at an irradiance sensor
off the mirror and off the pane (read 0), and a point light off the pane.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from simulator.engine.driver import Engine
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.surfaces import clear_slab_transmittance
from simulator.scene.usd import load_stage
from tests.test_surfaces import material, quad, slab, stage

H = 2.0  # the light's height above the plane (m)
Z_SENSOR = 1.0
D = H + Z_SENSOR  # sensor to the image
R_LIGHT = 0.2  # sphere and disk radius (m)
SIDE = 0.4  # rect light side (m)
SUN_ZENITH = 30.0  # degrees
SUN_ANGLE = 0.53  # degrees (apparent diameter)
RHO_MIRROR = 0.9
IOR = 1.5
HALF = 1.0e4  # the plane's half size (m)


def coat_f(mu: float) -> float:
    return 0.04 + 0.96 * (1.0 - mu) ** 5


SURFACES = ("mirror", "coat", "pane")


def reflectance(surface: str, tau: float):
    """F(μ) of a delta surface (module docstring); ``tau`` the pane's internal transmittance as read."""
    if surface == "mirror":
        return lambda mu: RHO_MIRROR
    if surface == "coat":
        return coat_f
    return lambda mu: slab(mu, IOR, tau)[0]


def _surface_body(kind: str) -> str:
    if kind == "mirror":
        return (material("Delta", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=RHO_MIRROR)
                + quad("Plane", 0.0, "Delta", half=HALF))
    if kind == "coat":
        return (material("Delta", "float inputs:metallic = 1\n        float inputs:clearcoat = 1", rho=0.0)
                + quad("Plane", 0.0, "Delta", half=HALF))
    t0 = clear_slab_transmittance(IOR)
    return (material("Delta", f"float probesim:transmittance = {t0!r}\n        float inputs:ior = {IOR}")
            + material("Black", rho=0.0) + quad("Plane", 0.0, "Delta", half=HALF)
            + quad("Floor", -1.0, "Black", half=HALF))


def _xform(z: float) -> str:
    return f'    float3 xformOp:translate = (0, 0, {z})\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n'


LIGHTS = {
    "point": 'def SphereLight "L"\n{\n    float inputs:intensity = 100\n    float inputs:radius = 0.1\n'
             '    bool treatAsPoint = 1\n' + _xform(H) + '}\n',
    "sphere": f'def SphereLight "L"\n{{\n    float inputs:intensity = 100\n    float inputs:radius = {R_LIGHT}\n'
              + _xform(H) + '}\n',
    "disk": f'def DiskLight "L"\n{{\n    float inputs:intensity = 100\n    float inputs:radius = {R_LIGHT}\n'
            + _xform(H) + '}\n',
    "rect": f'def RectLight "L"\n{{\n    float inputs:intensity = 100\n    float inputs:width = {SIDE}\n'
            f'    float inputs:height = {SIDE}\n' + _xform(H) + '}\n',
    "sun": f'def DistantLight "L"\n{{\n    float inputs:intensity = 1000\n    float inputs:angle = {SUN_ANGLE}\n'
           f'    bool inputs:normalize = 1\n    float3 xformOp:rotateXYZ = ({SUN_ZENITH}, 0, 0)\n'
           '    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]\n}\n',
    "dome": 'def DomeLight "L"\n{\n    float inputs:intensity = 100\n}\n',
}


def _gl(n: int = 64):
    x, w = np.polynomial.legendre.leggauss(n)
    return x, w


def _cone(L: float, f, alpha: float) -> float:
    """2πL ∫₀^α F(cos θ) cos θ sin θ dθ."""
    x, w = _gl()
    th = 0.5 * alpha * (x + 1.0)
    return 2.0 * math.pi * L * 0.5 * alpha * float(sum(wk * f(math.cos(t)) * math.cos(t) * math.sin(t)
                                                      for t, wk in zip(th, w)))


def _rect(L: float, f) -> float:
    """L ∫∫ F(D/ρ) D²/ρ⁴ dA over the SIDE × SIDE image, D below its centre."""
    x, w = _gl()
    u = 0.5 * SIDE * x
    tot = 0.0
    for ui, wi in zip(u, w):
        r2 = ui * ui + u * u + D * D
        mu = D / np.sqrt(r2)
        tot += wi * float(np.sum(w * np.array([f(m) for m in mu]) * D * D / (r2 * r2)))
    return L * tot * (0.5 * SIDE) ** 2


def _dome(L: float, f) -> float:
    x, w = _gl()
    mu = 0.5 * (x + 1.0)
    return 2.0 * math.pi * L * 0.5 * float(sum(wk * f(m) * m for m, wk in zip(mu, w)))


def irradiance_truth(light_kind: str, scene, f) -> float:
    light = scene.lights[0]
    L = light.emission[1]
    if light_kind == "point":
        return f(1.0) * L / D ** 2  # emission of a point-treated sphere: its intensity (cd)
    if light_kind == "sphere":
        return _cone(L, f, math.asin(R_LIGHT / D))
    if light_kind == "disk":
        return _cone(L, f, math.atan(R_LIGHT / D))
    if light_kind == "rect":
        return _rect(L, f)
    if light_kind == "sun":
        mu = math.cos(math.radians(SUN_ZENITH))
        return L * math.pi * math.sin(light.half_angle) ** 2 * mu * f(mu)
    return _dome(L, f)


def radiance_truth(light_kind: str, scene, f) -> float:
    mu = math.cos(math.radians(SUN_ZENITH)) if light_kind == "sun" else 1.0
    return f(mu) * scene.lights[0].emission[1]


def _meter_axis(light_kind: str, scene) -> np.ndarray:
    if light_kind != "sun":
        return np.array([0.0, 0.0, -1.0])
    to_sun = scene.lights[0].frame[:, 2]
    return np.array([to_sun[0], to_sun[1], -to_sun[2]])  # toward the sun's image in the plane


SAMPLES = {"irradiance": 16384, "radiance": 4096}
CASES = [(lk, sk, dk) for dk in SURFACES for lk in LIGHTS for sk in ("irradiance", "radiance")
         if not (lk == "point" and sk == "radiance")]


def assert_reads_its_image(scene, light_kind: str, sensor_kind: str, f) -> None:
    """The sensor at (0, 0, 1) reads the image-source closed form of reflectance ``f`` (module docstring):
    within 4 reported standard errors at seed 11, plus 1e-4 relative (2e-4 for the sun's Fresnel at its axis)."""
    pos = np.array([0.0, 0.0, Z_SENSOR])
    if sensor_kind == "irradiance":
        sensor = Sensor(name="s", kind=SensorKind.IRRADIANCE, position=pos, normal=np.array([0.0, 0.0, -1.0]))
        truth = irradiance_truth(light_kind, scene, f)
    else:
        sensor = Sensor(name="s", kind=SensorKind.RADIANCE, position=pos, normal=_meter_axis(light_kind, scene),
                        half_angle=math.radians(0.1))
        truth = radiance_truth(light_kind, scene, f)
    res = Engine(scene, [sensor]).run("path", samples=SAMPLES[sensor_kind], seed=11)
    v, se = float(res.mean[0, 1]), float(res.stderr[0, 1])
    rel = 2e-4 if light_kind == "sun" else 1e-4
    assert abs(v - truth) <= 4.0 * se + rel * truth, (v, se, truth)


@pytest.mark.parametrize("light_kind, sensor_kind, surface", CASES,
                         ids=[f"{d}-{l}-{s}" for l, s, d in CASES])
def test_light_reaches_the_sensor_through_a_delta_surface(tmp_path, light_kind, sensor_kind, surface):
    """Each light kind × sensor kind × delta surface reads its image-source closed form (module docstring)."""
    scene = load_stage(stage(tmp_path, _surface_body(surface) + LIGHTS[light_kind]))
    tau = 1.0
    if surface == "pane":
        row = scene.geometry.surfaces[int(scene.geometry.surface_id[0])]
        assert row.pane and row.ior == pytest.approx(IOR) and row.tau > 0.999
        tau = row.tau
    f = reflectance(surface, tau)
    assert_reads_its_image(scene, light_kind, sensor_kind, f)


# --------------------------------------------------------------------------- #
# the mirror planes (curved mirrors: tests/test_curved_mirrors.py)
# --------------------------------------------------------------------------- #


def test_mirror_clearcoat_is_a_mirror_plane(tmp_path):
    """A clearcoat at its fallback roughness (0.01, the mirror limit) is a delta lobe: its row says so in
    the plan's words and its faces are image-source planes (simulator.scene.surfaces.mirror_planes)."""
    from simulator.scene.surfaces import mirror_planes

    g = load_stage(stage(tmp_path, _surface_body("coat") + LIGHTS["point"])).geometry
    row = g.surfaces[int(g.surface_id[0])]
    assert row.delta_coat and not row.delta_base and row.delta
    assert any("clearcoat 1 (mirror)" in l for l in row.lobes()), row.lobes()
    planes, face_plane, _ = mirror_planes(g.points, g.triangles, g.surface_id, g.surfaces)
    assert len(planes) == 1 and np.all(face_plane == 0)


def test_mirror_under_a_lamp_and_a_globe_reads_both_images(tmp_path):
    """A point lamp and a sphere light (a globe) side by side over the mirror, both behind the
    down-facing sensor: it reads the lamp's image F·I/D² (the image source, exact) plus the globe's,
    πL·F·sin²α about its own axis, off the axis by 0.5 m: E = L·F·∫ cosθ dω over the globe's image cone,
    here by the cap formula E = πL sin²α · cos β for a cone wholly above the horizon (β its axis's angle
    from the normal). Bound: 4σ at a fixed seed, and 1e-4."""
    lamp = LIGHTS["point"].replace('"L"', '"Lamp"')
    globe = LIGHTS["sphere"].replace('"L"', '"Globe"').replace("(0, 0, 2.0)", "(0.5, 0, 2.0)")
    scene = load_stage(stage(tmp_path, _surface_body("mirror") + lamp + globe))
    by_name = {l.name.rsplit("/", 1)[-1]: l for l in scene.lights}
    assert by_name["Globe"].position[0] == pytest.approx(0.5)
    sensor = Sensor(name="s", kind=SensorKind.IRRADIANCE, position=np.array([0.0, 0.0, Z_SENSOR]),
                    normal=np.array([0.0, 0.0, -1.0]))
    e_lamp = RHO_MIRROR * by_name["Lamp"].emission[1] / D ** 2
    axis = np.array([0.5, 0.0, -D])  # sensor to the globe's image centre
    dist = float(np.linalg.norm(axis))
    cos_b = D / dist
    e_globe = RHO_MIRROR * math.pi * by_name["Globe"].emission[1] * (R_LIGHT / dist) ** 2 * cos_b
    res = Engine(scene, [sensor]).run("path", samples=SAMPLES["irradiance"], seed=11)
    v, se = float(res.mean[0, 1]), float(res.stderr[0, 1])
    truth = e_lamp + e_globe
    assert abs(v - truth) <= 4.0 * se + 1e-4 * truth, (v, se, truth, e_lamp)


def _globe_and_lamp(tmp_path):
    lamp = LIGHTS["point"].replace('"L"', '"Lamp"')
    globe = LIGHTS["sphere"].replace('"L"', '"Globe"').replace("(0, 0, 2.0)", "(0.5, 0, 2.0)")
    scene = load_stage(stage(tmp_path, _surface_body("mirror") + lamp + globe))
    by_name = {l.name.rsplit("/", 1)[-1]: l for l in scene.lights}
    e_lamp = RHO_MIRROR * by_name["Lamp"].emission[1] / D ** 2
    dist = math.hypot(0.5, D)
    e_globe = RHO_MIRROR * math.pi * by_name["Globe"].emission[1] * (R_LIGHT / dist) ** 2 * (D / dist)
    return scene, e_lamp, e_globe


def test_a_globe_seen_in_a_mirror_is_read_at_a_few_samples(tmp_path):
    """The lamp and globe of the test above at 256 samples, seeds 1–8: each reading is its closed form
    within 4 reported standard errors (and 1e-4), and that error is under a hundredth of a path's alone.
    A cosine direction meets the globe's image with probability p = E_g/(πLF) (0.4%), each hit worth
    πLF, so paths alone read it with the variance E_g(πLF − E_g) per sample; at 256 samples a third of
    the runs met it not once and read the lamp's image alone, with a standard error of 0 (seed 3 did:
    −79%), and an adaptive run stopped on such an error. The globe is now also sampled from the
    sensor's mirror image (kernels.mirrors.area_image), weighed against those paths by the power
    heuristic."""
    scene, e_lamp, e_globe = _globe_and_lamp(tmp_path)
    globe = next(l for l in scene.lights if l.name.endswith("Globe"))
    n = 256
    path_se = math.sqrt(e_globe * (math.pi * globe.emission[1] * RHO_MIRROR - e_globe) / n)
    sensor = Sensor(name="s", kind=SensorKind.IRRADIANCE, position=np.array([0.0, 0.0, Z_SENSOR]),
                    normal=np.array([0.0, 0.0, -1.0]))
    truth = e_lamp + e_globe
    for seed in range(1, 9):
        res = Engine(scene, [sensor]).run("path", samples=n, seed=seed)
        v, se = float(res.mean[0, 1]), float(res.stderr[0, 1])
        assert abs(v - truth) <= 4.0 * se + 1e-4 * truth, (seed, v, se, truth)
        assert se <= 0.01 * path_se, (seed, se, path_se)


SIDE_BIG = 2.0  # a rect light the glossy patch sees in the mirror over ~0.2 sr: both strategies matter there


def test_a_rect_lights_image_at_a_glossy_vertex_weighs_both_strategies(tmp_path):
    """A radiance meter aimed at a small rough-metal patch (10 cm, roughness 0.3, ρ 0.9, on a black floor)
    under a mirror ceiling (z = 3, ρ 0.9) with a 2 m rect light at z = 2 facing the ceiling: the patch sees
    the light only in the mirror, so L = ∫ f(wi, wo) cos θ_i · F·L_e cos θ_l/d² dA over the light's image
    (z = 4, facing down), f the float64 BSDF of simulator.reference.microfacet (64 × 64 Gauss–Legendre).
    The image's solid angle (~0.2 sr) and the GGX lobe (α 0.09) make light samples from the patch's image
    and the lobe's directions both worth their weight: the power heuristic's two weights must sum to one
    on each path. Within 4σ and 1%. (The patch's own image, ~3·10⁻⁴ sr, adds under 1e-4.)"""
    from simulator.reference.microfacet import bsdf_value, preview_lobes

    body = (material("Black", rho=0.0) + quad("Floor", 0.0, "Black", half=HALF)
            + material("Patch", "float inputs:roughness = 0.3\n        float inputs:metallic = 1", rho=RHO_MIRROR)
            + quad("Glossy", 0.001, "Patch", half=0.05)
            + material("Delta", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=RHO_MIRROR)
            + quad("Ceiling", 3.0, "Delta", half=HALF).replace("[0, 1, 2, 3]", "[0, 3, 2, 1]")
            + f'def RectLight "L"\n{{\n    float inputs:intensity = 100\n    float inputs:width = {SIDE_BIG}\n'
              f'    float inputs:height = {SIDE_BIG}\n    float3 xformOp:rotateXYZ = (180, 0, 0)\n'
              '    double3 xformOp:translate = (0.6, 0, 2)\n'
              '    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]\n}\n')
    scene = load_stage(stage(tmp_path, body))
    light = scene.lights[0]
    assert light.frame[2, 2] < 0 and abs(light.position[2] - 2.0) < 1e-9  # emits toward +z (UsdLux: along −ez)
    p = np.array([0.0, 0.0, 0.001])
    view = np.array([0.0, -math.sin(math.radians(40)), math.cos(math.radians(40))])  # toward the meter
    meter = Sensor(name="m", kind=SensorKind.RADIANCE, position=p + 1.5 * view, normal=-view,
                   half_angle=math.radians(0.5))
    lobes = preview_lobes(RHO_MIRROR, 0.3, 1.0)
    x, w = _gl()
    u = 0.5 * SIDE_BIG * x
    total = 0.0
    for ui, wi in zip(u, w):
        y = np.stack([0.6 + np.full_like(u, ui), u, np.full_like(u, 4.0 - 0.001)], axis=1) - p  # to the image
        d2 = np.einsum("ij,ij->i", y, y)
        wi_dir = y / np.sqrt(d2)[:, None]
        f = bsdf_value(lobes, wi_dir, np.broadcast_to(view, wi_dir.shape))
        total += wi * float(np.sum(w * f * wi_dir[:, 2] * wi_dir[:, 2] / d2))  # cos θ_i = cos θ_l = w_z
    truth = RHO_MIRROR * light.emission[1] * total * (0.5 * SIDE_BIG) ** 2
    res = Engine(scene, [meter]).run("path", samples=20000, seed=11)
    v, se = float(res.mean[0, 1]), float(res.stderr[0, 1])
    assert abs(v - truth) <= min(0.01 * truth, 4.0 * se + 1e-4 * truth), (v, se, truth)


# --------------------------------------------------------------------------- #
# a translucent layer: its slab is only the gap between its matte share
# --------------------------------------------------------------------------- #

LAYER_OPACITY = 0.25  # not 0.5: the gap 1 − o and the matte share o must differ
LAYER_CASES = [("point", "irradiance"), ("sun", "irradiance"), ("dome", "irradiance"), ("sun", "radiance")]


@pytest.mark.parametrize("light_kind, sensor_kind", LAYER_CASES, ids=[f"{l}-{s}" for l, s in LAYER_CASES])
def test_a_translucent_layer_reflects_through_its_gap_only(tmp_path, light_kind, sensor_kind):
    """UsdPreviewSurface ``opacity`` 0.25 in transparent mode at ior 1.5, black (ρ = 0), over a black floor:
    a translucent layer whose matte share o absorbs and whose gap 1 − o is the clear slab, so it
    mirrors F(μ) = (1 − o)·R(μ) (docs/DESIGN.md §Surfaces beyond Lambert). Image-source closed forms
    as in the module docstring, with that F: the sun and a point light reach an irradiance sensor
    only through the image source, which must take the gap's share, not the matte share c."""
    body = (material("Layer", f"float inputs:opacity = {LAYER_OPACITY}\n        float inputs:ior = {IOR}", rho=0.0)
            + material("Black", rho=0.0) + quad("Plane", 0.0, "Layer", half=HALF)
            + quad("Floor", -1.0, "Black", half=HALF))
    scene = load_stage(stage(tmp_path, body + LIGHTS[light_kind]))
    row = scene.geometry.surfaces[int(scene.geometry.surface_id[0])]
    assert row.pane and row.ior == pytest.approx(IOR)
    tau = row.tau
    f = lambda mu: (1.0 - LAYER_OPACITY) * slab(mu, IOR, tau)[0]  # noqa: E731
    assert_reads_its_image(scene, light_kind, sensor_kind, f)
