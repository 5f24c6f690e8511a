"""``probesim verify``: the registry's expected values, the pass rule, a quick
subset traced end to end, and the command line (table, CSV, exit status)."""

from __future__ import annotations

import csv
import dataclasses
import math

import numpy as np
import pytest

from simulator.reference import closed_forms as cf
from simulator.reference import cases as C
from simulator.reference.cases import direct as D
from simulator.commands import verify as V
from simulator.commands.cli import main

QUICK_SUBSET = ("cie171_5_2", "point_cm_yup", "distant_occluder", "radiance_floor [W]")


def _case(name: str) -> V.Case:
    (case,) = [c for c in V.CASES if c.name == name]
    return case


def present_cases():
    return [c for c in V.CASES if (V.default_configs_dir() / c.config).exists()]


@pytest.mark.parametrize("case", present_cases(), ids=lambda c: c.name)
def test_every_case_has_a_finite_expected_value_for_every_receiver(case):
    """Each bundled case's expected-value function covers all of its config's
    sensors (a receiver without a closed form is a registry error) and gives
    finite numbers, ≥ 0."""
    rows = V.expected_values(case)
    assert rows
    for s, ch, value, note in rows:
        assert math.isfinite(value) and value >= 0, (case.name, s.name, value)
        assert ch == 0 if case.light_units == "radiometric" else ch in (0, 1)


def test_cie171_5_2_expected_values_are_the_exact_case_values():
    """The CIE 171:2006 5.2 rows expect I0·h²/d⁴ with I0 = 1000 cd, h = 3 m —
    e.g. A: 1000/9 = 111.111 lx, J (d² = 13.5 m²): 9000/182.25 = 49.383 lx —
    and show the published table value and the disk model's deviation."""
    rows = {s.name: (value, note) for s, _, value, note in V.expected_values(_case("cie171_5_2"))}
    assert set(rows) == set("ABCDEFGHIJ")
    assert rows["A"][0] == pytest.approx(1000.0 / 9.0, rel=1e-12)
    assert rows["J"][0] == pytest.approx(1000.0 * 9.0 / 13.5**2, rel=1e-12)
    assert "CIE table 111.11" in rows["A"][1]
    grid = cf.cie171_point_source_grid()
    published = dict(zip(grid.names, grid.published_lx))
    for name, (value, _) in rows.items():  # the table agrees with the exact values to 0.03%
        assert value == pytest.approx(published[name], rel=3e-4)


def test_radiometric_twin_expects_the_same_numbers_in_watts():
    """The stages' numbers read as W m⁻² sr⁻¹ give the same expected W/m² as
    the photometric run gives lx (the closed forms are linear in L)."""
    lx = [v for _, _, v, _ in V.expected_values(_case("rect"))]
    w = [v for _, _, v, _ in V.expected_values(_case("rect [W]"))]
    np.testing.assert_allclose(w, lx, rtol=1e-12)


def test_point_cm_yup_expects_point_usda_readings():
    """The centimetre, Y-up stage must read what point.usda reads (same
    sensors in world metres): the same expected values."""
    a = [v for _, _, v, _ in V.expected_values(_case("point"))]
    b = [v for _, _, v, _ in V.expected_values(_case("point_cm_yup"))]
    np.testing.assert_allclose(b, a, rtol=1e-12)


def test_disk_bracket_contains_the_on_axis_closed_form():
    """The inscribed/circumscribed polygon bracket used for non-parallel disk
    receivers contains the exact on-axis value π·L·R²/(R²+h²) and is ~1e-7 wide."""
    from simulator.scene.model import Light, LightKind, Sensor, SensorKind

    light = Light("d", LightKind.DISK, np.array([0.0, 0.0, 2.0]), np.eye(3), (1.0, 1000.0), radius=0.5)
    s = Sensor("s", SensorKind.IRRADIANCE, np.zeros(3), np.array([0.0, 0.0, 1.0]))
    lo, hi = D.disk_bracket(light, s, 1)
    exact = float(cf.disk_irradiance_on_axis(1000.0, 0.5, 2.0))
    assert lo <= exact <= hi
    assert (hi - lo) / exact < 1e-6


@pytest.mark.parametrize(
    "expected, measured, stderr, ok",
    [
        (100.0, 100.5, 0.2, True),  # 0.5%, 2.5σ
        (100.0, 100.9, 0.2, False),  # 0.9% but 4.5σ
        (100.0, 101.5, 1.0, False),  # 1.5σ but 1.5%
        (100.0, 100.0001, 0.0, True),  # zero variance, within float32 slack (2e-6 × 100)
        (100.0, 100.001, 0.0, False),  # zero variance, beyond it
        (0.0, 0.0, 0.0, True),  # full shadow reads exactly 0
        (0.0, 1e-3, 1e-3, False),  # ... and nothing else
        (100.0, math.nan, 1.0, False),
    ],
)
def test_judge(expected, measured, stderr, ok):
    """Pass = within 1% AND within 4·stderr + 2e-6·|expected|."""
    assert V.judge(expected, measured, stderr) is ok


def test_quick_subset_passes():
    """A few cases traced end to end with --quick settings: every reading passes."""
    rows = []
    for name in QUICK_SUBSET:
        rows += V.run_case(_case(name), quick=True)
    assert rows and all(r.passed for r in rows), [V.format_row(r) for r in rows if not r.passed]
    assert {r.unit for r in rows} >= {"lx", "W/m²", "W/m²/sr", "lm"}


def test_missing_optional_config_is_skipped_with_a_note(tmp_path):
    """An optional case whose config is absent is reported, not failed."""
    case = V.Case("later", "not_yet.toml", "work in progress", lambda ctx, s, ch: 0.0, method="path", optional=True)
    notes = []
    result = V.run_suite(cases=(case,), on_skip=notes.append)
    assert result.rows == [] and result.passed and len(notes) == 1 and "not_yet.toml" in notes[0]


def test_a_broken_case_fails_its_row_and_the_others_still_run():
    """A case whose config is missing (and not optional) is one failing row
    naming the file; the next case still runs and passes."""
    broken = V.Case("broken", "missing.toml", "a config that is not there", lambda ctx, s, ch: 0.0)
    result = V.run_suite(cases=(broken, _case("point_cm_yup")), quick=True)
    assert not result.passed
    assert result.rows[0].case == "broken" and not result.rows[0].passed and "missing.toml" in result.rows[0].note
    assert all(r.passed for r in result.rows[1:]) and len(result.rows) == 5
    assert "FAIL" in V.format_row(result.rows[0])


def test_cli_prints_the_table_writes_csv_and_exits_0(tmp_path, capsys):
    """`probesim verify -k radiance_floor --csv OUT` prints a header, one row per
    receiver and a summary, writes the same rows as CSV, and exits 0."""
    out = tmp_path / "v.csv"
    assert main(["verify", "--quick", "-k", "radiance_floor", "--csv", str(out)]) == 0
    text = capsys.readouterr().out
    assert "receiver" in text and "all pass" in text and "nadir" in text
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 8 and all(r["pass"] == "true" for r in rows)
    assert {"case", "receiver", "unit", "expected", "measured", "stderr", "error_pct", "error_stderrs"} <= set(rows[0])


def test_cli_exits_1_when_a_reading_fails(monkeypatch, capsys):
    """A case whose expected value is 2% off fails its rows, and the command exits 1."""
    good = _case("distant_occluder")
    bad = dataclasses.replace(good, name="distant_occluder_wrong", expected=lambda ctx, s, ch: 1.02 * good.expected(ctx, s, ch))
    monkeypatch.setattr(V, "CASES", (bad,))
    assert main(["verify", "--quick"]) == 1
    text = capsys.readouterr().out
    assert "FAIL" in text


def test_the_registry_declares_each_case_once_with_its_suites():
    """One registry: names are unique, every case belongs to a known suite and
    says what it measures; verify's cases are the registry's verify suite, in
    order, stability's its hard cases, chart's default list its chart suite;
    every photometric direct-light case has a radiometric twin."""
    names = [c.name for c in C.CASES]
    assert len(names) == len(set(names))
    assert all(c.suites and set(c.suites) <= set(C.SUITES) and c.measures for c in C.CASES)
    assert V.CASES == C.suite("verify")
    from simulator.commands import chart, stability

    assert stability.CASES == C.suite("stability")
    assert all(c.config.startswith("stability/") for c in stability.CASES)
    assert chart.DEFAULT_CONFIGS == tuple(c.config[: -len(".toml")] for c in C.suite("chart"))
    assert [c.chart for c in C.suite("chart")] == list(range(len(chart.DEFAULT_CONFIGS)))
    twins = {c.name[: -len(" [W]")] for c in C.CASES if c.name.endswith(" [W]")}
    assert twins == {c.name for c in C.suite("verify") if c.method != "path" and c.light_units is None}


def test_cli_unknown_case_filter_is_a_user_error(capsys):
    assert main(["verify", "-k", "no_such_case"]) == 2
    assert "no case name contains" in capsys.readouterr().err
