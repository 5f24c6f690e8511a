"""Curved mirrors and glossy shapes shaded by their smooth normals, against closed forms.

A chrome ball (a UsdGeom.Sphere of radius R = 0.5 m at C = (0, 0, 1), metallic
1, roughness 0, diffuseColor ρ = 0.9: F = F0 = F90 = ρ at every angle, the
metallic Schlick Fresnel; or a clearcoat at its mirror limit over a black
metal base: F(μ) = 0.04 + 0.96(1 − μ)⁵) is traced as its facets, each
shaded by the Sphere's own normal at its corners, interpolated
(docs/DESIGN.md §Glossy vertices and mirrors). Closed forms:

- **a radiance meter aimed at a light's image** in the ball reads F(μ)·L,
  μ the incidence cosine at the highlight, L the light's radiance, where
  every ray of its cone reflects into the light: the sun (a distant light
  of 0.53°, its image in the ball about 2 mm across) and a sphere light;
- **an irradiance sensor lit only by a point light's image** reads the
  astigmatic beam of Coddington's equations, F·I·|s'_t||s'_s|/(s²(|s'_t| +
  t)(|s'_s| + t))·cos θ_x (docs/REFERENCES.md §Spherical mirror;
  ``simulator.reference.convex_mirror``, float64, no code shared with the
  engine), and for a distant light its s → ∞ limit; the sun's disc at 10°
  the quadrature of that limit over the disc;
- **a glossy ball under a uniform sky** seen by a meter reads L·A(μ), A the
  directional albedo at the view angle to the smooth normal
  (``simulator.reference.microfacet``), as a flat floor of the same
  material does.

The traced surface is the facets, not the sphere: a facet's plane tilts
from the sphere's tangent plane by up to half a facet, which moves a point
light's image irradiance by up to about 1.5% per degree of tilt at the
incidences used here (measured against the float64 formulas on the same
facets, 64 × 32 to 4096 × 2048). The irradiance cases therefore use 1024 ×
512 facets (tilt ≤ 0.18°) and a bound of 0.5%; the meters 256 × 128, where
the images lie well inside the light. On the tree before smooth normals
every case here read 0 (a facet's face normal sends the reflection off the
light) or the facet's view angle's albedo.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from simulator.engine.driver import Engine
from simulator.reference.convex_mirror import distant_image_irradiance, image_irradiance, reflection_point
from simulator.reference.microfacet import directional_albedo, preview_lobes
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.surfaces import curved_mirrors, shaded_faces
from simulator.scene.usd import load_stage
from simulator.scene.usd.tessellation import _sphere_polygons
from tests.test_surfaces import DOME, L_DOME, material, stage

R = 0.5
C = np.array([0.0, 0.0, 1.0])
RHO = 0.9
CHROME = material("Chrome", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=RHO)
COAT = material("Chrome", "float inputs:metallic = 1\n        float inputs:clearcoat = 1", rho=0.0)
MATERIALS = {"metal": (CHROME, lambda mu: RHO), "coat": (COAT, lambda mu: 0.04 + 0.96 * (1.0 - mu) ** 5)}


def _xform(p) -> str:
    return (f"    double3 xformOp:translate = ({float(p[0])!r}, {float(p[1])!r}, {float(p[2])!r})\n"
            '    uniform token[] xformOpOrder = ["xformOp:translate"]\n')


def ball(tess=(64, 32), bind: str = "Chrome") -> str:
    return (f'def Sphere "Ball"\n{{\n    double radius = {R}\n    rel material:binding = </{bind}>\n'
            f"    int2 probesim:tessellation = ({tess[0]}, {tess[1]})\n" + _xform(C) + "}\n")


def mesh_ball(n_lon: int, n_lat: int, bind: str = "Chrome") -> str:
    """The Sphere's own tessellation written as a Mesh with authored vertex normals (its radii)."""
    points, counts, indices = _sphere_polygons(R, n_lon, n_lat)
    normals = points / R
    fmt = lambda a: ", ".join(f"({float(x)!r}, {float(y)!r}, {float(z)!r})" for x, y, z in a)  # noqa: E731
    return f"""
def Mesh "Ball"
{{
    int[] faceVertexCounts = [{", ".join(map(str, counts))}]
    int[] faceVertexIndices = [{", ".join(map(str, indices))}]
    point3f[] points = [{fmt(points)}]
    normal3f[] normals = [{fmt(normals)}]
    uniform token normalsInterpolation = "vertex"
    uniform token subdivisionScheme = "none"
    rel material:binding = </{bind}>
{_xform(C)}}}
"""


def sun(angle_deg: float, zenith_deg: float = 30.0) -> str:
    return (f'def DistantLight "Sun"\n{{\n    float inputs:intensity = 1000\n    float inputs:angle = {angle_deg}\n'
            f'    bool inputs:normalize = 1\n    float3 xformOp:rotateXYZ = ({zenith_deg}, 0, 0)\n'
            '    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]\n}\n')


def lamp(pos, radius: float = 0.1, point: bool = True) -> str:
    return (f'def SphereLight "Lamp"\n{{\n    float inputs:intensity = 100\n    float inputs:radius = {radius}\n'
            + ("    bool treatAsPoint = 1\n" if point else "") + _xform(pos) + "}\n")


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def _meter(position, at, half_angle_deg: float) -> Sensor:
    return Sensor(name="m", kind=SensorKind.RADIANCE, position=np.asarray(position, float),
                  normal=_unit(np.asarray(at, float) - position), half_angle=math.radians(half_angle_deg))


def _read(scene, sensor, samples: int, seed: int = 11, method: str = "path"):
    res = Engine(scene, [sensor]).run(method, samples=samples, seed=seed)
    return float(res.mean[0, 1]), float(res.stderr[0, 1])


# --------------------------------------------------------------------------- #
# radiance meters at a light's image
# --------------------------------------------------------------------------- #

METER_AT = C + 2.0 * _unit([1.0, 0.3, 0.5])  # the meter, 2 m from the ball's centre


@pytest.mark.parametrize("surface", ["metal", "coat"])
def test_meter_reads_the_sun_in_a_mirror_ball(tmp_path, surface):
    """The sun (0.53°, zenith 30°) in a chrome ball: a meter of 0.02° aimed at its highlight (the point
    whose normal bisects the sun and the meter) reads F(μ)·L_sun, μ the incidence cosine there
    (0.73): within 4σ and 1e-4. Before smooth normals: 0 (no facet faces the sun's image)."""
    body, f = MATERIALS[surface]
    scene = load_stage(stage(tmp_path, body + ball((256, 128)) + sun(0.53)))
    s = scene.lights[0].frame[:, 2]
    h = reflection_point(C, R, METER_AT, None, s)
    mu = float(np.dot(_unit(METER_AT - h), _unit(h - C)))
    truth = f(mu) * scene.lights[0].emission[1]
    v, se = _read(scene, _meter(METER_AT, h, 0.02), 1024)
    assert abs(v - truth) <= 4 * se + 1e-4 * truth, (v, se, truth)


def test_meter_reads_a_globe_in_a_mirror_ball(tmp_path):
    """A sphere light (r = 0.03 m, 1.5 m from the ball) in a chrome ball of the default 64 × 32 facets: a
    meter of 0.02° aimed at the image of its centre reads F·L (its image, ~1 cm across, holds the whole
    cone): within 4σ and 1e-4. Before smooth normals the facet there (5.6° wide) sent the meter's rays off
    the globe (1.1° in radius seen from the ball)."""
    pos = C + 1.5 * _unit([-0.4, 0.6, 0.7])
    scene = load_stage(stage(tmp_path, CHROME + ball() + lamp(pos, 0.03, point=False)))
    h = reflection_point(C, R, METER_AT, pos)
    truth = RHO * scene.lights[0].emission[1]
    v, se = _read(scene, _meter(METER_AT, h, 0.02), 1024)
    assert abs(v - truth) <= 4 * se + 1e-4 * truth, (v, se, truth)


# --------------------------------------------------------------------------- #
# irradiance sensors lit only by an image in the ball
# --------------------------------------------------------------------------- #

X = np.array([1.2, 0.3, 1.4])  # the sensor, facing the ball
N_SENSOR = _unit([-1.0, -0.2, -0.3])
LAMP_AT = np.array([1.5, -0.8, 2.5])  # behind the sensor's plane: it reads the lamp's image only
BOUND = 5e-3  # the facets' tilt at 1024 × 512 (module docstring)


def _irradiance_sensor(x=X, n=N_SENSOR) -> Sensor:
    return Sensor(name="s", kind=SensorKind.IRRADIANCE, position=np.asarray(x, float), normal=np.asarray(n, float))


@pytest.mark.parametrize("surface", ["metal", "coat"])
def test_point_light_image_in_a_convex_mirror(tmp_path, surface):
    """A point lamp behind an irradiance sensor that faces a chrome ball: the sensor reads the lamp's
    image by Coddington's equations (module docstring; F at the incidence of the reflection point) within
    0.5% (the facets' tilt) and 4σ. Before smooth normals: 0 (no path can reach a point light off a
    mirror, and the image source knew flat planes only)."""
    body, f = MATERIALS[surface]
    scene = load_stage(stage(tmp_path, body + ball((1024, 512)) + lamp(LAMP_AT)))
    assert np.dot(N_SENSOR, LAMP_AT - X) < 0  # the lamp is behind the sensor
    m = reflection_point(C, R, X, LAMP_AT)
    mu = float(np.dot(_unit(X - m), _unit(m - C)))
    truth = image_irradiance(C, R, X, N_SENSOR, LAMP_AT, scene.lights[0].emission[1], f(mu))
    v, se = _read(scene, _irradiance_sensor(), 64)
    assert abs(v - truth) <= 4 * se + BOUND * truth, (v, se, truth)


@pytest.mark.parametrize("angle", [0.0, 0.53])
def test_sun_image_in_a_convex_mirror(tmp_path, angle):
    """The sun behind a sensor above and beside a chrome ball: its image's irradiance, the s → ∞ limit of
    Coddington's equations (module docstring) times its normal irradiance E⊥ = L·π sin²(angle/2) (E⊥ =
    the authored value at angle 0); the disc's directions change it by < 1e-4. Within 0.5% and 4σ."""
    scene = load_stage(stage(tmp_path, CHROME + ball((1024, 512)) + sun(angle)))
    light = scene.lights[0]
    s = light.frame[:, 2]
    x = np.array([0.9, 0.4, 1.6])
    n = _unit(C - x)
    assert np.dot(n, s) < 0
    e_perp = light.emission[1] * (math.pi * math.sin(light.half_angle) ** 2 if angle > 0 else 1.0)
    truth = distant_image_irradiance(C, R, x, n, s, e_perp, RHO)
    v, se = _read(scene, _irradiance_sensor(x, n), 256)
    assert abs(v - truth) <= 4 * se + BOUND * truth, (v, se, truth)


def test_a_wide_suns_image_is_counted_once(tmp_path):
    """A sun 10° across: paths off the ball now meet its disc (about one sample in a thousand), and the
    Newton connection samples it too; a path that meets it off the ball is left out exactly where the
    connection from its vertex lands on the same point (kernels.curved), so the reading is the quadrature
    of the distant image's irradiance over the disc (24 × 48 nodes), within 4σ and 0.5%, not twice it."""
    scene = load_stage(stage(tmp_path, CHROME + ball((1024, 512)) + sun(10.0)))
    light = scene.lights[0]
    ez = light.frame[:, 2]
    x = np.array([0.9, 0.4, 1.6])
    n = _unit(C - x)
    ex = _unit(np.cross(ez, [1.0, 0.0, 0.0]))
    ey = np.cross(ez, ex)
    xg, wg = np.polynomial.legendre.leggauss(24)
    th, wt = 0.5 * light.half_angle * (xg + 1), 0.5 * light.half_angle * wg
    phi = 2 * math.pi * np.arange(48) / 48
    total = sum(wk * math.sin(t) * (2 * math.pi / 48) * distant_image_irradiance(
        C, R, x, n, math.cos(t) * ez + math.sin(t) * (math.cos(p) * ex + math.sin(p) * ey), 1.0, RHO)
        for t, wk in zip(th, wt) for p in phi)
    truth = light.emission[1] * total
    v, se = _read(scene, _irradiance_sensor(x, n), 8192)
    assert abs(v - truth) <= 4 * se + BOUND * truth, (v, se, truth)


def test_a_mesh_with_authored_normals_reads_as_the_implicit_sphere(tmp_path):
    """A coarse (24 × 12) sphere written as a Mesh with authored vertex normals reads the point lamp's image
    as the implicit Sphere of the same tessellation does (the same facets, the same corner normals: within
    1e-5), and within 10% of the closed form (a 24 × 12 facet tilts up to ~4° from the sphere: about
    1.5%/° at this incidence). Before smooth normals both read 0."""
    truth = None
    readings = []
    for body in (ball((24, 12)), mesh_ball(24, 12)):
        scene = load_stage(stage(tmp_path, CHROME + body + lamp(LAMP_AT)))
        assert scene.geometry.shading_normals is not None
        if truth is None:
            truth = image_irradiance(C, R, X, N_SENSOR, LAMP_AT, scene.lights[0].emission[1], RHO)
        readings.append(_read(scene, _irradiance_sensor(), 16))
    (a, sa), (b, sb) = readings
    assert abs(a - b) <= 4 * math.hypot(sa, sb) + 1e-5 * truth, readings
    assert abs(a - truth) <= 0.1 * truth, (a, truth)


# --------------------------------------------------------------------------- #
# a glossy ball under a uniform sky
# --------------------------------------------------------------------------- #

COATED = (0.6, 0.0, 0.3, 1.0)  # roughness, metallic, ρ, clearcoat (roughness 0.2): A(μ) changes fast with μ


def test_glossy_ball_under_a_sky_reads_the_albedo_of_its_smooth_normal(tmp_path):
    """A clear-coated ball (32 × 16 facets) under a uniform sky, a meter of 0.1° aimed at a vertex of its
    tessellation at 60° from the vertex normal: L·A(cos 60°) (docs/REFERENCES.md §Microfacet BSDF, the
    quadrature of simulator.reference.microfacet), as the flat floor of tests/test_glossy.py reads, within
    1% and 4σ. With face normals the facet there is seen at 60° ± 5.6° (A 0.3275 → 0.31–0.35)."""
    rough, metal, rho, coat = COATED
    extra = (f"float inputs:roughness = {rough}\n        float inputs:metallic = {metal}\n"
             f"        float inputs:clearcoat = {coat}\n        float inputs:clearcoatRoughness = 0.2")
    scene = load_stage(stage(tmp_path, material("Chrome", extra, rho=rho) + ball((32, 16)) + DOME))
    k, j = 5, 3  # ring k + 1 (polar angle 6·180/16 = 67.5°), column j
    theta, phi = math.pi * (k + 1) / 16, 2 * math.pi * j / 32
    u = np.array([math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)])
    vertex = C + R * u
    toward_pole = _unit(np.array([0.0, 0.0, 1.0]) - u * u[2])  # the view turns in the latitude plane
    w = math.cos(math.radians(60)) * u + math.sin(math.radians(60)) * toward_pole
    meter = _meter(vertex + 2.0 * w, vertex, 0.1)
    truth = L_DOME * directional_albedo(preview_lobes(rho, rough, metal, 1.5, None, coat, 0.2), 0.5)
    v, se = _read(scene, meter, 20000)
    assert abs(v - truth) <= min(0.01 * truth, 4 * se + 1e-6 * truth), (v, se, truth)


# --------------------------------------------------------------------------- #
# what the reader gives the kernels
# --------------------------------------------------------------------------- #

def _quad_mesh(normals: str, interp: str, extra: str = "", indices: str = "") -> str:
    """A 1 × 1 quad (two triangles) in z = 0 with authored normals."""
    return f"""
def Mesh "Panel"
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    normal3f[] primvars:normals = [{normals}] (
        interpolation = "{interp}"
    )
    {indices}
    {extra}
    rel material:binding = </Chrome>
}}
"""


def _corner_normal(g, point) -> np.ndarray:
    """The shading normal of the corner at ``point`` in the first triangle that has it."""
    for t, tri in enumerate(g.triangles):
        for c, v in enumerate(tri):
            if np.allclose(g.points[v], point):
                return g.shading_normals[t, c]
    raise AssertionError(point)


TILTS = "(-0.2, 0, 1), (0.2, 0, 1), (0.2, 0, 1), (-0.2, 0, 1)"


@pytest.mark.parametrize("interp, normals, expect_at_origin", [
    ("vertex", TILTS, (-0.2, 0, 1)),
    ("varying", TILTS, (-0.2, 0, 1)),
    ("faceVarying", TILTS, (-0.2, 0, 1)),
    ("uniform", "(0.1, 0.3, 1)", (0.1, 0.3, 1)),
    ("constant", "(0, 0.2, 1)", (0, 0.2, 1)),
])
def test_authored_normals_at_each_interpolation(tmp_path, interp, normals, expect_at_origin):
    """primvars:normals at each interpolation reach the triangle corners as authored, made unit
    (UsdGeom primvar interpolation: vertex and varying per point, faceVarying per face corner, uniform
    per face, constant one for all)."""
    g = load_stage(stage(tmp_path, CHROME + _quad_mesh(normals, interp) + DOME)).geometry
    assert g.shading_normals is not None and g.shading_normals.shape == (2, 3, 3)
    np.testing.assert_allclose(_corner_normal(g, (0, 0, 0)), _unit(expect_at_origin), atol=1e-6)


def test_indexed_normals_and_the_attribute(tmp_path):
    """Indexed primvars:normals are flattened; the ``normals`` attribute with its normalsInterpolation is
    read where no primvar is authored."""
    idx = "int[] primvars:normals:indices = [1, 0, 0, 1]"
    g = load_stage(stage(tmp_path, CHROME + _quad_mesh("(0.3, 0, 1), (-0.3, 0, 1)", "vertex", indices=idx)
                         + DOME)).geometry
    np.testing.assert_allclose(_corner_normal(g, (0, 0, 0)), _unit((-0.3, 0, 1)), atol=1e-6)
    np.testing.assert_allclose(_corner_normal(g, (1, 0, 0)), _unit((0.3, 0, 1)), atol=1e-6)
    attr = _quad_mesh("(0, 0, 1)", "constant").replace(
        'normal3f[] primvars:normals = [(0, 0, 1)] (\n        interpolation = "constant"\n    )',
        f'normal3f[] normals = [{TILTS}]\n    uniform token normalsInterpolation = "vertex"')
    g = load_stage(stage(tmp_path, CHROME + attr + DOME, "attr.usda")).geometry
    np.testing.assert_allclose(_corner_normal(g, (1, 1, 0)), _unit((0.2, 0, 1)), atol=1e-6)


def test_normals_equal_to_the_faces_change_nothing(tmp_path):
    """A flat mesh that authors its face normals has no shading normals (its faces are read as before);
    neither has a matte Sphere (only glossy, mirror and pane faces keep them), so nothing is shaded."""
    g = load_stage(stage(tmp_path, CHROME + _quad_mesh("(0, 0, 1)", "constant") + DOME)).geometry
    assert g.shading_normals is None
    matte = load_stage(stage(tmp_path, material("Chrome") + ball() + DOME, "matte.usda")).geometry
    assert matte.shading_normals is None and shaded_faces(matte) is None


def test_a_subdivision_surface_is_shaded_by_its_cage(tmp_path):
    """subdivisionScheme catmullClark (authored): UsdGeomMesh's authored normals apply to "none" only, so
    they are not read and the cage's area-weighted vertex normals shade it; "none" or no scheme authored:
    the authored normals; bilinear (the cage's own flat faces): none."""
    pyramid = """
def Mesh "Panel"
{{
    int[] faceVertexCounts = [3, 3, 3, 3]
    int[] faceVertexIndices = [0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4]
    point3f[] points = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0), (0, 0, 1)]
    normal3f[] primvars:normals = [(0, 0, 1)] (
        interpolation = "constant"
    )
    {scheme}
    rel material:binding = </Chrome>
}}
"""
    out = {}
    for name, scheme in (("cc", 'uniform token subdivisionScheme = "catmullClark"'),
                         ("none", 'uniform token subdivisionScheme = "none"'), ("unset", ""),
                         ("bilinear", 'uniform token subdivisionScheme = "bilinear"')):
        g = load_stage(stage(tmp_path, CHROME + pyramid.format(scheme=scheme) + DOME, f"{name}.usda")).geometry
        out[name] = g
    np.testing.assert_allclose(_corner_normal(out["cc"], (0, 0, 1)), (0, 0, 1), atol=1e-9)  # the apex: symmetric
    p = out["cc"].points
    four = [np.cross(b - a, c - a) for a, b, c in ([p[0], p[1], p[4]], [p[3], p[0], p[4]])]
    np.testing.assert_allclose(_corner_normal(out["cc"], (-1, -1, 0)), _unit(four[0] + four[1]), atol=1e-6)
    for name in ("none", "unset"):
        np.testing.assert_allclose(_corner_normal(out[name], (-1, -1, 0)), (0, 0, 1), atol=1e-9)
    assert out["bilinear"].shading_normals is None


@pytest.mark.parametrize("shape", ["Cylinder", "Cone", "Capsule"])
def test_implicit_gprims_carry_their_analytic_normals(tmp_path, shape):
    """A Cylinder's side is shaded by its radial normal and its caps by their axis, a Cone's side by the
    normal tilted atan(r/h) toward its apex (its apex corner by its triangle's azimuth: not checked here),
    a Capsule's caps by their spheres' radii and its side radially; along axis X and scaled 2 × along Z
    (normals map by the inverse transpose)."""
    body = (f'def {shape} "Ball"\n{{\n    double radius = 0.5\n    double height = 1\n    uniform token axis = "X"\n'
            '    rel material:binding = </Chrome>\n    float3 xformOp:scale = (1, 1, 2)\n'
            '    uniform token[] xformOpOrder = ["xformOp:scale"]\n}\n')
    g = load_stage(stage(tmp_path, CHROME + body + DOME)).geometry
    local = g.points[g.triangles] * np.array([1.0, 1.0, 0.5])  # (T, 3, 3) corners in the unscaled frame
    x = local[..., 0]
    rho = np.hypot(local[..., 1], local[..., 2])
    radial = local * [0.0, 1.0, 1.0] / np.maximum(rho, 1e-12)[..., None]
    cap = np.all(np.abs(x - x[:, :1]) < 1e-9, axis=1) & (np.abs(np.abs(x[:, 0]) - 0.5) < 1e-9)  # flat end faces
    check = np.ones(x.shape, bool)
    if shape == "Cylinder":
        want = np.where(cap[:, None, None], np.sign(x)[..., None] * [1.0, 0.0, 0.0], radial)
    elif shape == "Cone":  # apex at x = +0.5, base of radius 0.5 at x = −0.5: the side normal is (h·ρ̂ + r·x̂)/|…|
        want = np.where(cap[:, None, None], [-1.0, 0.0, 0.0], radial + [0.5, 0.0, 0.0])
        check = rho > 1e-9
    else:  # Capsule: the nearest point of the axis segment |x| ≤ 0.5 is each corner's centre
        centre = np.clip(x, -0.5, 0.5)
        want = local - np.stack([centre, 0 * centre, 0 * centre], axis=-1)
    want = want * np.array([1.0, 1.0, 0.5])  # the inverse transpose of the scale
    want = want / np.maximum(np.linalg.norm(want, axis=-1, keepdims=True), 1e-300)
    got = g.shading_normals.astype(np.float64)
    got = got / np.maximum(np.linalg.norm(got, axis=-1, keepdims=True), 1e-300)
    assert check.sum() >= 0.6 * check.size  # (a cone: its apex and base centre are a third of its corners)
    np.testing.assert_allclose(got[check], want[check], atol=1e-5)


def test_curved_mirrors_are_pieces_with_their_spheres(tmp_path):
    """The ball's facets form one curved mirror, closed and convex, with its bounding sphere (C, R within
    the tessellation's 0.3%); no flat mirror plane is made of them (docs/DESIGN.md §Glossy vertices and
    mirrors)."""
    from simulator.scene.surfaces import mirror_planes

    g = load_stage(stage(tmp_path, CHROME + ball() + lamp(LAMP_AT))).geometry
    shaded = shaded_faces(g)
    assert shaded is not None and shaded.all()
    curves = curved_mirrors(g, shaded)
    assert curves.n == 1 and not curves.not_convex and np.all(curves.face_curve == 0)
    np.testing.assert_allclose(curves.spheres[0, :3], C, atol=1e-9)
    assert abs(curves.spheres[0, 3] - R) < 3e-3 * R
    planes, _, _ = mirror_planes(g.points, g.triangles, g.surface_id, g.surfaces, shaded)
    assert len(planes) == 0
    from simulator.plan.planner import surface_needs

    scene = load_stage(stage(tmp_path, CHROME + ball() + lamp(LAMP_AT), "plan.usda"))
    assert any(line.startswith("smooth normals: 3968 ") and "1 curved mirror" in line for line in surface_needs(scene))


def test_the_summary_names_curved_glass_and_concave_mirrors(tmp_path):
    """What is still read from flat facets is named: a curved pane (glass reflects about its facets), and a
    curved mirror that is not closed and convex (one reflection point read); a chrome ball says nothing
    of facets."""
    glass = material("Glass", "float inputs:opacity = 0\n        float inputs:ior = 1.5")
    said = load_stage(stage(tmp_path, glass + ball(bind="Glass") + lamp(LAMP_AT), "glass.usda")).warnings
    assert any("curved glass" in w and "/Ball" in w for w in said), said
    chrome = load_stage(stage(tmp_path, CHROME + ball() + lamp(LAMP_AT), "chrome.usda")).warnings
    assert not any("facets" in w or "not closed" in w for w in chrome), chrome
    bowl = _quad_mesh(TILTS, "vertex")
    said = load_stage(stage(tmp_path, CHROME + bowl + lamp(LAMP_AT), "bowl.usda")).warnings
    assert any("not closed and convex" in w and "/Panel" in w for w in said), said


def test_a_gold_ball_reflects_the_lamps_image_in_its_colour(tmp_path):
    """A gold ball (metallic 1, roughness 0, diffuseColor (1, 0.766, 0.336): F(λ) = ρ(λ), its uplift) beside
    the sensor, a 3000 K point lamp behind it, a spectral run: Coddington's image irradiance at F = 1 times
    ∫SρV/∫SV (tests/test_spectra_surfaces.py's v_weighted), within 4 standard errors (the wavelengths'
    noise) and the facets' 0.5%: the curved connection carries the mirror's lanes."""
    from simulator.config import load_config
    from simulator.pipeline import run
    from simulator.spectra.reflectance import uplift
    from tests.test_spectra_surfaces import GOLD, config, lx, readings, v_weighted

    gold = material("Chrome", "float inputs:roughness = 0\n        float inputs:metallic = 1", rho=1.0).replace(
        "color3f inputs:diffuseColor = (1.0, 1.0, 1.0)", f"color3f inputs:diffuseColor = {GOLD}")
    path = stage(tmp_path, gold + ball((1024, 512)) + lamp(LAMP_AT))
    sensor = (f'[[sensor]]\nname = "s"\nkind = "irradiance"\nposition = {list(map(float, X))}\n'
              f'normal = {list(map(float, N_SENSOR))}\n')
    out = run(load_config(config(tmp_path, path, sensor, "path", 1000)), log=lambda *a: None)
    assert out.record["plan"]["transport"] == "spectral"
    geometric = image_irradiance(C, R, X, N_SENSOR, LAMP_AT, out.scene.lights[0].emission[1], 1.0)
    truth = geometric * v_weighted(uplift(np.array(GOLD)))
    e, se = lx(readings(out)["s"])
    assert se > 0 and abs(e - truth) <= 4 * se + BOUND * truth, (e, se, truth)
