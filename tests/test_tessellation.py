"""The implicit gprims' polygons are convex, so fanning them without the test changes nothing.

The stage reader triangulates a Cube's, Sphere's, Cylinder's, Cone's,
Capsule's and Plane's own polygons with ``convex=True`` (no convexity test,
which on the integrating sphere's 130,560 quads cost more than the rest of
its reading). That is the same split only if the test would have passed
every face: checked here over sizes, segment counts and axes, including the
degenerate rings (a Cylinder_1 with radius 0 at one end, a Capsule of
height 0) whose zero-area triangles the reader drops later.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from simulator.scene.usd.tessellation import (
    _capsule_polygons,
    _cone_polygons,
    _convex_faces,
    _cube_polygons,
    _cylinder_polygons,
    _plane_polygons,
    _sphere_polygons,
    _triangulate_faces,
)

SHAPES = (
    [("cube", _cube_polygons(s)) for s in (0.01, 1.0, 37.0)]
    + [("sphere", _sphere_polygons(r, n, m)) for r, (n, m) in itertools.product((0.02, 1.0), ((3, 2), (64, 32), (512, 256)))]
    + [("cylinder", _cylinder_polygons(rt, rb, h, n, ax))
       for (rt, rb, h), n, ax in itertools.product(((1.0, 1.0, 2.0), (0.0, 0.5, 1.0), (0.3, 0.0, 0.2)), (3, 64), "XYZ")]
    + [("cone", _cone_polygons(r, h, n, ax)) for (r, h), n, ax in itertools.product(((1.0, 2.0), (0.1, 5.0)), (3, 48), "XYZ")]
    + [("capsule", _capsule_polygons(r, h, n, m, ax))
       for (r, h), (n, m), ax in itertools.product(((0.5, 2.0), (1.0, 0.0)), ((4, 2), (64, 32)), "XYZ")]
    + [("plane", _plane_polygons(w, length, ax)) for (w, length), ax in itertools.product(((1.0, 2.0), (3.0, 0.5)), "XYZ")]
)  # fmt: skip


@pytest.mark.parametrize("name, polygons", SHAPES, ids=[f"{n}{i}" for i, (n, _) in enumerate(SHAPES)])
def test_implicit_gprim_faces_are_convex_and_fan_the_same(name, polygons):
    points, counts, indices = polygons
    starts = np.cumsum(counts) - counts
    for n in np.unique(counts):
        faces = np.flatnonzero(counts == n)
        if n > 3:
            assert _convex_faces(points[indices[starts[faces][:, None] + np.arange(n)]]).all(), (name, int(n))
    tested = _triangulate_faces(points, counts, indices)
    fanned = _triangulate_faces(points, counts, indices, convex=True)
    assert tested[1] == fanned[1] == 0
    assert np.array_equal(tested[0], fanned[0]) and np.array_equal(tested[2], fanned[2])


def test_a_concave_face_is_still_ear_clipped():
    """A Mesh's faces keep the test: an L-shaped hexagon (not convex) is ear-clipped into four
    triangles of its winding whose areas add up to its own, 3 (three unit squares)."""
    points = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]], float)
    counts, indices = np.array([6]), np.arange(6)
    tris, fanned, face_of = _triangulate_faces(points, counts, indices)
    p = points[tris]
    area = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2]
    assert fanned == 0 and len(tris) == 4 and np.all(area > 0) and area.sum() == pytest.approx(3.0)
    assert not _convex_faces(points[None])[0]
    assert np.array_equal(face_of, np.zeros(4, np.int64))
