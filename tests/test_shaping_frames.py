"""A luminaire's photometric web in its prim's actual frame, and the point-light emission warning.

A photometric web gives I(θ, φ) in the luminaire's frame (θ from its −Z,
φ from +X toward +Y). A transform with a negative scale mirrors the
luminaire: a direction at local φ leaves the world at the mirror image of
φ, so an asymmetric distribution must read I(θ, φ_local) there, not the
rotation's I(θ, 360° − φ_local). Readings of a point light are exact
(E = I·cosψ/d², a delta source with one shadow ray per sample).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.scene.photometry import read_photometry
from tests.test_shaping import ASYM_IES, H_M, _ies_light, _run


def _mirrored_stage(tmp_path, light_body: str, scale) -> None:
    (tmp_path / "s.usda").write_text(f'''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{{
    def SphereLight "Lamp" (
        prepend apiSchemas = ["ShapingAPI"]
    )
    {{
{light_body}
        double3 xformOp:translate = (0, 0, {H_M})
        float3 xformOp:scale = {tuple(scale)}
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
    }}
}}
''')


@pytest.mark.parametrize("scale, world_phi_deg", [((-1, 1, 1), 180.0 - 75.0), ((1, -1, 1), 360.0 - 75.0)])
def test_mirrored_luminaire_reads_its_web_mirrored(tmp_path, scale, world_phi_deg):
    """Local φ 75° leaves a mirror-in-X luminaire at world φ 105° (a mirror in Y: 285°); receivers
    there read I(θ, 75°) = 381.0 cd at θ 30° (the rotation's φ 285° would read 138.6 cd)."""
    ies = Path(ASYM_IES).resolve()
    dist = read_photometry(ies)
    _mirrored_stage(tmp_path, _ies_light(ies), scale)
    r = 2.0
    rec = []
    for k, th_deg in enumerate((30.0, 45.0, 60.0)):
        th, ph = math.radians(th_deg), math.radians(world_phi_deg)
        d = np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), -math.cos(th)])
        p = np.array([0.0, 0.0, H_M]) + r * d
        rec.append((f"d{k}", tuple(map(float, p)), tuple(map(float, -d)), th_deg))
    scene, res = _run(tmp_path, [(n, p, d) for n, p, d, _ in rec])
    assert np.linalg.det(scene.lights[0].frame) < 0  # the prim's frame is left-handed, and so is the light's
    for i, (_, _, _, th_deg) in enumerate(rec):
        truth = float(dist.candela_at(th_deg, 75.0))
        assert abs(float(dist.candela_at(th_deg, 285.0)) - truth) > 0.2 * truth  # the web tells them apart
        got = res.mean[i, 1] * r * r  # E d² / cosψ, cosψ = 1
        assert abs(got - truth) <= 1e-5 * truth, (th_deg, got, truth)


def test_absolute_point_light_of_radius_zero_is_not_said_to_emit_nothing(tmp_path):
    """Absolute photometry on a radius-0 SphereLight with normalize 0: its candelas come from the file,
    so it emits; no "emits nothing" warning (the plain radius-0, normalize-0 light still gets it)."""
    ies = Path(ASYM_IES).resolve()
    body = _ies_light(ies).replace("bool inputs:normalize = 1", "bool inputs:normalize = 0")
    _mirrored_stage(tmp_path, body, (1, 1, 1))
    scene, res = _run(tmp_path, [("down", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))])
    assert not any("emits nothing" in w for w in scene.warnings), scene.warnings
    truth = float(read_photometry(ies).candela_at(0.0, 0.0)) / H_M**2
    assert abs(res.mean[0, 1] - truth) <= 1e-5 * truth
