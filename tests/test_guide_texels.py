"""Guided paths through a cut-out whose coverage is read per texel (an opacity texture in presence mode).

A guided segment passes a cut-out with the coverage at the point it crosses
it, (1 − c(st)), and one that ends on the sheet scatters there with the
coverage at that point: both expectations hold texel by texel, so guided
paths stay unbiased. Here:

- a furnace (walls emit L_e and reflect ρ, as stages/furnace.usda) split by
  a white (ρ = 1), non-emitting presence sheet with a checkerboard opacity
  texture: a gap passes radiance straight and the opaque texels send on all
  they receive, diffusely, so a uniform radiance L_e/(1 − ρ) stays uniform
  and every irradiance sensor reads π·L_e/(1 − ρ) whatever the pattern
  (docs/REFERENCES.md §Furnace), read with the guide forced on (a furnace's
  light is spread evenly, so the pilot would leave it out);
- a perforated screen (the checkerboard on a grey sheet) between a sunlit
  bright mat and a lamp-lit one on a dark floor and sensors above and below
  it, a bright panel over it lit through the holes: the pilot finds the
  light concentrated on the mats and the panel (the guide is used on its
  own merits), and guided readings agree with ``path`` within 4 combined
  standard errors at fixed seeds (no closed form: the holes' shadows and
  the interreflections have none).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from simulator.engine.driver import Engine
from simulator.reference import closed_forms as cf
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage
from tests.test_guide_surfaces import FURNACE_PANE, forced_guide  # noqa: F401 (a fixture)
from tests.test_texel_coverage import checker, material, png_grey

FLOAT32_SLACK = 2e-6


def _sensor(name, pos, normal):
    return Sensor(name=name, kind=SensorKind.IRRADIANCE, position=np.array(pos, float), normal=np.array(normal, float))


def _sheet(points: list, name: str = "Sheet") -> str:
    """A textured quad (st (0, 0), (1, 0), (1, 1), (0, 1) at its corners) bound to the texture material M."""
    return f"""
def Mesh "{name}" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [{", ".join(f"({x}, {y}, {z})" for x, y, z in points)}]
    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = "faceVarying")
    rel material:binding = </M>
}}
"""


def test_guided_furnace_through_a_perforated_white_sheet(tmp_path, forced_guide):  # noqa: F811 (the fixture)
    """The furnace (ρ = 0.5, L_e = 1 W m⁻² sr⁻¹) with its pane replaced by a white presence sheet, a
    16 × 16 checkerboard opacity texture: E = π·L_e/(1 − ρ) = 2π W/m² on sensors facing the sheet
    from both sides (one over a shut texel's centre, one over an open one's), along it and up,
    within 4 standard errors; the guide is used (forced on), 8192 samples, stderr ≤ 0.5%."""
    png_grey(tmp_path / "c.png", checker(16))
    walls = FURNACE_PANE[:FURNACE_PANE.index('def Mesh "Pane"')] + FURNACE_PANE[FURNACE_PANE.index('def Material "Wall"'):]
    walls = walls[:walls.index('def Material "Glass"')]
    body = walls + material("c.png", rho=1.0) + _sheet([(0.5, -1.5, 0), (0.5, 1.5, 0), (0.5, 1.5, 2.5), (0.5, -1.5, 2.5)])
    path = tmp_path / "furnace_screen.usda"
    path.write_text(body)
    scene = load_stage(path, light_units="radiometric")
    assert scene.geometry.has_surfaces and scene.geometry.surfaces[0].opacity_texture == 0
    # texel (i, j) of 16 spans s ∈ [i/16, (i+1)/16] along y from −1.5, t along z from 0 (row 0 at t = 1)
    open_y, top_z = -1.5 + 3.0 * 0.5 / 16, 2.5 * (1 - 0.5 / 16)  # column 0, row 0: even, open
    sensors = [_sensor("east_open", (1.0, open_y, top_z), (-1, 0, 0)),
               _sensor("east_shut", (1.0, open_y + 3.0 / 16, top_z), (-1, 0, 0)),
               _sensor("west", (-1.0, 0.3, 1.0), (1, 0, 0)),
               _sensor("along", (0.0, -0.5, 1.5), (0, 1, 0)),
               _sensor("up", (1.0, 0.0, 0.5), (0, 0, 1))]  # fmt: skip
    engine = Engine(scene, sensors)
    res = engine.run("guided", samples=8192, seed=31)
    assert engine.guide.sampled > 0 and "used" in engine.guide.reason
    truth = cf.furnace_irradiance(1.0, 0.5)
    for i, s in enumerate(sensors):
        est, se = float(res.mean[i, 0]), float(res.stderr[i, 0])
        assert abs(est - truth) <= 4.0 * se + FLOAT32_SLACK * truth, f"{s.name}: {est:.6g} vs {truth:.6g} (± {se:.3g})"
        assert se < 0.005 * truth, f"{s.name}: stderr {se / truth:.3%}"


def _quad(name: str, x0: float, x1: float, y0: float, y1: float, z: float, bind: str, down: bool = False) -> str:
    pts = [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
    if down:
        pts = pts[::-1]
    return (f'def Mesh "{name}"\n{{\n    int[] faceVertexCounts = [4]\n    int[] faceVertexIndices = [0, 1, 2, 3]\n'
            f'    point3f[] points = [{", ".join(f"({x}, {y}, {z})" for x, y, z in pts)}]\n'
            f'    rel material:binding = </{bind}>\n}}\n')


def _matte(name: str, rho: float) -> str:
    return (f'def Material "{name}"\n{{\n    token outputs:surface.connect = </{name}/S.outputs:surface>\n'
            f'    def Shader "S"\n    {{\n        uniform token info:id = "UsdPreviewSurface"\n'
            f'        color3f inputs:diffuseColor = ({rho}, {rho}, {rho})\n        token outputs:surface\n    }}\n}}\n')


def perforated_screen_stage(tmp_path: Path) -> Path:
    """A 4 m × 4 m grey (0.5) presence sheet at z = 1 m with a 16 × 16 checkerboard opacity texture over a
    dark floor (0.1, 8 m × 8 m); on the floor a bright mat (0.9) in the zenith sun's light through the
    holes and one lit by a lamp (20000 cd, radius 5 cm, 0.4 m above it) under the sheet; a bright panel
    (0.9, facing down) 1 m over the sheet, lit through the holes."""
    png_grey(tmp_path / "c.png", checker(16))
    body = material("c.png", rho=0.5) + _sheet([(-2, -2, 1), (2, -2, 1), (2, 2, 1), (-2, 2, 1)])
    body += _matte("Dark", 0.1) + _matte("Bright", 0.9) + _quad("Floor", -4, 4, -4, 4, 0.0, "Dark")
    body += _quad("SunMat", 0.5, 1.5, -0.5, 0.5, 0.01, "Bright") + _quad("LampMat", -1.5, -0.5, -0.5, 0.5, 0.01, "Bright")
    body += _quad("Panel", -0.5, 0.5, -0.5, 0.5, 2.0, "Bright", down=True)
    body += ('def SphereLight "Lamp"\n{\n    float inputs:intensity = 20000\n    float inputs:radius = 0.05\n'
             '    float3 xformOp:translate = (-1, 0, 0.4)\n    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')
    body += 'def DistantLight "Sun"\n{\n    float inputs:intensity = 1000\n    float inputs:angle = 0\n}\n'
    path = tmp_path / "screen.usda"
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n{body}\n')
    return path


def test_guided_paths_through_a_perforated_screen_agree_with_path(tmp_path):
    """The perforated screen stage: the pilot finds its light concentrated (some table's concentration
    > 4, so the guide is used unforced) and guided and path readings (lux) of sensors under the sheet
    facing up at it, over it facing down through it, and one along it, agree within 4 combined
    standard errors, each and summed, 8192 samples, independent seeds."""
    sensors = [_sensor("under_a", (0.3, 0.2, 0.6), (0, 0, 1)), _sensor("under_lamp", (-0.7, -0.3, 0.6), (0, 0, 1)),
               _sensor("under_sun", (1.2, 0.4, 0.6), (0, 0, 1)), _sensor("over_a", (0.1, 0.1, 1.6), (0, 0, -1)),
               _sensor("over_lamp", (-1.1, 0.3, 1.6), (0, 0, -1)), _sensor("along", (0.0, 0.0, 0.6), (1, 0, 0))]
    engine = Engine(load_stage(perforated_screen_stage(tmp_path)), sensors)
    g = engine.run("guided", samples=8192, seed=11)
    assert engine.guide.sampled > 0 and engine.guide.reason.endswith("used"), engine.guide.reason
    assert max(engine.guide.concentration) > 4.0, engine.guide.concentration
    p = engine.run("path", samples=8192, seed=12)
    z = (g.mean[:, 1] - p.mean[:, 1]) / np.hypot(g.stderr[:, 1], p.stderr[:, 1])
    assert np.all(np.abs(z) <= 4.0), (np.round(z, 2), [s.name for s in sensors])
    zs = (g.mean[:, 1].sum() - p.mean[:, 1].sum()) / np.sqrt(np.sum(g.stderr[:, 1] ** 2 + p.stderr[:, 1] ** 2))
    assert abs(zs) <= 4.0, zs
