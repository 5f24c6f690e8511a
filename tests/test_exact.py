"""Exact direct light through occluders: :mod:`simulator.engine.exact`.

Every expected value here is an independent closed form: the visible part of
the light is a rectangle (or a rectangle with a rectangular hole) in a
receiver-centred frame, read by the corner-rectangle factor algebra
(``rect_irradiance_parallel``), not by the contour code under test.
"""

import numpy as np
import pytest

from simulator.reference.closed_forms import polygon_irradiance, rect_irradiance_parallel, rect_light_vertices
from simulator.engine.exact import visible_polygon_irradiance
from simulator.engine.visible import clip_halfplane, lambert_pieces, signed_area

L = 1000.0  # cd/m²
H = 2.0  # light height, m
LIGHT = rect_light_vertices([0, 0, H], [1, 0, 0], [0, 1, 0], 1.0, 2.0)  # x ∈ [−0.5, 0.5], y ∈ [−1, 1]
DOWN = [0, 0, -1]
TOL = 1e-11  # relative: float64 contour sums and GEOS clipping of O(1) coordinates


def _quad(x0, x1, y0, y1, z):
    a, b, c, d = [x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]
    return np.array([[a, b, c], [a, c, d]], float)


def _floor(n=200, seed=1, half=2.0):
    rng = np.random.default_rng(seed)
    P = np.c_[rng.uniform(-half, half, (n, 2)), np.zeros(n)]
    return P, np.tile([0.0, 0.0, 1.0], (n, 1))


def _rect(px, py, x0, x1, y0, y1):
    """E from the part [x0, x1] × [y0, y1] of the light plane, receiver at (px, py, 0) facing up."""
    x0, x1 = max(x0, -0.5), min(x1, 0.5)
    y0, y1 = max(y0, -1.0), min(y1, 1.0)
    if x0 >= x1 or y0 >= y1:
        return 0.0
    return float(rect_irradiance_parallel(L, x0 - px, x1 - px, y0 - py, y1 - py, H))


def test_unoccluded_equals_lambert():
    """No occluder: the light's full Lambert integral (E = 415.838 lx under its centre)."""
    P, N = _floor()
    e = visible_polygon_irradiance(L, LIGHT, np.zeros((0, 3, 3)), P, N, DOWN)
    ref = np.array([_rect(px, py, -0.5, 0.5, -1, 1) for px, py, _ in P])
    np.testing.assert_allclose(e, ref, rtol=TOL)
    assert abs(visible_polygon_irradiance(L, LIGHT, [], [0, 0, 0], [0, 0, 1], DOWN) - 415.838) < 5e-4


@pytest.mark.parametrize("gap_m", [1e-4, 1e-2, 0.5])
def test_half_covered_lamp_penumbra(gap_m):
    """A half-plane shade x < 0 at gap g below the lamp: its edge projects from the
    receiver (px, py, 0) to x_e = px·(1 − H/(H − g)) on the light's plane, and the
    visible part is the rectangle [x_e, 0.5] × [−1, 1]."""
    P, N = _floor()
    shade = _quad(-10, 0, -10, 10, H - gap_m)
    e = visible_polygon_irradiance(L, LIGHT, shade, P, N, DOWN)
    ref = np.array([_rect(px, py, px * (1 - H / (H - gap_m)), 0.5, -1, 1) for px, py, _ in P])
    np.testing.assert_allclose(e, ref, rtol=TOL, atol=1e-9)


def test_flush_ceiling_hides_nothing_but_a_tenth_of_a_millimetre_does():
    """A ceiling in the light's own plane does not block it (flush luminaire); the
    same ceiling 0.1 mm lower, with no hole, blocks it completely. 300 m from the
    origin, where float32 would lose the 0.1 mm."""
    off = np.array([300.0, -300.0, 0.0])
    P, N = _floor(50)
    ceiling = _quad(-10, 10, -10, 10, H) + off
    e = visible_polygon_irradiance(L, LIGHT + off, ceiling, P + off, N, DOWN, length_scale_m=300.0)
    ref = np.array([_rect(px, py, -0.5, 0.5, -1, 1) for px, py, _ in P])
    np.testing.assert_allclose(e, ref, rtol=1e-9)
    shade = _quad(-10, 10, -10, 10, H - 1e-4) + off
    e = visible_polygon_irradiance(L, LIGHT + off, shade, P + off, N, DOWN, length_scale_m=300.0)
    assert np.all(e == 0.0)


def test_overlapping_shades_count_once():
    """Shades x < 0 and x < 0.2 at the same height overlap; the union hides x < 0.2
    (projected), never twice."""
    g = 0.3
    P, N = _floor(100)
    tris = np.concatenate([_quad(-10, 0.0, -10, 10, H - g), _quad(-10, 0.2, -10, 10, H - g)])
    e = visible_polygon_irradiance(L, LIGHT, tris, P, N, DOWN)
    k = H / (H - g)
    ref = np.array([_rect(px, py, px + (0.2 - px) * k, 0.5, -1, 1) for px, py, _ in P])
    np.testing.assert_allclose(e, ref, rtol=TOL, atol=1e-9)


def test_shade_with_a_hole():
    """A square frame (a shade with a square hole) 1 mm under the lamp, receiver
    under the centre: the light shows only through the hole's projection,
    [−a, a]² scaled by H/(H − g) about the receiver."""
    g, a = 1e-3, 0.2
    z = H - g
    frame = np.concatenate([_quad(-5, -a, -5, 5, z), _quad(a, 5, -5, 5, z), _quad(-a, a, -5, -a, z), _quad(-a, a, a, 5, z)])
    k = H / (H - g)
    e = visible_polygon_irradiance(L, LIGHT, frame, [0, 0, 0], [0, 0, 1], DOWN)
    assert e == pytest.approx(_rect(0, 0, -a * k, a * k, -a * k, a * k), rel=TOL)


def test_what_cannot_block_is_ignored():
    """Occluders beyond the light, behind the receiver, or outside its pyramid
    change nothing."""
    P, N = _floor(100, half=0.3)
    tris = np.concatenate([
        _quad(-10, 10, -10, 10, H + 0.5),  # above the lamp
        _quad(-10, 10, -10, 10, -0.5),  # under the floor
        _quad(3, 4, -1, 1, 1.0),  # off to the side
    ])
    e = visible_polygon_irradiance(L, LIGHT, tris, P, N, DOWN)
    ref = np.array([_rect(px, py, -0.5, 0.5, -1, 1) for px, py, _ in P])
    np.testing.assert_allclose(e, ref, rtol=TOL)


def test_one_sided_light_is_dark_behind():
    assert visible_polygon_irradiance(L, LIGHT, [], [0, 0, 3], [0, 0, -1], DOWN) == 0.0


def test_straddling_the_horizon_and_a_straddling_wall():
    """A tilted receiver sees part of the lamp below its horizon; a wall
    standing through the receiver's height (clipped by both planes) hides the
    x < −0.2 side. Expected: the clipped-polygon closed form on the visible
    polygon, computed by the reference ``polygon_irradiance``."""
    p = np.array([0.3, 0.1, 0.5])
    n = np.array([0.8, 0.0, 0.6])
    wall = np.array([[[-0.2, -5, -1], [-0.2, 5, -1], [-0.2, 5, 5]], [[-0.2, -5, -1], [-0.2, 5, 5], [-0.2, -5, 5]]], float)
    e = visible_polygon_irradiance(L, LIGHT, wall, p, n, DOWN)
    # the wall x = −0.2 projects from p onto z = H at x = p_x + (−0.2 − p_x)·1 (vertical plane through x = −0.2)
    vis = rect_light_vertices([0.15, 0, H], [1, 0, 0], [0, 1, 0], 0.7, 2.0)  # x ∈ [−0.2, 0.5]
    assert e == pytest.approx(float(polygon_irradiance(L, vis, p, n)), rel=1e-10)


def test_lambert_pieces_matches_closed_form():
    """The vectorised contour sum of convex pieces above the horizon equals the one-receiver
    closed form (``polygon_irradiance``, docs/REFERENCES.md §Lambert's polygon formula) of the same polygon."""
    rng = np.random.default_rng(3)
    P = np.c_[rng.uniform(-2, 2, (40, 2)), rng.uniform(0.0, 1.5, 40)]
    N = np.c_[rng.normal(size=(40, 2)) * 0.3, np.ones(40)]
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    keep = np.all((LIGHT[None] - P[:, None]) @ N[:, :, None] > 0, axis=(1, 2))  # wholly above each horizon
    P, N = P[keep], N[keep]
    got, scale = lambert_pieces(LIGHT[None] - P[:, None], N)
    ref = np.array([float(polygon_irradiance(1.0, LIGHT, P[i], N[i])) for i in range(len(P))])
    assert len(P) > 10
    np.testing.assert_allclose(got, ref, rtol=1e-12, atol=1e-15)
    assert np.all(scale >= got)


def test_clip_halfplane_matches_halfplane_area():
    """Vectorised Sutherland–Hodgman: random triangles cut by x < c keep exactly the area GEOS gives
    for their intersection with that half-plane (an independent 2-D clipper), and nothing on the far
    side; the two sides of one cut add up to the triangle."""
    import shapely

    rng = np.random.default_rng(7)
    T = rng.uniform(-1, 1, (300, 3, 2))
    T = np.where((signed_area(T) < 0)[:, None, None], T[:, ::-1], T)
    cut = rng.uniform(-0.5, 0.5, 300)
    W, n = clip_halfplane(T, np.full(300, 3), cut[:, None] - T[:, :, 0])
    Wo, no = clip_halfplane(T, np.full(300, 3), T[:, :, 0] - cut[:, None])
    valid = np.arange(4)[None, :] < n[:, None]
    assert np.all(W[:, :, 0][valid] <= np.broadcast_to(cut[:, None], (300, 4))[valid] + 1e-12)
    np.testing.assert_allclose(signed_area(W) + signed_area(Wo), signed_area(T), rtol=1e-12, atol=1e-15)
    for i in range(300):
        ref = shapely.Polygon(T[i]).intersection(shapely.box(-5, -5, cut[i], 5)).area
        assert signed_area(W[i : i + 1])[0] == pytest.approx(ref, rel=1e-9, abs=1e-14)
