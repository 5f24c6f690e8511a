"""Lights flush with surfaces: a luminaire authored in a ceiling's plane.

A 1 m × 1 m RectLight of 1000 cd/m² lies in the plane of a black ceiling
(CIE 171:2006 case 5.3's layout: a closed 4 m × 4 m × 3 m room). Shadow rays
end on the light's points, which lie on the ceiling; rounding put about half
of those ends behind it, and the room read 21–29% low. The readings must
match Lambert's contour formula for a uniform polygon (Lambert 1760;
:func:`simulator.reference.closed_forms.polygon_irradiance`) within 4
standard errors plus float32 slack, whatever the stage's units and up axis,
near the origin or 300 m from it, and with the light exactly in the plane
or a few float32 spacings inside the ceiling (1e-6 m, 4 ulps at 3 m).
"""

from __future__ import annotations

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.pipeline import collect_sensors, load_scene
from simulator.reference import closed_forms as cf

FLOAT32_SLACK = 2e-6
L_CD_M2 = 1000.0
CEILING_M = 3.0

#: (name, world position m, normal): floor centre, floor off-axis, floor near a
#: corner, high on a wall (0.1 m under the ceiling), low on a wall
RECEIVERS = [
    ("floor_centre", (0.0, 0.0, 0.0), (0, 0, 1)),
    ("floor_mid", (1.0, 0.0, 0.0), (0, 0, 1)),
    ("floor_corner", (1.9, 1.9, 0.0), (0, 0, 1)),
    ("wall_high", (2.0, 0.0, 2.9), (-1, 0, 0)),
    ("wall_low_side", (2.0, 1.5, 0.75), (-1, 0, 0)),
]


def _stage_text(units: str, up: str, x0_m: float, inside_m: float) -> str:
    """The room and light, authored in ``units`` (m or cm) with ``up`` (Z or
    Y), shifted x0_m along world X; the light sits ``inside_m`` above the
    ceiling plane (inside the ceiling)."""
    k = 1.0 if units == "m" else 100.0

    def pt(x, y, z):  # world metres, Z up -> authored coordinates
        x, y, z = (x + x0_m) * k, y * k, z * k
        return (x, y, z) if up == "Z" else (x, z, -y)

    corners = [pt(x, y, z) for z in (0, CEILING_M) for (x, y) in ((-2, -2), (2, -2), (2, 2), (-2, 2))]
    pts = ", ".join(f"({a!r}, {b!r}, {c!r})" for a, b, c in corners)
    light = pt(0.0, 0.0, CEILING_M + inside_m)
    rot = 'double3 xformOp:rotateXYZ = (-90, 0, 0)\n        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]' if up == "Y" else 'uniform token[] xformOpOrder = ["xformOp:translate"]'
    return f'''#usda 1.0
(
    metersPerUnit = {1.0 / k!r}
    upAxis = "{up}"
    defaultPrim = "World"
)

def Xform "World"
{{
    def RectLight "Source"
    {{
        float inputs:intensity = {L_CD_M2}
        bool inputs:normalize = 0
        float inputs:width = {k!r}
        float inputs:height = {k!r}
        double3 xformOp:translate = ({light[0]!r}, {light[1]!r}, {light[2]!r})
        {rot}
    }}

    def Mesh "Room" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {{
        point3f[] points = [{pts}]
        int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
        int[] faceVertexIndices = [0, 1, 2, 3,  4, 7, 6, 5,  0, 4, 5, 1,  2, 6, 7, 3,  0, 3, 7, 4,  1, 5, 6, 2]
        rel material:binding = </World/Black>
    }}

    def Material "Black"
    {{
        token outputs:surface.connect = </World/Black/Surface.outputs:surface>
        def Shader "Surface"
        {{
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0, 0, 0)
            token outputs:surface
        }}
    }}
}}
'''


def _config(tmp_path, units, up, x0_m, inside_m):
    (tmp_path / "room.usda").write_text(_stage_text(units, up, x0_m, inside_m))
    sensors = "\n".join(
        f'[[sensor]]\nname = "{n}"\nkind = "irradiance"\nposition = [{p[0] + x0_m!r}, {p[1]!r}, {p[2]!r}]\nnormal = [{d[0]}, {d[1]}, {d[2]}]\n'
        for n, p, d in RECEIVERS
    )
    (tmp_path / "room.toml").write_text(f'stage = "room.usda"\n\n[simulation]\nsamples = 4096\nseed = 1\n\n{sensors}')
    return load_config(tmp_path / "room.toml")


def _lambert_lx(x0_m: float, p, n) -> float:
    """Lambert's contour formula for the 1 m square at z = 3 m facing down."""
    verts = cf.rect_light_vertices(np.array([x0_m, 0.0, CEILING_M]), np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), 1.0, 1.0)
    return float(cf.polygon_irradiance(L_CD_M2, verts, np.array(p, float) + [x0_m, 0, 0], np.array(n, float), one_sided_normal=np.array([0, 0, -1.0])))


@pytest.mark.parametrize("method", ["light", "mis"])
@pytest.mark.parametrize(
    "units, up, x0_m, inside_m",
    [
        ("m", "Z", 0.0, 0.0),
        ("cm", "Y", 0.0, 0.0),
        ("m", "Z", 300.0, 0.0),
        ("cm", "Y", 300.0, 0.0),
        ("m", "Z", 0.0, 1e-6),
        ("cm", "Y", 300.0, 1e-6),
    ],
)
def test_flush_rect_light_matches_lambert(tmp_path, units, up, x0_m, inside_m, method):
    """Every receiver reads Lambert's formula within 4σ (+ float32 slack);
    before the fix floor_centre read ~83 lx for 107.15."""
    cfg = _config(tmp_path, units, up, x0_m, inside_m)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    res = Engine(scene, sensors).run(method, samples=4096, seed=1)
    for i, (name, p, n) in enumerate(RECEIVERS):
        truth = _lambert_lx(x0_m, p, n)
        est, se = res.mean[i, 1], res.stderr[i, 1]
        assert abs(est - truth) <= 4.0 * se + FLOAT32_SLACK * truth + 1e-12, f"{name}: {est} ± {se} vs {truth}"
        assert se < 0.01 * truth, f"{name}: stderr {se / truth:.2%}"


def test_light_behind_the_ceiling_is_shadowed(tmp_path):
    """The bound is not a licence to leak: a light 1 mm inside the ceiling
    (~100 times the bound) is hidden by it and every receiver reads 0."""
    cfg = _config(tmp_path, "m", "Z", 0.0, 1e-3)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    res = Engine(scene, sensors).run("mis", samples=1024, seed=1)
    assert np.all(res.mean[:, 1] == 0.0), res.mean[:, 1]
