"""The BVH ray queries against a brute-force loop over every triangle.

The engine builds one ``wp.Mesh`` (a BVH) from the scene's triangle soup;
the kernels ask it for the nearest hit (``wp.mesh_query_ray``: paths,
radiance meters) and for shadow tests (``unoccluded``). Here random triangle
soups and random rays go through the engine's own mesh and a test kernel,
and every answer is compared with a float64 Möller–Trumbore intersection
against all triangles in numpy.

Rays that pass within a hair of a triangle's edge, or whose two nearest hits
are nearly tied, can legitimately be decided either way in float32; those
rays (identified from the float64 geometry alone, a few per cent) are left
out of the exact comparisons, and the rest must agree exactly (hit or miss,
face) and to float32 precision (distance).
"""

from __future__ import annotations

import numpy as np
import pytest
import warp as wp

from simulator.engine import device
from simulator.engine.device import BVH_LEAF_SIZE
from simulator.engine.driver import Engine
from simulator.kernels.rays import unoccluded
from simulator.kernels.lights import SceneRec
from simulator.reference.geometry import ray_triangles
from simulator.scene.model import Geometry, Scene, Sensor, SensorKind

wp.set_module_options({"enable_backward": False})

#: a ray is ambiguous when it passes this close (in barycentric units) to a
#: triangle's edge, or when its two nearest hits are this close (relative)
EDGE_MARGIN = 1e-4
TIE_MARGIN = 1e-4


@wp.kernel
def k_nearest(
    scene: SceneRec, o: wp.array(dtype=wp.vec3), d: wp.array(dtype=wp.vec3), t_max: float,
    hit: wp.array(dtype=int), t: wp.array(dtype=float), face: wp.array(dtype=int),
):  # fmt: skip
    i = wp.tid()
    q = wp.mesh_query_ray(scene.mesh, o[i], d[i], t_max)
    hit[i] = wp.where(q.result, 1, 0)
    t[i] = wp.where(q.result, q.t, -1.0)
    face[i] = wp.where(q.result, q.face, -1)


@wp.kernel
def k_shadow(
    scene: SceneRec, o: wp.array(dtype=wp.vec3), d: wp.array(dtype=wp.vec3), dist: wp.array(dtype=float),
    clear: wp.array(dtype=int),
):  # fmt: skip
    i = wp.tid()
    clear[i] = wp.where(unoccluded(scene, o[i], d[i], dist[i], -1), 1, 0)


def brute_force(points: np.ndarray, tris: np.ndarray, o: np.ndarray, d: np.ndarray, chunk: int = 256):
    """Möller–Trumbore in float64 for every ray against every triangle (both
    faces), ``chunk`` rays at a time.

    Returns
    -------
    t : ndarray, shape (R, T)
        Hit distance, inf where the ray misses.
    margin : ndarray, shape (R, T)
        Smallest barycentric coordinate at the plane crossing (negative outside).
    t_plane : ndarray, shape (R, T)
        Distance to each triangle's plane along the ray (may be negative).
    """
    parts = [_brute_force(points, tris, o[i : i + chunk], d[i : i + chunk]) for i in range(0, len(o), chunk)]
    return tuple(np.concatenate(x) for x in zip(*parts))


def _brute_force(points, tris, o, d):
    t, u, v, ok = ray_triangles(o[:, None, :], d[:, None, :], points[tris][None], det_min=1e-14)
    margin = np.minimum(np.minimum(u, v), 1.0 - u - v)
    hit = ok & (margin >= 0) & (t > 0)
    return np.where(hit, t, np.inf), np.where(ok, margin, -np.inf), t


def random_soup(rng, n_tri: int, size: float) -> tuple[np.ndarray, np.ndarray]:
    """Triangles of random size and orientation in a box of side ``size``."""
    centres = rng.uniform(-0.5 * size, 0.5 * size, (n_tri, 1, 3))
    scale = rng.uniform(0.02, 0.25, (n_tri, 1, 1)) * size
    pts = (centres + scale * rng.normal(size=(n_tri, 3, 3))).reshape(-1, 3)
    return pts, np.arange(3 * n_tri, dtype=np.int32).reshape(-1, 3)


def random_rays(rng, n: int, size: float) -> tuple[np.ndarray, np.ndarray]:
    o = rng.uniform(-0.8 * size, 0.8 * size, (n, 3))
    d = rng.normal(size=(n, 3))
    return o, d / np.linalg.norm(d, axis=1, keepdims=True)


def engine_for(points, tris) -> Engine:
    n = len(tris)
    geo = Geometry(points=points, triangles=tris, albedo=np.zeros(n), emission=np.zeros((n, 2)),
                   two_sided=np.zeros(n, bool), prim=np.zeros(n, np.int32), prim_names=["/Soup"])  # fmt: skip
    scene = Scene(geometry=geo, lights=[], sensors=[], path="<soup>")
    return Engine(scene, [Sensor("s", SensorKind.IRRADIANCE, np.zeros(3), np.array([0.0, 0.0, 1.0]))], threads=1)


def arr(a, dtype):
    return wp.array(np.asarray(a, np.float32), dtype=dtype, device="cpu")


def ambiguous(t_all: np.ndarray, margin: np.ndarray, t_raw: np.ndarray, t_max: float) -> np.ndarray:
    """Rays whose answer float32 may legitimately flip: a near-edge crossing
    at a distance that matters, or a near tie between the two nearest hits."""
    near_edge = (np.abs(margin) < EDGE_MARGIN) & (t_raw > 0) & (t_raw < t_max * (1 + 1e-4))
    srt = np.sort(t_all, axis=1)
    with np.errstate(invalid="ignore"):
        tie = np.isfinite(srt[:, 1]) & (srt[:, 1] - srt[:, 0] <= TIE_MARGIN * srt[:, 1])
    return near_edge.any(axis=1) | tie


@pytest.mark.parametrize("leaf", [1, BVH_LEAF_SIZE, 4])
@pytest.mark.parametrize("n_tri, size, seed", [(40, 1.0, 1), (400, 3.0, 2), (2000, 100.0, 3)])
def test_nearest_hit_matches_brute_force(n_tri, size, seed, leaf, monkeypatch):
    """wp.mesh_query_ray on the engine's mesh: same hit/miss, same face and the
    same distance (to float32 precision) as the nearest float64 Möller–Trumbore
    hit over all triangles, for 4000 random rays through random soups (unit
    box, 3 m room, a 100 m site), whatever the BVH's leaf size (the engine's
    BVH_LEAF_SIZE, Warp's default 1, and 4): a leaf size changes only the
    speed of a query, never its answer."""
    monkeypatch.setattr(device, "BVH_LEAF_SIZE", leaf)
    rng = np.random.default_rng(seed)
    pts, tris = random_soup(rng, n_tri, size)
    o, d = random_rays(rng, 4000, size)
    eng = engine_for(pts, tris)
    t_max = 10.0 * size
    hit, t, face = (wp.empty(len(o), dtype=dt, device="cpu") for dt in (int, float, int))
    wp.launch(k_nearest, dim=len(o), inputs=[eng.scene_rec, arr(o, wp.vec3), arr(d, wp.vec3), t_max], outputs=[hit, t, face], device="cpu")
    hit, t, face = hit.numpy(), t.numpy(), face.numpy()
    # the float32 rays the kernel saw, in float64
    o32, d32 = o.astype(np.float32).astype(np.float64), d.astype(np.float32).astype(np.float64)
    t_all, margin, t_raw = brute_force(pts.astype(np.float32).astype(np.float64), tris, o32, d32)
    t_all[t_all >= t_max] = np.inf
    skip = ambiguous(t_all, margin, t_raw, t_max)
    assert skip.mean() < 0.05, f"{skip.mean():.1%} ambiguous rays"
    keep = ~skip
    bf_hit = np.isfinite(t_all.min(axis=1))
    assert 0.1 < bf_hit[keep].mean() < 0.95  # the soup is neither empty nor opaque
    np.testing.assert_array_equal(hit[keep], bf_hit[keep].astype(int))
    both = keep & bf_hit
    np.testing.assert_array_equal(face[both], np.argmin(t_all[both], axis=1))
    np.testing.assert_allclose(t[both], t_all[both].min(axis=1), rtol=2e-5, atol=2e-6 * size)


@pytest.mark.parametrize("seed", [4, 5])
def test_shadow_query_matches_brute_force(seed):
    """unoccluded(scene, o, d, dist, −1), the kernels' shadow test: clear
    exactly when no triangle is hit at 0 < t < dist (float64 brute force),
    for random segments, including ones that end just short of or just past
    a surface (dist = nearest hit ∓ 1%)."""
    rng = np.random.default_rng(seed)
    pts, tris = random_soup(rng, 300, 2.0)
    o, d = random_rays(rng, 3000, 2.0)
    o32, d32 = o.astype(np.float32).astype(np.float64), d.astype(np.float32).astype(np.float64)
    t_all, margin, t_raw = brute_force(pts.astype(np.float32).astype(np.float64), tris, o32, d32)
    nearest = t_all.min(axis=1)
    dist = rng.uniform(0.05, 4.0, len(o))
    k = np.isfinite(nearest)
    third = rng.integers(0, 3, len(o))
    dist[k & (third == 0)] = 0.99 * nearest[k & (third == 0)]
    dist[k & (third == 1)] = 1.01 * nearest[k & (third == 1)]
    eng = engine_for(pts, tris)
    clear = wp.empty(len(o), dtype=int, device="cpu")
    wp.launch(k_shadow, dim=len(o), inputs=[eng.scene_rec, arr(o, wp.vec3), arr(d, wp.vec3), arr(dist, float)], outputs=[clear], device="cpu")
    clear = clear.numpy().astype(bool)
    skip = np.zeros(len(o), bool)
    for i in range(len(o)):  # ambiguity relative to this ray's own segment length
        skip[i] = ambiguous(t_all[i : i + 1], margin[i : i + 1], t_raw[i : i + 1], dist[i])[0]
    assert skip.mean() < 0.05
    bf_clear = ~(t_all < dist[:, None]).any(axis=1)
    keep = ~skip
    assert 0.2 < bf_clear[keep].mean() < 0.9
    np.testing.assert_array_equal(clear[keep], bf_clear[keep])
