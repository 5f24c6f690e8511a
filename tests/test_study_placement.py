"""Greedy sensor placement: brute force on small cases, the (1 − 1/e) bound, lazy evaluation, separability, zone figures."""

import math

import numpy as np
import pytest

from simulator.study.figures.objectives import calibrated_errors, compliance, zone_figures
from simulator.study.figures.placement import brute_force, gains, greedy_lazy, place_sensors, set_value


def _plain_greedy(q, k):
    chosen = []
    for _ in range(k):
        vals = [(float(set_value(q, chosen + [i])), -i) for i in range(q.shape[0]) if i not in chosen]
        chosen.append(-max(vals)[1])
    return chosen


@pytest.mark.parametrize("seed", range(6))
def test_lazy_greedy_equals_plain_greedy_and_brute_force(seed):
    """Random facility-location gains, 9 candidates × 3 zones, K = 2: lazy and plain greedy
    pick the same set; it is the brute-force best or within (1 − 1/e) of it."""
    q = np.random.default_rng(seed).random((9, 3))
    chosen, g, evals = greedy_lazy(q, 2)
    assert chosen == _plain_greedy(q, 2)
    assert math.isclose(sum(g), float(set_value(q, chosen)), rel_tol=1e-12)
    best_set, best = brute_force(q, 2)
    assert float(set_value(q, chosen)) >= (1 - 1 / math.e) * best - 1e-12
    assert evals <= 9 * 2


def test_greedy_equals_brute_force_on_a_zone_per_sensor_case():
    """Each zone has one sensor clearly best for it: greedy finds the brute-force best set."""
    q = np.array([[0.9, 0.1, 0.0], [0.1, 0.8, 0.1], [0.0, 0.2, 0.95], [0.3, 0.3, 0.3], [0.3, 0.3, 0.2]])
    chosen, _, _ = greedy_lazy(q, 3)
    assert tuple(sorted(chosen)) == brute_force(q, 3)[0] == (0, 1, 2)


def test_greedy_is_within_the_bound_where_it_is_not_optimal():
    """A case where greedy is suboptimal (named: the 'generalist trap'): a sensor that is
    fair for both zones is picked first; the best pair is the two specialists (F = 1.0);
    greedy gets F = (1.0 + 0.6)/2 = 0.8 ≥ (1 − 1/e)·1.0 = 0.632."""
    q = np.array([[0.6, 0.6], [1.0, 0.0], [0.0, 1.0]])
    chosen, _, _ = greedy_lazy(q, 2)
    assert chosen[0] == 0
    best_set, best = brute_force(q, 2)
    assert best_set == (1, 2) and math.isclose(best, 1.0)
    v = float(set_value(q, chosen))
    assert v < best and v >= (1 - 1 / math.e) * best


def test_calibration_recovers_a_linear_sensor():
    """A sensor reading 3·T + 5 predicts T exactly after calibration: ρ = 1, errors 0."""
    t = np.array([100.0, 300.0, 700.0, 250.0])
    r = np.stack([3 * t + 5, np.ones(4), t**2])
    corr, rel = calibrated_errors(r, t)
    assert math.isclose(corr[0], 1.0, rel_tol=1e-12) and np.allclose(rel[0], 0.0, atol=1e-12)
    assert corr[1] == 0.0 and 0.9 < corr[2] < 1.0


def test_placement_flags_inseparable_candidates():
    """Two sensors with the same signal (up to noise) cannot be told apart; a distinct one can."""
    rng = np.random.default_rng(1)
    t = np.array([[100.0, 200.0, 400.0, 800.0, 300.0, 600.0]])
    r = np.stack([2 * t[0] + rng.normal(0, 5, 6), 2 * t[0] + rng.normal(0, 5, 6), rng.random(6) * 100])
    pl = place_sensors(["a", "b", "c"], r, np.full_like(r, 20.0), t, np.full_like(t, 1.0), ["z"], 1, "p95_rel_error", 200, 7)
    assert pl.steps[0].sensor in ("a", "b") and pl.steps[0].runner_up in ("a", "b")
    assert not pl.steps[0].separable
    pl2 = place_sensors(["a", "c"], r[[0, 2]], np.full((2, 6), 0.5), t, np.full_like(t, 0.1), ["z"], 1, "correlation", 200, 7)
    assert pl2.steps[0].sensor == "a" and pl2.steps[0].separable and pl2.steps[0].score_se > 0


def test_error_gains_are_against_no_sensor():
    """q = e0 − e ≥ 0: a perfect sensor's gain is the constant predictor's error."""
    t = np.array([[100.0, 200.0, 400.0]])
    q, base = gains(np.stack([t[0] * 2.0]), t, "max_rel_error")
    assert math.isclose(q[0, 0], base[0], rel_tol=1e-9) and base[0] > 0


def test_uniformity_standard_error_matches_monte_carlo():
    """Delta-method σ(U0) and σ(Ē) against the spread of U0 over 20 000 noisy redraws (within 5%)."""
    rng = np.random.default_rng(4)
    e = np.array([300.0, 420.0, 510.0, 480.0, 650.0, 390.0])
    se = np.array([6.0, 8.0, 9.0, 7.0, 12.0, 8.0])
    f = zone_figures(e, se)
    draws = e + se * rng.standard_normal((20000, 6))
    u0 = draws[:, 0] / draws.mean(axis=1)  # the minimum stays at sensor 0 (300 ± 6 vs 390 ± 8)
    assert abs(np.std(u0) / f.u0_se - 1) < 0.05
    assert abs(np.std(draws.mean(axis=1)) / f.mean_se - 1) < 0.05
    assert math.isclose(f.u0, 300 / e.mean()) and math.isclose(f.min_max, 300 / 650)


def test_compliance_needs_two_standard_errors():
    f = zone_figures(np.array([500.0, 520.0]), np.array([5.0, 5.0]))  # mean 510 ± 3.5
    assert compliance(f, {"mean": 500})["mean"] == "pass"
    assert compliance(f, {"mean": 505})["mean"] == "unsure"
    assert compliance(f, {"mean": 600, "max": 400}) == {"mean": "fail", "max": "fail"}
