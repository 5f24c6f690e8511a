"""Tests for the USD stage reader (the simulator/scene/usd package).

Each test builds a tiny stage as usda text in ``tmp_path`` and checks what the
reader hands on: positions in metres with Z up, triangle counts and winding,
material greys, and UsdLux emission per the rules in DESIGN.md ("UsdLux
emission"). No Warp here: these run in well under a second each.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.errors import UserError
from simulator.scene.model import LightKind, SensorKind
from simulator.scene.usd import DEFAULT_ALBEDO, SPHERE_SEGMENTS, load_stage
from simulator.units import luminous_efficacy, luminance_grey

STAGES = Path(__file__).resolve().parents[1] / "stages"


def write_stage(tmp_path: Path, body: str, mpu: float = 1.0, up: str = "Z", name: str = "s.usda") -> Path:
    """Write a usda layer with ``body`` as its root prims; return its path."""
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = {mpu}\n    upAxis = "{up}"\n)\n\n{body}\n')
    return path


def quad_mesh(name: str, points, extra: str = "", counts=None, indices=None) -> str:
    """A Mesh prim from a point list (one polygon unless counts/indices are given)."""
    counts = counts or [len(points)]
    indices = indices or list(range(len(points)))
    pts = ", ".join(f"({x}, {y}, {z})" for x, y, z in points)
    return f"""
def Mesh "{name}"
{{
    int[] faceVertexCounts = {list(counts)}
    int[] faceVertexIndices = {list(indices)}
    point3f[] points = [{pts}]
    {extra}
}}
"""


def material(name: str, diffuse=(0.5, 0.5, 0.5), emissive=None, opacity=None) -> str:
    lines = [f"color3f inputs:diffuseColor = {tuple(diffuse)}"]
    if emissive is not None:
        lines.append(f"color3f inputs:emissiveColor = {tuple(emissive)}")
    if opacity is not None:
        lines.append(f"float inputs:opacity = {opacity}")
    inputs = "\n        ".join(lines)
    return f"""
def Material "{name}"
{{
    token outputs:surface.connect = </{name}/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        {inputs}
        token outputs:surface
    }}
}}
"""


def bound(mat: str) -> str:
    return f"rel material:binding = </{mat}>"


def tri_normals(scene) -> np.ndarray:
    """Geometric (front-face) normal of every triangle, cross(p1 - p0, p2 - p0), not normalised."""
    p = scene.geometry.points[scene.geometry.triangles]
    return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])


def light_stage(tmp_path, typ: str, attrs: str, xform: str = "") -> object:
    return load_stage(write_stage(tmp_path, f'def {typ} "L"\n{{\n    {attrs}\n    {xform}\n}}'))


K_D65 = luminous_efficacy("D65")


# --------------------------------------------------------------------------- #
# world frame
# --------------------------------------------------------------------------- #


def test_point_cm_yup_lands_at_3_m():
    """point_cm_yup.usda: (0, 300, 0) cm in a Y-up stage is (0, 0, 3) m in the Z-up world.

    metersPerUnit 0.01 scales 300 -> 3; the +90 deg rotation about X maps
    (x, y, z)_Yup to (x, -z, y)_Zup. Emission (normalized treatAsPoint:
    I = 400/4 = 100 cd) matches point.usda.
    """
    s = load_stage(STAGES / "point_cm_yup.usda")
    ref = load_stage(STAGES / "point.usda")
    assert s.meters_per_unit == 0.01 and s.up_axis == "Y"
    (light,) = s.lights
    assert light.kind == LightKind.POINT
    np.testing.assert_allclose(light.position, [0, 0, 3], atol=1e-12)
    np.testing.assert_allclose(light.position, ref.lights[0].position, atol=1e-12)
    assert light.emission == pytest.approx(ref.lights[0].emission, rel=1e-12)
    assert light.emission[1] == pytest.approx(100.0)


def test_y_up_directions_frames_and_lengths(tmp_path):
    """A Y-up cm stage: a RectLight's stage -Z becomes world +Y; sizes and points are in metres.

    Stage +Z = (0, 0, 1) maps to (0, -1, 0), so frame[:, 2] = (0, -1, 0) and
    the light emits along -frame_z = +Y. width 100 cm -> 1 m. A mesh point
    (100, 200, 300) cm -> (1, -3, 2) m.
    """
    body = 'def RectLight "L"\n{\n    float inputs:width = 100\n    float inputs:height = 50\n}\n'
    body += quad_mesh("M", [(100, 200, 300), (200, 200, 300), (200, 300, 300)])
    s = load_stage(write_stage(tmp_path, body, mpu=0.01, up="Y"))
    (light,) = s.lights
    np.testing.assert_allclose(light.frame[:, 2], [0, -1, 0], atol=1e-12)
    np.testing.assert_allclose(light.frame[:, 0], [1, 0, 0], atol=1e-12)
    assert np.linalg.det(light.frame) == pytest.approx(1.0)
    assert (light.width, light.height) == pytest.approx((1.0, 0.5))
    np.testing.assert_allclose(s.geometry.points[0], [1, -3, 2], atol=1e-6)


# --------------------------------------------------------------------------- #
# geometry
# --------------------------------------------------------------------------- #


def test_quad_and_pentagon_triangulate_with_front_face_up(tmp_path):
    """A quad gives 2 triangles, a convex pentagon 3 (n - 2), all facing +Z (counter-clockwise seen from +Z).

    Total area = 1 (unit quad) + pentagon area (shoelace formula).
    """
    pent = [(math.cos(a), math.sin(a), 0.0) for a in np.linspace(0, 2 * np.pi, 6)[:-1]]
    body = quad_mesh("Quad", [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]) + quad_mesh("Pent", pent)
    s = load_stage(write_stage(tmp_path, body))
    g = s.geometry
    assert g.n_triangles == 5
    assert g.prim_names == ["/Quad", "/Pent"]
    assert np.bincount(g.prim).tolist() == [2, 3]
    n = tri_normals(s)
    assert np.all(n[:, 2] > 0) and np.allclose(n[:, :2], 0, atol=1e-6)
    pent_area = 0.5 * 5 * math.sin(2 * math.pi / 5)
    assert 0.5 * np.linalg.norm(n, axis=1).sum() == pytest.approx(1 + pent_area, rel=1e-6)


def test_concave_polygon_is_ear_clipped(tmp_path):
    """An L-shaped hexagon (concave at (1, 1)) gives 4 triangles covering area 3, none flipped.

    A fan from vertex 0 would produce a triangle outside the L (wrong area /
    a back-facing sliver); ear clipping keeps every triangle inside, facing +Z.
    """
    ell = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0), (1, 2, 0), (0, 2, 0)]
    # start the loop at the reflex corner's neighbour so a fan would go wrong
    ell = ell[2:] + ell[:2]
    s = load_stage(write_stage(tmp_path, quad_mesh("L", ell)))
    n = tri_normals(s)
    assert s.geometry.n_triangles == 4
    assert np.all(n[:, 2] > 0)
    assert 0.5 * np.linalg.norm(n, axis=1).sum() == pytest.approx(3.0)


def test_left_handed_mesh_is_rewound(tmp_path):
    """orientation = leftHanded: the same counter-clockwise quad's front face is -Z, so triangles are re-wound."""
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    body = quad_mesh("R", pts) + quad_mesh("Lh", pts, 'uniform token orientation = "leftHanded"')
    s = load_stage(write_stage(tmp_path, body))
    n = tri_normals(s)
    assert np.all(n[s.geometry.prim == 0, 2] > 0)
    assert np.all(n[s.geometry.prim == 1, 2] < 0)


@pytest.mark.parametrize("left, expected_sign", [(False, 1), (True, -1)])
def test_mirror_transform_keeps_front_face(tmp_path, left, expected_sign):
    """A negative-determinant transform (scale (-1, 1, 1)) swaps handedness, so the reader re-winds.

    Mirroring across the YZ plane does not move a +Z-facing surface's normal,
    so a right-handed quad still faces +Z; leftHanded and the mirror cancel
    twice over, giving -Z.
    """
    orient = 'uniform token orientation = "leftHanded"' if left else ""
    extra = f'{orient}\n    float3 xformOp:scale = (-1, 1, 1)\n    uniform token[] xformOpOrder = ["xformOp:scale"]'
    s = load_stage(write_stage(tmp_path, quad_mesh("M", [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], extra)))
    assert np.all(np.sign(tri_normals(s)[:, 2]) == expected_sign)
    assert s.geometry.points[:, 0].max() == 0.0  # the mirror did move the points to x <= 0


def test_nested_transforms_with_scale(tmp_path):
    """Parent translate (1, 2, 3) and scale 2; child Cube (size 1) translated (1, 0, 0).

    World centre = (1, 2, 3) + 2 * (1, 0, 0) = (3, 2, 3); half-size 2 * 0.5 = 1,
    so the cube spans [2, 4] x [1, 3] x [2, 4]. A RectLight under the same
    parent is 2x as wide in world metres, and its normalized radiance divides by
    the world area (2 * 1) * (2 * 1) = 4.
    """
    body = """
def Xform "P"
{
    double3 xformOp:translate = (1, 2, 3)
    float3 xformOp:scale = (2, 2, 2)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
    def Cube "C"
    {
        double size = 1
        double3 xformOp:translate = (1, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def RectLight "L"
    {
        float inputs:width = 1
        float inputs:height = 1
        float inputs:intensity = 8
        bool inputs:normalize = 1
    }
}
"""
    s = load_stage(write_stage(tmp_path, body))
    np.testing.assert_allclose(s.geometry.points.min(axis=0), [2, 1, 2])
    np.testing.assert_allclose(s.geometry.points.max(axis=0), [4, 3, 4])
    (light,) = s.lights
    np.testing.assert_allclose(light.position, [1, 2, 3])
    assert (light.width, light.height) == pytest.approx((2.0, 2.0))
    assert light.emission[1] == pytest.approx(8 / 4)
    np.testing.assert_allclose(light.frame, np.eye(3), atol=1e-12)


def test_cube_and_sphere_face_outward(tmp_path):
    """Cube: 12 triangles, every normal points away from the centre; Sphere: a 64 x 32 UV sphere.

    UV sphere triangle count = 2 * n_lon (caps) + 2 * n_lon * (n_lat - 2) (quads).
    Its vertices lie on the radius; every face points outward.
    """
    body = 'def Cube "C"\n{\n    double size = 2\n}\ndef Sphere "S"\n{\n    double radius = 0.5\n    ' \
           'double3 xformOp:translate = (5, 0, 0)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n'
    s = load_stage(write_stage(tmp_path, body))
    g = s.geometry
    n = tri_normals(s)
    centroid = g.points[g.triangles].mean(axis=1)
    centre = np.where(g.prim[:, None] == 0, 0.0, [5.0, 0, 0])
    assert np.all(np.einsum("ij,ij->i", n, centroid - centre) > 0)
    n_lon, n_lat = SPHERE_SEGMENTS
    assert np.bincount(g.prim).tolist() == [12, 2 * n_lon + 2 * n_lon * (n_lat - 2)]
    cube_pts = g.points[np.unique(g.triangles[g.prim == 0])]
    np.testing.assert_allclose(np.abs(cube_pts), 1.0)
    sph_pts = g.points[np.unique(g.triangles[g.prim == 1])]
    np.testing.assert_allclose(np.linalg.norm(sph_pts - [5, 0, 0], axis=1), 0.5)


def test_instanceable_prims_read_through_instance_proxies(tmp_path):
    """Two instanceable references to one prototype (a 1-triangle mesh) give 2 triangles at 2 places."""
    body = """
class "Proto"
{
    def Mesh "Tri"
    {
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    }
}
def Xform "A" (instanceable = true
    references = </Proto>)
{
    double3 xformOp:translate = (10, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Xform "B" (instanceable = true
    references = </Proto>)
{
    double3 xformOp:translate = (20, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
"""
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.n_triangles == 2
    assert sorted(s.geometry.prim_names) == ["/A/Tri", "/B/Tri"]
    xs = {s.geometry.points[s.geometry.triangles[i], 0].min() for i in range(2)}
    assert xs == {10.0, 20.0}


def test_inactive_invisible_guide_and_proxy_prims_are_skipped(tmp_path):
    """Only /Kept (default purpose) and /Render (purpose render) survive.

    Skipped: an inactive mesh, a mesh under an invisible Xform (visibility is
    inherited), guide- and proxy-purpose meshes, and an invisible light.
    """
    tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    body = quad_mesh("Kept", tri)
    body += quad_mesh("Render", tri, 'uniform token purpose = "render"')
    body += quad_mesh("Guide", tri, 'uniform token purpose = "guide"')
    body += quad_mesh("Proxy", tri, 'uniform token purpose = "proxy"')
    body += quad_mesh("Off", tri).replace('def Mesh "Off"', 'def Mesh "Off" (active = false)')
    body += 'def Xform "Hidden"\n{\n    token visibility = "invisible"\n' + quad_mesh("Child", tri) + "\n}\n"
    body += 'def SphereLight "Dark"\n{\n    token visibility = "invisible"\n}\n'
    body += 'def SphereLight "Lit"\n{\n}\n'
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.prim_names == ["/Kept", "/Render"]
    assert [l.name for l in s.lights] == ["/Lit"]


def test_degenerate_faces_skipped_and_bad_indices_rejected(tmp_path):
    """A 2-vertex face is skipped (with a warning); an index past the points is a UserError naming the prim."""
    pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    s = load_stage(write_stage(tmp_path, quad_mesh("M", pts, counts=[2, 3], indices=[0, 1, 0, 1, 2])))
    assert s.geometry.n_triangles == 1
    assert any("fewer than 3" in w for w in s.warnings)
    with pytest.raises(UserError, match=r"s\.usda: /Bad: .*out of range"):
        load_stage(write_stage(tmp_path, quad_mesh("Bad", pts, indices=[0, 1, 7])))


def test_unsupported_gprims_are_one_summary_warning_with_counts(tmp_path):
    """Three BasisCurves and two Points are not read: no triangles, and exactly one
    warning line that counts them by type ("not read: 3 BasisCurves, 2 Points")."""
    body = "".join(f'def BasisCurves "C{i}"\n{{\n}}\n' for i in range(3))
    body += "".join(f'def Points "P{i}"\n{{\n}}\n' for i in range(2))
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.n_triangles == 0
    lines = [w for w in s.warnings if "not read" in w]
    assert lines == ["s.usda: not read: 3 BasisCurves, 2 Points"], s.warnings


# --------------------------------------------------------------------------- #
# materials
# --------------------------------------------------------------------------- #


def test_coloured_albedo_becomes_luminance_grey_with_one_warning(tmp_path):
    """diffuseColor (0.5, 0.25, 0.15) -> 0.2126*0.5 + 0.7152*0.25 + 0.0722*0.15 = 0.29593.

    Two prims share the coloured material, a third is grey: exactly one
    warning, naming both coloured prims and not the grey one.
    """
    tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    body = material("Rust", (0.5, 0.25, 0.15)) + material("Grey", (0.4, 0.4, 0.4))
    body += quad_mesh("Sofa", tri, bound("Rust")) + quad_mesh("Rug", tri, bound("Rust"))
    body += quad_mesh("Wall", tri, bound("Grey"))
    s = load_stage(write_stage(tmp_path, body))
    expected = 0.2126 * 0.5 + 0.7152 * 0.25 + 0.0722 * 0.15
    assert s.geometry.albedo.tolist() == pytest.approx([expected, expected, 0.4])
    grey_warnings = [w for w in s.warnings if "luminance grey" in w]
    assert len(grey_warnings) == 1
    assert "/Sofa" in grey_warnings[0] and "/Rug" in grey_warnings[0] and "/Wall" not in grey_warnings[0]


def test_albedo_defaults_display_color_and_connections(tmp_path):
    """No material: displayColor (0.6 grey) if authored, else UsdPreviewSurface's 0.18.

    A diffuseColor connected to a Material interface input (0.3 grey) is
    followed to that constant.
    """
    tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    body = quad_mesh("Plain", tri)
    body += quad_mesh("Shown", tri, "color3f[] primvars:displayColor = [(0.6, 0.6, 0.6)]")
    body += quad_mesh("Linked", tri, bound("Mat")).replace(
        'def Mesh "Linked"', 'def Mesh "Linked" (\n    prepend apiSchemas = ["MaterialBindingAPI"]\n)')
    body += """
def Material "Mat"
{
    color3f inputs:base = (0.3, 0.3, 0.3)
    token outputs:surface.connect = </Mat/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor.connect = </Mat.inputs:base>
        token outputs:surface
    }
}
"""
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.albedo.tolist() == pytest.approx([DEFAULT_ALBEDO, 0.6, 0.3])
    assert DEFAULT_ALBEDO == 0.18
    assert not s.warnings


def test_emissive_geometry_and_double_sided(tmp_path):
    """emissiveColor 50 (grey) in photometric mode: emission = (50 / K(D65), 50) per triangle; doubleSided flags it."""
    tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    body = material("Glow", (0.1, 0.1, 0.1), emissive=(50, 50, 50))
    body += quad_mesh("Panel", tri, bound("Glow") + "\n    uniform bool doubleSided = 1")
    body += quad_mesh("Dull", tri, bound("Glow"))
    s = load_stage(write_stage(tmp_path, body))
    np.testing.assert_allclose(s.geometry.emission, [[50 / K_D65, 50]] * 2, rtol=1e-12)
    assert s.geometry.two_sided.tolist() == [True, False]


def test_opacity_zero_prim_left_out(tmp_path):
    """opacity 0 in presence mode: the prim blocks no light, so it is not in the geometry; a warning
    says so. In the default transparent mode the same opacity is a clear pane, and kept."""
    tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    cut = material("Cut", opacity=0).replace("float inputs:opacity = 0", 'float inputs:opacity = 0\n'
                                              '        token inputs:opacityMode = "presence"')
    body = cut + quad_mesh("Pane", tri, bound("Cut")) + quad_mesh("Wall", tri)
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.prim_names == ["/Wall"]
    assert any("/Pane" in w and "opacity 0 in presence mode" in w for w in s.warnings)
    body = material("Glass", opacity=0) + quad_mesh("Pane", tri, bound("Glass")) + quad_mesh("Wall", tri)
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.prim_names == ["/Pane", "/Wall"] and not any("left out" in w for w in s.warnings)


@pytest.mark.parametrize("diffuse", [(1.2, 1.2, 1.2), (1.0, 1.0, 1.01), (-0.1, -0.1, -0.1)])
def test_albedo_out_of_range_is_user_error(tmp_path, diffuse):
    """Albedo > 1 (or < 0) breaks energy conservation: UserError naming file and prim."""
    tri = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    path = write_stage(tmp_path, material("White", diffuse) + quad_mesh("Snow", tri, bound("White")))
    with pytest.raises(UserError, match=r"s\.usda: /Snow: albedo .*\[0, 1\]"):
        load_stage(path)


# --------------------------------------------------------------------------- #
# lights
# --------------------------------------------------------------------------- #

LIGHT_CASES = [
    # (id, type, attributes, expected kind, expected value: intensity * 2^exposure * grey(color) / sizeFactor)
    ("rect", "RectLight", "float inputs:intensity = 10\nfloat inputs:exposure = 1", LightKind.RECT, 20.0),
    ("rect-normalized", "RectLight", "float inputs:intensity = 10\nfloat inputs:width = 2\n"
     "float inputs:height = 0.5\nbool inputs:normalize = 1", LightKind.RECT, 10.0 / 1.0),
    ("rect-colour", "RectLight", "float inputs:intensity = 10\ncolor3f inputs:color = (0.5, 0.5, 0.5)",
     LightKind.RECT, 5.0),
    ("disk-normalized", "DiskLight", "float inputs:intensity = 10\nfloat inputs:radius = 0.5\n"
     "bool inputs:normalize = 1", LightKind.DISK, 10.0 / (math.pi * 0.25)),
    ("sphere", "SphereLight", "float inputs:intensity = 10\nfloat inputs:exposure = -2", LightKind.SPHERE, 2.5),
    ("sphere-normalized", "SphereLight", "float inputs:intensity = 10\nfloat inputs:radius = 0.5\n"
     "bool inputs:normalize = 1", LightKind.SPHERE, 10.0 / (4 * math.pi * 0.25)),
    ("cylinder-normalized", "CylinderLight", "float inputs:intensity = 10\nfloat inputs:radius = 0.5\n"
     "float inputs:length = 2\nbool inputs:normalize = 1", LightKind.CYLINDER, 10.0 / (2 * math.pi * 0.5 * 2)),
    ("point", "SphereLight", "float inputs:intensity = 10\nfloat inputs:radius = 0.1\nbool treatAsPoint = 1",
     LightKind.POINT, 10.0 * math.pi * 0.01),
    ("point-normalized", "SphereLight", "float inputs:intensity = 10\nfloat inputs:radius = 0.1\n"
     "bool treatAsPoint = 1\nbool inputs:normalize = 1", LightKind.POINT, 10.0 / 4),
    ("point-r0-normalized", "SphereLight", "float inputs:intensity = 10\nfloat inputs:radius = 0\n"
     "bool inputs:normalize = 1", LightKind.POINT, 10.0 / 4),
    ("distant-delta", "DistantLight", "float inputs:intensity = 10\nfloat inputs:angle = 0", LightKind.DISTANT, 10.0),
    ("distant-delta-normalized", "DistantLight", "float inputs:intensity = 10\nfloat inputs:angle = 0\n"
     "bool inputs:normalize = 1", LightKind.DISTANT, 10.0),
    ("distant-cone", "DistantLight", "float inputs:intensity = 10\nfloat inputs:angle = 10", LightKind.DISTANT, 10.0),
    ("distant-cone-normalized", "DistantLight", "float inputs:intensity = 10\nfloat inputs:angle = 10\n"
     "bool inputs:normalize = 1", LightKind.DISTANT, 10.0 / (math.pi * math.sin(math.radians(5)) ** 2)),
    ("dome", "DomeLight", "float inputs:intensity = 10\nbool inputs:normalize = 1", LightKind.DOME, 10.0),
]


@pytest.mark.parametrize("typ, attrs, kind, value", [c[1:] for c in LIGHT_CASES], ids=[c[0] for c in LIGHT_CASES])
def test_light_emission_rule(tmp_path, typ, attrs, kind, value):
    """emission = (value / K(D65), value) in photometric mode, value per DESIGN.md "UsdLux emission".

    value = intensity * 2^exposure * grey(color) / sizeFactor, sizeFactor = world
    area (rect w*h, disk pi r^2, sphere 4 pi r^2, cylinder 2 pi r len) or
    pi sin^2(angle/2) for a DistantLight when normalize is on. Point lights
    (treatAsPoint or r = 0) carry I = L pi r^2 (normalized: intensity/4); a
    zero-angle DistantLight carries the normal irradiance = value.
    """
    s = light_stage(tmp_path, typ, attrs.replace("\n", "\n    "))
    (light,) = s.lights
    assert light.kind == kind
    assert light.emission[1] == pytest.approx(value, rel=1e-12)
    assert light.emission[0] == pytest.approx(value / K_D65, rel=1e-12)


def test_normalized_distant_light_gives_irradiance_equal_to_intensity(tmp_path):
    """A normalized DistantLight of angle 10 deg: normal irradiance = L * pi sin^2(5 deg) = intensity.

    A uniform cone of half-angle t and radiance L gives E = L pi sin^2 t on a
    surface facing it, which is exactly the sizeFactor the reader divides by.
    """
    s = light_stage(tmp_path, "DistantLight", "float inputs:intensity = 1000\n    float inputs:angle = 10\n"
                    "    bool inputs:normalize = 1")
    (light,) = s.lights
    assert light.half_angle == pytest.approx(math.radians(5))
    assert light.emission[1] * math.pi * math.sin(light.half_angle) ** 2 == pytest.approx(1000.0)
    assert not light.is_delta


def test_distant_light_shines_down_by_default(tmp_path):
    """With no transform a DistantLight shines along -Z: frame[:, 2] = +Z (toward the light); angle 0 is a delta."""
    s = light_stage(tmp_path, "DistantLight", "float inputs:angle = 0")
    (light,) = s.lights
    np.testing.assert_allclose(light.frame, np.eye(3))
    assert light.half_angle == 0.0 and light.is_delta


def test_sphere_radius_zero_without_normalize_warns(tmp_path):
    """radius 0, no treatAsPoint, no normalize: a point of intensity L pi 0^2 = 0.

    The reader warns that it emits nothing.
    """
    s = light_stage(tmp_path, "SphereLight", "float inputs:radius = 0")
    (light,) = s.lights
    assert light.kind == LightKind.POINT and light.emission == (0.0, 0.0)
    assert any("/L" in w and "emits nothing" in w for w in s.warnings)


def test_non_uniform_scale_on_sphere_light_uses_mean_and_warns(tmp_path):
    """Scale (1, 2, 3) on a radius-1 SphereLight: world radius = mean scale = 2, with a warning."""
    s = light_stage(tmp_path, "SphereLight", "float inputs:radius = 1",
                    'float3 xformOp:scale = (1, 2, 3)\n    uniform token[] xformOpOrder = ["xformOp:scale"]')
    assert s.lights[0].radius == pytest.approx(2.0)
    assert any("non-uniform scale" in w for w in s.warnings)


def test_color_temperature_in_photometric_mode(tmp_path):
    """Photometric mode, colorTemperature 3000 K enabled: the photometric value stays intensity (blackbody
    colour is luminance-normalised in UsdLux); the radiometric twin becomes intensity / K(3000 K), not / K(D65)."""
    s = light_stage(tmp_path, "RectLight", "float inputs:intensity = 100\n    bool inputs:enableColorTemperature = 1\n"
                    "    float inputs:colorTemperature = 3000")
    rad, phot = s.lights[0].emission
    assert phot == pytest.approx(100.0)
    assert rad == pytest.approx(100.0 / luminous_efficacy(3000.0))
    assert rad != pytest.approx(100.0 / K_D65, rel=1e-3)


def test_radiometric_mode_and_color_temperature(tmp_path):
    """Radiometric mode: the stated number is the radiometric value; its twin uses the emitter's spectrum.

    Plain light: spectrum = radiometric_spectrum ("E"): (100, 100 K(E)).
    colorTemperature 3000 K: (100, 100 K(3000 K)). Surfaces use "E" too.
    """
    body = 'def RectLight "A"\n{\n    float inputs:intensity = 100\n}\n'
    body += 'def RectLight "B"\n{\n    float inputs:intensity = 100\n    bool inputs:enableColorTemperature = 1\n' \
            '    float inputs:colorTemperature = 3000\n}\n'
    body += material("Glow", (0.1, 0.1, 0.1), emissive=(2, 2, 2))
    body += quad_mesh("Panel", [(0, 0, 0), (1, 0, 0), (0, 1, 0)], bound("Glow"))
    s = load_stage(write_stage(tmp_path, body), light_units="radiometric", radiometric_spectrum="E")
    a, b = s.lights
    assert a.emission == pytest.approx((100.0, 100.0 * luminous_efficacy("E")))
    assert b.emission == pytest.approx((100.0, 100.0 * luminous_efficacy(3000.0)))
    assert s.geometry.emission[0].tolist() == pytest.approx([2.0, 2.0 * luminous_efficacy("E")])


def test_coloured_light_reduced_to_grey(tmp_path):
    """color (1, 0, 0): grey = 0.2126, so value = 10 * 0.2126; the light is named in the grey warning."""
    s = light_stage(tmp_path, "DiskLight", "float inputs:intensity = 10\n    color3f inputs:color = (1, 0, 0)")
    assert s.lights[0].emission[1] == pytest.approx(10 * luminance_grey((1, 0, 0)))
    assert any("luminance grey" in w and "/L" in w for w in s.warnings)


def test_rotated_rect_light_frame(tmp_path):
    """rotateXYZ (0, -90, 0): local -Z (the emission direction) becomes world +X, local X becomes world +Z."""
    s = light_stage(tmp_path, "RectLight", "float inputs:width = 2",
                    'float3 xformOp:rotateXYZ = (0, -90, 0)\n    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]')
    f = s.lights[0].frame
    np.testing.assert_allclose(-f[:, 2], [1, 0, 0], atol=1e-7)
    np.testing.assert_allclose(f[:, 0], [0, 0, 1], atol=1e-7)
    np.testing.assert_allclose(f.T @ f, np.eye(3), atol=1e-12)


def test_dome_texture_resolved(tmp_path):
    """texture:file is stored as an absolute path; a missing texture is a UserError naming the prim."""
    from simulator.io import exr

    exr.write_channels(tmp_path / "sky.exr", {"Y": np.ones((2, 4))})  # the map is read too (test_more_lights)
    s = light_stage(tmp_path, "DomeLight", "asset inputs:texture:file = @./sky.exr@")
    assert s.lights[0].texture == str((tmp_path / "sky.exr").resolve())
    assert light_stage(tmp_path, "DomeLight", "").lights[0].texture == ""
    with pytest.raises(UserError, match=r"s\.usda: /L: texture:file"):
        light_stage(tmp_path, "DomeLight", "asset inputs:texture:file = @./missing.exr@")


def test_lights_are_not_geometry(tmp_path):
    """A stage of lights only has an empty triangle soup."""
    s = load_stage(STAGES / "sphere.usda")
    assert s.geometry.n_triangles == 0 and len(s.lights) == 1


# --------------------------------------------------------------------------- #
# sensors
# --------------------------------------------------------------------------- #


def test_stage_sensors_face_local_minus_z(tmp_path):
    """Sensors sit at the prim's world origin and face world(-Z); up = world(+Y).

    * desk: irradiance, rotated 180 deg about X -> normal (0, 0, 1) (faces up), up (0, -1, 0).
    * meter: radiance, unrotated -> normal (0, 0, -1); half-angle 5 deg; name defaults to the prim path.
    * patch: size (50, 20) cm in a cm stage -> (0.5, 0.2) m.
    * probe: resolution defaults to (64, 32).
    """
    body = """
def Xform "Desk"
{
    token probesim:sensor:kind = "irradiance"
    string probesim:sensor:name = "desk"
    double3 xformOp:translate = (100, 200, 75)
    float3 xformOp:rotateXYZ = (180, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
}
def Xform "Meter"
{
    token probesim:sensor:kind = "radiance"
    float probesim:sensor:halfAngleDeg = 5
}
def Xform "Patch"
{
    string probesim:sensor:kind = "patch"
    float2 probesim:sensor:size = (50, 20)
}
def Xform "Probe"
{
    token probesim:sensor:kind = "probe"
}
"""
    s = load_stage(write_stage(tmp_path, body, mpu=0.01))
    desk, meter, patch, probe = s.sensors
    assert (desk.name, desk.kind, desk.source) == ("desk", SensorKind.IRRADIANCE, "/Desk")
    np.testing.assert_allclose(desk.position, [1, 2, 0.75])
    np.testing.assert_allclose(desk.normal, [0, 0, 1], atol=1e-7)
    np.testing.assert_allclose(desk.up, [0, -1, 0], atol=1e-7)
    assert (meter.name, meter.kind) == ("/Meter", SensorKind.RADIANCE)
    np.testing.assert_allclose(meter.normal, [0, 0, -1])
    assert meter.half_angle == pytest.approx(math.radians(5))
    assert patch.kind == SensorKind.PATCH and patch.size == pytest.approx((0.5, 0.2))
    assert probe.kind == SensorKind.PROBE and probe.resolution == (64, 32)


def test_stage_sensor_in_y_up_stage(tmp_path):
    """In a Y-up stage an unrotated sensor faces stage -Z = (0, 0, -1)_Yup -> (0, 1, 0)_Zup; its up (+Y) -> +Z."""
    body = 'def Xform "S"\n{\n    token probesim:sensor:kind = "irradiance"\n}\n'
    (sensor,) = load_stage(write_stage(tmp_path, body, up="Y")).sensors
    np.testing.assert_allclose(sensor.normal, [0, 1, 0], atol=1e-12)
    np.testing.assert_allclose(sensor.up, [0, 0, 1], atol=1e-12)


def test_quickstart_sensors_and_lights():
    """quickstart.usda: the desk sensor faces up on the table (z = 0.76); the meter looks at the window (-X).

    The luminaire faces down (-frame_z = -Z) and the window light faces into the room (+X).
    """
    s = load_stage(STAGES / "quickstart.usda")
    sensors = {x.name: x for x in s.sensors}
    np.testing.assert_allclose(sensors["desk"].normal, [0, 0, 1], atol=1e-7)
    np.testing.assert_allclose(sensors["window_view"].normal, [-1, 0, 0], atol=1e-7)
    lights = {l.name.rsplit("/", 1)[-1]: l for l in s.lights}
    np.testing.assert_allclose(-lights["Luminaire"].frame[:, 2], [0, 0, -1], atol=1e-7)
    np.testing.assert_allclose(-lights["Window"].frame[:, 2], [1, 0, 0], atol=1e-7)
    assert sum("luminance grey" in w for w in s.warnings) == 1


# --------------------------------------------------------------------------- #
# errors
# --------------------------------------------------------------------------- #


def test_missing_file_is_user_error(tmp_path):
    """A path that does not exist: UserError starting with the path."""
    path = tmp_path / "nope.usda"
    with pytest.raises(UserError, match=r"nope\.usda: no such file"):
        load_stage(path)


@pytest.mark.parametrize("name, content", [("junk.usda", "hello world"), ("junk.txt", "hello"),
                                           ("junk.usd", "\x00\x01garbage")])
def test_not_usd_file_is_user_error(tmp_path, name, content):
    """Text that is not usda, an unknown extension, binary junk: a one-line UserError naming the file."""
    path = tmp_path / name
    path.write_text(content)
    with pytest.raises(UserError) as info:
        load_stage(path)
    msg = str(info.value)
    assert msg.startswith(str(path)) and "not a readable USD stage" in msg and "\n" not in msg


@pytest.mark.parametrize("typ, attrs, what", [
    ("SphereLight", "float inputs:intensity = -1", "intensity"),
    ("SphereLight", "float inputs:radius = -0.5", "radius"),
    ("RectLight", "float inputs:width = -1", "width"),
])
def test_negative_light_values_are_user_errors(tmp_path, typ, attrs, what):
    """Negative intensity or size has no physical meaning: UserError naming file, prim and attribute."""
    with pytest.raises(UserError, match=rf"s\.usda: /L: {what} must be"):
        light_stage(tmp_path, typ, attrs)


def test_nan_transform_is_user_error(tmp_path):
    """A NaN in a transform: UserError '<file>: <prim>: transform contains NaN or Inf'."""
    xform = 'double3 xformOp:translate = (nan, 0, 0)\n    uniform token[] xformOpOrder = ["xformOp:translate"]'
    body = quad_mesh("M", [(0, 0, 0), (1, 0, 0), (0, 1, 0)], xform)
    with pytest.raises(UserError, match=r"s\.usda: /M: transform contains NaN or Inf"):
        load_stage(write_stage(tmp_path, body))


def test_unknown_sensor_kind_is_user_error(tmp_path):
    """kind 'lux' is not a sensor kind: UserError naming the prim and listing the valid kinds."""
    body = 'def Xform "S"\n{\n    token probesim:sensor:kind = "lux"\n}\n'
    with pytest.raises(UserError, match=r"s\.usda: /S: .*'lux'.*irradiance, radiance, patch, probe"):
        load_stage(write_stage(tmp_path, body))


def test_bad_options_are_user_errors(tmp_path):
    """light_units and radiometric_spectrum are checked before the stage is read."""
    path = write_stage(tmp_path, "")
    with pytest.raises(UserError, match="light_units"):
        load_stage(path, light_units="lux")
    with pytest.raises(UserError, match="radiometric_spectrum"):
        load_stage(path, light_units="radiometric", radiometric_spectrum="A")


# --------------------------------------------------------------------------- #
# bundled stages
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("path", sorted(STAGES.glob("*.usda")), ids=lambda p: p.name)
def test_bundled_stage_loads(path):
    """Every stage in stages/ loads, emits light (a UsdLux light or emissive
    geometry), and its arrays are consistent."""
    s = load_stage(path)
    g = s.geometry
    assert s.path == str(path)
    assert s.lights or np.any(g.emission > 0)
    assert len(g.albedo) == len(g.emission) == len(g.two_sided) == len(g.prim) == g.n_triangles
    assert np.all((g.albedo >= 0) & (g.albedo < 1))
    assert np.all(np.isfinite(g.points))


def test_bundled_closed_form_stages_have_no_blockers():
    """point, sphere, rect, disk and point_cm_yup have no geometry: their closed forms assume nothing occludes."""
    for name in ("point", "sphere", "rect", "disk", "point_cm_yup"):
        assert load_stage(STAGES / f"{name}.usda").geometry.n_triangles == 0, name


@pytest.mark.parametrize("typ, up, pole", [
    ("DomeLight", "Z", [0, 1, 0]),      # DomeLight: pole on its own +Y, whatever the stage's up axis
    ("DomeLight", "Y", [0, 0, 1]),      # ... which a Y-up stage maps to world +Z
    ("DomeLight_1", "Z", [0, 0, 1]),    # DomeLight_1, poleAxis "scene": pole on the stage up axis
    ("DomeLight_1", "Y", [0, 0, 1]),
])
def test_dome_texture_frame_pole(tmp_path, typ, up, pole):
    """Dome frame = lat-long texture frame (OpenEXR): frame[:, 1] is the map's north pole.

    UsdLux DomeLight puts the pole on the light's +Y; DomeLight_1 with poleAxis
    "scene" on the stage's up axis. Both read as DOME lights.
    """
    s = load_stage(write_stage(tmp_path, f'def {typ} "Sky"\n{{\n    float inputs:intensity = 2\n}}\n', up=up))
    (light,) = s.lights
    assert light.kind == LightKind.DOME and light.emission[1] == pytest.approx(2.0)
    np.testing.assert_allclose(light.frame[:, 1], pole, atol=1e-12)
    assert np.linalg.det(light.frame) == pytest.approx(1.0)


def test_composition_error_is_a_warning(tmp_path):
    """An unresolvable reference does not stop the read; it becomes a warning."""
    body = 'def Xform "A" (references = @./missing.usda@)\n{\n}\n' + quad_mesh("M", [(0, 0, 0), (1, 0, 0), (0, 1, 0)])
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.n_triangles == 1
    assert any("composition error" in w and "missing.usda" in w for w in s.warnings)


def test_unsupported_light_warns(tmp_path):
    """Two PluginLights are not read: no light, one summary warning counting
    them. (PortalLights are read onto their dome: tests/test_portals_reader.py.)"""
    s = load_stage(write_stage(tmp_path, 'def PluginLight "Plugin"\n{\n}\ndef PluginLight "P2"\n{\n}\n'))
    assert not s.lights
    assert [w for w in s.warnings if "not read" in w] == ["s.usda: not read: 2 PluginLight"]


def test_mesh_light_is_emitting_geometry(tmp_path):
    """A Mesh with MeshLightAPI is geometry (it blocks light) that emits its UsdLux light
    value (default intensity 1 nit: the pair (1/K(D65), 1)) from its front face; no material
    bound: albedo 0. It is not a UsdLux light record. (More in test_more_lights.)"""
    body = quad_mesh("Panel", [(0, 0, 0), (1, 0, 0), (0, 1, 0)]).replace(
        'def Mesh "Panel"', 'def Mesh "Panel" (prepend apiSchemas = ["MeshLightAPI"])')
    s = load_stage(write_stage(tmp_path, body))
    assert s.geometry.prim_names == ["/Panel"] and not s.lights
    np.testing.assert_allclose(s.geometry.emission, [(1.0 / luminous_efficacy("D65"), 1.0)], rtol=1e-12)
    assert np.all(s.geometry.albedo == 0)


def test_dome_stage_ground_is_wide_and_faces_up():
    """dome.usda: the black ground faces +Z and reaches 10 km out, so the infinite-ground
    closed form E = pi L (1 + cos b) / 2 holds to ~1e-4 for receivers 1 m up; its centre
    tile is 2 m wide so a sensor on the ground at the origin sits on a small triangle."""
    s = load_stage(STAGES / "dome.usda")
    g = s.geometry
    assert np.all(tri_normals(s)[:, 2] > 0) and np.all(g.albedo == 0)
    assert g.points[:, 0].max() == 10000 and g.points[:, 1].min() == -10000
    p = g.points[g.triangles]
    at_origin = [i for i in range(g.n_triangles) if np.abs(p[i, :, :2]).max() <= 1.0]
    assert at_origin  # the origin lies in a triangle no larger than the 2 m centre tile


def test_float_attributes_keep_their_digits_whatever_numpy_print_options(tmp_path):
    """A float32 intensity of 1234.5677 must read back as authored even when
    some imported package has switched numpy to its 6-digit legacy print mode
    (the reader recovers authored decimals from float32 without str())."""
    stage = tmp_path / "s.usda"
    stage.write_text(
        '#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n'
        'def SphereLight "L"\n{\n    float inputs:intensity = 1234.5677\n    float inputs:radius = 0.1\n'
        '    bool treatAsPoint = 1\n}\n'
    )
    saved = np.get_printoptions()
    try:
        np.set_printoptions(legacy="1.13")
        light = load_stage(stage, light_units="radiometric").lights[0]
    finally:
        np.set_printoptions(**saved)
    assert light.emission[0] == pytest.approx(1234.5677 * np.pi * 0.1**2, rel=1e-12)
