"""The emitter pieces' table: which piece of the emissive geometry a receiver samples, per cell.

A window emitter seen through its opening, a row of diffusers seen from
under a desk: which pieces a path vertex can see changes across the room,
and one learned factor per piece for the whole stage (the pick of
``kernels/lights/emissive.py`` without a table) spends many light samples
on pieces hidden from where the vertex is. Here the stage's surfaces (both
sides of every face) and the sensors are cut into *cells*, a voxel of a
grid of spacing h and one of six buckets of the receiver's normal (its
largest axis and that axis's sign), and for every cell c and piece k

    T_ck = mean over the cell's receivers x_i and light samples q of piece k
           of L(q)·cosθ_x·cosθ_q/d²·V(x_i, q)/p(q)     (W + lm/683 per m²)

is measured by ``kernels.estimators.piece_table_kernel`` (shadow rays, panes
and cut-outs at their share), an estimate of the piece's irradiance over
the cell, occluders included. A receiver in cell c then picks piece k with

    P(k | c) = (1 − α)·T_ck/Σ_j T_cj + α·π_k,

π_k the piece's share of the emitted power (> 0 for every piece: a piece
the measurement missed keeps a probability, so the estimate stays
unbiased whatever T holds), α = ``kernels.lights.emissive.PIECE_UNIFORM``;
a cell whose every T is 0 picks ∝ power. The device keeps each cell's
inclusive CDF (float32; the pick and its pdf both read its differences)
and Σ_k T_ck, the emissive record's weight in the light pick.

Deterministic: the receivers come from a generator of fixed seed, each
table entry is one kernel thread with its own random stream, the sums are
the host's; so the table, and every reading, is the same at any thread
count.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

__all__ = ["CELL_M", "MAX_CELLS", "TABLE_RAYS", "PieceTable", "normal_buckets", "cell_grid", "piece_table"]

#: target voxel edge of the cells (metres), grown ×1.5 until the cells and the grid fit their caps
CELL_M = 0.5
#: most cells
MAX_CELLS = 8192
#: most grid slots (voxels × 6 buckets): the device's lookup table
MAX_GRID = 1 << 22
#: rays for the whole table: cells × pieces × rays per entry at most this (rays per entry 4 to 32)
TABLE_RAYS = 1 << 21
#: receivers kept per cell (the entry's rays take them in turn)
PER_CELL = 8
#: surface points drawn ∝ area over the stage's faces, each read on both sides
SURFACE_POINTS = 1 << 16
#: the receivers' and the rays' seed (the table does not depend on a run's seed)
TABLE_SEED = 0x51ED27
#: where the grid starts below the points' box, in voxels: not a simple fraction, so that the planes of
#: axis-aligned rooms (walls at whole metres) fall inside voxels, not on their faces
GRID_SHIFT = 0.4142135623730951


@dataclass(frozen=True)
class PieceTable:
    """The cells and their probabilities over the pieces.

    Attributes
    ----------
    lo : ndarray, shape (3,)
        The grid's lowest corner (m).
    h : float
        Its spacing (m).
    dims : tuple of int
        Voxels along x, y, z.
    grid : ndarray of int32, shape (nx·ny·nz·6,)
        Each slot's cell, −1 for none (slot ((ix·ny + iy)·nz + iz)·6 + bucket).
    cdf : ndarray of float32, shape (C, K)
        Each cell's inclusive CDF over the pieces (last 1).
    total : ndarray of float32, shape (C,)
        Σ_k T_ck per cell.
    rays : int
        Rays per entry.
    seconds : float
        Wall seconds to build it.
    """

    lo: np.ndarray
    h: float
    dims: tuple
    grid: np.ndarray
    cdf: np.ndarray
    total: np.ndarray
    rays: int
    seconds: float

    @property
    def n_cells(self) -> int:
        return int(len(self.total))

    def cell_of(self, p: np.ndarray, n: np.ndarray) -> np.ndarray:
        """The cell of each receiver (points (N, 3) m, unit normals (N, 3)), −1 for none: the host's twin
        of ``kernels.lights.emissive.piece_cell``."""
        p, n = np.atleast_2d(p).astype(np.float64), np.atleast_2d(n).astype(np.float64)
        q = (p - self.lo) / self.h
        dims = np.array(self.dims)
        inside = np.all((q >= 0) & (q < dims), axis=1)
        iv = np.minimum(np.floor(np.where(inside[:, None], q, 0)).astype(np.int64), dims - 1)
        key = ((iv[:, 0] * dims[1] + iv[:, 1]) * dims[2] + iv[:, 2]) * 6 + normal_buckets(n)
        return np.where(inside, self.grid[key], -1)

    def summary(self) -> dict:
        """What the run record keeps of it."""
        return {"cells": self.n_cells, "cell_m": round(self.h, 4), "rays_per_entry": self.rays,
                "seconds": self.seconds}  # fmt: skip


def normal_buckets(n: np.ndarray) -> np.ndarray:
    """Bucket of each normal (N, 3): 2·(its largest axis, x first on ties) + 1 where that component is
    negative (the twin of ``kernels.lights.emissive.normal_bucket``)."""
    a = np.abs(n)
    axis = np.where((a[:, 0] >= a[:, 1]) & (a[:, 0] >= a[:, 2]), 0, np.where(a[:, 1] >= a[:, 2], 1, 2))
    return 2 * axis + (n[np.arange(len(n)), axis] < 0)


def surface_points(points: np.ndarray, tris: np.ndarray, n_points: int, rng) -> tuple[np.ndarray, np.ndarray]:
    """``n_points`` points drawn ∝ area over the triangles, with each one's unit face normal."""
    p = points[tris]
    cr = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    area2 = np.linalg.norm(cr, axis=1)
    ok = np.flatnonzero(area2 > 0)
    if not len(ok):
        return np.zeros((0, 3)), np.zeros((0, 3))
    pick = ok[np.searchsorted(np.cumsum(area2[ok]) / area2[ok].sum(), rng.random(n_points), side="right").clip(0, len(ok) - 1)]
    u, v = rng.random(n_points), rng.random(n_points)
    flip = u + v > 1
    u, v = np.where(flip, 1 - u, u), np.where(flip, 1 - v, v)
    x = p[pick, 0] + u[:, None] * (p[pick, 1] - p[pick, 0]) + v[:, None] * (p[pick, 2] - p[pick, 0])
    return x, cr[pick] / area2[pick][:, None]


def cell_grid(x: np.ndarray, n: np.ndarray, h: float = CELL_M, max_cells: int = MAX_CELLS,
              max_grid: int = MAX_GRID) -> tuple[np.ndarray, float, tuple, np.ndarray, np.ndarray]:  # fmt: skip
    """The grid of the receivers x (N, 3) with unit normals n: ``(lo, h, dims, cell of each receiver,
    the slots' cells)``, h grown ×1.5 from the given one until at most ``max_cells`` cells and
    ``max_grid`` slots."""
    b = normal_buckets(n)
    box_lo, box_hi = x.min(axis=0), x.max(axis=0)
    while True:
        lo = box_lo - GRID_SHIFT * h
        dims = np.floor((box_hi - lo) / h).astype(np.int64) + 1
        slots = int(np.prod(dims)) * 6
        if slots <= max_grid:
            iv = np.minimum(np.floor((x - lo) / h).astype(np.int64), dims - 1)
            key = ((iv[:, 0] * dims[1] + iv[:, 1]) * dims[2] + iv[:, 2]) * 6 + b
            keys, cell = np.unique(key, return_inverse=True)
            if len(keys) <= max_cells:
                grid = np.full(slots, -1, np.int32)
                grid[keys] = np.arange(len(keys), dtype=np.int32)
                return lo, h, tuple(int(d) for d in dims), cell.reshape(-1), grid
        h *= 1.5


def cell_receivers(cell: np.ndarray, n_cells: int, per_cell: int) -> np.ndarray:
    """(C, per_cell) indices of receivers per cell: the first ``per_cell`` of each (in the order drawn),
    repeated in turn where a cell has fewer."""
    order = np.argsort(cell, kind="stable")
    counts = np.bincount(cell, minlength=n_cells)
    start = np.cumsum(counts) - counts
    j = np.arange(per_cell)[None, :] % counts[:, None]
    return order[start[:, None] + j]


def probabilities(T: np.ndarray, power: np.ndarray, uniform: float) -> tuple[np.ndarray, np.ndarray]:
    """(CDF (C, K) float32, totals (C,)) of the table T (C, K): P = (1 − α)·T/ΣT + α·π, ∝ π where ΣT = 0."""
    tot = T.sum(axis=1)
    pi = power / power.sum()
    P = np.where(tot[:, None] > 0, (1 - uniform) * T / np.where(tot > 0, tot, 1.0)[:, None] + uniform * pi[None], pi[None])
    cdf = np.cumsum(P, axis=1)
    cdf = (cdf / cdf[:, -1:]).astype(np.float32)
    cdf[:, -1] = 1.0
    return cdf, tot


def piece_table(engine) -> PieceTable | None:
    """Measure and upload the table of ``engine``'s device scene (None where its emissive geometry is
    one piece, or there is nothing to sample from)."""
    from simulator.engine.device import warp
    from simulator.engine.fanout import fan_out
    from simulator.kernels.lights.emissive import PIECE_UNIFORM

    dev = engine._dev
    pieces = dev.pieces
    if pieces is None or pieces.n <= 1 or int(dev.rec.has_mesh) == 0:
        return None
    t0 = time.perf_counter()
    rng = np.random.default_rng(TABLE_SEED)
    pts = dev.rec.points.numpy().astype(np.float64)
    tris = dev.rec.tris.numpy().reshape(-1, 3)
    x, n = surface_points(pts, tris, SURFACE_POINTS, rng)
    x, n = np.concatenate([x, x]), np.concatenate([n, -n])  # both sides of every face reflect
    sensors = [s for s in engine.sensors if np.all(np.isfinite(s.position)) and np.linalg.norm(s.normal) > 0]
    if sensors:
        sp = np.array([s.position for s in sensors], np.float64)
        sn = np.array([s.normal for s in sensors], np.float64)
        x, n = np.concatenate([x, sp]), np.concatenate([n, sn / np.linalg.norm(sn, axis=1, keepdims=True)])
    if not len(x):
        return None
    lo, h, dims, cell, grid = cell_grid(x, n)
    C, K = int(cell.max()) + 1, pieces.n
    rays = int(np.clip(TABLE_RAYS // max(C * K, 1), 4, 32))
    idx = cell_receivers(cell, C, PER_CELL)
    wp = warp()
    kernel = engine.trace_variant.piece_table_kernel
    with wp.ScopedDevice(engine.device):
        cp = wp.array(np.ascontiguousarray(x[idx].reshape(-1, 3), np.float32), dtype=wp.vec3)
        cn = wp.array(np.ascontiguousarray(n[idx].reshape(-1, 3), np.float32), dtype=wp.vec3)
        out = wp.zeros(C * K, dtype=float)
        rec = dev.rec

        def run(offset: int, dim: int):
            wp.launch(kernel, dim=dim, inputs=[rec, cp, cn, PER_CELL, rays, int(engine.emissive_light), TABLE_SEED,
                                               offset], outputs=[out])  # fmt: skip

        fan_out(engine.threads, run, C * K)
        wp.synchronize_device()
        T = out.numpy().astype(np.float64).reshape(C, K)
    cdf, tot = probabilities(T, np.asarray(pieces.power_share, np.float64), float(PIECE_UNIFORM))
    table = PieceTable(lo, float(h), dims, grid, cdf, tot.astype(np.float32), rays, time.perf_counter() - t0)
    dev.set_piece_table(table)
    return table
