"""Glass authored as MaterialX standard_surface, OmniGlass and OmniSurface transmission, traced.

Each maps its transmission weight t onto UsdPreviewSurface's ``opacity = 1 − t`` in the default
``transparent`` mode (:mod:`simulator.scene.usd.surface_mapping`), which is clear glass of the
material's ior at t = 1 and a translucent layer (the opaque base over 1 − t, the clear pane over t)
below it (docs/DESIGN.md §Surfaces beyond Lambert).

Closed forms, written here independently of the code under test: a clear slab of index n at normal
incidence, r = ((n − 1)/(n + 1))², its inner reflections summed, transmits T = 2n/(n² + 1)
(n = 1.5: 92.3077%) and reflects R = 2r/(1 + r) (7.6923%) (Born & Wolf, *Principles of Optics*,
§1.5). Under a zero-angle sun of normal illuminance E at the zenith an up-facing sensor under one
sheet reads E·T exactly (light sampling through the pane); under a closed box whose faces are thin
sheets (thin-walled) it reads E·T² (two sheets), under the same box read as a solid E·T (a slab
entered once); a translucent layer of weight t over a black base passes E·t·T. A radiance meter
looking straight down at a sheet under a sun disk of radiance L sees R·L.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from simulator.engine.driver import Engine
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage
from tests.test_surfaces import box

E_SUN = 1000.0  # lx
L_SUN = 1.0e5  # cd/m²
N = 1.5
T_CLEAR = 2 * N / (N * N + 1)
R_CLEAR = 2 * ((N - 1) / (N + 1)) ** 2 / (1 + ((N - 1) / (N + 1)) ** 2)


def mtlx(inputs: str) -> str:
    """A Material /Looks/G whose ``outputs:mtlx:surface`` is an inline standard_surface."""
    return f"""
def Scope "Looks"
{{
    def Material "G"
    {{
        token outputs:mtlx:surface.connect = </Looks/G/S.outputs:out>
        def Shader "S"
        {{
            uniform token info:id = "ND_standard_surface_surfaceshader"
            {inputs}
            token outputs:out
        }}
    }}
}}
"""


def mdl(module: str, inputs: str) -> str:
    """A Material /Looks/G whose ``outputs:mdl:surface`` is an Omniverse MDL shader."""
    return f"""
def Scope "Looks"
{{
    def Material "G"
    {{
        token outputs:mdl:surface.connect = </Looks/G/S.outputs:out>
        def Shader "S"
        {{
            uniform token info:implementationSource = "sourceAsset"
            uniform asset info:mdl:sourceAsset = @{module}.mdl@
            uniform token info:mdl:sourceAsset:subIdentifier = "{module}"
            {inputs}
            token outputs:out
        }}
    }}
}}
"""


def sheet(z: float = 1.0, half: float = 50.0, name: str = "Pane") -> str:
    h = half
    return f"""
def Mesh "{name}"
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-{h}, -{h}, {z}), ({h}, -{h}, {z}), ({h}, {h}, {z}), (-{h}, {h}, {z})]
    rel material:binding = </Looks/G>
}}
"""



def sun(angle_deg: float = 0.0, intensity: float = E_SUN) -> str:
    return f'def DistantLight "Sun"\n{{\n    float inputs:intensity = {intensity}\n    float inputs:angle = {angle_deg}\n}}\n'


BLACK_FLOOR = """
def Material "Black"
{
    token outputs:surface.connect = </Black/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (0, 0, 0)
        token outputs:surface
    }
}
def Mesh "Floor"
{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-1000, -1000, -0.5), (1000, -1000, -0.5), (1000, 1000, -0.5), (-1000, 1000, -0.5)]
    rel material:binding = </Black>
}
"""


def stage(tmp_path: Path, body: str) -> Path:
    path = tmp_path / "g.usda"
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n{body}\n')
    return path


def under(tmp_path: Path, body: str) -> float:
    """An up-facing sensor at the origin under a zero-angle zenith sun, light sampling (exact)."""
    s = [Sensor(name="s", kind=SensorKind.IRRADIANCE, position=np.zeros(3), normal=np.array([0.0, 0.0, 1.0]))]
    res = Engine(load_stage(stage(tmp_path, body + sun())), s).run("light", samples=16, seed=3)
    return float(res.mean[0, 1])


GLASSES = {
    "standard_surface": mtlx("float inputs:transmission = 1\n            float inputs:specular_IOR = 1.5"),
    "OmniGlass": mdl("OmniGlass", "float inputs:glass_ior = 1.5"),
    "OmniSurface": mdl("OmniSurface", "float inputs:specular_transmission_weight = 1\n"
                                      "            float inputs:specular_reflection_ior = 1.5"),
}


@pytest.mark.parametrize("model", sorted(GLASSES))
def test_glass_passes_the_clear_slab(tmp_path, model):
    """transmission 1 at ior 1.5 (standard_surface, OmniGlass, OmniSurface): E·2n/(n² + 1) = 923.08 lx
    pass a sheet, not the 1000 lx of a sheet left out."""
    v = under(tmp_path, GLASSES[model] + sheet())
    assert abs(v - E_SUN * T_CLEAR) <= 2e-6 * E_SUN, (model, v)


def test_standard_surface_glass_reflects_the_sun(tmp_path):
    """A radiance meter looking straight down at the standard_surface glass under a 1° sun of radiance
    L (a black floor beneath): R·L = 2r/(1 + r)·L, where a sheet left out reflected nothing."""
    meter = [Sensor(name="m", kind=SensorKind.RADIANCE, position=np.array([0.0, 0.0, 2.0]),
                    normal=np.array([0.0, 0.0, -1.0]))]
    body = GLASSES["standard_surface"] + sheet(0.0) + BLACK_FLOOR + sun(1.0, L_SUN)
    res = Engine(load_stage(stage(tmp_path, body)), meter).run("path", samples=20000, seed=5)
    v, se = float(res.mean[0, 1]), float(res.stderr[0, 1])
    assert se > 0 and abs(v - R_CLEAR * L_SUN) <= 4 * se, (v, se, R_CLEAR * L_SUN)


def test_partial_transmission_is_a_translucent_layer(tmp_path):
    """standard_surface transmission 0.5 over a black base: the clear pane over half the face,
    E·0.5·T (the opaque half absorbs), where any transmission used to pass as a whole pane."""
    body = mtlx("float inputs:transmission = 0.5\n            float inputs:specular_IOR = 1.5\n"
                "            float inputs:base = 0") + sheet()
    v = under(tmp_path, body)
    assert abs(v - E_SUN * 0.5 * T_CLEAR) <= 2e-6 * E_SUN, v


@pytest.mark.parametrize("thin, sheets", [(1, 2), (0, 1)])
def test_thin_walled_box_is_two_sheets_and_a_solid_one_slab(tmp_path, thin, sheets):
    """A closed glass box: thin_walled 1 makes its top and bottom faces two thin sheets, E·T²; a solid
    (thin_walled 0) is one slab entered once, E·T."""
    body = mtlx(f"float inputs:transmission = 1\n            float inputs:specular_IOR = 1.5\n"
                f"            bool inputs:thin_walled = {thin}") + box("Box", 1.0, 2.0, "Looks/G")
    v = under(tmp_path, body)
    assert abs(v - E_SUN * T_CLEAR ** sheets) <= 2e-6 * E_SUN, (thin, v)
    g = load_stage(stage(tmp_path, body)).geometry
    assert g.surfaces[0].thin_walled == bool(thin) and (g.solid_side is None) == bool(thin)


@pytest.mark.parametrize("module, flag", [("OmniGlass", "thin_walled"), ("OmniSurface", "thin_walled")])
def test_mdl_thin_walled_is_read(tmp_path, module, flag):
    """OmniGlass and OmniSurface thin_walled 1 on the closed box: two sheets, E·T²."""
    body = GLASSES[module].replace("token outputs:out", f"bool inputs:{flag} = 1\n            token outputs:out") + box("Box", 1.0, 2.0, "Looks/G")
    v = under(tmp_path, body)
    assert abs(v - E_SUN * T_CLEAR ** 2) <= 2e-6 * E_SUN, (module, v)
