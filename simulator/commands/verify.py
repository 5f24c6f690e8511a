"""``probesim verify``: the reference suite, run through the normal pipeline.

Every case is a bundled config (``configs/*.toml``) on a bundled stage
(``stages/*.usda``), so every case is also an example a user can run with
``probesim run``. The suite reads each config with
:func:`simulator.config.loader.load_config`, the stage with
:func:`simulator.pipeline.load_scene`, collects the sensors with
:func:`simulator.pipeline.collect_sensors`, traces them with
:class:`simulator.engine.driver.Engine`, and compares each reading with its
expected value. It writes none of the configs' CSVs.

The cases, their expected values and tolerances are the verify suite of
the reference registry, :mod:`simulator.reference.cases` (closed forms from
:mod:`simulator.reference.closed_forms` evaluated with the light, surface and
sensor parameters the stage reader produced; each function names its
formula and source). The only typed-in numbers are the published CIE
171:2006 table values, shown beside the exact ones for comparison.

Pass criterion per reading (``judge``): the error is within 1% of the
expected value AND within 4 standard errors plus a float32 slack of 2e-6
relative (the kernels compute in float32, so a zero-variance reading of a
delta light is exact only to that precision). Four standard errors is a
6e-5 two-sided false-alarm chance per reading for a correct estimator; the
1% bound is the project's accuracy target (CIE 171:2006 validations commonly
use 5% per point). A case whose expected value is 0 must read 0.

Each run is adaptive: sensors stop when their 95% confidence half-width is
under ``Case.rel_target`` of the reading (``REL_TARGET``, 0.2%, so stderr
≤ 0.1%; 0.4% for the slow interreflection cases and for every case with
``--quick``), so that the 1% bound is at least five standard errors wide and
a noisy reading cannot pass the 4σ test merely by being noisy.

Photometric cases run again with ``light_units = "radiometric"``, where the
stage's numbers are W m⁻² sr⁻¹ (W/sr, W/m²), and those rows compare the
radiometric (W) channel.
"""

from __future__ import annotations

import csv
import io
import math
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from simulator.bundled import configs_dir as bundled_configs_dir
from simulator.errors import UserError
from simulator.reference.cases import (
    FLOAT32_SLACK, K_SIGMA, REL_TARGET, REL_TARGET_QUICK, REL_TOL, Case, CaseContext, read_config, suite,
)  # fmt: skip
from simulator.scene.model import Sensor, SensorKind

__all__ = [
    "REL_TOL",
    "K_SIGMA",
    "FLOAT32_SLACK",
    "REL_TARGET",
    "REL_TARGET_QUICK",
    "Case",
    "CASES",
    "Row",
    "SuiteResult",
    "default_configs_dir",
    "judge",
    "expected_values",
    "run_case",
    "run_suite",
    "format_row",
    "format_header",
    "format_summary",
    "csv_text",
    "write_csv",
]

#: per-sensor sample cap of the adaptive runs
MAX_SAMPLES = 1 << 24
MAX_SAMPLES_QUICK = 1 << 21
#: first batch per sensor
FIRST_BATCH = 1 << 14
#: the verify suite of the reference registry: the photometric cases, then
#: each direct-light case again in radiometric light units
CASES: tuple[Case, ...] = suite("verify")

_UNITS = {
    (SensorKind.IRRADIANCE, 0): "W/m²",
    (SensorKind.IRRADIANCE, 1): "lx",
    (SensorKind.RADIANCE, 0): "W/m²/sr",
    (SensorKind.RADIANCE, 1): "cd/m²",
    (SensorKind.PATCH, 0): "W",
    (SensorKind.PATCH, 1): "lm",
    (SensorKind.CYLINDRICAL, 0): "W/m²",
    (SensorKind.CYLINDRICAL, 1): "lx",
    (SensorKind.SEMICYLINDRICAL, 0): "W/m²",
    (SensorKind.SEMICYLINDRICAL, 1): "lx",
}


def _unit(s: Sensor, ch: int, flux: bool) -> str:
    kind = s.kind if (s.kind != SensorKind.PATCH or flux) else SensorKind.IRRADIANCE
    return _UNITS[(kind, ch)]


# --------------------------------------------------------------------------- results


@dataclass
class Row:
    """One reading compared with its expected value."""

    case: str
    receiver: str
    unit: str
    expected: float
    measured: float
    stderr: float
    samples: int
    method: str
    passed: bool
    note: str = ""

    @property
    def error(self) -> float:
        return self.measured - self.expected

    @property
    def error_pct(self) -> float:
        """Error in % of |expected| (NaN when expected is 0)."""
        return 100.0 * self.error / abs(self.expected) if self.expected != 0 else math.nan

    @property
    def exact(self) -> bool:
        """The reading equals the expected value to float32 precision
        (FLOAT32_SLACK), a closer agreement than its standard error can
        resolve: a zero-variance reading, or one whose error is float32
        rounding larger than K_SIGMA of its tiny standard error."""
        within = abs(self.error) <= FLOAT32_SLACK * abs(self.expected) + 1e-12
        return within and (self.stderr == 0 or abs(self.error) > K_SIGMA * self.stderr)

    @property
    def error_sigma(self) -> float:
        """Error in standard errors (0 for an exact reading, ±inf when stderr is 0 and it is not)."""
        if math.isnan(self.error) or math.isnan(self.stderr):
            return math.nan
        if self.stderr > 0:
            return self.error / self.stderr
        return 0.0 if self.error == 0 else math.copysign(math.inf, self.error)


@dataclass
class SuiteResult:
    rows: list[Row]
    skipped: list[str]
    cases_run: list[str]
    wall_s: float

    @property
    def passed(self) -> bool:
        return all(r.passed for r in self.rows)


def judge(expected: float, measured: float, stderr: float, rel_tol: float = REL_TOL, k_sigma: float = K_SIGMA) -> bool:
    """True when ``measured`` is within ``rel_tol`` (1%) of ``expected`` and within
    ``k_sigma``·stderr + 2e-6·|expected| (4 standard errors) of it (see the module docstring)."""
    err = abs(measured - expected)
    if not (math.isfinite(measured) and math.isfinite(stderr)):
        return False
    within_rel = err <= rel_tol * abs(expected) if expected != 0 else err <= 1e-12
    within_sigma = err <= k_sigma * stderr + FLOAT32_SLACK * abs(expected) + 1e-12
    return within_rel and within_sigma


# --------------------------------------------------------------------------- running


def default_configs_dir() -> Path:
    """The bundled configs folder."""
    return bundled_configs_dir(command="verify")


def _load_case(case: Case, configs_dir: Path):
    """``(cfg, scene, sensors, context)`` of a case."""
    cfg, scene, sensors = read_config(configs_dir / case.config, case.light_units, case.variants)
    if case.optics:  # the heads' readings: the optics twins of the modelled sensors
        from simulator.sensor_models.readings import optics_twins

        sensors = optics_twins(sensors)
    return cfg, scene, sensors, CaseContext(cfg, scene, configs_dir, sensors)


def expected_values(case: Case, configs_dir: Path | None = None) -> list[tuple[Sensor, int, float, str]]:
    """Expected reading of every receiver of a case, without tracing.

    Returns
    -------
    list of (sensor, channel, expected, note)
        Channel 1 (photometric) for photometric cases, 0 (radiometric) for
        radiometric ones.
    """
    configs_dir = configs_dir or default_configs_dir()
    cfg, scene, sensors, ctx = _load_case(case, configs_dir)
    ch = 0 if cfg.light_units == "radiometric" else 1
    return [
        (s, ch, float(case.expected(ctx, s, ch)) * _scale(case, s), case.note(ctx, s, ch) if case.note else "")
        for s in sensors
    ]


def _scale(case: Case, s: Sensor) -> float:
    """Factor from the kernel's reading to the table's: a patch's area when it reports flux."""
    return s.size[0] * s.size[1] if s.kind == SensorKind.PATCH and case.patch_flux else 1.0


def run_case(case: Case, *, quick: bool = False, device: str = "cpu", configs_dir: Path | None = None) -> list[Row]:
    """Trace one case through the normal pipeline and judge every receiver."""
    from simulator.engine.driver import Engine  # imports warp

    configs_dir = configs_dir or default_configs_dir()
    cfg, scene, sensors, ctx = _load_case(case, configs_dir)
    ch = 0 if cfg.light_units == "radiometric" else 1
    expected = [float(case.expected(ctx, s, ch)) * _scale(case, s) for s in sensors]  # before tracing: a bad case fails fast
    notes = [case.note(ctx, s, ch) if case.note else "" for s in sensors]
    sim = cfg.simulation
    engine = Engine(scene, sensors, device=device, threads=sim.threads)
    res = engine.run(
        case.method,
        samples=FIRST_BATCH,
        seed=sim.seed,
        rel_error=max(case.rel_target, REL_TARGET_QUICK) if quick else case.rel_target,
        abs_error=0.0,
        max_samples=MAX_SAMPLES_QUICK if quick else MAX_SAMPLES,
        max_depth=sim.max_depth,
        component=sim.component,
    )
    rows = []
    for i, s in enumerate(sensors):
        scale = _scale(case, s)
        m, se = float(res.mean[i, ch]) * scale, float(res.stderr[i, ch]) * scale
        note = notes[i]
        if res.target_met is not None and not res.target_met[i]:
            note = "; ".join(x for x in (note, "error target not met") if x)
        rows.append(
            Row(case.name, s.name, _unit(s, ch, case.patch_flux), expected[i], m, se, int(res.samples[i]), res.method,
                judge(expected[i], m, se, case.rel_tol, case.k_sigma), note)
        )
    return rows


def run_suite(
    *,
    quick: bool = False,
    device: str = "cpu",
    configs_dir: Path | None = None,
    cases: tuple[Case, ...] | None = None,
    on_row: Callable[[Row], None] | None = None,
    on_skip: Callable[[str], None] | None = None,
) -> SuiteResult:
    """Run every case (or ``cases``); absent optional configs are skipped with a note.

    A case that cannot run (its config is missing or invalid, or a receiver
    has no closed form) gives one failing row carrying the message.

    Parameters
    ----------
    quick : bool
        Looser adaptive target (stderr ≤ 0.2% instead of 0.1%).
    device : str
        cpu, cuda or auto.
    on_row, on_skip : callable, optional
        Called with each row as its case finishes, and with each skip note.
    """
    configs_dir = Path(configs_dir) if configs_dir else default_configs_dir()
    if not configs_dir.is_dir():
        raise UserError(f"{configs_dir}: reference configs folder not found (run from a source checkout)")
    t0 = time.perf_counter()
    rows: list[Row] = []
    skipped: list[str] = []
    ran: list[str] = []
    for case in CASES if cases is None else cases:
        if quick and not case.quick:
            continue
        if not (configs_dir / case.config).exists() and case.optional:
            msg = f"skipped {case.name}: {case.config} is not in {configs_dir.name}/ yet"
            skipped.append(msg)
            if on_skip:
                on_skip(msg)
            continue
        try:
            case_rows = run_case(case, quick=quick, device=device, configs_dir=configs_dir)
        except UserError as e:  # a broken case fails its row; the others still run
            case_rows = [Row(case.name, "(case)", "", math.nan, math.nan, math.nan, 0, case.method, False, str(e))]
        ran.append(case.name)
        rows.extend(case_rows)
        if on_row:
            for r in case_rows:
                on_row(r)
    return SuiteResult(rows, skipped, ran, time.perf_counter() - t0)


# --------------------------------------------------------------------------- output

_HEADER = (
    f"{'case':<24} {'receiver':<16} {'unit':<8} {'expected':>13} {'measured':>13} "
    f"{'stderr':>9} {'error':>9} {'err/σ':>7}  {'result':<6} note"
)


def format_header() -> str:
    return _HEADER


def _g(x: float, width: int, prec: int) -> str:
    return f"{x:>{width}.{prec}g}"


def format_row(r: Row) -> str:
    pct = "—" if math.isnan(r.error_pct) else f"{r.error_pct:+.3f}%"
    sig = r.error_sigma
    if r.exact:
        sig_s = "exact"  # equal to float32 precision: a count of standard errors says nothing
    elif math.isnan(sig):
        sig_s = "—"
    else:
        sig_s = f"{sig:+.2f}" if math.isfinite(sig) else ("+inf" if sig > 0 else "-inf")
    return (
        f"{r.case[:24]:<24} {r.receiver[:16]:<16} {r.unit:<8} {_g(r.expected, 13, 8)} {_g(r.measured, 13, 8)} "
        f"{_g(r.stderr, 9, 2)} {pct:>9} {sig_s:>7}  {'pass' if r.passed else 'FAIL':<6} {r.note}"
    ).rstrip()


def format_summary(result: SuiteResult) -> str:
    n_fail = sum(not r.passed for r in result.rows)
    worst_pct = max((abs(r.error_pct) for r in result.rows if not math.isnan(r.error_pct)), default=0.0)
    finite_sig = [abs(r.error_sigma) for r in result.rows if math.isfinite(r.error_sigma) and not r.exact]
    worst_sig = max(finite_sig, default=0.0)
    verdict = "all pass" if n_fail == 0 else f"{n_fail} FAIL"
    n_exact = sum(r.exact for r in result.rows)
    skipped = f", {len(result.skipped)} skipped" if result.skipped else ""
    return (
        f"{len(result.rows) - n_fail} of {len(result.rows)} readings pass ({verdict}); "
        f"{len(result.cases_run)} cases run{skipped}; worst error {worst_pct:.3f}%, "
        f"worst {worst_sig:.2f} standard errors ({n_exact} readings exact to float32 precision); "
        f"{result.wall_s:.1f} s. "
        f"Pass: within {100 * REL_TOL:g}% and within {K_SIGMA:g}·stderr + {FLOAT32_SLACK:g}·|expected|."
    )


_CSV_COLUMNS = (
    "case", "receiver", "unit", "expected", "measured", "stderr", "error_pct", "error_stderrs",
    "exact_float32", "pass", "samples", "method", "note",
)  # fmt: skip


def csv_text(rows: list[Row]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(_CSV_COLUMNS)
    for r in rows:
        w.writerow([
            r.case, r.receiver, r.unit, f"{r.expected:.12g}", f"{r.measured:.12g}", f"{r.stderr:.6g}",
            "" if math.isnan(r.error_pct) else f"{r.error_pct:.6g}", f"{r.error_sigma:.6g}",
            "true" if r.exact else "false", "true" if r.passed else "false", r.samples, r.method, r.note,
        ])  # fmt: skip
    return buf.getvalue()


def write_csv(path: Path, rows: list[Row]) -> None:
    """Write the table as CSV atomically (temporary sibling, then rename)."""
    from simulator.io.atomic import write_all_atomic

    write_all_atomic({Path(path): csv_text(rows)})
