"""Skinned meshes (UsdSkel) posed at the run's time code.

A two-joint skeleton (``root`` at the origin, ``root/arm`` at (1, 0, 0))
stands 2 m up (the Skeleton prim's translate); its animation turns ``arm``
about +Z from 0° at time 0 to 90° at time 10 (quaternion slerp: θ = 9°·t).
Three mesh points follow ``arm`` alone, so they turn rigidly about (1, 0, 0):
p' = R_z(θ)(p − c) + c with c = (1, 0, 0). The fourth has weight ½ on each
joint, so linear blend skinning puts it at ½ p + ½ (R_z(θ)(p − c) + c):
(3, 0, 0) goes to (2, 1, 0) at 90° (the blend shrinks it toward the joint).
Posed points are in skeleton space, placed by the skeleton's world transform
(the mesh's own transform is not used), so every posed z is 2 m.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from simulator.scene.usd import load_stage

I4 = "((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))"
ARM = "((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (1, 0, 0, 1))"
S45 = math.sin(math.radians(45.0))

STAGE = f'''#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    startTimeCode = 0
    endTimeCode = 10
)
def SkelRoot "Rig"
{{
    def Skeleton "Skel" (
        prepend apiSchemas = ["SkelBindingAPI"]
    )
    {{
        uniform token[] joints = ["root", "root/arm"]
        uniform matrix4d[] bindTransforms = [{I4}, {ARM}]
        uniform matrix4d[] restTransforms = [{I4}, {ARM}]
        {{anim}}
        double3 xformOp:translate = (0, 0, 2)
        uniform token[] xformOpOrder = ["xformOp:translate"]

        def SkelAnimation "Anim"
        {{
            uniform token[] joints = ["root/arm"]
            float3[] translations = [(1, 0, 0)]
            quatf[] rotations.timeSamples = {{ 0: [(1, 0, 0, 0)], 10: [({S45!r}, 0, 0, {S45!r})] }}
            half3[] scales = [(1, 1, 1)]
        }}
    }}
    def Mesh "Arm" (
        prepend apiSchemas = ["SkelBindingAPI"]
    )
    {{
        int[] faceVertexCounts = [3, 3]
        int[] faceVertexIndices = [0, 1, 2, 1, 3, 2]
        point3f[] points = [(1, 0, 0), (2, 0, 0), (1, 0.5, 0), (3, 0, 0)]
        int[] primvars:skel:jointIndices = [1, 0, 1, 0, 1, 0, 1, 0] (
            elementSize = 2
            interpolation = "vertex"
        )
        float[] primvars:skel:jointWeights = [1, 0, 1, 0, 1, 0, 0.5, 0.5] (
            elementSize = 2
            interpolation = "vertex"
        )
        matrix4d primvars:skel:geomBindTransform = {I4}
        rel skel:skeleton = </Rig/Skel>
        double3 xformOp:translate = (50, 50, 50)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }}
}}
def SphereLight "L"
{{
}}
'''

BIND = np.array([(1, 0, 0), (2, 0, 0), (1, 0.5, 0), (3, 0, 0)], float)


def _expected(theta_deg: float) -> np.ndarray:
    th = math.radians(theta_deg)
    r = np.array([[math.cos(th), -math.sin(th), 0], [math.sin(th), math.cos(th), 0], [0, 0, 1]])
    c = np.array([1.0, 0.0, 0.0])
    arm = (BIND - c) @ r.T + c
    out = arm.copy()
    out[3] = 0.5 * BIND[3] + 0.5 * arm[3]  # half on root (which does not move), half on arm
    return out + np.array([0.0, 0.0, 2.0])


def _posed(scene) -> np.ndarray:
    g = scene.geometry
    tris = g.triangles[g.prim == g.prim_names.index("/Rig/Arm")]
    pts = g.points[tris.ravel()]
    return pts[np.unique(tris.ravel(), return_index=True)[1]]  # each vertex once, in index order


@pytest.fixture
def rig(tmp_path: Path) -> Path:
    p = tmp_path / "rig.usda"
    p.write_text(STAGE.replace("{anim}", "rel skel:animationSource = </Rig/Skel/Anim>"))
    return p


@pytest.mark.parametrize("time, theta_deg", [(0.0, 0.0), (5.0, 45.0), (10.0, 90.0)])
def test_skinned_points_at_the_time_match_the_closed_form(rig, time, theta_deg):
    s = load_stage(rig, time=time)
    np.testing.assert_allclose(_posed(s), _expected(theta_deg), rtol=0, atol=1e-6)  # float32 skinning
    assert not any("skinning" in w or "animated" in w for w in s.warnings), s.warnings


def test_at_90_degrees_the_blended_point_is_2_1_2(rig):
    np.testing.assert_allclose(_posed(load_stage(rig, time=10.0))[3], [2.0, 1.0, 2.0], atol=1e-6)


def test_no_time_reads_the_earliest_pose_and_names_the_skinned_mesh(rig):
    s = load_stage(rig)
    np.testing.assert_allclose(_posed(s), _expected(0.0), atol=1e-6)
    (line,) = [w for w in s.warnings if "animated prim" in w]
    assert "/Rig/Arm" in line


def test_no_animation_is_the_rest_pose(tmp_path):
    p = tmp_path / "rest.usda"
    p.write_text(STAGE.replace("{anim}", ""))
    s = load_stage(p, time=10.0)
    np.testing.assert_allclose(_posed(s), _expected(0.0), atol=1e-6)  # rest = bind: the authored points, 2 m up


def test_joint_influences_without_a_skeleton_are_named(tmp_path):
    p = tmp_path / "loose.usda"
    p.write_text(STAGE.replace("{anim}", "").replace("rel skel:skeleton = </Rig/Skel>", ""))
    s = load_stage(p)
    assert any("skinning with no skeleton bound" in w for w in s.warnings), s.warnings


def test_posed_points_agree_with_pxrs_own_bake(rig, tmp_path):
    """UsdSkel.BakeSkinning writes the posed points into the mesh (in its own space): read back through
    the mesh's transform they are the points the reader posed, at every time sampled."""
    from pxr import Gf, Usd, UsdGeom, UsdSkel

    stage = Usd.Stage.Open(str(rig))
    assert UsdSkel.BakeSkinning(UsdSkel.Root(stage.GetPrimAtPath("/Rig")), Gf.Interval(0, 10))
    mesh = UsdGeom.Mesh(stage.GetPrimAtPath("/Rig/Arm"))
    for time in (0.0, 2.5, 7.0, 10.0):
        m = np.array(UsdGeom.XformCache(time).GetLocalToWorldTransform(mesh.GetPrim()))
        baked = np.asarray(mesh.GetPointsAttr().Get(time), float) @ m[:3, :3] + m[3, :3]
        np.testing.assert_allclose(_posed(load_stage(rig, time=time)), baked, atol=1e-6)
