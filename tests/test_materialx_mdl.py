"""Materials as people author them: MaterialX (inline UsdShade networks and referenced .mtlx documents) and
Omniverse MDL (OmniPBR, OmniGlass, OmniSurface) mapped onto UsdPreviewSurface inputs.

Each mapping's albedo and emission are read as authored, and a traced reading under it matches the
furnace's closed form: a closed box whose walls emit L_e and reflect with albedo ρ reads
E = π L_e / (1 − ρ) on any irradiance sensor inside (docs/REFERENCES.md §Furnace), within 4 standard
errors at a fixed seed. Unmapped inputs are named in the summary warning; an unreadable .mtlx is one line,
exit 2, nothing written. The facts in the public-example tests (colours, luminances) are those the
MaterialX project's example materials author (docs/REFERENCES.md §MaterialX surfaces).
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from simulator.commands.cli import main
from simulator.config import load_config
from simulator.io.images import srgb_to_linear
from simulator.pipeline import run
from simulator.scene.usd import load_stage
from simulator.scene.usd.surface_mapping import slab_transmittance
from simulator.units import luminous_efficacy

WALLS = '''
    def Mesh "Walls" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        point3f[] points = [(-2, -1.5, 0), (2, -1.5, 0), (2, 1.5, 0), (-2, 1.5, 0),
                            (-2, -1.5, 2.5), (2, -1.5, 2.5), (2, 1.5, 2.5), (-2, 1.5, 2.5)]
        int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
        int[] faceVertexIndices = [0, 1, 2, 3,  4, 7, 6, 5,  0, 4, 5, 1,  2, 6, 7, 3,  0, 3, 7, 4,  1, 5, 6, 2]
        rel material:binding = </World/Looks/Wall>
    }
'''


def _stage(tmp_path: Path, looks: str, name: str = "furnace.usda") -> Path:
    """The furnace box (stages/furnace.usda's walls) with ``looks`` as the body of /World/Looks."""
    p = tmp_path / name
    p.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n    defaultPrim = "World"\n)\n'
                 f'def Xform "World"\n{{\n{WALLS}\n    def Scope "Looks"{looks}\n}}\n')
    return p


def _shader_material(shader_id: str, inputs: str, context: str = "mtlx") -> str:
    """A Material /World/Looks/Wall whose ``outputs:<context>:surface`` is one shader with ``info:id``."""
    return f'''
    {{
        def Material "Wall"
        {{
            token outputs:{context}:surface.connect = </World/Looks/Wall/Surface.outputs:out>
            def Shader "Surface"
            {{
                uniform token info:id = "{shader_id}"
{inputs}
                token outputs:out
            }}
        }}
    }}'''


def _mdl_material(module: str, inputs: str) -> str:
    """A Material whose ``outputs:mdl:surface`` is an Omniverse MDL shader authored as sourceAsset."""
    return f'''
    {{
        def Material "Wall"
        {{
            token outputs:mdl:surface.connect = </World/Looks/Wall/Shader.outputs:out>
            def Shader "Shader"
            {{
                uniform token info:implementationSource = "sourceAsset"
                uniform asset info:mdl:sourceAsset = @{module}.mdl@
                uniform token info:mdl:sourceAsset:subIdentifier = "{module}"
{inputs}
                token outputs:out
            }}
        }}
    }}'''


def _furnace_run(tmp_path: Path, stage: Path, units: str, samples: int = 3000):
    cfg = tmp_path / "furnace.toml"
    cfg.write_text(f'''stage = "{stage.as_posix()}"
light_units = "{units}"

[simulation]
method = "path"
samples = {samples}
seed = 5

[[sensor]]
name = "up"
kind = "irradiance"
position = [0, 0, 1.25]
normal = [0, 0, 1]

[output]
csv = "out/furnace.csv"
''')
    out = run(load_config(cfg), log=lambda *a: None)
    with open(out.csv_path, newline="") as f:
        row = next(csv.DictReader(f))
    return out, row


def _preview_twin(tmp_path: Path, surface, rho: float, emitted: float) -> Path:
    """The same furnace with a plain UsdPreviewSurface carrying the inputs the mapping gave ``surface``."""
    spec = ", ".join(f"{c:.9g}" for c in surface.specular_color)
    inputs = (f"                color3f inputs:diffuseColor = ({rho!r}, {rho!r}, {rho!r})\n"
              f"                color3f inputs:emissiveColor = ({emitted!r}, {emitted!r}, {emitted!r})\n"
              f"                float inputs:roughness = {surface.roughness!r}\n"
              f"                float inputs:metallic = {surface.metallic!r}\n"
              f"                float inputs:clearcoat = {surface.clearcoat!r}\n"
              f"                float inputs:clearcoatRoughness = {surface.clearcoat_roughness!r}\n"
              f"                float inputs:ior = {surface.ior!r}\n"
              f"                int inputs:useSpecularWorkflow = {int(surface.use_specular_workflow)}\n"
              f"                color3f inputs:specularColor = ({spec})")
    looks = f'''
    {{
        def Material "Wall"
        {{
            token outputs:surface.connect = </World/Looks/Wall/Surface.outputs:surface>
            def Shader "Surface"
            {{
                uniform token info:id = "UsdPreviewSurface"
{inputs}
                token outputs:surface
            }}
        }}
    }}'''
    return _stage(tmp_path, looks, name="twin.usda")


def _check_furnace(tmp_path, stage, units, rho, emitted):
    """Albedo ρ on every wall face, and the traced reading as the surface's lobes make it.

    A matte mapping: the sensor's E = π L_e/(1 − ρ) within 4 standard errors (lx for photometric light
    units, W/m² for radiometric ones). A mapping that gives the walls a specular or clear-coat lobe has no
    closed form in the box: its reading agrees, within 4 combined standard errors, with the same box
    authored as a plain UsdPreviewSurface with the mapped inputs (whose lobes tests/test_bsdf.py and
    tests/test_glossy.py check against closed forms and quadrature).
    """
    out, row = _furnace_run(tmp_path, stage, units)
    np.testing.assert_allclose(out.scene.geometry.albedo, rho, rtol=1e-6)
    col = "illuminance_lx" if units == "photometric" else "irradiance_W_m2"
    err_col = col.replace("_lx", "_stderr_lx").replace("_W_m2", "_stderr_W_m2")
    e, se = float(row[col]), float(row[err_col])
    rows = out.scene.geometry.surfaces
    glossy = [r for r in rows if getattr(r, "glossy", False)]
    if not glossy:
        truth = math.pi * emitted / (1.0 - rho)
        assert se > 0 and abs(e - truth) <= 4 * se, (e, se, truth)
        return out
    twin_dir = tmp_path / "twin"
    twin_dir.mkdir()
    _, twin = _furnace_run(twin_dir, _preview_twin(twin_dir, glossy[0], rho, emitted), units)
    e2, se2 = float(twin[col]), float(twin[err_col])
    assert se > 0 and se2 > 0 and abs(e - e2) <= 4 * math.hypot(se, se2), (e, se, e2, se2)
    return out


def test_inline_usd_preview_surface_node_reads_as_usd_preview_surface(tmp_path):
    """ND_UsdPreviewSurface_surfaceshader on outputs:mtlx:surface: diffuseColor 0.5 and emissiveColor 1 are
    the walls' albedo and radiance (W m⁻² sr⁻¹): E = π/(1 − 0.5) = 2π W/m²."""
    looks = _shader_material("ND_UsdPreviewSurface_surfaceshader",
                             "                color3f inputs:diffuseColor = (0.5, 0.5, 0.5)\n"
                             "                color3f inputs:emissiveColor = (1, 1, 1)")
    _check_furnace(tmp_path, _stage(tmp_path, looks), "radiometric", 0.5, 1.0)


def test_inline_standard_surface_base_times_base_color_and_emission(tmp_path):
    """standard_surface: diffuseColor = base · base_color (0.8 × 0.625 = 0.5), emissiveColor =
    emission · emission_color (2 × 0.5 = 1); E = 2π W/m². The lamp is an emitter: no UsdLux light, yet the
    run is not refused as having no light."""
    looks = _shader_material("ND_standard_surface_surfaceshader",
                             "                float inputs:base = 0.8\n"
                             "                color3f inputs:base_color = (0.625, 0.625, 0.625)\n"
                             "                float inputs:emission = 2\n"
                             "                color3f inputs:emission_color = (0.5, 0.5, 0.5)")
    _check_furnace(tmp_path, _stage(tmp_path, looks), "radiometric", 0.5, 1.0)


def test_inline_open_pbr_emission_luminance_is_in_nits(tmp_path):
    """open_pbr_surface: diffuseColor = base_weight · base_color = 0.5; emission_luminance 100 cd/m² (× white
    emission_color) is the walls' luminance in photometric light units: E_v = 100π/(1 − 0.5) = 200π lx."""
    looks = _shader_material("ND_open_pbr_surface_surfaceshader",
                             "                float inputs:base_weight = 0.5\n"
                             "                color3f inputs:base_color = (1, 1, 1)\n"
                             "                float inputs:emission_luminance = 100")
    _check_furnace(tmp_path, _stage(tmp_path, looks), "photometric", 0.5, 100.0)


def test_inline_gltf_pbr_base_color_and_emissive_strength(tmp_path):
    """gltf_pbr: diffuseColor = base_color 0.5; emissiveColor = emissive 0.25 × emissive_strength 4 = 1
    W m⁻² sr⁻¹: E = 2π W/m²."""
    looks = _shader_material("ND_gltf_pbr_surfaceshader",
                             "                color3f inputs:base_color = (0.5, 0.5, 0.5)\n"
                             "                float inputs:metallic = 0\n"
                             "                color3f inputs:emissive = (0.25, 0.25, 0.25)\n"
                             "                float inputs:emissive_strength = 4")
    _check_furnace(tmp_path, _stage(tmp_path, looks), "radiometric", 0.5, 1.0)


def test_open_pbr_emission_in_radiometric_units_divides_by_the_efficacy(tmp_path):
    """With radiometric light units, 100 cd/m² of an equal-energy emitter is 100/K W m⁻² sr⁻¹,
    K = 182.46 lm/W (the run's spectrum): the reader's radiometric emission is exactly that."""
    looks = _shader_material("ND_open_pbr_surface_surfaceshader",
                             "                float inputs:emission_luminance = 100")
    scene = load_stage(_stage(tmp_path, looks), light_units="radiometric")
    k = luminous_efficacy("E")
    np.testing.assert_allclose(scene.geometry.emission[:, 0], 100.0 / k, rtol=1e-9)
    np.testing.assert_allclose(scene.geometry.emission[:, 1], 100.0, rtol=1e-9)


def _ctx():
    """A reading context for one material, photometric light units (D65)."""
    from pxr import Usd

    from simulator.scene.usd.context import _Context

    return _Context(path="looks.usda", time=Usd.TimeCode.Default(), to_world=np.eye(3),
                    light_units="photometric", default_spectrum="D65")


def _png(path: Path, value: int) -> Path:
    from PIL import Image

    Image.fromarray(np.full((4, 4, 3), value, np.uint8)).save(path)
    return path


MTLX = '''<?xml version="1.0"?>
<materialx version="1.39" colorspace="lin_rec709">
  <nodegraph name="NG_wall">
    <image name="albedo" type="color3">
      <input name="file" type="filename" value="{texture}" colorspace="srgb_texture" />
    </image>
    <output name="base_color_out" type="color3" nodename="albedo" />
  </nodegraph>
  <standard_surface name="Wall_shader" type="surfaceshader">
    <input name="base_color" type="color3" nodegraph="NG_wall" output="base_color_out" />
    <input name="emission" type="float" value="1" />
    <input name="sheen" type="float" value="0.5" />
  </standard_surface>
  <surfacematerial name="Wall" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="Wall_shader" />
  </surfacematerial>
</materialx>
'''


def _mtlx_stage(tmp_path: Path, mtlx_text: str | None) -> Path:
    """A furnace whose /World/Looks references look.mtlx at </MaterialX/Materials> (the layout usdMtlx
    gives a document), binding /World/Looks/Wall, the document's material "Wall"."""
    if mtlx_text is not None:
        (tmp_path / "look.mtlx").write_text(mtlx_text)
    p = tmp_path / "furnace_mtlx.usda"
    p.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n    defaultPrim = "World"\n)\n'
                 f'def Xform "World"\n{{\n{WALLS}\n'
                 '    def Scope "Looks" (\n        prepend references = @./look.mtlx@</MaterialX/Materials>\n'
                 '    )\n    {\n    }\n}\n')
    return p


def test_referenced_mtlx_reads_the_texture_mean_and_names_what_is_not_mapped(tmp_path):
    """A .mtlx referenced the way usdMtlx lays a document out (usd-core from PyPI has no usdMtlx): the
    standard_surface's base_color comes from an sRGB image node, so the albedo is base (1) × the decoded
    texel (188/255 through the sRGB curve); emission 1 emits 1 W m⁻² sr⁻¹; the furnace reads π/(1 − ρ).
    The sheen, which no UsdPreviewSurface input holds, is named in the summary warning."""
    _png(tmp_path / "grey.png", 188)
    stage = _mtlx_stage(tmp_path, MTLX.format(texture="grey.png"))
    rho = float(srgb_to_linear(np.array([188 / 255]))[0])
    out = _check_furnace(tmp_path, stage, "radiometric", rho, 1.0)
    warnings = out.record["warnings"]
    assert any("inputs:sheen of standard_surface (not mapped)" in w for w in warnings), warnings
    assert any("1 x inputs:base_color" in w and "texture" in w for w in warnings), warnings
    assert not any("composition error" in w for w in warnings), warnings


def test_inline_image_network_through_math_nodes(tmp_path):
    """An inline UsdShade network: base_color = multiply(image, constant 0.5) feeding standard_surface; the
    mean passes through the product with a constant exactly: ρ = 0.5 · linear(128/255)."""
    _png(tmp_path / "mid.png", 128)
    looks = '''
    {
        def Material "Wall"
        {
            token outputs:mtlx:surface.connect = </World/Looks/Wall/Surface.outputs:out>
            def Shader "Surface"
            {
                uniform token info:id = "ND_standard_surface_surfaceshader"
                color3f inputs:base_color.connect = </World/Looks/Wall/Half.outputs:out>
                token outputs:out
            }
            def Shader "Half"
            {
                uniform token info:id = "ND_multiply_color3FA"
                color3f inputs:in1.connect = </World/Looks/Wall/Tex.outputs:out>
                float inputs:in2.connect = </World/Looks/Wall/K.outputs:out>
                color3f outputs:out
            }
            def Shader "K"
            {
                uniform token info:id = "ND_constant_float"
                float inputs:value = 0.5
                float outputs:out
            }
            def Shader "Tex"
            {
                uniform token info:id = "ND_image_color3"
                asset inputs:file = @mid.png@ (
                    colorSpace = "srgb_texture"
                )
                color3f outputs:out
            }
        }
    }'''
    scene = load_stage(_stage(tmp_path, looks))
    rho = 0.5 * float(srgb_to_linear(np.array([128 / 255]))[0])
    np.testing.assert_allclose(scene.geometry.albedo, rho, rtol=1e-9)


def test_a_node_with_no_uniform_value_is_named_and_its_default_used(tmp_path):
    """base_color from a noise node: the default base_color (0.8 × base 1) is used, and the input is named."""
    looks = '''
    {
        def Material "Wall"
        {
            token outputs:mtlx:surface.connect = </World/Looks/Wall/Surface.outputs:out>
            def Shader "Surface"
            {
                uniform token info:id = "ND_standard_surface_surfaceshader"
                color3f inputs:base_color.connect = </World/Looks/Wall/Noise.outputs:out>
                float inputs:coat = 0.5
                float inputs:specular_anisotropy = 0.3
                token outputs:out
            }
            def Shader "Noise"
            {
                uniform token info:id = "ND_noise3d_color3"
                color3f outputs:out
            }
        }
    }'''
    scene = load_stage(_stage(tmp_path, looks))
    # diffuseColor = base · base_color · mix(1, coat_color, coat) with a white coat: 0.8
    np.testing.assert_allclose(scene.geometry.albedo, 0.8, rtol=1e-9)
    line = next(w for w in scene.warnings if "ignored:" in w)
    assert "inputs:base_color of standard_surface connected to a noise3d node" in line, line
    assert "inputs:specular_anisotropy of standard_surface (not mapped)" in line, line
    assert "inputs:clearcoat" not in line, line  # mapped onto the clear-coat lobe: modelled, not ignored


def test_omnipbr_albedo_constant_times_tint_and_emission(tmp_path):
    """OmniPBR: diffuseColor = diffuse_color_constant · diffuse_tint = 0.625 × 0.8 = 0.5; with
    enable_emission, emissive_intensity (an exitance, lm/m²) · emissive_color / π = 10π/π = 10 cd/m²:
    E_v = 10π/(1 − 0.5) = 20π lx."""
    looks = _mdl_material("OmniPBR",
                          "                color3f inputs:diffuse_color_constant = (0.625, 0.625, 0.625)\n"
                          "                color3f inputs:diffuse_tint = (0.8, 0.8, 0.8)\n"
                          "                bool inputs:enable_emission = 1\n"
                          "                color3f inputs:emissive_color = (1, 1, 1)\n"
                          f"                float inputs:emissive_intensity = {10 * math.pi!r}")
    _check_furnace(tmp_path, _stage(tmp_path, looks), "photometric", 0.5, 10.0)


def test_omnipbr_texture_brightness_and_disabled_emission(tmp_path):
    """OmniPBR with a diffuse_texture: the texture's decoded mean × albedo_brightness; emission authored but
    not enabled emits nothing (and is not named: it changes nothing)."""
    _png(tmp_path / "tex.png", 200)
    looks = _mdl_material("OmniPBR",
                          "                asset inputs:diffuse_texture = @tex.png@\n"
                          "                float inputs:albedo_brightness = 0.5\n"
                          "                float inputs:emissive_intensity = 1000")
    scene = load_stage(_stage(tmp_path, looks))
    rho = 0.5 * float(srgb_to_linear(np.array([200 / 255]))[0])
    np.testing.assert_allclose(scene.geometry.albedo, rho, rtol=1e-9)
    assert np.all(scene.geometry.emission == 0.0)
    assert not any("emissive" in w for w in scene.warnings), scene.warnings


def test_omnisurface_nit_emission(tmp_path):
    """OmniSurface: diffuseColor = diffuse_reflection_weight · diffuse_reflection_color = 0.5; emission_mode 1
    (nit): emission_weight · emission_intensity · emission_color = 10 cd/m²: E_v = 20π lx."""
    looks = _mdl_material("OmniSurface",
                          "                float inputs:diffuse_reflection_weight = 0.5\n"
                          "                float inputs:emission_weight = 1\n"
                          "                int inputs:emission_mode = 1\n"
                          "                float inputs:emission_intensity = 10")
    _check_furnace(tmp_path, _stage(tmp_path, looks), "photometric", 0.5, 10.0)


def test_omnisurface_lux_emission_is_an_exitance():
    """emission_mode 0 (lux, the default): the intensity is a luminous exitance, luminance = M/π."""
    from simulator.scene.usd.mdl import _mdl_inputs
    from pxr import Usd, UsdShade

    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString("#usda 1.0\n" + 'def Scope "Looks"' + _mdl_material(
        "OmniSurfaceBase", "                float inputs:emission_weight = 1\n"
                           "                float inputs:emission_intensity = 100").replace("/World/Looks", "/Looks"))
    ctx = _ctx()
    out = _mdl_inputs(ctx, UsdShade.Material(stage.GetPrimAtPath("/Looks/Wall")))
    np.testing.assert_allclose(out["emissiveColor"][0], (100 / math.pi,) * 3, rtol=1e-12)


def test_omniglass_is_a_dielectric_with_its_tint_as_a_datasheet_transmittance(tmp_path):
    """OmniGlass: opacity 0 (a dielectric), ior = glass_ior, roughness = frosting_roughness, and a tinted
    glass_color (grey τ = 0.8) the thin slab's normal transmittance (1 − R)² τ/(1 − R² τ²),
    R = ((n−1)/(n+1))².
    The glazing inputs are modelled by the pane (simulator.scene.surfaces): none is counted as ignored."""
    from pxr import Usd, UsdShade

    from simulator.scene.usd.mdl import _mdl_inputs

    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString("#usda 1.0\n" + 'def Scope "Looks"' + _mdl_material(
        "OmniGlass", "                color3f inputs:glass_color = (0.8, 0.8, 0.8)\n"
                     "                float inputs:glass_ior = 1.52\n"
                     "                float inputs:frosting_roughness = 0.1").replace("/World/Looks", "/Looks"))
    ctx = _ctx()
    out = _mdl_inputs(ctx, UsdShade.Material(stage.GetPrimAtPath("/Looks/Wall")))
    r = ((1.52 - 1) / (1.52 + 1)) ** 2
    assert out["opacity"][0] == 0.0 and out["ior"][0] == pytest.approx(1.52) and out["roughness"][0] == 0.1
    assert out["probesim:transmittance"][0] == pytest.approx((1 - r) ** 2 * 0.8 / (1 - r * r * 0.64), rel=1e-12)
    assert slab_transmittance(1.0, 1.5) == pytest.approx((1 - 0.04) / (1 + 0.04), rel=1e-12)
    assert ctx.ignored["inputs:probesim:transmittance"] == 0 and ctx.ignored["inputs:ior"] == 0


def test_unknown_mdl_material_is_named(tmp_path):
    """An MDL material this reader does not know is named in the summary warning, not silently 0.18."""
    looks = _mdl_material("Steel", "                float inputs:brushed = 1")
    scene = load_stage(_stage(tmp_path, looks))
    assert any("Steel.mdl" in w and "not mapped" in w for w in scene.warnings), scene.warnings


def test_unreadable_mtlx_is_one_line_exit_2_nothing_written(tmp_path, capsys):
    """A referenced .mtlx that is not XML: one line naming the file and the prim, exit 2, no output."""
    (tmp_path / "look.mtlx").write_text("<materialx version='1.39'><surfacematerial name=")
    stage = _mtlx_stage(tmp_path, None)
    cfg = tmp_path / "run.toml"
    cfg.write_text(f'stage = "{stage.as_posix()}"\n[simulation]\nsamples = 64\n[[sensor]]\nkind = "irradiance"\n'
                   'position = [0, 0, 1]\nnormal = [0, 0, 1]\n[output]\ncsv = "out/run.csv"\n')
    code = main(["run", str(cfg), "-q"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and err.count("\n") == 0, err
    assert "look.mtlx" in err and "/World/Looks" in err and "not a readable MaterialX document" in err, err
    assert not (tmp_path / "out").exists()


def test_missing_mtlx_is_one_line(tmp_path):
    from simulator.errors import UserError

    with pytest.raises(UserError, match=r"look\.mtlx: not a readable MaterialX document"):
        load_stage(_mtlx_stage(tmp_path, None))


def test_open_pbr_lightbulb_reads_as_its_authors_set_it(tmp_path):
    """The MaterialX project's open_pbr_lightbulb example authors emission_color (1.000, 0.415, 0.099) and
    emission_luminance 10000 cd/m²: in photometric units the walls emit the BT.709 grey of their product
    and keep the colour for spectral transport."""
    doc = ('<?xml version="1.0"?>\n<materialx version="1.39" colorspace="lin_rec709">\n'
           '  <surfacematerial name="Wall" type="material">\n'
           '    <input name="surfaceshader" type="surfaceshader" nodename="bulb" />\n  </surfacematerial>\n'
           '  <open_pbr_surface name="bulb" type="surfaceshader">\n'
           '    <input name="emission_color" type="color3" value="1.000, 0.415, 0.099" />\n'
           '    <input name="emission_luminance" type="float" value="10000" />\n  </open_pbr_surface>\n'
           '</materialx>\n')
    scene = load_stage(_mtlx_stage(tmp_path, doc))
    grey = 10000 * (0.2126 * 1.0 + 0.7152 * 0.415 + 0.0722 * 0.099)
    # MaterialX stores colours in float32: 1e-6 relative
    np.testing.assert_allclose(scene.geometry.emission[:, 1], grey, rtol=1e-6)
    np.testing.assert_allclose(scene.geometry.albedo, 0.8, rtol=1e-6)  # OpenPBR's default base 0.8


def test_defaults_tables_match_the_materialx_library():
    """Every default in the mapping tables is the MaterialX standard library nodedef's own value."""
    mx = pytest.importorskip("MaterialX")
    from simulator.scene.usd.materialx import (GLTF_PBR_DEFAULTS, OPEN_PBR_DEFAULTS, PREVIEW_DEFAULTS,
                                               STANDARD_SURFACE_DEFAULTS)

    lib = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), lib)
    for nodedef, table in (("ND_standard_surface_surfaceshader", STANDARD_SURFACE_DEFAULTS),
                           ("ND_open_pbr_surface_surfaceshader", OPEN_PBR_DEFAULTS),
                           ("ND_UsdPreviewSurface_surfaceshader", PREVIEW_DEFAULTS),
                           ("ND_gltf_pbr_surfaceshader", GLTF_PBR_DEFAULTS)):
        nd = lib.getNodeDef(nodedef)
        assert nd is not None, nodedef
        for name, default in table.items():
            inp = nd.getActiveInput(name)
            assert inp is not None, (nodedef, name)
            value = inp.getValue()
            if name == "opacityMode":  # MaterialX's nodedef states the token as an int: 0 transparent
                assert value == 0 and default == "transparent", (nodedef, name, value)
            elif isinstance(default, str):
                assert value == default, (nodedef, name, value)
            else:
                np.testing.assert_allclose(np.atleast_1d(np.asarray(tuple(value) if hasattr(value, "__len__")
                                                                    else value, float)),
                                           np.atleast_1d(np.asarray(default, float)), rtol=0, atol=1e-7,
                                           err_msg=f"{nodedef}.{name}")


def test_a_material_missing_from_the_referenced_mtlx_is_one_line(tmp_path):
    """A binding to /World/Looks/Wall where look.mtlx holds no material "Wall": one line naming the prim and
    the document, not a silent 0.18."""
    from simulator.errors import UserError

    doc = MTLX.format(texture="grey.png").replace('surfacematerial name="Wall"', 'surfacematerial name="Floor"')
    with pytest.raises(UserError, match=r"/World/Looks: material 'Wall' is not in .*look\.mtlx"):
        load_stage(_mtlx_stage(tmp_path, doc))


def test_a_local_mdl_material_beside_a_mtlx_reference_is_read_as_mdl(tmp_path):
    """A Looks scope that references a .mtlx and also defines an OmniPBR material of its own: the OmniPBR
    is read from its inputs (its own surface output), not looked up in the document."""
    (tmp_path / "look.mtlx").write_text(MTLX.format(texture="grey.png").replace('"Wall"', '"Other"'))
    body = _mdl_material("OmniPBR", "                color3f inputs:diffuse_color_constant = (0.3, 0.3, 0.3)")
    p = tmp_path / "both.usda"
    p.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n'
                 f'def Xform "World"\n{{\n{WALLS}\n'
                 '    def Scope "Looks" (\n        prepend references = @./look.mtlx@</MaterialX/Materials>\n    )'
                 f'{body}\n}}\n')
    scene = load_stage(p)
    np.testing.assert_allclose(scene.geometry.albedo, 0.3, rtol=1e-6)


def test_product_of_two_textures_is_read_as_the_product_of_means_and_named(tmp_path):
    """multiply(image, image): mean(a·b) is not mean(a)·mean(b) in general, so the product of the means is
    used and the approximation named in the summary warning."""
    _png(tmp_path / "a.png", 128)
    _png(tmp_path / "b.png", 200)
    looks = '''
    {
        def Material "Wall"
        {
            token outputs:mtlx:surface.connect = </World/Looks/Wall/Surface.outputs:out>
            def Shader "Surface"
            {
                uniform token info:id = "ND_standard_surface_surfaceshader"
                color3f inputs:base_color.connect = </World/Looks/Wall/Mul.outputs:out>
                token outputs:out
            }
            def Shader "Mul"
            {
                uniform token info:id = "ND_multiply_color3"
                color3f inputs:in1.connect = </World/Looks/Wall/A.outputs:out>
                color3f inputs:in2.connect = </World/Looks/Wall/B.outputs:out>
                color3f outputs:out
            }
            def Shader "A"
            {
                uniform token info:id = "ND_image_color3"
                asset inputs:file = @a.png@ ( colorSpace = "srgb_texture" )
                color3f outputs:out
            }
            def Shader "B"
            {
                uniform token info:id = "ND_image_color3"
                asset inputs:file = @b.png@ ( colorSpace = "srgb_texture" )
                color3f outputs:out
            }
        }
    }'''
    scene = load_stage(_stage(tmp_path, looks))
    rho = float(np.prod(srgb_to_linear(np.array([128 / 255, 200 / 255]))))
    np.testing.assert_allclose(scene.geometry.albedo, rho, rtol=1e-9)
    assert any("a multiply node of two textures" in w for w in scene.warnings), scene.warnings


def test_standard_surface_transmission_is_glazing_and_opacity_a_cutout():
    """transmission 1 with colour grey 0.9 and specular_IOR 1.5: opacity 0 and the slab's
    probesim:transmittance; a cut-out opacity 0.4 alone is opacity 0.4 in presence mode."""
    from pxr import Usd, UsdShade

    from simulator.scene.usd.materialx import _materialx_inputs

    def mapped(inputs):
        stage = Usd.Stage.CreateInMemory()
        stage.GetRootLayer().ImportFromString("#usda 1.0\n" + 'def Scope "Looks"' + _shader_material(
            "ND_standard_surface_surfaceshader", inputs).replace("/World/Looks", "/Looks"))
        return _materialx_inputs(_ctx(), UsdShade.Material(stage.GetPrimAtPath("/Looks/Wall")))

    glass = mapped("                float inputs:transmission = 1\n"
                   "                color3f inputs:transmission_color = (0.9, 0.9, 0.9)")
    assert glass["opacity"][0] == 0.0
    assert glass["probesim:transmittance"][0] == pytest.approx(slab_transmittance(0.9, 1.5), rel=1e-12)
    cut = mapped("                color3f inputs:opacity = (0.4, 0.4, 0.4)")
    assert cut["opacity"][0] == pytest.approx(0.4) and cut["opacityMode"][0] == "presence"


def test_omnipbr_opacity_is_a_cutout():
    """OmniPBR with enable_opacity: opacity_constant in presence mode with its opacity_threshold."""
    from pxr import Usd, UsdShade

    from simulator.scene.usd.mdl import _mdl_inputs

    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString("#usda 1.0\n" + 'def Scope "Looks"' + _mdl_material(
        "OmniPBR", "                bool inputs:enable_opacity = 1\n"
                   "                float inputs:opacity_constant = 0.25\n"
                   "                float inputs:opacity_threshold = 0.1").replace("/World/Looks", "/Looks"))
    out = _mdl_inputs(_ctx(), UsdShade.Material(stage.GetPrimAtPath("/Looks/Wall")))
    assert out["opacity"][0] == 0.25 and out["opacityMode"][0] == "presence" and out["opacityThreshold"][0] == 0.1


def test_a_binding_on_a_parent_into_a_referenced_mtlx_reaches_its_meshes(tmp_path):
    """The binding authored on an Xform above the mesh (bindings inherit down the namespace) still finds the
    material in the referenced .mtlx: base_color's texture mean is the albedo."""
    _png(tmp_path / "grey.png", 188)
    (tmp_path / "look.mtlx").write_text(MTLX.format(texture="grey.png"))
    mesh = WALLS.replace('    def Mesh "Walls" (\n        prepend apiSchemas = ["MaterialBindingAPI"]\n    )',
                         '    def Mesh "Walls"').replace("        rel material:binding = </World/Looks/Wall>\n", "")
    assert "material:binding" not in mesh
    p = tmp_path / "parent.usda"
    p.write_text('#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\ndef Xform "World"\n{\n'
                 '    def Xform "Box" (\n        prepend apiSchemas = ["MaterialBindingAPI"]\n    )\n    {\n'
                 f'        rel material:binding = </World/Looks/Wall>\n{mesh}    }}\n'
                 '    def Scope "Looks" (\n        prepend references = @./look.mtlx@</MaterialX/Materials>\n'
                 '    )\n    {\n    }\n}\n')
    scene = load_stage(p)
    np.testing.assert_allclose(scene.geometry.albedo, float(srgb_to_linear(np.array([188 / 255]))[0]), rtol=1e-9)


def test_usd_prints_nothing_for_the_mtlx_reference_it_cannot_compose(tmp_path, capfd):
    """usd-core's own stderr warning for the .mtlx reference (no usdMtlx plugin) is dropped, and the run's
    warnings do not call it a composition error: the reader reads the document."""
    _png(tmp_path / "grey.png", 188)
    scene = load_stage(_mtlx_stage(tmp_path, MTLX.format(texture="grey.png")))
    err = capfd.readouterr().err
    assert "look.mtlx" not in err, err
    assert not any("composition error" in w for w in scene.warnings), scene.warnings


def test_gltf_pbr_orm_channels_of_a_1_38_document(tmp_path):
    """A MaterialX 1.38 document (the layout of the MaterialX project's gltf_pbr examples) picks metallic,
    roughness and occlusion out of one ORM image with ``channels``: the document upgrade turns each into an
    extract node, so metallic is the mean of B (200/255), roughness of G (100/255), occlusion of R (50/255)."""
    from PIL import Image

    (tmp_path / "tex").mkdir()
    orm = np.dstack([np.full((2, 2), v, np.uint8) for v in (50, 100, 200)])
    Image.fromarray(orm).save(tmp_path / "tex" / "orm.png")
    doc = ('<?xml version="1.0"?>\n<materialx version="1.38" colorspace="lin_rec709" fileprefix="tex/">\n'
           '  <nodegraph name="NG">\n    <tiledimage name="orm" type="vector3">\n'
           '      <input name="file" type="filename" value="orm.png" />\n    </tiledimage>\n'
           '    <output name="out_orm" type="vector3" nodename="orm" />\n  </nodegraph>\n'
           '  <gltf_pbr name="SR" type="surfaceshader">\n'
           '    <input name="metallic" type="float" nodegraph="NG" output="out_orm" channels="z" />\n'
           '    <input name="roughness" type="float" nodegraph="NG" output="out_orm" channels="y" />\n'
           '    <input name="occlusion" type="float" nodegraph="NG" output="out_orm" channels="x" />\n'
           '  </gltf_pbr>\n  <surfacematerial name="Wall" type="material">\n'
           '    <input name="surfaceshader" type="surfaceshader" nodename="SR" />\n  </surfacematerial>\n'
           '</materialx>\n')
    from pxr import Sdf, Usd

    from simulator.scene.usd.materialx import _from_document, _mtlx_binding

    stage = Usd.Stage.Open(str(_mtlx_stage(tmp_path, doc)))
    ctx = _ctx()
    out = _from_document(ctx, _mtlx_binding(ctx, stage, Sdf.Path("/World/Looks/Wall")))
    assert out["metallic"][0] == pytest.approx(200 / 255, rel=1e-9)
    assert out["roughness"][0] == pytest.approx(100 / 255, rel=1e-9)
    assert out["occlusion"][0] == pytest.approx(50 / 255, rel=1e-9)
    assert out["diffuseColor"][0] == (1.0, 1.0, 1.0)  # glTF's default base_color


WRAPPER_MDL = '''mdl 1.4;

using ::OmniPBR import OmniPBR;
import ::tex::gamma_mode;

// a per-asset material: a template called with literal arguments
export material Painted(*)
 = OmniPBR(
    diffuse_color_constant: color(0.625f),
    diffuse_tint: color(0.8, 0.8, 0.8),   /* 0.625 x 0.8 = 0.5 */
    diffuse_texture: texture_2d(),
    reflection_roughness_constant: 0.55,
    enable_emission: true,
    emissive_color: color(1.0, 1.0, 1.0),
    emissive_intensity: {intensity},
    normalmap_texture: texture_2d("./Painted_Normal.png", ::tex::gamma_linear),
    bump_factor: math::pow(2.0, 0.5)
);
'''


def test_a_wrapper_mdl_is_read_from_its_literal_arguments(tmp_path):
    """``Painted.mdl`` only calls OmniPBR with literal arguments: they are the material's inputs
    (albedo 0.625 × 0.8 = 0.5; emissive_intensity 10π → 10 cd/m²), so the furnace reads 20π lx; the
    normal map is named and the argument that is not a literal (a call) is named too."""
    (tmp_path / "Painted.mdl").write_text(WRAPPER_MDL.replace("{intensity}", repr(10 * math.pi)))
    looks = _mdl_material("Painted", "")
    out = _check_furnace(tmp_path, _stage(tmp_path, looks), "photometric", 0.5, 10.0)
    line = next(w for w in out.record["warnings"] if "ignored:" in w)
    assert "bump_factor of Painted.mdl (not a literal" in line, line
    assert "inputs:normalmap_texture of OmniPBR (not mapped)" in line, line


def test_the_stage_input_wins_over_the_wrapper_argument(tmp_path):
    """An input the stage authors on the shader overrides the wrapper module's argument of the same name."""
    (tmp_path / "Painted.mdl").write_text(WRAPPER_MDL.replace("{intensity}", "0.0"))
    looks = _mdl_material("Painted", "                color3f inputs:diffuse_tint = (0.4, 0.4, 0.4)")
    scene = load_stage(_stage(tmp_path, looks))
    np.testing.assert_allclose(scene.geometry.albedo, 0.625 * 0.4, rtol=1e-6)
