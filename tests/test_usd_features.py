"""USD as people author it, read (no tracing): shapes, instancers, bindings, textures, warnings, refusals.

Each test writes a tiny stage as usda text under ``tmp_path`` and checks what
the stage reader hands on. The traced counterparts (shadows, rho E / pi,
dome readings) are in ``test_usd_features_traced.py``.
"""

from __future__ import annotations

import math
import struct
import zlib
from pathlib import Path

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.errors import UserError
from simulator.io.hdr import decode_rgbe, encode_rgbe
from simulator.io.images import srgb_to_linear
from simulator.scene.usd import load_stage


def stage(tmp_path: Path, body: str, header: str = "metersPerUnit = 1\n    upAxis = \"Z\"",
          name: str = "s.usda") -> Path:
    path = tmp_path / name
    path.write_text(f"#usda 1.0\n(\n    {header}\n)\n\n{body}\n")
    return path


def shader_material(name: str, inputs: str) -> str:
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


def grey(name: str, rho: float, extra: str = "") -> str:
    return shader_material(name, f"color3f inputs:diffuseColor = ({rho}, {rho}, {rho})\n        {extra}")


TRI = """
def Mesh "{name}"
{{
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    {extra}
}}
"""


def tri(name: str, extra: str = "") -> str:
    return TRI.format(name=name, extra=extra)


def area_volume(scene) -> tuple[float, float]:
    """Surface area and enclosed volume (divergence theorem: sum p0 . (p1 x p2) / 6) of the soup."""
    p = scene.geometry.points[scene.geometry.triangles]
    cross = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    return 0.5 * float(np.linalg.norm(cross, axis=1).sum()), float(np.einsum("ij,ij->", p[:, 0], cross)) / 6.0


# --------------------------------------------------------------------------- #
# Capsule, Cone, Cylinder, Plane
# --------------------------------------------------------------------------- #

R, H = 0.5, 1.0
SHAPES = {
    # type: (attrs, analytic area, analytic volume)
    "Capsule": ("", 2 * math.pi * R * H + 4 * math.pi * R * R, math.pi * R * R * H + 4 / 3 * math.pi * R ** 3),
    "Cone": ("", math.pi * R * math.hypot(R, H) + math.pi * R * R, math.pi * R * R * H / 3),
    "Cylinder": ("", 2 * math.pi * R * H + 2 * math.pi * R * R, math.pi * R * R * H),
}


@pytest.mark.parametrize("segments", [None, (512, 256)], ids=["default", "fine"])
@pytest.mark.parametrize("typ", sorted(SHAPES))
def test_round_shapes_area_and_volume_match_the_analytic_ones(tmp_path, typ, segments):
    """Tessellated area and volume fall short of the analytic ones (vertices lie on
    the surface) by at most 2 (2 pi / n)^2 / 6: an inscribed regular n-gon keeps a
    fraction sin(2 pi/n)/(2 pi/n) ~ 1 - (2 pi/n)^2/6 of the circle's area, and a
    Capsule's latitude bands lose about as much again. n = 64 (0.32%) by default;
    ``probesim:tessellation = (512, 256)`` brings it to 5e-5. The volume is
    positive: every face points outward."""
    attr = "" if segments is None else f"int2 probesim:tessellation = {segments}"
    body = f'def {typ} "S"\n{{\n    double radius = {R}\n    double height = {H}\n    {attr}\n}}\n'
    area, volume = area_volume(load_stage(stage(tmp_path, body)))
    _, a_true, v_true = SHAPES[typ]
    n = 64 if segments is None else segments[0]
    tol = 2 * (2 * math.pi / n) ** 2 / 6
    assert 0 < 1 - area / a_true <= tol, (area, a_true)
    assert 0 < 1 - volume / v_true <= tol, (volume, v_true)


def test_cylinder_1_frustum_and_capsule_1(tmp_path):
    """Cylinder_1 with radiusTop 0.2, radiusBottom 0.5 is a capped frustum of
    volume pi h (r1^2 + r1 r2 + r2^2)/3; Capsule_1 with equal radii is a capsule;
    Capsule_1 with two radii is not read (counted in the summary warning)."""
    body = 'def Cylinder_1 "F"\n{\n    double radiusTop = 0.2\n    double radiusBottom = 0.5\n    double height = 1\n}\n'
    _, volume = area_volume(load_stage(stage(tmp_path, body)))
    truth = math.pi * 1.0 * (0.04 + 0.1 + 0.25) / 3
    assert 0 < 1 - volume / truth <= 2 * (2 * math.pi / 64) ** 2 / 6
    body = 'def Capsule_1 "C"\n{\n    double radiusTop = 0.5\n    double radiusBottom = 0.5\n    double height = 1\n}\n'
    _, volume = area_volume(load_stage(stage(tmp_path, body)))
    assert 0 < 1 - volume / SHAPES["Capsule"][2] <= 2 * (2 * math.pi / 64) ** 2 / 6
    s = load_stage(stage(tmp_path, body.replace("radiusBottom = 0.5", "radiusBottom = 0.3")))
    assert s.geometry.n_triangles == 0
    assert "s.usda: not read: 1 Capsule_1 with two radii" in s.warnings


@pytest.mark.parametrize("axis, long_axis", [("X", 0), ("Y", 1), ("Z", 2)])
def test_axis_turns_the_shape(tmp_path, axis, long_axis):
    """A Cylinder of height 4 and radius 0.5 along ``axis`` spans [-2, 2] along it
    and [-0.5, 0.5] across it."""
    body = f'def Cylinder "C"\n{{\n    double radius = 0.5\n    double height = 4\n    uniform token axis = "{axis}"\n}}\n'
    pts = load_stage(stage(tmp_path, body)).geometry.points
    span = pts.max(axis=0) - pts.min(axis=0)
    np.testing.assert_allclose(span[long_axis], 4.0)
    np.testing.assert_allclose(np.delete(span, long_axis), 1.0, atol=1e-12)


@pytest.mark.parametrize("axis, width_axis, length_axis", [("Z", 0, 1), ("Y", 0, 2), ("X", 2, 1)])
def test_plane_width_length_axis_and_double_sided(tmp_path, axis, width_axis, length_axis):
    """UsdGeom.Plane: width 2 and length 3 along the axes the schema names, front
    face along +axis, double-sided by its fallback; area 6."""
    body = f'def Plane "P"\n{{\n    double width = 2\n    double length = 3\n    uniform token axis = "{axis}"\n}}\n'
    s = load_stage(stage(tmp_path, body))
    g = s.geometry
    span = g.points.max(axis=0) - g.points.min(axis=0)
    assert span[width_axis] == 2.0 and span[length_axis] == 3.0
    p = g.points[g.triangles]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert np.all(n[:, "XYZ".index(axis)] > 0)
    assert math.isclose(area_volume(s)[0], 6.0)
    assert g.two_sided.all()


# --------------------------------------------------------------------------- #
# PointInstancer (read), scene-graph instancing
# --------------------------------------------------------------------------- #


def test_point_instancer_places_prototypes_only_where_instances_stand(tmp_path):
    """Prototypes under the instancer (in a Scope) and in an ``over`` elsewhere are
    drawn only at the instances: 3 instances of a 1-triangle prototype and one of
    a 2-triangle one give 5 triangles, at the instance positions plus the
    instancer's translate (0, 0, 2); the prototype in the ``over`` keeps its own
    transform (a translate (0, 0, 1)) inside each instance."""
    body = """
def PointInstancer "I"
{
    double3 xformOp:translate = (0, 0, 2)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    rel prototypes = [</I/Protos/Tri>, </Elsewhere/Pair>]
    int[] protoIndices = [0, 0, 0, 1]
    point3f[] positions = [(10, 0, 0), (20, 0, 0), (30, 0, 0), (40, 0, 0)]
    def Scope "Protos"
    {
        def Mesh "Tri"
        {
            int[] faceVertexCounts = [3]
            int[] faceVertexIndices = [0, 1, 2]
            point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
        }
    }
}
over "Elsewhere"
{
    def Mesh "Pair"
    {
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        int[] faceVertexCounts = [3, 3]
        int[] faceVertexIndices = [0, 1, 2, 0, 2, 3]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    }
}
"""
    g = load_stage(stage(tmp_path, body)).geometry
    assert g.n_triangles == 5
    corner = g.points[g.triangles].min(axis=1)
    assert sorted(map(tuple, np.unique(corner, axis=0))) == [(10, 0, 2), (20, 0, 2), (30, 0, 2), (40, 0, 3)]


def test_point_instancer_hides_invisible_and_guide_prims_inside_prototypes(tmp_path):
    """Inside a prototype, a mesh with ``visibility = "invisible"`` and one of
    ``purpose = "guide"`` are not drawn; the visible sibling is, at both instances;
    a light inside a prototype is not read and is counted in the summary."""
    body = """
def PointInstancer "I"
{
    rel prototypes = [</I/P>]
    int[] protoIndices = [0, 0]
    point3f[] positions = [(0, 0, 0), (5, 0, 0)]
    def Xform "P"
    {
""" + tri("Shown") + tri("Hidden", 'token visibility = "invisible"') + tri("Guide", 'uniform token purpose = "guide"') + """
        def SphereLight "Lamp"
        {
        }
    }
}
"""
    s = load_stage(stage(tmp_path, body))
    assert s.geometry.n_triangles == 2
    assert s.geometry.prim_names == ["/I[2 x /I/P/Shown]"]
    assert "s.usda: not read: 1 UsdLux light(s) in PointInstancer prototypes" in s.warnings


def test_point_instancer_errors_name_the_prim(tmp_path):
    """A protoIndex past the prototypes is a UserError naming the instancer."""
    body = """
def PointInstancer "I"
{
    rel prototypes = [</I/P>]
    int[] protoIndices = [0, 1]
    point3f[] positions = [(0, 0, 0), (1, 0, 0)]
    def Cube "P"
    {
    }
}
"""
    with pytest.raises(UserError, match=r"s\.usda: /I: protoIndices out of range"):
        load_stage(stage(tmp_path, body))


# --------------------------------------------------------------------------- #
# bindings: purpose, collections, subsets
# --------------------------------------------------------------------------- #


def test_purpose_bindings_full_then_all_purpose(tmp_path):
    """``material:binding:full`` wins over the all-purpose binding and over
    ``material:binding:preview`` (a final render); with only preview and
    all-purpose bindings, the all-purpose one is read."""
    mats = grey("Full", 0.7) + grey("Preview", 0.3) + grey("All", 0.5)
    body = mats + tri("A", "rel material:binding = </All>\n    rel material:binding:full = </Full>\n"
                           "    rel material:binding:preview = </Preview>")
    body += tri("B", "rel material:binding = </All>\n    rel material:binding:preview = </Preview>")
    g = load_stage(stage(tmp_path, body)).geometry
    assert g.prim_names == ["/A", "/B"]
    np.testing.assert_allclose(g.albedo, [0.7, 0.5], rtol=1e-12)


def test_collection_binding(tmp_path):
    """A collection-based binding on an ancestor binds its material to the prims in
    the collection (and not to the others)."""
    body = grey("Red", 0.4) + """
def Xform "World" (
    prepend apiSchemas = ["CollectionAPI:walls", "MaterialBindingAPI"]
)
{
    rel collection:walls:includes = [</World/Wall>]
    rel material:binding:collection:paint = [</World.collection:walls>, </Red>]
""" + tri("Wall") + tri("Floor") + "}\n"
    g = load_stage(stage(tmp_path, body)).geometry
    assert g.prim_names == ["/World/Wall", "/World/Floor"]
    np.testing.assert_allclose(g.albedo, [0.4, 0.18], rtol=1e-12)


def test_geom_subsets_bind_per_face(tmp_path):
    """A 2-face mesh with one materialBind subset (face 1): face 0 keeps the mesh's
    material (0.5), face 1 reads the subset's (0.9); a subset with opacity 0
    in presence mode removes its faces."""
    quads = """
def Mesh "M"
{{
    int[] faceVertexCounts = [4, 4]
    int[] faceVertexIndices = [0, 1, 4, 3, 1, 2, 5, 4]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0)]
    rel material:binding = </Half>
    def GeomSubset "S"
    {{
        uniform token elementType = "face"
        uniform token familyName = "materialBind"
        int[] indices = [1]
        rel material:binding = </{mat}>
    }}
}}
"""
    mats = grey("Half", 0.5) + grey("White", 0.9) + shader_material("Glass", 'float inputs:opacity = 0\n        token inputs:opacityMode = "presence"')
    g = load_stage(stage(tmp_path, mats + quads.format(mat="White"))).geometry
    centre_x = g.points[g.triangles].mean(axis=1)[:, 0]
    np.testing.assert_allclose(g.albedo, np.where(centre_x < 1, 0.5, 0.9), rtol=1e-12)
    g = load_stage(stage(tmp_path, mats + quads.format(mat="Glass"))).geometry
    assert g.n_triangles == 2 and np.all(g.points[g.triangles].mean(axis=1)[:, 0] < 1)


# --------------------------------------------------------------------------- #
# textured inputs
# --------------------------------------------------------------------------- #


def _png_rgb(path: Path, pixels: np.ndarray) -> None:
    """An 8-bit RGB PNG (colour type 2) from an (H, W, 3) uint8 array, written from the PNG specification."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    h, w, _ = pixels.shape
    raw = b"".join(b"\x00" + pixels[j].tobytes() for j in range(h))
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw))
                     + chunk(b"IEND", b""))


def _textured(name: str, file: str, extra: str = "", output: str = "rgb") -> str:
    kind = "color3f" if output == "rgb" else "float"
    return f"""
def Material "{name}"
{{
    token outputs:surface.connect = </{name}/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor.connect = </{name}/T.outputs:{output}>
        token outputs:surface
    }}
    def Shader "T"
    {{
        uniform token info:id = "UsdUVTexture"
        asset inputs:file = @{file}@
        {extra}
        {kind} outputs:{output}
    }}
}}
"""


def test_textured_diffuse_reads_the_srgb_decoded_mean_with_one_warning(tmp_path):
    """A 2 x 2 grey 8-bit PNG of values (0, 64, 128, 255): UsdUVTexture's ``auto``
    colour space decodes 8-bit images as sRGB, so the albedo is the mean of
    srgb_to_linear(v/255) (IEC 61966-2-1), not the mean of v/255. A second
    material reads the same file with ``scale`` 0.5 and ``bias`` 0.1:
    0.5 mean + 0.1. A third with ``sourceColorSpace = "raw"``: mean of v/255.
    Three textured inputs, one file: one summary warning."""
    v = np.array([[0, 64], [128, 255]], np.uint8)
    _png_rgb(tmp_path / "t.png", np.repeat(v[..., None], 3, axis=-1))
    mats = _textured("TA", "t.png") + _textured("TB", "t.png", "float4 inputs:scale = (0.5, 0.5, 0.5, 1)\n"
                                                             "        float4 inputs:bias = (0.1, 0.1, 0.1, 0)")
    mats += _textured("TC", "t.png", 'token inputs:sourceColorSpace = "raw"')
    body = mats + "".join(tri(m, f"rel material:binding = </T{m}>") for m in "ABC")
    s = load_stage(stage(tmp_path, body))
    srgb_mean = float(np.mean(((v / 255 + 0.055) / 1.055) ** 2.4 * (v / 255 > 0.04045) + (v / 255 / 12.92) * (v / 255 <= 0.04045)))
    albedo = dict(zip(s.geometry.prim_names, s.geometry.albedo))
    assert math.isclose(albedo["/A"], srgb_mean, rel_tol=1e-9)
    assert math.isclose(albedo["/B"], 0.5 * srgb_mean + 0.1, rel_tol=1e-9)
    assert math.isclose(albedo["/C"], float(np.mean(v / 255)), rel_tol=1e-9)
    lines = [w for w in s.warnings if "texture" in w]
    assert lines == ["textured inputs read as their texture's mean value (a uniform surface): "
                     "3 x inputs:diffuseColor (2 texture file(s))"], s.warnings


def test_srgb_decode_values():
    """IEC 61966-2-1 §5.2: 0 -> 0, 0.04045 -> 0.04045/12.92 (the linear segment's end),
    0.5 -> 0.2140411, 1 -> 1."""
    np.testing.assert_allclose(srgb_to_linear([0.0, 0.04045, 0.5, 1.0]),
                               [0.0, 0.04045 / 12.92, 0.21404114, 1.0], rtol=1e-7)


def test_missing_texture_is_counted_not_fatal(tmp_path):
    """A texture file that is not there: the default albedo, counted in the summary warning."""
    body = _textured("TA", "nowhere.png") + tri("A", "rel material:binding = </TA>")
    s = load_stage(stage(tmp_path, body))
    assert s.geometry.albedo.tolist() == [0.18]
    assert any("ignored: 1 x inputs:diffuseColor its texture file not found" in w for w in s.warnings), s.warnings


# --------------------------------------------------------------------------- #
# summary warnings, units, subdivision
# --------------------------------------------------------------------------- #


def test_ignored_inputs_are_one_summary_line_with_counts(tmp_path):
    """occlusion authored away from its fallback on two materials, displacement on one
    (inputs not read); occlusion authored at its fallback (1), ``doc``, ``kind``, extent
    and normals change nothing and are not named. One line for the whole stage."""
    mats = grey("MA", 0.5, "float inputs:occlusion = 0.2\n        float inputs:displacement = 1")
    mats += grey("MB", 0.5, "float inputs:occlusion = 0.9") + grey("MC", 0.5, "float inputs:occlusion = 1")
    extra = 'float3[] extent = [(0, 0, 0), (1, 1, 0)]\n    normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1)]'
    body = mats + "".join(tri(m, f"rel material:binding = </M{m}>\n    {extra}") for m in "ABC")
    api = '    prepend apiSchemas = ["MaterialBindingAPI"]\n'  # bindings as pxr wants them: no pxr diagnostic
    body = body.replace('def Mesh "A"', f'def Mesh "A" (\n    doc = "a note"\n    kind = "component"\n{api})')
    for m in "BC":
        body = body.replace(f'def Mesh "{m}"', f'def Mesh "{m}" (\n{api})')
    s = load_stage(stage(tmp_path, body))
    summary = [w for w in s.warnings if w.startswith("s.usda:")]
    assert summary == ["s.usda: ignored: 1 x inputs:displacement, 2 x inputs:occlusion"], s.warnings


def test_unauthored_meters_per_unit_is_centimetres_with_a_warning(tmp_path):
    """No metersPerUnit: UsdGeom's fallback 0.01 (centimetres), said in a warning."""
    s = load_stage(stage(tmp_path, tri("T"), header='upAxis = "Z"'))
    assert s.meters_per_unit == 0.01
    assert s.geometry.points.max() == 0.01
    assert any("metersPerUnit not authored" in w for w in s.warnings)
    assert not any("metersPerUnit" in w for w in load_stage(stage(tmp_path, tri("T"))).warnings)


def test_subdivision_surfaces_are_read_as_their_cage_with_one_warning(tmp_path):
    """Two meshes authored catmullClark, one "none": the cages are read, one line says so."""
    body = tri("A", 'uniform token subdivisionScheme = "catmullClark"')
    body += tri("B", 'uniform token subdivisionScheme = "catmullClark"') + tri("C", 'uniform token subdivisionScheme = "none"')
    s = load_stage(stage(tmp_path, body))
    assert s.geometry.n_triangles == 3
    assert [w for w in s.warnings if "subdivision" in w] == [
        "subdivision surfaces read as their control cage (not refined; glossy and mirror faces shaded by the "
        "cage's smooth normals): 2 catmullClark mesh(es)"]


# --------------------------------------------------------------------------- #
# no light
# --------------------------------------------------------------------------- #


def test_stage_without_light_is_refused(tmp_path):
    """Nothing emits: with ``require_light`` (as a run asks) a UserError naming the
    stage. An emissive surface counts as a light."""
    path = stage(tmp_path, tri("T"))
    with pytest.raises(UserError, match=r"s\.usda: no light in the stage"):
        load_stage(path, require_light=True)
    assert load_stage(path).geometry.n_triangles == 1  # geometry alone is readable
    glow = shader_material("Glow", "color3f inputs:emissiveColor = (1, 1, 1)")
    assert load_stage(stage(tmp_path, glow + tri("T", "rel material:binding = </Glow>")), require_light=True).lights == []


def test_cli_refuses_a_stage_without_light(tmp_path, capsys):
    """``probesim run`` on a light-free stage: one line on stderr, exit 2, no CSV."""
    stage(tmp_path, tri("T"), name="dark.usda")
    cfg = tmp_path / "run.toml"
    cfg.write_text('stage = "dark.usda"\n[simulation]\nsamples = 64\n[[sensor]]\nkind = "irradiance"\n'
                   'position = [0, 0, 1]\nnormal = [0, 0, 1]\n[output]\ncsv = "out/run.csv"\n')
    code = main(["run", str(cfg)])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert err.count("\n") == 0 and "dark.usda: no light in the stage" in err, err
    assert not (tmp_path / "out" / "run.csv").exists()


# --------------------------------------------------------------------------- #
# Radiance .hdr reader
# --------------------------------------------------------------------------- #


def test_rgbe_decodes_flat_and_run_length_scanlines():
    """Hand-built bytes: a 8 x 2 picture, row 0 run-length encoded (each channel one
    run of 8: count byte 128 + 8), row 1 flat. Each pixel decodes as
    (m + 1/2) 2**(e - 136) (Radiance ``colr_color``): (128, 64, 0, 129) ->
    (1.00390625, 0.50390625, 0.00390625); (0, 0, 0, 0) -> 0."""
    head = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 8\n"
    row0 = bytes([2, 2, 0, 8]) + bytes([136, 128, 136, 64, 136, 0, 136, 129])
    row1 = bytes([0, 0, 0, 0]) * 8
    rgb = decode_rgbe(head + row0 + row1)
    assert rgb.shape == (2, 8, 3)
    np.testing.assert_array_equal(rgb[0], np.tile([1.00390625, 0.50390625, 0.00390625], (8, 1)))
    np.testing.assert_array_equal(rgb[1], 0.0)


def test_rgbe_round_trip_orientation_and_exposure():
    """encode -> decode is within half a mantissa step (2**-8 of the largest channel)
    per pixel; a ``+Y`` picture is stored bottom row first; ``EXPOSURE=2`` halves
    the values read."""
    rng = np.random.default_rng(1)
    rgb = rng.uniform(0, 50, (5, 40, 3)) * (rng.uniform(size=(5, 40, 1)) > 0.3)
    rgb[:, 10:30] = 7.0  # a long run of equal bytes
    back = decode_rgbe(encode_rgbe(rgb))
    assert np.all(np.abs(back - rgb) <= 2.0 ** -8 * rgb.max(axis=-1, keepdims=True) + 1e-30)
    np.testing.assert_array_equal(decode_rgbe(encode_rgbe(rgb, rle=False)), back)
    data = encode_rgbe(rgb)
    flipped = data.replace(b"-Y 5 +X 40", b"+Y 5 +X 40")
    np.testing.assert_array_equal(decode_rgbe(flipped), back[::-1])
    exposed = data.replace(b"FORMAT=32-bit_rle_rgbe\n", b"FORMAT=32-bit_rle_rgbe\nEXPOSURE=2\n")
    np.testing.assert_array_equal(decode_rgbe(exposed), back / 2)


def test_dome_texture_errors_name_the_file(tmp_path):
    """A truncated .hdr dome texture: one UserError naming the stage, the prim and the file."""
    (tmp_path / "sky.hdr").write_bytes(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n" + b"\x01" * 10)
    body = 'def DomeLight "Sky"\n{\n    asset inputs:texture:file = @sky.hdr@\n}\n'
    with pytest.raises(UserError, match=r"s\.usda: /Sky: texture:file .*sky\.hdr: not a readable Radiance"):
        load_stage(stage(tmp_path, body))


# --------------------------------------------------------------------------- #
# albedo 1: accepted with a warning, refused when it seals light in
# --------------------------------------------------------------------------- #

WHITE = grey("Snow", 1.0)
BULB = ('def SphereLight "Bulb"\n{{\n    float inputs:radius = 0.1\n    double3 xformOp:translate = {at}\n'
        '    uniform token[] xformOpOrder = ["xformOp:translate"]\n}}\n')


def _quad(name: str, corners) -> str:
    pts = ", ".join(f"({x}, {y}, {z})" for x, y, z in corners)
    return (f'def Mesh "{name}"\n{{\n    int[] faceVertexCounts = [4]\n    int[] faceVertexIndices = [0, 1, 2, 3]\n'
            f'    point3f[] points = [{pts}]\n    rel material:binding = </Snow>\n}}\n')


def _room_of_quads(skip: int | None = None) -> str:
    """The six faces of the cube [-2, 2]^3 as six separate Meshes (their corners coincide exactly)."""
    h = 2
    faces = [
        [(-h, -h, -h), (h, -h, -h), (h, h, -h), (-h, h, -h)], [(-h, -h, h), (-h, h, h), (h, h, h), (h, -h, h)],
        [(-h, -h, -h), (-h, -h, h), (h, -h, h), (h, -h, -h)], [(-h, h, -h), (h, h, -h), (h, h, h), (-h, h, h)],
        [(-h, -h, -h), (-h, h, -h), (-h, h, h), (-h, -h, h)], [(h, -h, -h), (h, -h, h), (h, h, h), (h, h, -h)],
    ]
    return "".join(_quad(f"Wall{i}", f) for i, f in enumerate(faces) if i != skip)


@pytest.mark.parametrize("room", ["cube", "quads"])
def test_light_sealed_in_a_closed_white_room_is_refused(tmp_path, room):
    """A sphere light inside a closed albedo-1 room (one Cube, or six separate quads
    whose corners meet): nothing absorbs, the reading diverges: a UserError naming
    the light and a wall."""
    walls = 'def Cube "Room"\n{\n    double size = 4\n    rel material:binding = </Snow>\n}\n' if room == "cube" \
        else _room_of_quads()
    path = stage(tmp_path, WHITE + walls + BULB.format(at=(0, 0, 1)))
    with pytest.raises(UserError, match=r"s\.usda: /Bulb is sealed inside a closed surface of albedo 1 \(/(Room|Wall0)\)"):
        load_stage(path)


def test_white_surfaces_that_let_light_out_are_accepted_with_a_warning(tmp_path):
    """The same room with one wall missing, or the light outside the closed cube:
    accepted, albedo exactly 1, with the albedo-1 warning."""
    for body in (_room_of_quads(skip=1) + BULB.format(at=(0, 0, 1)),
                 'def Cube "Room"\n{\n    double size = 4\n    rel material:binding = </Snow>\n}\n'
                 + BULB.format(at=(0, 0, 5))):
        s = load_stage(stage(tmp_path, WHITE + body))
        assert np.all(s.geometry.albedo == 1.0)
        assert sum(w.startswith("albedo 1 (no absorption)") for w in s.warnings) == 1


def test_white_emitting_walls_are_refused(tmp_path):
    """A closed albedo-1 cube whose walls emit (a lossless furnace): refused."""
    mat = shader_material("Snow", "color3f inputs:diffuseColor = (1, 1, 1)\n        color3f inputs:emissiveColor = (1, 1, 1)")
    body = mat + 'def Cube "Room"\n{\n    double size = 4\n    rel material:binding = </Snow>\n}\n'
    with pytest.raises(UserError, match=r"emissive surface is sealed inside a closed surface of albedo 1 \(/Room\)"):
        load_stage(stage(tmp_path, body))
