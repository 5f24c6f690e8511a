"""The planner's bounding-box hierarchy (``simulator.plan.bounds``) gives the
answers of a scan of every triangle, and the plan of a large stage is quick.

The scan is the definition: a triangle is in front of a sensor's plane when
any vertex has (v − o)·n > tol. The hierarchy must return, per subset, the
lowest index of such a triangle, exactly (including vertices lying on the
plane, which are behind it, and planes through the middle of the soup).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from simulator.plan.bounds import LEAF, FrontIndex, front_of_plane

sys.path.insert(0, str(Path(__file__).resolve().parent))
from big_stage import floor_mesh, time_plan, write_big_stage  # noqa: E402


def _scan(points, subsets, o, n, tol):
    front = front_of_plane(points, o, n, tol)
    return {k: (int(np.flatnonzero(front & m)[0]) if (front & m).any() else -1) for k, m in subsets.items()}


def _planes(rng, points, k):
    """Random planes: random points and normals, planes through vertices
    (a sensor lying on a face), and axis-aligned ones through the soup."""
    out = []
    for _ in range(k):
        n = rng.normal(size=3)
        out.append((rng.uniform(-1.2, 1.2, 3), n / np.linalg.norm(n)))
    for _ in range(k):
        tri = points[rng.integers(len(points))]
        n = np.cross(tri[1] - tri[0], tri[2] - tri[0])
        out.append((tri[0].copy(), n / np.linalg.norm(n)))
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = np.zeros(3)
            n[axis] = sign
            out.append((np.zeros(3), n))
    return out


@pytest.mark.parametrize("n_tri, seed", [(1, 1), (LEAF * 8 + 3, 2), (5000, 3)])
def test_first_in_front_matches_a_scan_of_every_triangle(n_tri, seed):
    """Random soups (and one lone triangle), four subsets, random planes and
    planes through vertices: the hierarchy's lowest index in front equals the scan's."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(-1, 1, (n_tri, 1, 3))
    points = centres + 0.1 * rng.normal(size=(n_tri, 3, 3))
    subsets = {"all": np.ones(n_tri, bool), "half": rng.random(n_tri) < 0.5, "few": rng.random(n_tri) < 0.01,
               "none": np.zeros(n_tri, bool)}  # fmt: skip
    tol = 1e-9 * max(1.0, float(np.abs(points).max()))
    index = FrontIndex(points, subsets, tol)
    for o, n in _planes(rng, points, 40):
        assert index.first_in_front(o, n) == _scan(points, subsets, o, n, tol), (o, n)


def test_a_floor_under_a_sensor_lying_on_it_is_behind():
    """A flat grid floor at z = 0 and sensors on it facing up: every vertex is
    on the plane, within tol, so nothing is in front; facing down, all of it is."""
    pts, quads = floor_mesh(20000, size_m=4.0)
    pts[:, 2] = 0.0
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    points = pts[tris]
    index = FrontIndex(points, {"all": np.ones(len(points), bool)}, 1e-9 * 2.0)
    for x, y in [(0.0, 0.0), (1.3, -0.7), (2.0, 2.0)]:
        assert index.first_in_front(np.array([x, y, 0.0]), np.array([0.0, 0.0, 1.0])) == {"all": -1}
        down = index.first_in_front(np.array([x, y, 1e-6]), np.array([0.0, 0.0, -1.0]))
        assert down == {"all": 0}


def test_big_stage_plans_quickly(tmp_path):
    """200,000 triangles and 1,000 sensors (most of whose planes cut the
    floor) are planned in well under the 2 s budget of a 1M-triangle stage:
    the hierarchy's cost per sensor grows about as √T, a scan's as T (which
    took about 0.1 s per sensor here). Bound 3 s: a loaded shared CPU."""
    cfg = write_big_stage(tmp_path, 200_000, 1000)
    t = time_plan(cfg)
    assert t["triangles"] >= 190_000 and t["sensors"] >= 1000
    assert t["plan_s"] < 3.0, t
