"""The engine's parts on their own: the thread fan-out, the adaptive stopping
rule and batch loop, and the kind declarations the kernels are generated from."""

from __future__ import annotations

import math
import threading

import numpy as np
import pytest

from simulator.engine.adaptive import StoppingRule, run_batches
from simulator.engine.fanout import fan_out
from simulator.engine.stats import Z95
from simulator.io.results import COLUMNS, PROBE_COLUMNS
from simulator.scene.model import SENSOR_KINDS, SENSOR_SPECS, LightKind, SensorKind, patch_width_axis


@pytest.mark.parametrize("threads", [1, 2, 3, 7])
@pytest.mark.parametrize("n", [1, 5, 6, 101])
def test_fan_out_covers_every_kernel_thread_once(threads, n):
    """Every index in [0, n) is launched exactly once, in at most ``threads`` slices."""
    hits = np.zeros(n, int)
    calls = []
    lock = threading.Lock()

    def run(offset, dim):
        with lock:
            calls.append((offset, dim))
            hits[offset : offset + dim] += 1

    fan_out(threads, run, n)
    assert np.all(hits == 1)
    assert len(calls) == min(threads, n)


def test_stopping_rule_target_is_the_larger_of_relative_and_absolute():
    """met ⇔ z·se ≤ max(rel·|value|, abs) in every channel (z = 1.96 at 95%)."""
    rule = StoppingRule(0.01, 0.5, 0.95)
    assert rule.z == pytest.approx(Z95, rel=1e-12)
    value = np.array([[100.0, 10.0], [100.0, 10.0], [-100.0, 1.0]])
    se = np.array([[0.5, 0.2], [0.52, 0.2], [0.5, 0.26]])
    met, target = rule.check(value, se)
    np.testing.assert_allclose(target, [[1.0, 0.5], [1.0, 0.5], [1.0, 0.5]])
    # 1.96·0.5 = 0.98 ≤ 1 and 1.96·0.2 = 0.39 ≤ 0.5; 1.96·0.52 = 1.02 > 1; 1.96·0.26 = 0.51 > 0.5
    assert met.tolist() == [True, False, False]


def test_next_batch_reaches_the_target_if_the_variance_holds():
    """need = ⌈n·(z·se/target)²·1.1⌉ − n, clipped to [block, n]; a unit with
    no variance estimate (se = inf) doubles."""
    rule = StoppingRule(0.01, 0.0, 0.95)
    count = np.array([1000, 1000, 1000, 0])
    target = np.ones((4, 2))
    ratio = np.array([1.1, 4.0, np.inf, np.inf])
    se = np.sqrt(ratio)[:, None] / rule.z * np.ones((1, 2))
    want = rule.next_batch(count, se, target, 32)
    assert want[0] == math.ceil(1000 * 1.1 * 1.1) - 1000  # 210 more
    assert want[1] == 1000  # 4× needed: at most doubling
    assert want[2] == 1000  # inf → ratio 2: doubling
    assert want[3] == 32  # nothing yet: one block


def test_run_batches_stops_each_unit_when_its_target_is_met():
    """Units with se = σ/√n stop at the first batch where z·σ/√n ≤ rel·|v|;
    a unit with no variance-free target runs to the cap."""
    sigma = np.array([[10.0, 10.0], [40.0, 40.0], [1e9, 1e9]])  # need n ≥ (1.96σ)²: 385, 6147, never
    value = np.full((3, 2), 100.0)
    count = np.zeros(3, np.int64)

    def step(ids, first, n):
        assert np.array_equal(first, count[ids])  # each batch starts where the last ended
        count[ids] += n

    def measure():
        with np.errstate(divide="ignore"):
            return value, sigma / np.sqrt(count)[:, None]

    rule = StoppingRule(0.01, 0.0, 0.95)
    drawn, met = run_batches(step, np.ones(3, bool), np.full(3, 64, np.int64), 1 << 14, block=32, rule=rule, measure=measure)
    assert np.array_equal(drawn, count)
    assert met.tolist() == [True, True, False]
    assert drawn[2] == 1 << 14
    for k in range(2):  # met now, and not at the batch before (at most doubling: ≥ half the samples)
        assert rule.z * sigma[k, 0] / math.sqrt(drawn[k]) <= 1.0
        assert rule.z * sigma[k, 0] / math.sqrt(drawn[k] / 2) > 1.0


def test_run_batches_fixed_budget_and_time_limit():
    """Without a rule every unit draws ``cap`` in batches of ``want``; a time
    limit of 0 stops everything after the first batch."""
    batches = []
    drawn, met = run_batches(lambda ids, first, n: batches.append(n.copy()), np.ones(2, bool), np.array([100, 300]), 500, block=32)
    assert drawn.tolist() == [500, 500] and not met.any()
    assert [b.tolist() for b in batches][:2] == [[100, 300], [100, 200]]
    drawn, _ = run_batches(lambda *a: None, np.ones(2, bool), np.array([100, 300]), 500, block=32, time_limit_s=0.0)
    assert drawn.tolist() == [100, 300]


def test_every_light_kind_has_one_kernel_file():
    """The kernels' dispatch covers every LightKind, in integer order, and a
    kind whose surface rays can hit also has the pdf MIS weighs the hit with."""
    from simulator.kernels.lights import KERNELS

    assert [k.kind for k in KERNELS] == list(LightKind)
    for k in KERNELS:
        assert k.sample is not None
        if k.hit is not None or k.escaped is not None:
            assert k.pdf is not None, k.kind


def test_sensor_declarations_drive_the_kernel_and_the_csv():
    """Each estimator-read sensor kind has one kernel entry; the CSV header is
    the fixed columns around every kind's value columns, each once."""
    from simulator.kernels.estimators import SENSOR_KERNELS

    assert [s.kind for s in SENSOR_SPECS] == list(SensorKind)
    assert sorted(k.kind for k in SENSOR_KERNELS) == [s.kind for s in SENSOR_SPECS if s.reader == "estimate"]
    assert SENSOR_KINDS == {"irradiance": SensorKind.IRRADIANCE, "radiance": SensorKind.RADIANCE,
                            "patch": SensorKind.PATCH, "probe": SensorKind.PROBE, "cylindrical": SensorKind.CYLINDRICAL,
                            "semicylindrical": SensorKind.SEMICYLINDRICAL, "glare": SensorKind.GLARE}  # fmt: skip
    assert COLUMNS[:8] == ("sensor", "kind", "x", "y", "z", "dx", "dy", "dz")
    assert COLUMNS[-4:] == ("samples", "seconds", "method", "target_met")
    assert len(set(COLUMNS)) == len(COLUMNS) == 32
    assert PROBE_COLUMNS == COLUMNS[COLUMNS.index("scalar_irradiance_W_m2") : COLUMNS.index("samples")]


def test_patch_width_axis_is_right_handed():
    """(width, up, normal) is right-handed: width × up = normal for unit,
    orthogonal up and normal."""
    up, normal = np.array([0.0, 0.0, 1.0]), np.array([0.0, -1.0, 0.0])
    right = patch_width_axis(up, normal)
    np.testing.assert_allclose(right, [1.0, 0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(np.cross(right, up), normal, atol=1e-15)


@pytest.mark.parametrize("threads", [2, 3, 7])
@pytest.mark.parametrize("n, align", [(101, 8), (64, 8), (9, 8), (5, 8), (100, 1)])
def test_aligned_fan_out_never_cuts_a_chunk(threads, n, align):
    """With ``align`` every slice starts at a multiple of it (a guide pilot's
    tally blocks then stay on one worker), the slices still cover [0, n)
    once, and there are at most min(threads, ⌈n/align⌉) of them."""
    hits = np.zeros(n, int)
    calls = []
    lock = threading.Lock()

    def run(offset, dim):
        with lock:
            calls.append((offset, dim))
            hits[offset : offset + dim] += 1

    fan_out(threads, run, n, align=align)
    assert np.all(hits == 1)
    assert len(calls) == min(threads, -(-n // align))
    assert all(o % align == 0 for o, _ in calls)