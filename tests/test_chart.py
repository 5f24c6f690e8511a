"""``probesim chart``: the CSV, the curve maths, and the −½ slope of an unbiased estimator."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from simulator.commands.chart import CSV_COLUMNS, fit_slope, run_chart, time_to
from simulator.commands.cli import main

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


def test_fit_slope_and_time_to_on_an_exact_power_law():
    """On err = 0.1/√t at t = 1e-3 … 1 s the fit returns −0.5 exactly; the
    time to err 0.5 is (0.1/0.5)² = 0.04 s, between rungs (log-log
    interpolation is exact on a power law); err 0.01 needs t = 100 s, beyond
    the ladder; err 10 is met by the first rung already."""
    t = np.logspace(-3, 0, 10)
    e = 0.1 / np.sqrt(t)
    slope, used = fit_slope(t, e)
    assert slope == pytest.approx(-0.5, abs=1e-12)
    assert used == [i for i in range(10) if t[i] >= 10 * t[0]]
    # err = 0.5 lies between rungs: log-log interpolation is exact on a power law
    t_half, first = time_to(t, e, 0.5)
    assert t_half == pytest.approx(0.04, rel=1e-12) and not first
    assert time_to(t, e, 0.01) == (None, False)  # never reached on this ladder
    assert time_to(t, e, 10.0) == (pytest.approx(1e-3), True)  # the first rung already meets it


def test_fit_slope_leaves_out_rungs_near_the_reference_floor():
    """Rungs whose error is under 3× the reference's own error measure the
    reference, not the method: a curve that flattens at 1e-4 on a 1e-4 floor
    still fits −½ on the rungs above 3e-4."""
    n = 2.0 ** np.arange(4, 24)
    e = np.sqrt(1.0 / n + 1e-8)  # 1/√N with a 1e-4 floor added in quadrature
    slope, used = fit_slope(n, e, floor=1e-4, min_time_ratio=0.0)
    assert all(e[i] >= 3e-4 for i in used)
    assert slope == pytest.approx(-0.5, abs=0.03)


def test_chart_csv_columns_and_the_unbiased_slope(tmp_path):
    """Chart the disk stage (closed-form reference) with ``light`` on a fixed
    ladder, 16 … 16384 samples per sensor, 16 seeds per rung, every run its own
    seed.

    The CSV has the documented columns and one row per (rung, seed, sensor);
    the reference column is the closed form.

    The slope of log(RMS relative error) on log(samples) is −½ for an unbiased
    estimator. Statistical tolerance: a rung's squared error is a mean of K
    squared, nearly normal relative errors (K = seeds × sensors), whose log
    has standard deviation √(2/K_eff), so log RMS error has √(1/(2·K_eff)),
    with K_eff = seeds·(Σvᵢ)²/Σvᵢ² for per-sensor relative variances vᵢ
    (measured here from the runs' standard errors); the least-squares slope
    over rungs xᵣ = log Nᵣ then has standard error √(1/(2·K_eff)/Σ(xᵣ − x̄)²).
    The test allows 4 of them (a fixed seed: deterministic, a 6e-5 chance of
    a false alarm had it been drawn at random)."""
    seeds = 16
    charts = run_chart([CONFIGS / "disk.toml"], tmp_path, seeds=seeds, max_seconds=1e9, methods=("analytic", "light"),
                       max_budget=1 << 14, log=lambda m: None)  # fmt: skip
    (ch,) = charts
    assert ch.reference_kind.startswith("closed form") and ch.reference_rel_stderr == 0.0
    with open(tmp_path / "chart.csv", newline="") as f:
        reader = csv.DictReader(f)
        assert tuple(reader.fieldnames) == CSV_COLUMNS
        rows = list(reader)
    light = [r for r in rows if r["method"] == "light"]
    rungs = sorted({int(r["budget"]) for r in light})
    assert rungs == [16 << k for k in range(11)]
    assert len(light) == len(rungs) * seeds * ch.sensors
    assert len({(r["budget"], r["seed"]) for r in light}) == len(rungs) * seeds  # every run its own seed
    assert len({r["seed"] for r in light}) == len(rungs) * seeds
    assert {r["device"] for r in rows} == {"cpu"}
    analytic = [r for r in rows if r["method"] == "analytic"]
    assert all(float(r["estimate"]) == pytest.approx(float(r["reference"]), rel=1e-6) for r in analytic)
    assert (tmp_path / "chart_disk.png").read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "chart_disk.png").stat().st_size < 300_000

    # per-sensor relative variance per sample, from the runs' standard errors
    v = {}
    for r in light:
        v.setdefault(r["sensor"], []).append(int(r["budget"]) * (float(r["stderr"]) / float(r["reference"])) ** 2)
    v = np.array([np.mean(x) for x in v.values()])
    k_eff = seeds * v.sum() ** 2 / (v**2).sum()
    x = np.log(np.array(rungs, float))
    se_slope = math.sqrt(1.0 / (2.0 * k_eff) / np.sum((x - x.mean()) ** 2))
    curve = next(c for c in ch.curves if c.method == "light")
    assert curve.slope_samples is not None
    assert abs(curve.slope_samples + 0.5) <= 4.0 * se_slope, (curve.slope_samples, se_slope)


def test_chart_command_writes_outputs_and_rejects_bad_options(tmp_path, capsys):
    """``probesim chart`` on the point stage (a closed form; every run under a
    millisecond) writes the CSV and a PNG and prints the summary; a seed count
    of 0 is one line on stderr, exit 2, nothing written."""
    out = tmp_path / "out"
    assert main(["chart", str(CONFIGS / "point.toml"), "--out", str(out), "--seeds", "2", "--max-seconds", "0.002"]) == 0
    text = capsys.readouterr().out
    assert "to 1%" in text and "point" in text
    assert (out / "chart.csv").exists() and (out / "chart_point.png").exists()
    bad = tmp_path / "bad"
    assert main(["chart", str(CONFIGS / "point.toml"), "--out", str(bad), "--seeds", "0"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("probesim: error:") and "--seeds" in err and "\n" not in err
    assert not bad.exists()
