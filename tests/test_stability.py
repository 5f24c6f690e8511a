"""The stability matrix: verdicts that physics dictates, and the kernel fixes it exposed.

Cells here run a fixed number of samples with a fixed seed (reproducible),
not the wall-clock budget of ``probesim stability``. Readings are compared
with the closed forms of ``simulator.commands.stability`` (``simulator.reference.closed_forms``)
within 4 standard errors plus float32 slack (2e-6 relative, as in
test_direct_light.py).
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from simulator.config.loader import load_config
from simulator.engine.driver import Engine
from simulator.pipeline import collect_sensors, load_scene
from simulator.commands.stability import (
    CASES,
    CSV_COLUMNS,
    METHODS,
    load_case,
    run_cell,
    verdict,
    worst,
    write_stability,
)

FLOAT32_SLACK = 2e-6


@pytest.fixture(scope="module")
def cases():
    """Every bundled case loaded once: name -> (engine, truth, scale)."""
    return {c.name: load_case(c.name) for c in CASES}


def _assert_reads_truth(cell, what: str, slack: float = FLOAT32_SLACK):
    for name, truth, scale, est, se, bad, _ in cell.per_sensor:
        assert bad == 0, f"{what}/{name}: {bad} non-finite samples"
        bound = 4.0 * se + slack * max(abs(truth), 1e-12)
        assert abs(est - truth) <= bound, f"{what}/{name}: {est} vs {truth} ± {se}"


# ------------------------------------------------------------------ the verdict function


@pytest.mark.parametrize(
    "args, kwargs, expected",
    [
        ((10.0, 10.01, 0.01), {}, "ok"),  # 1 stderr off, 0.1% relative stderr
        ((10.0, 10.00005, 0.0), {}, "ok"),  # zero variance, off by float32 rounding only (under the 0.1% floor)
        ((10.0, 10.2, 0.5), {}, "noisy"),  # within 4 stderr, but a 5% stderr
        ((10.0, 10.5, 0.01), {}, "biased"),  # 50 stderr and 5% off
        ((10.0, 3.0, 0.01), {}, "biased"),  # far off, but it does see something: not blind
        ((10.0, 0.0, 0.0), {}, "blind"),  # reads nothing where the truth is positive
        ((10.0, 0.005, 0.001), {}, "blind"),  # under 0.1% of the truth, 5 stderr from it
        ((10.0, 0.0, 5.0), {}, "noisy"),  # reads 0 but cannot tell: 2 stderr from the truth
        ((0.0, 1e-3, 1e-5), {"scale": 100.0}, "ok"),  # a shadow: 1e-5 of the unshadowed reading is float noise
        ((0.0, 1.0, 1e-3), {"scale": 100.0}, "biased"),  # a shadow reading 1% of the lit value: a leak
        ((10.0, 10.0, 0.01, 3), {}, "biased"),  # NaN/Inf samples were dropped: the mean is biased
        ((10.0, math.nan, 0.01), {}, "biased"),
    ],
)
def test_verdict_classifies_synthetic_readings(args, kwargs, expected):
    """Synthetic (truth, estimate, stderr[, non_finite]) readings get the verdict
    their definition gives (REL_FLOOR 1e-3, NOISY_REL_STDERR 1e-2,
    BLIND_FRACTION 1e-3, 4 standard errors)."""
    assert verdict(*args, **kwargs) == expected


def test_worst_verdict_orders_blind_biased_noisy_ok():
    """A cell shows its worst sensor: blind > biased > noisy > ok."""
    assert worst(["ok", "noisy", "ok"]) == "noisy"
    assert worst(["noisy", "biased"]) == "biased"
    assert worst(["biased", "blind", "ok"]) == "blind"
    assert worst([]) == "ok"


# ------------------------------------------------------------------ verdicts physics dictates


@pytest.mark.parametrize("case", ["delta_point", "delta_distant"])
def test_bsdf_is_blind_and_light_sampling_exact_for_delta_lights(cases, case):
    """A point light and an angle-0 distant light are delta distributions: no
    sampled direction hits them, so ``bsdf`` reads 0 (blind), while ``light``,
    ``mis`` and ``path`` sample the one direction and read E = I·cosξ/d² (or
    E⊥·cosξ) with zero variance: ok."""
    engine, truth, scale = cases[case]
    assert run_cell(engine, case, "bsdf", truth, scale, samples=4096).verdict == "blind"
    for m in ("light", "mis", "path", "analytic"):
        cell = run_cell(engine, case, m, truth, scale, samples=256)
        assert cell.verdict == "ok", (m, cell.per_sensor)
        _assert_reads_truth(cell, f"{case}/{m}")


def test_no_method_yields_nan_or_inf_on_any_case(cases):
    """Every method on every hard case: no sample comes out NaN or Inf (the
    engine would drop and count it), and every reading is finite."""
    for name, (engine, truth, scale) in cases.items():
        for m in METHODS:
            cell = run_cell(engine, name, m, truth, scale, samples=1024 if name == "furnace99" else 4096)
            assert cell.non_finite == 0, (name, m)
            assert all(math.isfinite(r[3]) and math.isfinite(r[4]) for r in cell.per_sensor), (name, m)


def test_furnace99_path_is_unbiased_direct_methods_are_not(cases):
    """In a closed box of albedo 0.99 every sensor reads E = π·L_e/(1 − ρ) =
    100π; ``path`` follows the interreflections (within 4 stderr), the
    direct-only methods see the walls' emission only, π·L_e: biased."""
    engine, truth, scale = cases["furnace99"]
    cell = run_cell(engine, "furnace99", "path", truth, scale, samples=4096)
    _assert_reads_truth(cell, "furnace99/path")
    for m in ("light", "bsdf", "mis"):
        assert run_cell(engine, "furnace99", m, truth, scale, samples=1024).verdict == "biased", m


# ------------------------------------------------------------------ the fixes


def test_leak_case_reads_zero_under_every_shade(cases):
    """Three lamps sit in black trays whose floors are 1e-4 m below them, one
    lamp 300 m from the origin (where rays are pushed 3 mm off surfaces): no
    straight line from outside reaches a lamp, so every receiver reads exactly
    0 with every method. Before the fix, light sampling's shadow segment ran
    parallel to the sample direction from the pushed origin and ended beside
    the far lamp, under its tray floor: 1.4 W/m² leaked."""
    engine, truth, scale = cases["leak"]
    assert np.all(truth == 0)
    for m in ("light", "bsdf", "mis", "path"):
        cell = run_cell(engine, "leak", m, truth, scale, samples=1 << 14)
        for name, _, _, est, _, bad, _ in cell.per_sensor:
            assert est == 0.0 and bad == 0, (m, name, est)


def test_receiver_on_a_ten_km_plane_reads_the_unshadowed_closed_form(cases):
    """Receivers lying on a tilted 10 km plane (float32 vertices 5 km out)
    read the unshadowed sphere-light closed form, and a meter looking down at
    it ρ/π times the irradiance there. Warp's float32 ray-triangle test
    reported the plane as hit by rays leaving it (error ~5e-4 m, above the
    1e-5 m push): the receiver at the origin read 0 with every method."""
    engine, truth, scale = cases["on_surface"]
    for m in ("light", "mis", "path"):
        cell = run_cell(engine, "on_surface", m, truth, scale, samples=1 << 14)
        _assert_reads_truth(cell, f"on_surface/{m}")
        assert cell.verdict == "ok", (m, cell.per_sensor)
    # bsdf finds the 0.1 m lamps by chance: unbiased, within 4 stderr
    _assert_reads_truth(run_cell(engine, "on_surface", "bsdf", truth, scale, samples=1 << 16), "on_surface/bsdf")


def test_receiver_one_micron_from_a_sphere_light(cases):
    """A receiver 1 µm below a 0.5 m sphere light facing it reads
    sphere_irradiance ≈ πL (sin²σ → 1). The stage holds a floor, so rays used
    to start pushed 1e-5 m off every receiver: inside the sphere, whence
    ``bsdf`` saw nothing (0) and ``mis`` lost the bsdf share (0.4·πL). Now a
    receiver within that push of a light starts its rays at itself. Slack
    1e-5 relative: at 1 µm the sphere leaves 4e-6 of the hemisphere's
    cosine-weighted measure open, a sliver of grazing directions that float32
    ray–sphere tests do not resolve (bsdf then reads πL with zero variance)."""
    engine, truth, scale = cases["near_sphere"]
    for m in ("light", "bsdf", "mis", "path"):
        cell = run_cell(engine, "near_sphere", m, truth, scale, samples=1 << 14)
        _assert_reads_truth(cell, f"near_sphere/{m}", slack=1e-5)


def test_mis_sees_a_distant_light_of_angle_1e_minus_9_degrees(tmp_path):
    """A DistantLight of angle 1e-9° (normalize on, 1000 W/m² normal
    irradiance, 45° from the zenith) gives E = 1000·cos 45° on a horizontal
    receiver. Its cone pdf, 1/(2π(1 − cos θ)) ≈ 4e21 sr⁻¹, overflowed float32
    when squared in the power heuristic; the weight became inf/inf = NaN and
    ``mis`` and ``path`` read 0. The heuristic now works from pdf ratios."""
    (tmp_path / "sun.usda").write_text(
        '#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\ndef DistantLight "Sun"\n{\n'
        "    float inputs:angle = 1e-9\n    float inputs:intensity = 1000\n    bool inputs:normalize = 1\n"
        '    float3 xformOp:rotateXYZ = (0, 45, 0)\n    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]\n}\n'
    )
    (tmp_path / "sun.toml").write_text(
        'stage = "sun.usda"\nlight_units = "radiometric"\n[[sensor]]\nname = "up"\nkind = "irradiance"\n'
        "position = [0, 0, 0]\nnormal = [0, 0, 1]\n"
    )
    cfg = load_config(tmp_path / "sun.toml")
    scene = load_scene(cfg)
    engine = Engine(scene, collect_sensors(cfg, scene))
    truth = 1000.0 * math.cos(math.radians(45.0))
    for m in ("light", "mis", "path"):
        res = engine.run(m, samples=1024, seed=1)
        assert res.non_finite[0] == 0
        assert abs(res.mean[0, 0] - truth) <= 4 * res.stderr[0, 0] + 1e-5 * truth, (m, res.mean[0, 0])


# ------------------------------------------------------------------ outputs


def test_stability_outputs_csv_and_small_heat_map(cases, tmp_path):
    """write_stability writes one CSV row per cell with the documented columns,
    a per-sensor CSV, and a PNG heat map under 300 KB."""
    engine, truth, scale = cases["delta_point"]
    cells = [run_cell(engine, "delta_point", m, truth, scale, samples=256) for m in METHODS]
    paths = write_stability(cells, tmp_path, "test")
    with open(paths[0], newline="") as f:
        rows = list(csv.DictReader(f))
    assert tuple(rows[0].keys()) == CSV_COLUMNS
    assert [r["method"] for r in rows] == list(METHODS)
    assert {r["method"]: r["verdict"] for r in rows}["bsdf"] == "blind"
    assert paths[2].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert paths[2].stat().st_size < 300_000
