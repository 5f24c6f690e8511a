"""``probesim stability``: where each estimator fails, case by case.

A matrix of estimators (``analytic``, ``light``, ``bsdf``, ``mis``, ``path``, ``guided``)
× hard cases. Each case is a bundled stage in ``stages/stability/`` with its
config in ``configs/stability/``, and a reference answer per sensor from the
closed forms of :mod:`simulator.reference.closed_forms`: the stability suite of
the reference registry, :mod:`simulator.reference.cases` (see :data:`CASES`):

=================  ==========================================================
case               what it stresses
=================  ==========================================================
``grazing``        a receiver 89° (and 89.5°, straddling) from a sphere light
``near_rect``      receivers 1 mm under a 2 m × 2 m rect light
``near_sphere``    receivers 1 mm and 1 µm off a sphere light, one inside it
``tiny_source``    a sphere light of radius 1 mm, for direction sampling
``delta_point``    a point light (no direction sample can hit it)
``delta_distant``  an angle-0 distant light (likewise)
``leak``           occluders 10⁻⁴ m below a rect light and an emissive quad
``on_surface``     receivers lying on a 10 km plane (self-intersection)
``furnace99``      a closed box of albedo 0.99: E = π·L_e/(1 − ρ)
``hdr``            a 10⁵ W/m² sun and a ~1 W/m² lamp on one receiver
``degenerate``     zero-area, sliver and duplicate faces
=================  ==========================================================

Every cell runs one estimator on one case for a fixed wall-clock budget
(samples doubling from batch to batch, independent seeds merged), then
reports, over the case's sensors, the worst bias in standard errors, the
RMS relative error, the largest relative standard error, any NaN/Inf samples
(:attr:`simulator.engine.driver.EngineResult.non_finite`) and a :func:`verdict`.
Readings are compared in the radiometric channel (the stages are read with
``light_units = "radiometric"``).
"""

from __future__ import annotations

import csv
import io
import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.bundled import configs_dir as bundled_configs_dir
from simulator.engine.methods import READ_METHODS
from simulator.reference.cases import Case, CaseContext, suite
from simulator.reference.cases import case as find_case
from simulator.scene.model import Scene, Sensor

__all__ = [
    "BIAS_SIGMAS",
    "BLIND_FRACTION",
    "CASES",
    "METHODS",
    "NOISY_REL_STDERR",
    "REL_FLOOR",
    "VERDICTS",
    "Case",
    "Cell",
    "verdict",
    "worst",
    "truth_for",
    "run_cell",
    "run_stability",
    "format_matrix",
    "write_stability",
]

#: estimators in matrix column order
METHODS = READ_METHODS
#: verdicts from best to worst; a cell shows the worst over its sensors
VERDICTS = ("ok", "noisy", "biased", "blind")

#: a deviation is significant beyond this many standard errors (the test
#: suite's bound: a 6e-5 two-sided false-alarm chance per reading)
BIAS_SIGMAS = 4.0
#: ... and only counts as bias above this fraction of the reading's scale:
#: float32 geometry moves readings by ~1e-6..1e-4 relative in degenerate
#: configurations, and 0.1% is the finest target ``probesim chart`` times
REL_FLOOR = 1.0e-3
#: correct but slow: relative standard error above this at the budget
#: (1%, the coarse target of ``probesim chart`` and ``probesim bench``)
NOISY_REL_STDERR = 0.01
#: blind: reads under this fraction of a positive truth
BLIND_FRACTION = 1.0e-3


def verdict(
    truth: float,
    estimate: float,
    stderr: float,
    non_finite: int = 0,
    scale: float | None = None,
    *,
    sigmas: float = BIAS_SIGMAS,
    rel_floor: float = REL_FLOOR,
    noisy_rel_stderr: float = NOISY_REL_STDERR,
    blind_fraction: float = BLIND_FRACTION,
) -> str:
    """Classify one reading against its reference: ``ok``, ``noisy``, ``biased`` or ``blind``.

    Parameters
    ----------
    truth : float
        Reference value (closed form), W/m² or W m⁻² sr⁻¹.
    estimate, stderr : float
        The estimator's mean and its standard error, same unit.
    non_finite : int
        NaN/Inf samples the engine dropped. Dropping samples biases the mean,
        so any count makes a reading at best ``biased``.
    scale : float, optional
        Magnitude the floors are relative to, same unit; default ``|truth|``.
        Pass the unoccluded reading where the truth is 0 (a shadow).

    Returns
    -------
    str
        - ``blind``: the truth is positive (above the floor) and the
          estimate is under ``blind_fraction`` of it by more than
          ``sigmas`` standard errors: a light the estimator cannot see;
        - ``biased``: |estimate − truth| > ``sigmas``·stderr and
          > ``rel_floor``·scale, or any non-finite sample;
        - ``noisy``: unbiased so far, but stderr > ``noisy_rel_stderr``·scale;
        - ``ok`` otherwise.
    """
    scale = abs(truth) if scale is None else max(abs(scale), abs(truth))
    err = estimate - truth
    significant = abs(err) > sigmas * stderr or not math.isfinite(estimate)
    floor = rel_floor * scale
    if truth > floor and significant and abs(estimate) < blind_fraction * truth:
        return "blind"
    if non_finite > 0 or not math.isfinite(estimate) or (significant and abs(err) > floor):
        return "biased"
    if scale > 0 and stderr > noisy_rel_stderr * scale:
        return "noisy"
    return "ok"


def worst(verdicts) -> str:
    """The worst of several verdicts (``blind`` > ``biased`` > ``noisy`` > ``ok``)."""
    return max(verdicts, key=VERDICTS.index, default="ok")


# --------------------------------------------------------------------------- references

#: the stability suite of the reference registry (:mod:`simulator.reference.cases`)
CASES: tuple[Case, ...] = suite("stability")


def configs_dir() -> Path:
    """The stability cases' configs folder."""
    return bundled_configs_dir("stability", command="stability")


def truth_for(case_name: str, scene: Scene, sensors: list[Sensor], cfg=None) -> tuple[np.ndarray, np.ndarray]:
    """Reference readings and scales (W/m², radiometric) of a case's sensors:
    the registry case's expected value and its scale (|expected| where it has none)."""
    c = find_case(case_name)
    ctx = CaseContext(cfg, scene, configs_dir().parent, sensors)
    truth = np.array([float(c.expected(ctx, s, 0)) for s in sensors])
    scale = np.abs(truth) if c.scale is None else np.array([float(c.scale(ctx, s, 0)) for s in sensors])
    return truth, scale


# --------------------------------------------------------------------------- cells


@dataclass
class Cell:
    """One estimator on one case.

    ``bias_sigma`` is (estimate − truth)/stderr of the sensor that deviates
    most (±inf where a zero-variance reading is off); ``rel_error`` the RMS
    over sensors of |estimate − truth|/scale; ``rel_stderr`` the largest
    stderr/scale. ``verdict`` is the worst over the sensors, or ``n/a`` when
    the estimator cannot read any of them (analytic where something may block).
    """

    case: str
    method: str
    verdict: str
    sensors: int = 0
    bias_sigma: float = 0.0
    rel_error: float = 0.0
    rel_stderr: float = 0.0
    non_finite: int = 0
    samples: int = 0
    seconds: float = 0.0
    note: str = ""
    per_sensor: list = field(default_factory=list)  # (sensor, truth, scale, estimate, stderr, non_finite, verdict)


def _z(err: float, se: float) -> float:
    if se > 0:
        return err / se
    return 0.0 if err == 0 else math.copysign(math.inf, err)


def _cell_from(case: str, method: str, sensors, truth, scale, mean, stderr, nonfinite, samples, seconds, note="") -> Cell:
    rows, verdicts = [], []
    for i, s in enumerate(sensors):
        v = verdict(truth[i], mean[i], stderr[i], int(nonfinite[i]), scale[i])
        verdicts.append(v)
        rows.append((s.name, float(truth[i]), float(scale[i]), float(mean[i]), float(stderr[i]), int(nonfinite[i]), v))
    with np.errstate(divide="ignore", invalid="ignore"):
        sc = np.where(scale > 0, scale, 1.0)
        rel = np.abs(mean - truth) / sc
        rel_se = stderr / sc
    z = [_z(mean[i] - truth[i], stderr[i]) for i in range(len(sensors))]
    k = int(np.argmax([abs(x) if math.isfinite(x) else math.inf for x in z])) if z else 0
    return Cell(
        case=case, method=method, verdict=worst(verdicts), sensors=len(sensors),
        bias_sigma=float(z[k]) if z else 0.0,
        rel_error=float(np.sqrt(np.mean(rel**2))) if len(rel) else 0.0,
        rel_stderr=float(np.max(rel_se)) if len(rel_se) else 0.0,
        non_finite=int(np.sum(nonfinite)), samples=int(samples), seconds=float(seconds), note=note, per_sensor=rows,
    )  # fmt: skip


def _merge(parts):
    """Pool independent runs (mean, stderr, n per sensor) into one mean and
    standard error: Chan's parallel variance, in float64."""
    n = np.zeros_like(parts[0][2], dtype=np.float64)
    mean = np.zeros_like(parts[0][0])
    m2 = np.zeros_like(parts[0][0])
    for m, se, cnt in parts:
        cnt = cnt.astype(np.float64)
        m2_i = se**2 * cnt * np.maximum(cnt - 1, 0)
        tot = n + cnt
        with np.errstate(divide="ignore", invalid="ignore"):
            delta = m - mean
            mean = np.where(tot > 0, mean + delta * cnt / np.maximum(tot, 1), mean)
            m2 = m2 + m2_i + np.where(tot > 0, delta**2 * n * cnt / np.maximum(tot, 1), 0.0)
        n = tot
    with np.errstate(divide="ignore", invalid="ignore"):
        se = np.where(n > 1, np.sqrt(m2 / np.maximum(n - 1, 1) / np.maximum(n, 1)), 0.0)
    return mean, se, n


def run_cell(
    engine, case: str, method: str, truth: np.ndarray, scale: np.ndarray,
    *, samples: int | None = None, seconds: float | None = None, seed: int = 1,
) -> Cell:  # fmt: skip
    """Run ``method`` on an engine holding a case's scene and sensors.

    Either a fixed ``samples`` per sensor (one run, reproducible: what the
    tests use) or a wall-clock budget ``seconds``: batches of doubling size
    with seeds ``seed, seed+1, …`` (independent streams), pooled, until the
    next batch would overrun the budget.
    """
    from simulator.plan.planner import closed_form_refusal

    sensors = engine.sensors
    if method in ("analytic", "exact"):
        ok = [i for i, s in enumerate(sensors) if closed_form_refusal(method, engine.scene, s) is None]
        if not ok:
            why = closed_form_refusal(method, engine.scene, sensors[0])
            return Cell(case, method, "n/a", note=f"no closed form: {why}")
        if method == "exact":  # lights behind a sensor are culled for it, as a run's plan does
            from simulator.plan.planner import cull_mask

            engine.set_light_mask(cull_mask(engine.scene, sensors))
        res = engine.run(method, samples=1, seed=seed, sensor_ids=np.array(ok))
        if method == "exact":  # give the other methods every light again, as before
            engine.set_light_mask(np.ones((len(sensors), len(engine.scene.lights)), np.int32))
        sub = np.array(ok)
        note = "" if len(ok) == len(sensors) else f"{len(ok)} of {len(sensors)} sensors (the rest: no closed form)"
        return _cell_from(case, method, [sensors[i] for i in ok], truth[sub], scale[sub], res.mean[sub, 0],
                          res.stderr[sub, 0], res.non_finite[sub], 0, res.wall_s, note)  # fmt: skip
    if samples is not None:
        res = engine.run(method, samples=samples, seed=seed)
        return _cell_from(case, method, sensors, truth, scale, res.mean[:, 0], res.stderr[:, 0], res.non_finite,
                          samples, res.wall_s)  # fmt: skip
    if seconds is None:
        raise ValueError("run_cell: give samples or seconds")
    engine.run(method, samples=32, seed=seed + 100_000)  # warm caches; compilation is not timed
    parts, bad = [], np.zeros(len(sensors), np.int64)
    batch, k, spent, last = 256, 0, 0.0, 0.0
    while True:
        res = engine.run(method, samples=batch, seed=seed + k)
        parts.append((res.mean[:, 0], res.stderr[:, 0], res.samples))
        bad += res.non_finite
        spent += res.wall_s
        last = res.wall_s
        k += 1
        # the next batch is twice this one: stop if it would overrun the budget
        if spent + 2.0 * last > seconds or batch >= 1 << 24:
            break
        batch *= 2
    mean, se, n = _merge(parts)
    return _cell_from(case, method, sensors, truth, scale, mean, se, bad, int(n.min()), spent)


def load_case(name: str, device: str = "cpu"):
    """``(engine, truth, scale)`` for a bundled case."""
    from simulator.config.loader import load_config
    from simulator.engine.driver import Engine
    from simulator.pipeline import collect_sensors, load_scene

    cfg = load_config(configs_dir().parent / find_case(name).config)
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    truth, scale = truth_for(name, scene, sensors, cfg)
    return Engine(scene, sensors, device=device), truth, scale


def run_stability(
    cases=None, methods=METHODS, *, seconds: float = 1.0, device: str = "cpu", log=print
) -> list[Cell]:  # fmt: skip
    """Every method on every case at a budget of ``seconds`` per cell."""
    cells = []
    for case in cases or [c.name for c in CASES]:
        engine, truth, scale = load_case(case, device)
        for m in methods:
            c = run_cell(engine, case, m, truth, scale, seconds=seconds)
            cells.append(c)
            log(f"  {case:<14} {m:<9} {_cell_text(c)}")
    return cells


# --------------------------------------------------------------------------- output


def _cell_text(c: Cell) -> str:
    if c.verdict == "n/a":
        return "n/a"
    s = f"{c.verdict} {c.rel_error:.1e}"
    if c.non_finite:
        s += f" NaN{c.non_finite}"
    return s


def format_matrix(cells: list[Cell]) -> str:
    """Cases × methods: verdict and RMS relative error per cell."""
    methods = [m for m in METHODS if any(c.method == m for c in cells)]
    cases = list(dict.fromkeys(c.case for c in cells))
    by = {(c.case, c.method): c for c in cells}
    w = 16
    lines = [f"{'case':<14}" + "".join(f"{m:>{w}}" for m in methods)]
    for case in cases:
        lines.append(f"{case:<14}" + "".join(f"{_cell_text(by[case, m]) if (case, m) in by else '':>{w}}" for m in methods))
    return "\n".join(lines)


CSV_COLUMNS = ("case", "method", "verdict", "sensors", "bias_sigma", "rel_error", "rel_stderr", "non_finite",
               "samples_per_sensor", "seconds", "note")  # fmt: skip
SENSOR_COLUMNS = ("case", "method", "sensor", "truth", "scale", "estimate", "stderr", "non_finite", "verdict")


def _g(x) -> str:
    if isinstance(x, float):
        return f"{x:.9g}"
    return str(x)


def _csv(cells: list[Cell]) -> tuple[str, str]:
    a, b = io.StringIO(), io.StringIO()
    wa, wb = csv.writer(a, lineterminator="\n"), csv.writer(b, lineterminator="\n")
    wa.writerow(CSV_COLUMNS)
    wb.writerow(SENSOR_COLUMNS)
    for c in cells:
        wa.writerow([_g(x) for x in (c.case, c.method, c.verdict, c.sensors, c.bias_sigma, c.rel_error, c.rel_stderr,
                                     c.non_finite, c.samples, c.seconds, c.note)])  # fmt: skip
        for r in c.per_sensor:
            wb.writerow([_g(x) for x in (c.case, c.method, *r)])
    return a.getvalue(), b.getvalue()


_COLOURS = {"ok": "#4caf50", "noisy": "#ffd54f", "biased": "#e53935", "blind": "#5e35b1", "n/a": "#d9d9d9"}


def _heatmap(cells: list[Cell], path: Path, title: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch

    methods = [m for m in METHODS if any(c.method == m for c in cells)]
    cases = list(dict.fromkeys(c.case for c in cells))
    by = {(c.case, c.method): c for c in cells}
    fig, ax = plt.subplots(figsize=(1.25 * len(methods) + 2.2, 0.52 * len(cases) + 1.5), dpi=100)
    for i, case in enumerate(cases):
        for j, m in enumerate(methods):
            c = by.get((case, m))
            v = c.verdict if c else "n/a"
            ax.add_patch(plt.Rectangle((j, i), 1, 1, facecolor=_COLOURS[v], edgecolor="white", linewidth=2))
            if c and v != "n/a":
                txt = f"{v}\n{c.rel_error:.1e}" + (" NaN" if c.non_finite else "")
                ax.text(j + 0.5, i + 0.5, txt, ha="center", va="center", fontsize=7.5,
                        color="white" if v in ("biased", "blind") else "black")  # fmt: skip
            else:
                ax.text(j + 0.5, i + 0.5, "n/a", ha="center", va="center", fontsize=7.5, color="#666666")
    ax.set_xlim(0, len(methods))
    ax.set_ylim(len(cases), 0)
    ax.set_xticks(np.arange(len(methods)) + 0.5, methods)
    ax.set_yticks(np.arange(len(cases)) + 0.5, cases)
    ax.xaxis.tick_top()
    ax.tick_params(length=0)
    for s in ax.spines.values():
        s.set_visible(False)
    ax.set_title(title, fontsize=9, pad=22)
    ax.legend(handles=[Patch(color=_COLOURS[v], label=v) for v in (*VERDICTS, "n/a")], loc="upper center",
              bbox_to_anchor=(0.5, -0.01), ncol=5, fontsize=7.5, frameon=False)  # fmt: skip
    fig.tight_layout()
    fig.savefig(path, format="png")
    plt.close(fig)


def write_stability(cells: list[Cell], out_dir: Path, title: str) -> list[Path]:
    """Write ``stability.csv`` (one row per cell), ``stability_sensors.csv``
    (one per sensor and method) and the heat map ``stability.png``."""
    from simulator.io.atomic import write_all_atomic

    out_dir = Path(out_dir)
    a, b = _csv(cells)
    paths = [out_dir / "stability.csv", out_dir / "stability_sensors.csv", out_dir / "stability.png"]
    write_all_atomic({paths[0]: a, paths[1]: b, paths[2]: lambda p: _heatmap(cells, Path(p), title)})
    return paths


def legend() -> str:
    """How to read the matrix."""
    return (
        f"verdicts: ok; noisy (relative stderr > {NOISY_REL_STDERR:g} at the budget); "
        f"biased (|error| > {BIAS_SIGMAS:g} stderr and > {REL_FLOOR:g} of the reading, or NaN/Inf samples); "
        f"blind (reads < {BLIND_FRACTION:g} of a positive truth); n/a (no closed form for analytic). "
        "Numbers: RMS relative error over the case's sensors (radiometric)."
    )


def main_stability(out_dir: Path, quick: bool = False, device: str = "cpu", seconds: float | None = None, log=print) -> int:
    """The ``probesim stability`` command."""
    budget = seconds if seconds is not None else (0.25 if quick else 1.0)
    t0 = time.perf_counter()
    log(f"stability: {len(CASES)} cases x {len(METHODS)} methods, {budget:g} s per cell")
    cells = run_stability(seconds=budget, device=device, log=log)
    from simulator.commands.bench import processor_name

    title = f"probesim stability: {budget:g} s per cell, {device} ({processor_name()})"
    paths = write_stability(cells, out_dir, title)
    log("")
    log(format_matrix(cells))
    log(legend())
    log(f"wrote {', '.join(str(p) for p in paths)} in {time.perf_counter() - t0:.1f} s")
    return 0
