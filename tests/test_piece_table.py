"""The emitter pieces' table per cell (simulator.engine.piece_table, kernels/lights/emissive.py).

A receiver in a cell picks piece k with P(k | c) = (1 − α)·T_ck/Σ T + α·π_k:
the grid finds every receiver it was built from, every piece keeps a
probability (so the estimate is unbiased whatever the measured T holds), the
host's normal buckets are the kernel's, the table is the same bytes at any
thread count, and on the furnished office it leaves the readings where the
pieces' own pick puts them while cutting their variance.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import warp as wp

from simulator.config import load_config
from simulator.engine import piece_table as PT
from simulator.engine.driver import Engine
from simulator.kernels.lights.emissive import PIECE_UNIFORM, normal_bucket
from simulator.scene.model import SensorKind

ROOT = Path(__file__).resolve().parents[1]


def test_grid_finds_every_receiver_and_keeps_its_caps():
    """Every receiver the grid is built from lies in a cell (PieceTable.cell_of, the kernel's lookup
    on the host) whose voxel and normal bucket are its own; a cap of 40 cells grows the spacing from
    0.5 m (×1.5 each time) until the cells fit, and the grid then holds at most 40."""
    rng = np.random.default_rng(3)
    x = rng.uniform([0, 0, 0], [8, 6, 3], (2000, 3))
    n = rng.normal(size=(2000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    for cap, grown in ((8192, False), (40, True)):
        lo, h, dims, cell, grid = PT.cell_grid(x, n, 0.5, cap)
        assert (h > 0.5) == grown and (grid >= 0).sum() <= cap
        table = PT.PieceTable(lo, h, dims, grid, np.ones((cell.max() + 1, 1), np.float32), np.zeros(cell.max() + 1), 4, 0.0)
        np.testing.assert_array_equal(table.cell_of(x, n), cell)
        # a cell holds one bucket of one voxel
        iv = np.floor((x - lo) / h).astype(np.int64)
        key = iv[:, 0] * 10**8 + iv[:, 1] * 10**4 + iv[:, 2] * 10 + PT.normal_buckets(n)
        assert len(np.unique(key)) == cell.max() + 1
        assert table.cell_of(np.array([[-100.0, 0, 0]]), np.array([[0.0, 0, 1]]))[0] == -1  # outside the grid


def test_every_piece_keeps_a_probability():
    """P(k | c) = (1 − α)·T_ck/Σ_j T_cj + α·π_k: each row of the CDF ends at 1, each piece's probability is
    at least α·π_k (a piece the rays never saw lit can still be drawn), and a cell where every T is 0
    picks ∝ power (α = PIECE_UNIFORM = 0.1)."""
    T = np.array([[4.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    power = np.array([0.5, 0.3, 0.2])
    cdf, tot = PT.probabilities(T, power, PIECE_UNIFORM)
    P = np.diff(np.concatenate([np.zeros((3, 1)), cdf.astype(np.float64)], axis=1), axis=1)
    assert np.all(cdf[:, -1] == 1.0)
    np.testing.assert_allclose(tot, T.sum(axis=1))
    assert np.all(P >= PIECE_UNIFORM * power - 1e-7)
    np.testing.assert_allclose(P[0], 0.9 * np.array([0.8, 0.0, 0.2]) + 0.1 * power, atol=1e-7)
    np.testing.assert_allclose(P[1], power, atol=1e-7)


@wp.kernel
def _buckets(n: wp.array(dtype=wp.vec3), out: wp.array(dtype=wp.int32)):
    i = wp.tid()
    out[i] = normal_bucket(n[i])


def test_host_buckets_are_the_kernels():
    """normal_buckets (host) and normal_bucket (kernel) put every normal in the same bucket, ties between
    axes included (the first axis wins): the cells the host builds are the ones the kernel reads."""
    rng = np.random.default_rng(5)
    n = rng.normal(size=(4000, 3)).astype(np.float32)
    ties = np.array([[1, 1, 0], [-1, 1, 0], [0, -1, -1], [1, 1, 1], [-1, -1, -1], [0, 0, -1], [0, 0, 0]], np.float32)
    n = np.concatenate([n, ties])
    with wp.ScopedDevice("cpu"):
        out = wp.zeros(len(n), dtype=wp.int32)
        wp.launch(_buckets, dim=len(n), inputs=[wp.array(n, dtype=wp.vec3)], outputs=[out])
        np.testing.assert_array_equal(out.numpy(), PT.normal_buckets(n.astype(np.float64)))


def _furnished(n_sensors: int = 12):
    from simulator.pipeline import collect_sensors, load_scene

    cfg = load_config(ROOT / "configs" / "office_furnished.toml")
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind == SensorKind.IRRADIANCE]
    return scene, sensors[:: len(sensors) // n_sensors][:n_sensors]


def test_table_is_the_same_at_any_thread_count():
    """The table of the furnished office (its window emitter in pieces) is the same bytes built by one
    worker or two: each entry is one kernel thread with its own stream, summed on the host."""
    scene, sensors = _furnished()
    tables = []
    for threads in (1, 2):
        eng = Engine(scene, sensors, threads=threads)
        eng.scene_rec  # uploads the scene, builds the table
        tables.append(eng.piece_table)
    assert tables[0] is not None and tables[0].n_cells > 100
    np.testing.assert_array_equal(tables[0].cdf, tables[1].cdf)
    np.testing.assert_array_equal(tables[0].grid, tables[1].grid)


@pytest.mark.parametrize("method", ["path", "mis"])
def test_table_keeps_the_readings_and_cuts_their_variance(method):
    """The furnished office (a window onto an 8 m × 4 m emitter its wall mostly hides, eight diffusers,
    furniture on legs), 12 work-plane sensors, the pieces kept: read with each cell's table and with the
    pieces weighed one by one (``Engine.piece_table = False``), the readings agree within 4 combined
    standard errors (both are unbiased: only the pieces' pdf differs), and the table's relative variance
    per sample is under 0.8× the other's (measured 0.49× with path, 0.27× with mis: each cell's
    visibility of each piece in place of one factor per piece for the whole room)."""
    scene, sensors = _furnished()
    res = {}
    for table in (True, False):
        eng = Engine(scene, sensors)
        eng.emitter_pieces = True
        if not table:
            eng.piece_table = False
        res[table] = eng.run(method, samples=1024 if method == "path" else 512, seed=11)
        assert bool(eng.piece_table) == table
    a, b = res[True], res[False]
    se = np.hypot(a.stderr, b.stderr)
    assert np.all(np.abs(a.mean - b.mean) <= 4 * se), (a.mean - b.mean) / se
    rv = [np.mean((r.stderr[:, 1] / r.mean[:, 1]) ** 2) for r in (a, b)]
    assert rv[0] < 0.8 * rv[1], rv
