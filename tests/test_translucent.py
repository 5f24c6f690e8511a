"""UsdPreviewSurface ``opacity`` in its default ``transparent`` mode, and the opacity channel a material selects.

Model (docs/DESIGN.md §Surfaces beyond Lambert; :mod:`simulator.scene.surfaces`): in ``transparent``
mode opacity 0 is clear glass of the material's ``ior`` (the specification: "even a fully
transparent object still receives lighting as, for example, perfectly clear glass still has a
specular response"), and 0 < o < 1 is a translucent layer: the face's matte surface over a share o
of it, the clear pane over the rest (UsdPreviewSurface's path-traced reference in OpenUSD, hdPrman's
``UsdPreviewSurfaceParameters.osl``: diffuse gain o, refraction gain 1 − o, glass of ``ior`` at
roughness 0). Only ``presence`` mode or an ``opacityThreshold`` removes a face.

Closed forms, written here independently of the code under test:

- a clear slab of index n at normal incidence, r = ((n − 1)/(n + 1))², the incoherent sum of its
  inner reflections: T = (1 − r)/(1 + r) = 2n/(n² + 1), R = 2r/(1 + r) (n = 1.5: T = 0.923077,
  R = 0.076923; without the inner reflections T would be (1 − r)² = 0.9216); at other angles each
  polarisation's r from Fresnel's equations, averaged (Born & Wolf, *Principles of Optics*, §1.5);
- a translucent layer of opacity o over a black (albedo 0) matte part passes (1 − o)·T(θ) and
  reflects (1 − o)·R(θ) as a mirror; two such layers in turn, direct light only, (1 − o)²·T₁·T₂
  (the light passed between them by two mirror reflections, ((1 − o)R)² ≈ 0.15% of it at o = 0.5,
  n = 1.5, is a delta-to-delta path no estimator draws; at n = 1 there is none and the two-layer
  transmittance is (1 − o)² exactly);
- under a zero-angle sun of normal illuminance E at zenith angle θ an up-facing sensor reads
  E cosθ · (what the layers pass) exactly (light sampling, a shadow ray's transmittance); under a
  uniform dome of luminance L an up-facing sensor below a sheet reads 2πL ∫ t(θ) cosθ sinθ dθ and a
  down-facing one above it 2πL ∫ ρ(θ) cosθ sinθ dθ; a radiance meter sees ρ(θ)·L.

Monte Carlo readings are held within 4 standard errors at fixed seeds.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.engine.driver import Engine
from simulator.errors import UserError
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage
from tests.test_surfaces import box, quad
from tests.test_surfaces import material as surfaces_material

E_SUN = 1000.0  # lx
L_DOME = 100.0  # cd/m²
L_SUN = 1.0e5  # cd/m², the radiance of a sun disk of finite angle (UsdLux intensity, not normalized)


def fresnel(c: float, n: float) -> tuple[float, float]:
    """(r_s, r_p) at incidence cosine c from air into index n (Fresnel's equations)."""
    s = math.sqrt(max(0.0, 1.0 - c * c))
    ct = math.sqrt(1.0 - (s / n) ** 2)
    return ((c - n * ct) / (c + n * ct)) ** 2, ((n * c - ct) / (n * c + ct)) ** 2


def clear_slab(c: float, n: float) -> tuple[float, float]:
    """Unpolarised (R, T) of a clear plane-parallel slab, inner reflections summed: per polarisation
    R = 2r/(1 + r), T = (1 − r)/(1 + r)."""
    rs = fresnel(c, n)
    return sum(r / (1 + r) for r in rs), sum(0.5 * (1 - r) / (1 + r) for r in rs)


def hemispherical(f) -> float:
    """2π ∫ f(cosθ) cosθ sinθ dθ over the hemisphere (adaptive quadrature)."""
    from scipy.integrate import quad as integrate

    return 2 * math.pi * integrate(lambda t: f(math.cos(t)) * math.cos(t) * math.sin(t), 0, math.pi / 2,
                                   epsabs=1e-12)[0]


def stage(tmp_path: Path, body: str, name: str = "s.usda") -> Path:
    path = tmp_path / name
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n{body}\n')
    return path


def material(name: str, extra: str = "", rho: float = 0.0) -> str:
    """:func:`tests.test_surfaces.material`, black unless ``rho`` says otherwise."""
    return surfaces_material(name, extra, rho)


def glass(name: str, opacity: float, ior: float, rho: float = 0.0) -> str:
    return material(name, f"float inputs:opacity = {opacity}\n        float inputs:ior = {ior}", rho)



def st_quad(name: str, z: float, bind: str, half: float = 5.0) -> str:
    """:func:`quad` with ``primvars:st`` from (0, 0) at its (−half, −half) corner to (1, 1)."""
    return quad(name, z, bind, half).replace(
        "    rel material:binding",
        '    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (\n        interpolation = "vertex"\n    )\n'
        "    rel material:binding")



def sun(zenith_deg: float = 0.0, angle_deg: float = 0.0, intensity: float = E_SUN) -> str:
    return f"""
def DistantLight "Sun"
{{
    float inputs:intensity = {intensity}
    float inputs:angle = {angle_deg}
    float3 xformOp:rotateXYZ = ({zenith_deg}, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
}}
"""


DOME = f'def DomeLight "Sky"\n{{\n    float inputs:intensity = {L_DOME}\n}}\n'


def sensor(z: float, facing: float = 1.0, kind: SensorKind = SensorKind.IRRADIANCE, y: float = 0.0) -> list[Sensor]:
    return [Sensor(name="s", kind=kind, position=np.array([0.0, y, z]), normal=np.array([0.0, 0.0, facing]))]


def run(path: Path, sensors, method: str, samples: int, seed: int = 7):
    res = Engine(load_stage(path), sensors).run(method, samples=samples, seed=seed)
    return res.mean[:, 1], res.stderr[:, 1]


# --------------------------------------------------------------------------- #
# reading
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("opacity, layered", [(0.0, False), (0.25, True), (0.5, True), (0.75, True)])
def test_transparent_opacity_is_kept_as_glass(tmp_path, opacity, layered):
    """transparent mode: opacity 0 is a clear pane (coverage 1), 0 < o < 1 a translucent layer whose
    coverage is o; neither is left out, and no warning says so."""
    s = load_stage(stage(tmp_path, glass("G", opacity, 1.5) + quad("Pane", 1.0, "G")))
    row = s.geometry.surfaces[0]
    assert row.pane and row.layered == layered and row.ior == pytest.approx(1.5)
    assert row.coverage == pytest.approx(opacity if layered else 1.0)
    assert s.geometry.prim_names == ["/Pane"] and not any("left out" in w for w in s.warnings), s.warnings


def test_presence_and_threshold_still_remove(tmp_path):
    """Only presence mode (opacity 0) or an opacityThreshold above the opacity removes a face."""
    body = (material("P", 'float inputs:opacity = 0\n        token inputs:opacityMode = "presence"')
            + material("T", "float inputs:opacity = 0.2\n        float inputs:opacityThreshold = 0.5")
            + quad("A", 1.0, "P") + quad("B", 2.0, "T") + quad("Floor", 0.0, "G") + material("G"))
    s = load_stage(stage(tmp_path, body))
    assert s.geometry.prim_names == ["/Floor"]
    assert any("/A" in w and "presence" in w for w in s.warnings) and any("/B" in w for w in s.warnings)


# --------------------------------------------------------------------------- #
# opacity 0: clear glass of its ior
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("method", ["light", "path"])
def test_opacity_zero_slab_passes_the_clear_slab(tmp_path, method):
    """opacity 0, ior 1.5, a zero-angle sun at normal incidence: 92.3077% (2n/(n² + 1), both
    interfaces and their inner reflections) of 1000 lx pass, not 100% (the face left out) nor the
    92.16% of two interfaces without inner reflections."""
    v, se = run(stage(tmp_path, glass("G", 0.0, 1.5) + quad("Pane", 1.0, "G") + sun()), sensor(0.0), method, 64)
    truth = E_SUN * 2 * 1.5 / (1.5 ** 2 + 1)
    assert truth == pytest.approx(E_SUN * clear_slab(1.0, 1.5)[1], rel=1e-12)
    assert abs(v[0] - truth) <= 2e-6 * truth, (v, truth)


def test_opacity_zero_slab_reflects_the_sun_to_a_radiance_meter(tmp_path):
    """A radiance meter looking straight down at the same pane under a 1° sun at the zenith (a black
    floor beneath): the sun's reflection, R(0)·L_sun = 2r/(1 + r)·L_sun = 0.076923·L_sun (0 while the
    pane was left out)."""
    body = (glass("G", 0.0, 1.5) + material("Black") + quad("Pane", 0.0, "G", half=50)
            + quad("Floor", -0.5, "Black", half=1e3) + sun(angle_deg=1.0, intensity=L_SUN))
    v, se = run(stage(tmp_path, body), sensor(2.0, -1.0, SensorKind.RADIANCE), "path", 20000)
    r = (0.5 / 2.5) ** 2
    truth = 2 * r / (1 + r) * L_SUN
    assert se[0] > 0 and abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


def test_opacity_zero_slab_reflects_the_sky_to_an_irradiance_sensor(tmp_path):
    """A down-facing irradiance sensor above the pane (a black floor beneath) under a uniform sky:
    2πL ∫ R(θ) cosθ sinθ dθ, the sky in the glass (0 while the pane was left out)."""
    body = (glass("G", 0.0, 1.5) + material("Black") + quad("Pane", 0.0, "G", half=1e3)
            + quad("Floor", -0.5, "Black", half=1e4) + DOME)
    v, se = run(stage(tmp_path, body), sensor(0.5, -1.0), "path", 20000)
    truth = L_DOME * hemispherical(lambda c: clear_slab(c, 1.5)[0])
    assert se[0] > 0 and abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


# --------------------------------------------------------------------------- #
# 0 < opacity < 1: a translucent layer
# --------------------------------------------------------------------------- #


@pytest.mark.parametrize("opacity", [0.75, 0.5, 0.25])
@pytest.mark.parametrize("method", ["light", "path"])
def test_two_translucent_layers_at_ior_1_pass_one_minus_opacity_squared(tmp_path, opacity, method):
    """Two black translucent sheets of opacity o at ior 1 under a zero-angle sun: E(1 − o)²
    (62.5, 250, 562.5 lx of 1000), where every opacity below 1 used to pass it all."""
    body = glass("G", opacity, 1.0) + quad("Upper", 2.0, "G") + quad("Lower", 1.0, "G") + sun()
    v, _ = run(stage(tmp_path, body), sensor(0.0), method, 64)
    truth = E_SUN * (1 - opacity) ** 2
    assert abs(v[0] - truth) <= 2e-6 * E_SUN, (v, truth)


def test_translucent_closed_mesh_is_two_layers(tmp_path):
    """A closed box of opacity 0.5 at ior 1 (a sun ray crosses its top and bottom faces): E(1 − o)²."""
    body = glass("G", 0.5, 1.0) + box("Cube", 1.0, 2.0, "G") + sun()
    v, _ = run(stage(tmp_path, body), sensor(0.0), "light", 16)
    assert abs(v[0] - 0.25 * E_SUN) <= 2e-6 * E_SUN, v


@pytest.mark.parametrize("zenith", [0.0, 60.0])
def test_two_translucent_layers_at_ior_1_5(tmp_path, zenith):
    """Two black sheets of opacity 0.5 at ior 1.5, zero-angle sun at θ, direct light:
    E cosθ ((1 − o)·T(θ))² (the module docstring's two-layer form)."""
    body = glass("G", 0.5, 1.5) + quad("Upper", 2.0, "G", half=50) + quad("Lower", 1.0, "G", half=50) + sun(zenith)
    v, _ = run(stage(tmp_path, body), sensor(0.0), "light", 16)
    c = math.cos(math.radians(zenith))
    truth = E_SUN * c * (0.5 * clear_slab(c, 1.5)[1]) ** 2
    assert abs(v[0] - truth) <= 2e-6 * E_SUN, (v, truth)


def test_translucent_layer_passes_its_share_of_the_sky_to_direction_samples(tmp_path):
    """Cosine directions under one black sheet of opacity 0.5, ior 1.5, and a uniform sky: each meets
    the slab with probability 1 − o and passes or reflects there: 2πL (1 − o) ∫ T(θ) cosθ sinθ dθ."""
    body = glass("G", 0.5, 1.5) + quad("Sheet", 1.0, "G", half=1e3) + DOME
    v, se = run(stage(tmp_path, body), sensor(0.0), "bsdf", 20000)
    truth = L_DOME * 0.5 * hemispherical(lambda c: clear_slab(c, 1.5)[1])
    assert se[0] > 0 and abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


def test_translucent_layer_reflects_its_share_as_glass(tmp_path):
    """A radiance meter looking at that sheet at 45° under a uniform sky (black floor beneath): the sky
    reflected by the clear share, (1 − o)·R(45°)·L."""
    d = (0.0, math.sqrt(0.5), -math.sqrt(0.5))
    meter = [Sensor(name="m", kind=SensorKind.RADIANCE, position=np.array([0.0, -2.0 * d[1], 2.0]),
                    normal=np.array(d))]
    body = (glass("G", 0.5, 1.5) + material("Black") + quad("Sheet", 0.0, "G", half=50)
            + quad("Floor", -0.5, "Black", half=1e3) + DOME)
    v, se = run(stage(tmp_path, body), meter, "path", 40000)
    truth = 0.5 * clear_slab(math.sqrt(0.5), 1.5)[0] * L_DOME
    assert se[0] > 0 and abs(v[0] - truth) <= 4 * se[0], (v, se, truth)


def test_translucent_layer_is_read_per_texel(tmp_path):
    """transparent mode, ior 1.5, opacity from a 4 x 4 black/white checker texture (mean 0.5) on a 2 m
    sheet with st: under the centre of a white (opaque) texel the sheet's black matte part takes the
    sun, 0; under a black texel (opacity 0) the clear slab passes E·2n/(n² + 1)."""
    from PIL import Image

    board = np.where((np.arange(4)[:, None] + np.arange(4)[None, :]) % 2 == 0, 255, 0).astype(np.uint8)
    Image.fromarray(board, "L").save(tmp_path / "board.png")
    mat = f"""
def Material "M"
{{
    token outputs:surface.connect = </M/S.outputs:surface>
    def Shader "S"
    {{
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0, 0, 0)
        float inputs:ior = 1.5
        float inputs:opacity.connect = </M/T.outputs:r>
        token outputs:surface
    }}
    def Shader "T"
    {{
        uniform token info:id = "UsdUVTexture"
        asset inputs:file = @{tmp_path / "board.png"}@
        float2 inputs:st.connect = </M/R.outputs:result>
        token inputs:wrapS = "repeat"
        token inputs:wrapT = "repeat"
        float outputs:r
    }}
    def Shader "R"
    {{
        uniform token info:id = "UsdPrimvarReader_float2"
        string inputs:varname = "st"
        float2 outputs:result
    }}
}}
"""
    # texel (col i, row j from the top): white where i + j is even; its centre on x, y ∈ [-1, 1]
    centre = lambda i, j: np.array([-1 + 2 * (i + 0.5) / 4, 1 - 2 * (j + 0.5) / 4, 0.0])
    sensors = [Sensor(name=f"s{k}", kind=SensorKind.IRRADIANCE, position=centre(*ij), normal=np.array([0.0, 0.0, 1.0]))
               for k, ij in enumerate(((0, 0), (1, 0)))]
    path = stage(tmp_path, mat + st_quad("Sheet", 1.0, "M", half=1.0) + sun())
    row = load_stage(path).geometry.surfaces[0]
    assert row.layered and row.opacity_texture >= 0 and row.coverage == pytest.approx(0.5)
    v, _ = run(path, sensors, "light", 16)
    assert abs(v[0]) <= 2e-6 * E_SUN and abs(v[1] - E_SUN * clear_slab(1.0, 1.5)[1]) <= 2e-6 * E_SUN, v


# --------------------------------------------------------------------------- #
# the opacity channel a material selects (OmniPBR opacity_mode)
# --------------------------------------------------------------------------- #


def leaf_png(path: Path) -> float:
    """A 4 x 4 RGBA leaf: opaque red RGB (255, 0, 0) everywhere, alpha 255 on 5 texels (the leaf) and 0
    elsewhere; returns the mean alpha, 5/16."""
    from PIL import Image

    px = np.zeros((4, 4, 4), np.uint8)
    px[..., 0] = 255
    px[..., 3][[0, 1, 1, 2, 3], [1, 0, 1, 2, 2]] = 255
    Image.fromarray(px, "RGBA").save(path)
    return 5 / 16


def omnipbr(texture: Path, mode: str | None) -> str:
    mode_line = "" if mode is None else f"                {mode} inputs:opacity_mode\n"
    return f"""
def Material "Leaf"
{{
    token outputs:mdl:surface.connect = </Leaf/Shader.outputs:out>
    def Shader "Shader"
    {{
        uniform token info:implementationSource = "sourceAsset"
        uniform asset info:mdl:sourceAsset = @OmniPBR.mdl@
        uniform token info:mdl:sourceAsset:subIdentifier = "OmniPBR"
        bool inputs:enable_opacity = 1
        bool inputs:enable_opacity_texture = 1
        asset inputs:opacity_texture = @{texture}@
{mode_line}        token outputs:out
    }}
}}
"""


# base.mdl's mono_mode: 0 alpha, 1 average (OmniPBR's default), 2 luminance, 3 maximum; for opaque red
# texels (linear (1, 0, 0)) and the leaf's alpha
@pytest.mark.parametrize("mode, expect", [
    ("int", "alpha"), ('token', "alpha"), (None, 1 / 3), ("int2", 0.2126), ("int3", 1.0)])
def test_omnipbr_opacity_reads_the_channel_opacity_mode_selects(tmp_path, mode, expect):
    """OmniPBR's opacity map read by opacity_mode: the alpha leaf (mean 5/16) with mono_alpha (as 0 or
    as the enum's name), the RGB mean with the default mono_average, BT.709 luminance, the maximum."""
    alpha = leaf_png(tmp_path / "leaf.png")
    authored = {"int": "int", "token": "token", None: None, "int2": "int", "int3": "int"}[mode]
    value = {"int": "= 0", "token": '= "base::mono_alpha"', None: "", "int2": "= 2", "int3": "= 3"}[mode]
    text = omnipbr(tmp_path / "leaf.png", authored)
    if authored is not None:
        text = text.replace("inputs:opacity_mode\n", f"inputs:opacity_mode {value}\n")
    g = load_stage(stage(tmp_path, text + st_quad("Sheet", 1.0, "Leaf"))).geometry
    want = alpha if expect == "alpha" else expect
    row = g.surfaces[0]
    assert row.coverage == pytest.approx(want, abs=1e-6) and not row.pane and row.opacity_mode == "presence"
    assert row.opacity_texture >= 0 and g.coverage_textures[row.opacity_texture].mean == pytest.approx(want, abs=1e-6)


def test_omnipbr_alpha_leaf_casts_its_shadow_without_texture_coordinates(tmp_path):
    """The leaf sheet (opacity_mode 0) with no primvars:st under a zero-angle sun: its mean coverage,
    E(1 − 5/16), not E(1 − 1/3) (the RGB mean)."""
    alpha = leaf_png(tmp_path / "leaf.png")
    text = omnipbr(tmp_path / "leaf.png", "int").replace("inputs:opacity_mode\n", "inputs:opacity_mode = 0\n")
    v, _ = run(stage(tmp_path, text + quad("Sheet", 1.0, "Leaf") + sun()), sensor(0.0), "light", 16)
    assert abs(v[0] - E_SUN * (1 - alpha)) <= 2e-6 * E_SUN, v


@pytest.mark.parametrize("threshold", [0.0, 0.5])
def test_omnipbr_alpha_leaf_is_cut_out_per_texel(tmp_path, threshold):
    """The leaf on a 2 m sheet with st (a texel is 0.5 m): a sensor under the centre of a leaf texel
    (alpha 1) is in shade, one under a clear texel (alpha 0) reads the whole sun, with and without an
    opacity_threshold (texel centres: the bilinear value is the texel's own)."""
    leaf_png(tmp_path / "leaf.png")
    text = omnipbr(tmp_path / "leaf.png", "int").replace("inputs:opacity_mode\n", "inputs:opacity_mode = 0\n")
    text = text.replace("        token outputs:out", f"        float inputs:opacity_threshold = {threshold}\n"
                                                   "        token outputs:out")
    # texel (col i, row j from the top) centre: s = (i + ½)/4, t = 1 − (j + ½)/4 on x, y ∈ [-1, 1]
    leaf = (1, 0)  # column 1, row 0: alpha 255
    clear = (0, 0)  # column 0, row 0: alpha 0
    sensors = [Sensor(name=f"s{k}", kind=SensorKind.IRRADIANCE,
                      position=np.array([-1 + 2 * (i + 0.5) / 4, 1 - 2 * (j + 0.5) / 4, 0.0]),
                      normal=np.array([0.0, 0.0, 1.0])) for k, (i, j) in enumerate((leaf, clear))]
    v, _ = run(stage(tmp_path, text + st_quad("Sheet", 1.0, "Leaf", half=1.0) + sun()), sensors, "light", 16)
    assert abs(v[0]) <= 2e-6 * E_SUN and abs(v[1] - E_SUN) <= 2e-6 * E_SUN, v


def test_omnipbr_bad_opacity_mode_is_one_line(tmp_path):
    leaf_png(tmp_path / "leaf.png")
    text = omnipbr(tmp_path / "leaf.png", "int").replace("inputs:opacity_mode\n", "inputs:opacity_mode = 7\n")
    with pytest.raises(UserError, match=r"inputs:opacity_mode 7 must be one of 0 \(mono_alpha\)"):
        load_stage(stage(tmp_path, text + quad("Sheet", 1.0, "Leaf")))
