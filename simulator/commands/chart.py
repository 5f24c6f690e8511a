"""``probesim chart``: speed against accuracy, per estimator, on configs.

For each config and each estimator that applies (``analytic``, ``exact``,
``light``, ``bsdf``, ``mis``, ``path``, and the planner's per-sensor ``auto``,
run at the same fixed budgets; a method blind to the scene's lights or biased
for it is listed with the reason and not run) it climbs a ladder of budgets,
samples per sensor doubling from 16 until a run takes ``max_seconds``, with
several independent seeds at each rung, and measures:

- the wall time of each run (:attr:`simulator.engine.driver.EngineResult.wall_s`,
  after a warm-up run, so kernel compilation is not timed);
- the relative RMS error over the config's sensors,
  ``sqrt(mean_i ((estimate_i − reference_i)/reference_i)²)``, radiometric
  channel (photometric against a stored reference, which is in lx), over
  sensors whose reference is not 0 (a shadow's 0 has no
  relative error; it counts in the CSV).

The reference is the config's stored reference
(``configs/references/NAME.csv``, the one ``probesim bench`` uses) where it
has one; else the closed form where the ``analytic`` estimator applies to
every sensor; otherwise a long ``path`` run, made once and cached in
``<out>/<config>.reference.npz``, keyed by a hash of the config, the stage,
the run settings and the package version. Its own relative standard error is
drawn on the chart as a floor: errors near it measure the reference.

Per rung the seeds are pooled as the root mean square of their errors (a
mean of squared errors: for an unbiased estimator it falls exactly as 1/N)
and the median of their times. From that curve:

- the time to reach 1% and 0.1%, interpolated on the log-log line between
  rungs (``-`` if the ladder never got there, ``≤`` if its first rung did);
- the efficiency 1/(variance·time), variance = the pooled squared relative
  error, median over the fitted rungs (higher is better; for an unbiased
  estimator it is constant along the ladder);
- the least-squares slope of log(error) against log(time), over rungs whose
  time is at least 10× the first rung's (there the fixed cost of a launch,
  about the first rung's time, is under a tenth and does not steepen it) and
  whose error is at least 3× the reference floor: −½ for an unbiased
  estimator at a constant sample rate.

Every run of the ladder has its own seed (rung r, seed k → ``1 + k + r·seeds``),
so rungs are independent draws: a run of 2N samples under the seed of a run
of N would repeat its N samples, and the curve would be a random walk.

Outputs in ``--out``: ``chart.csv`` (one row per config, method, budget, seed
and sensor), ``chart_<config>.png`` (log-log error against seconds, one line
per method, the 1/√t slope, 1% marked) and a summary table on the terminal.
"""

from __future__ import annotations

import csv
import hashlib
import io
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator import __version__
from simulator.bundled import bundled_configs
from simulator.engine.methods import READ_METHODS
from simulator.errors import UserError
from simulator.reference.cases import suite

__all__ = [
    "CSV_COLUMNS",
    "DEFAULT_CONFIGS",
    "MethodCurve",
    "ConfigChart",
    "chart_config",
    "fit_slope",
    "time_to",
    "format_summary",
    "run_chart",
]

#: the bundled reference stages charted when no config is named: the chart
#: suite of the reference registry (:mod:`simulator.reference.cases`), config stems
DEFAULT_CONFIGS = tuple(Path(c.config).stem for c in suite("chart"))
CSV_COLUMNS = ("config", "method", "budget", "seed", "sensor", "estimate", "reference", "stderr", "seconds", "device")
#: the curves charted: every method that reads a sensor, and the planner's ``auto``
METHODS = (*READ_METHODS, "auto")
#: first rung of the ladder, samples per sensor
FIRST_BUDGET = 16
#: last possible rung (sample indices are int32 in the kernel)
MAX_BUDGET = 1 << 24
#: errors under this are float32 round-off of an exact estimator
EXACT_REL = 1.0e-6
#: reference run: path tracing for this multiple of ``max_seconds`` (about
#: 40× the samples of a ladder's last rung, so its error sits ~6× under the
#: last rung's), with samples sent where the variance is (adaptive, a target
#: no sensor reaches first unless it has zero variance)
REFERENCE_TIME_FACTOR = 40.0
REFERENCE_REL_ERROR = 1.0e-6
REFERENCE_SEED = 1_000_003
TARGETS = (1.0e-2, 1.0e-3)
#: the planner check: adaptive runs to this relative 95% half-width, from
#: this first batch, median wall time over this many seeds
ADAPTIVE_REL_ERROR = 0.01
ADAPTIVE_PILOT = 256
ADAPTIVE_SEEDS = 5


@dataclass
class MethodCurve:
    """One estimator's ladder on one config.

    ``budgets``, ``seconds``, ``errors``: per rung, samples per sensor, the
    median wall time over seeds (s) and the pooled relative RMS error.
    ``skipped`` holds the reason when the method was not run.
    """

    method: str
    budgets: list[int] = field(default_factory=list)
    seconds: list[float] = field(default_factory=list)
    errors: list[float] = field(default_factory=list)
    skipped: str = ""
    slope: float | None = None  # log error on log seconds
    slope_samples: float | None = None  # log error on log samples: −½ exactly in expectation if unbiased
    efficiency: float | None = None
    exact: bool = False
    fitted: list[int] = field(default_factory=list)  # rung indices used by the fit

    def time_to(self, target: float) -> tuple[float | None, bool]:
        """See :func:`time_to`."""
        return time_to(self.seconds, self.errors, target)


@dataclass
class ConfigChart:
    config: str
    device: str
    sensors: int
    reference_kind: str  # "closed form" or "path, N samples/sensor (...)"
    reference_rel_stderr: float  # RMS over sensors; 0 for a closed form
    curves: list[MethodCurve]
    rows: list[tuple]
    png: Path | None = None
    notes: list[str] = field(default_factory=list)
    #: method (and "auto") → (median seconds of an adaptive run to 1%, every sensor met it)
    adaptive: dict[str, tuple[float, bool]] = field(default_factory=dict)

    def auto_ratio(self) -> tuple[float, str] | None:
        """auto's adaptive time over the fastest single method's, and that method."""
        singles = {m: t for m, (t, met) in self.adaptive.items() if m != "auto" and met}
        if "auto" not in self.adaptive or not singles:
            return None
        best = min(singles, key=singles.get)
        return self.adaptive["auto"][0] / singles[best], best


# --------------------------------------------------------------------------- curve maths


def time_to(seconds, errors, target: float) -> tuple[float | None, bool]:
    """Time at which a ladder's error first reaches ``target``.

    Interpolated linearly in log(time)–log(error) between the last rung above
    the target and the first at or under it. Returns ``(time, first)``:
    ``first`` is True when the first rung already met it (the time is then an
    upper bound); ``(None, False)`` when no rung did.
    """
    t = np.asarray(seconds, float)
    e = np.asarray(errors, float)
    order = np.argsort(t, kind="stable")
    t, e = t[order], e[order]
    below = np.flatnonzero(e <= target)
    if len(below) == 0:
        return None, False
    k = int(below[0])
    if k == 0:
        return float(t[0]), True
    t0, t1, e0, e1 = t[k - 1], t[k], e[k - 1], e[k]
    if e1 <= 0 or e0 <= e1 or t0 <= 0 or t1 <= 0:
        return float(t1), False
    f = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
    return float(math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0)))), False


def fit_slope(
    seconds, errors, floor: float = 0.0, min_points: int = 3, min_time_ratio: float = 10.0
) -> tuple[float | None, list[int]]:
    """Least-squares slope of log(error) on log(time) and the rungs it used.

    Rungs count when their time is ≥ ``min_time_ratio`` × the first rung's
    (fixed launch costs matter below 10×; pass 0 to fit error against sample
    counts instead of times) and their error ≥ 3× ``floor`` (the reference's
    own error) and > 0. Returns ``(None, used)`` with fewer than ``min_points``.
    """
    t = np.asarray(seconds, float)
    e = np.asarray(errors, float)
    if len(t) == 0:
        return None, []
    used = [i for i in range(len(t)) if t[i] >= min_time_ratio * t[0] and e[i] > 0 and e[i] >= 3.0 * floor and t[i] > 0]
    if len(used) < min_points:
        return None, used
    x, y = np.log(t[used]), np.log(e[used])
    slope = float(np.polyfit(x, y, 1)[0])
    return slope, used


# --------------------------------------------------------------------------- references


def _reference_key(cfg, extra: dict) -> str:
    h = hashlib.sha256()
    h.update(Path(cfg.path).read_bytes())
    h.update(Path(cfg.stage).read_bytes())
    h.update(repr(sorted(extra.items())).encode())
    h.update(__version__.encode())
    return h.hexdigest()


def _samples_text(samples) -> str:
    lo, hi = int(np.min(samples)), int(np.max(samples))
    return f"{lo:,} samples/sensor" if lo == hi else f"{lo:,}-{hi:,} samples/sensor"


def _stored_reference(cfg, sensors) -> tuple[np.ndarray, np.ndarray, str] | None:
    """The config's stored reference (``configs/references/NAME.csv``, as
    ``probesim bench`` reads it: illuminance in lx, photometric channel), or
    None when it has none."""
    from simulator.commands.bench_reference import read_reference, reference_path

    path = reference_path(Path(cfg.path))
    if not path.is_file():
        return None
    table = read_reference(path)
    missing = [s.name for s in sensors if s.name not in table]
    if missing:
        raise UserError(f"{path}: no reference for sensor {missing[0]!r} of {cfg.path} ({len(missing)} missing)")
    mean = np.array([table[s.name][0] for s in sensors])
    se = np.array([table[s.name][1] for s in sensors])
    return mean, se, f"stored reference {path.parent.name}/{path.name}"


def _reference(cfg, engine, sensors, max_seconds: float, cache_dir: Path, log) -> tuple[np.ndarray, np.ndarray, str, int]:
    """Per-sensor reference (mean, stderr), how it was made, and the channel
    it is in (0 radiometric, 1 photometric: a stored reference is in lx)."""
    from simulator.plan.planner import analytic_refusal

    stored = _stored_reference(cfg, sensors)
    if stored is not None:
        log(f"  reference: {stored[2]}")
        return (*stored, 1)
    sim = cfg.simulation
    if sim.component == "total" and all(analytic_refusal(engine.scene, s) is None for s in sensors):
        res = engine.run("analytic", samples=1, seed=1)
        return res.mean[:, 0].copy(), np.zeros(len(sensors)), "closed form (analytic)", 0
    seconds = REFERENCE_TIME_FACTOR * max_seconds
    extra = {"component": sim.component, "max_depth": sim.max_depth, "rel": REFERENCE_REL_ERROR,
             "seconds": seconds, "seed": REFERENCE_SEED, "sensors": tuple(s.name for s in sensors)}  # fmt: skip
    key = _reference_key(cfg, extra)
    path = cache_dir / f"{Path(cfg.path).stem}.reference.npz"
    if path.exists():
        try:
            z = np.load(path, allow_pickle=False)
            if str(z["key"]) == key:
                what = _samples_text(z["samples"])
                log(f"  reference: path, {what}, cached in {path}")
                return z["mean"], z["stderr"], f"path, {what} (cached)", 0
        except (OSError, KeyError, ValueError):
            pass
    log(f"  reference: path tracing for {seconds:.0f} s; cached in {path}")
    res = engine.run("path", samples=4096, seed=REFERENCE_SEED, rel_error=REFERENCE_REL_ERROR, abs_error=0.0,
                     max_samples=1 << 28, time_limit_s=seconds, max_depth=sim.max_depth, component=sim.component)  # fmt: skip
    mean, se = res.mean[:, 0].copy(), res.stderr[:, 0].copy()
    cache_dir.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.npz")
    np.savez(tmp, key=np.array(key), mean=mean, stderr=se, samples=res.samples, seconds=np.array(res.wall_s))
    os.replace(tmp, path)
    return mean, se, f"path, {_samples_text(res.samples)}", 0


# --------------------------------------------------------------------------- ladders


def _skip_reason(method: str, scene, sensors, component: str) -> str:
    from simulator.engine.driver import METHOD_FLAGS

    if method in ("analytic", "exact"):
        from simulator.plan.planner import closed_form_refusal

        if component != "total":
            return f"closed forms give the total, not the {component} component"
        for s in sensors:
            why = closed_form_refusal(method, scene, s)
            if why is not None:
                return f"no closed form: {why}"
        return ""
    reflects = scene.geometry.n_triangles > 0 and bool(np.any(scene.geometry.albedo > 0))
    if method == "auto":
        return ""
    if component == "indirect" and not METHOD_FLAGS[method][3]:
        return "biased: the indirect component needs paths"
    if method == "bsdf" and any(l.is_delta for l in scene.lights):
        return "blind: point/angle-0 distant lights"
    if method != "auto" and not METHOD_FLAGS[method][3] and reflects and component != "direct":
        return "biased: ignores interreflection"
    return ""


def _adaptive_times(engine, scene, sensors, sim, methods: list[str], log) -> dict[str, tuple[float, bool]]:
    """Wall time for every sensor to reach a 1% relative 95% half-width, for
    each method and for the planner's ``auto`` (which reads each sensor its
    own way): the measure the planner is judged by. Lights are culled per
    sensor (the plan's mask) for every method alike."""
    from dataclasses import replace

    from simulator.plan.planner import make_plan
    from simulator.pipeline import run_plan

    plan = make_plan(scene, sensors, "auto", sim.component)
    engine.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
    base = replace(sim, rel_error=ADAPTIVE_REL_ERROR, samples=ADAPTIVE_PILOT, samples_set=True, confidence=0.95,
                   time_limit_s=None)

    def once(m: str, seed: int) -> tuple[float, bool]:
        s = replace(base, seed=seed)
        if m == "auto":
            r = run_plan(engine, plan, s)
        else:
            r = engine.run(m, samples=s.samples, seed=seed, rel_error=s.rel_error, abs_error=s.abs_error,
                           max_samples=s.sample_cap, max_depth=s.max_depth, component=s.component)  # fmt: skip
        met = True if r.target_met is None else bool(np.all(r.target_met))
        return r.wall_s, met

    out = {}
    for m in [*methods, "auto"]:
        once(m, 0)  # warm-up
        runs = [once(m, 7001 + k) for k in range(ADAPTIVE_SEEDS)]
        out[m] = (float(np.median([t for t, _ in runs])), all(met for _, met in runs))
    ratio = ", ".join(f"{m} {_fmt_time(t, False)}" + ("" if met else "*") for m, (t, met) in out.items())
    log(f"  adaptive to 1%: {ratio}")
    return out


def _ladder_runner(method: str, engine, scene, sensors, sim):
    """``run(budget, seed) -> EngineResult``: one fixed-budget run of
    ``method``; for ``auto`` the planner's per-sensor plan, as ``probesim run``
    reads it (each sensor by its own method, lights culled per sensor)."""
    run_kw = dict(max_depth=sim.max_depth, component=sim.component)
    if method != "auto":
        return lambda budget, seed: engine.run(method, samples=budget, seed=seed, **run_kw)
    from dataclasses import replace

    from simulator.pipeline import run_plan
    from simulator.plan.planner import make_plan

    plan = make_plan(scene, sensors, "auto", sim.component)
    fixed = replace(sim, rel_error=None, time_limit_s=None)
    return lambda budget, seed: run_plan(engine, plan, replace(fixed, samples=budget, seed=seed))


def _rel_rms(est: np.ndarray, ref: np.ndarray, use: np.ndarray) -> float:
    if not use.any():
        return 0.0
    return float(np.sqrt(np.mean(((est[use] - ref[use]) / ref[use]) ** 2)))


def chart_config(
    path: Path, out_dir: Path, *, seeds: int = 4, max_seconds: float = 0.5, device: str = "cpu",
    methods=METHODS, max_budget: int = MAX_BUDGET, plot: bool = True, adaptive: bool = True, log=print,
) -> ConfigChart:  # fmt: skip
    """Ladders of every applicable method in ``methods`` on one config (see
    the module docstring). A ladder stops at the first rung whose median run
    takes ``max_seconds``, or at ``max_budget`` samples per sensor (a fixed
    ladder, whatever the machine: what the tests use)."""
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, config_engine, load_scene

    cfg = load_config(path)
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.spec.reader == "estimate"]
    if not sensors:
        raise UserError(f"{cfg.path}: chart: no irradiance, radiance or patch sensors to chart")
    name = Path(cfg.path).stem
    engine = config_engine(cfg, scene, sensors, device=device)
    sim = cfg.simulation
    log(f"{name}: {len(sensors)} sensors on {engine.device}")
    ref, ref_se, ref_kind, c = _reference(cfg, engine, sensors, max_seconds, Path(out_dir), log)
    # sensors whose reference is 0 (a shadow; or within 3 of its standard errors of 0) have no relative error
    use = np.abs(ref) > 3.0 * ref_se
    use &= ref != 0
    with np.errstate(divide="ignore", invalid="ignore"):
        ref_floor = float(np.sqrt(np.mean((ref_se[use] / ref[use]) ** 2))) if use.any() else 0.0
    chart = ConfigChart(name, engine.device, len(sensors), ref_kind, ref_floor, [], [])
    if not use.all():
        chart.notes.append(f"{int((~use).sum())} sensor(s) with a zero reference left out of the relative error")
    for m in methods:
        curve = MethodCurve(m)
        chart.curves.append(curve)
        curve.skipped = _skip_reason(m, scene, sensors, sim.component)
        if curve.skipped:
            log(f"  {m:<9} skipped: {curve.skipped}")
            continue
        if m in ("analytic", "exact"):
            if m == "exact":  # lights behind a sensor are culled for it, as a run's plan does
                from simulator.plan.planner import cull_mask

                engine.set_light_mask(cull_mask(scene, sensors))
            engine.run(m, samples=1, seed=1)  # warm-up
            times = []
            for seed in range(1, seeds + 1):
                res = engine.run(m, samples=1, seed=seed)
                times.append(res.wall_s)
                for i, s in enumerate(sensors):
                    chart.rows.append((name, m, 0, seed, s.name, res.mean[i, c], ref[i], 0.0, res.wall_s, engine.device))
            curve.budgets, curve.seconds = [0], [float(np.median(times))]
            curve.errors = [_rel_rms(res.mean[:, c], ref, use)]
            curve.exact = True
            if m == "exact":  # give the other methods every light again, as before
                engine.set_light_mask(np.ones((len(sensors), len(scene.lights)), np.int32))
            log(f"  {m:<9} {curve.seconds[0] * 1e3:.3f} ms, error {curve.errors[0]:.1e}")
            continue
        run = _ladder_runner(m, engine, scene, sensors, sim)
        run(FIRST_BUDGET, 0)  # warm-up: compilation and caches are not timed
        budget = FIRST_BUDGET
        while True:
            sq, times = [], []
            rung = len(curve.budgets)
            for seed in range(1 + rung * seeds, 1 + (rung + 1) * seeds):
                res = run(budget, seed)
                times.append(res.wall_s)
                sq.append(_rel_rms(res.mean[:, c], ref, use) ** 2)
                for i, s in enumerate(sensors):
                    chart.rows.append((name, m, budget, seed, s.name, res.mean[i, c], ref[i], res.stderr[i, c],
                                       res.wall_s, engine.device))  # fmt: skip
            curve.budgets.append(budget)
            curve.seconds.append(float(np.median(times)))
            curve.errors.append(float(math.sqrt(np.mean(sq))))
            if curve.seconds[-1] >= max_seconds or budget >= min(max_budget, MAX_BUDGET):
                break
            budget *= 2
        curve.exact = max(curve.errors) < EXACT_REL
        if not curve.exact:
            curve.slope, curve.fitted = fit_slope(curve.seconds, curve.errors, ref_floor)
            curve.slope_samples, _ = fit_slope(curve.budgets, curve.errors, ref_floor, min_time_ratio=0.0)
            idx = curve.fitted or list(range(len(curve.errors)))
            eff = [1.0 / (curve.errors[i] ** 2 * curve.seconds[i]) for i in idx if curve.errors[i] > 0 and curve.seconds[i] > 0]
            curve.efficiency = float(np.median(eff)) if eff else None
        slope = "exact" if curve.exact else ("-" if curve.slope is None else f"{curve.slope:+.2f}")
        log(f"  {m:<9} {len(curve.budgets)} rungs to {curve.budgets[-1]:,} samples/sensor in {curve.seconds[-1]:.3f} s, "
            f"error {curve.errors[-1]:.1e}, slope {slope}")  # fmt: skip
    if "auto" in methods:  # the plan culled lights per sensor: give every light back
        engine.set_light_mask(np.ones((len(sensors), len(scene.lights)), np.int32))
    if adaptive:
        singles = [c.method for c in chart.curves if not c.skipped and c.method != "auto"]
        chart.adaptive = _adaptive_times(engine, scene, sensors, sim, singles, log)
    suspect = _reference_suspect(chart.curves)
    if suspect:
        chart.notes.append(suspect)
        log(f"  note: {suspect}")
    if plot:
        chart.png = Path(out_dir) / f"chart_{name}.png"
        _plot(chart, chart.png)
    return chart


def _reference_suspect(curves: list[MethodCurve]) -> str:
    """A note when two or more Monte Carlo methods level off together
    (error flat in samples, slope > −0.25) at nearly the same error: unbiased
    estimators that agree with one another and not with the reference
    point at the reference."""
    flat = [c for c in curves if not c.skipped and not c.exact and c.method != "analytic"
            and c.slope_samples is not None and c.slope_samples > -0.25]  # fmt: skip
    if len(flat) < 2:
        return ""
    best = min(c.errors[-1] for c in flat)
    together = [c.method for c in flat if c.errors[-1] <= 2.0 * best]
    if len(together) < 2:
        return ""
    return (f"{', '.join(together)} level off together at a relative error of {best:.1e}: they agree with one "
            f"another, not with the reference, which is likely off by about that much")


# --------------------------------------------------------------------------- outputs

_STYLE = {
    "analytic": dict(color="black", marker="*"),
    "light": dict(color="#1f77b4", marker="o"),
    "bsdf": dict(color="#ff7f0e", marker="s"),
    "mis": dict(color="#2ca02c", marker="^"),
    "path": dict(color="#d62728", marker="D"),
    "exact": dict(color="#8c564b", marker="P"),
    "auto": dict(color="#7f7f7f", marker="X", lw=2.4),
    "guided": dict(color="#9467bd", marker="v"),
}


def _plot(chart: ConfigChart, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from simulator.io.atomic import write_all_atomic

    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=100)
    plotted = [c for c in chart.curves if not c.skipped and c.errors]
    floor_y = 1e-7
    all_t = [t for c in plotted for t in c.seconds if t > 0]
    for c in plotted:
        st = _STYLE.get(c.method, {})
        y = np.maximum(np.asarray(c.errors), floor_y)
        label = c.method
        if c.exact:
            label += " (exact)"
        elif c.slope is not None:
            label += f" (slope {c.slope:+.2f})"
        ax.loglog(c.seconds, y, "-", marker=st.get("marker"), color=st.get("color"), ms=4, lw=st.get("lw", 1.3), label=label)
        if c.exact and c.method == "analytic":
            ax.annotate("closed form", (c.seconds[0], floor_y), textcoords="offset points", xytext=(6, 4), fontsize=7.5)
        t1, _ = c.time_to(1e-2)
        if t1 is not None and not c.exact:
            ax.plot([t1], [1e-2], marker="|", color=st.get("color"), ms=14, mew=2)
    if all_t:
        hi = max(all_t)
        ax.axhline(1e-2, color="grey", lw=0.8, ls=":")
        ax.text(hi, 1e-2, " 1%", va="center", ha="left", fontsize=8, color="grey")
        # the 1/√t slope through the first fitted rung of a Monte Carlo method
        anchor = next((c for c in plotted if c.fitted), None)
        if anchor is not None:
            i = anchor.fitted[0]
            t0, e0 = anchor.seconds[i], anchor.errors[i]
            ts = np.array([t0, hi * 2])
            ax.loglog(ts, e0 * np.sqrt(t0 / ts), color="grey", lw=1, ls="--", label=r"$\propto t^{-1/2}$")
        if chart.reference_rel_stderr > 0:
            ax.axhline(chart.reference_rel_stderr, color="#9467bd", lw=0.8, ls="-.", label="reference 1σ")
    ax.set_ylim(bottom=floor_y / 3)
    ax.set_xlabel("wall time per run, s")
    ax.set_ylabel("relative RMS error over sensors (exact: 1e-7)")
    ax.set_title(f"{chart.config}: {chart.sensors} sensors, {chart.device}; reference: {chart.reference_kind}", fontsize=8.5)
    ax.grid(True, which="major", lw=0.4, alpha=0.5)
    ax.legend(fontsize=7.5, loc="best")
    fig.tight_layout()
    write_all_atomic({path: lambda p: fig.savefig(p, format="png")})
    plt.close(fig)


def _csv_text(rows) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_COLUMNS)
    for r in rows:
        w.writerow([f"{x:.9g}" if isinstance(x, (float, np.floating)) else str(x) for x in r])
    return buf.getvalue()


def _fmt_time(t: float | None, first: bool) -> str:
    if t is None:
        return "-"
    s = f"{t * 1e3:.3g} ms" if t < 1 else f"{t:.3g} s"
    return ("<= " if first else "") + s


def format_summary(charts: list[ConfigChart]) -> str:
    """Per config and method: time to 1% and 0.1%, efficiency, slope."""
    head = (f"{'config':<18} {'method':<9} {'to 1%':>11} {'to 0.1%':>11} {'1/(var*t)':>10} {'slope t':>7} "
            f"{'slope N':>7}  note")  # fmt: skip
    lines = [head, "-" * len(head)]
    for ch in charts:
        for c in ch.curves:
            if c.skipped:
                lines.append(f"{ch.config:<18} {c.method:<9} {'':>11} {'':>11} {'':>10} {'':>7} {'':>7}  {c.skipped}")
                continue
            t1 = _fmt_time(*c.time_to(1e-2))
            t2 = _fmt_time(*c.time_to(1e-3))
            eff = "exact" if c.exact else ("-" if c.efficiency is None else f"{c.efficiency:.3g}")
            slope = "exact" if c.exact else ("-" if c.slope is None else f"{c.slope:+.2f}")
            slope_n = "exact" if c.exact else ("-" if c.slope_samples is None else f"{c.slope_samples:+.2f}")
            note = f"{len(c.budgets)} rungs to {c.budgets[-1]:,}/sensor" if c.budgets[-1] else "closed form"
            lines.append(f"{ch.config:<18} {c.method:<9} {t1:>11} {t2:>11} {eff:>10} {slope:>7} {slope_n:>7}  {note}")
    lines += ["", format_auto_check(charts)]
    return "\n".join(lines)


def format_auto_check(charts: list[ConfigChart]) -> str:
    """The planner check: per config, each method's adaptive time to 1% and
    auto's, with auto's ratio to the fastest single method."""
    head = f"{'config':<18} {'auto':>10} {'fastest single':>24} {'ratio':>6}  all methods (* = a sensor missed the target)"
    lines = [head, "-" * len(head)]
    for ch in charts:
        r = ch.auto_ratio()
        if r is None:
            continue
        ratio, best = r
        others = ", ".join(f"{m} {_fmt_time(t, False)}" + ("" if met else "*") for m, (t, met) in ch.adaptive.items() if m != "auto")
        fastest = f"{best} {_fmt_time(ch.adaptive[best][0], False)}"
        lines.append(f"{ch.config:<18} {_fmt_time(ch.adaptive['auto'][0], False):>10} {fastest:>24} {ratio:>6.2f}  {others}")
    return "\n".join(lines)


def default_configs() -> list[Path]:
    """The bundled reference stages' configs."""
    return bundled_configs(DEFAULT_CONFIGS, "chart")


def run_chart(
    configs: list[Path], out_dir: Path, *, seeds: int = 4, max_seconds: float = 0.5, device: str = "cpu",
    methods=METHODS, max_budget: int = MAX_BUDGET, adaptive: bool = True, log=print,
) -> list[ConfigChart]:  # fmt: skip
    """Chart each config; write ``chart.csv`` and the PNGs into ``out_dir``."""
    from simulator.io.atomic import write_all_atomic

    if seeds < 1:
        raise UserError(f"--seeds: must be >= 1, got {seeds}")
    if not (max_seconds > 0 and math.isfinite(max_seconds)):
        raise UserError(f"--max-seconds: must be a positive number of seconds, got {max_seconds}")
    for p in configs:
        if not Path(p).is_file():
            raise UserError(f"chart: config {p} does not exist")
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    charts = []
    for p in configs:
        charts.append(chart_config(Path(p), out_dir, seeds=seeds, max_seconds=max_seconds, device=device,
                                   methods=methods, max_budget=max_budget, adaptive=adaptive, log=log))  # fmt: skip
    rows = [r for ch in charts for r in ch.rows]
    write_all_atomic({out_dir / "chart.csv": _csv_text(rows)})
    return charts


def main_chart(configs: list[str], out: str, seeds: int, max_seconds: float, device: str, log=print,
               methods=None, adaptive: bool = True) -> int:  # fmt: skip
    """The ``probesim chart`` command."""
    from simulator.commands.bench import processor_name

    t0 = time.perf_counter()
    paths = [Path(c) for c in configs] or default_configs()
    charts = run_chart(paths, Path(out), seeds=seeds, max_seconds=max_seconds, device=device, log=log,
                       methods=tuple(methods) if methods else METHODS, adaptive=adaptive)  # fmt: skip
    log("")
    log(format_summary(charts))
    dev = charts[0].device if charts else device
    log(f"device {dev} ({processor_name()}, {os.cpu_count()} cores); {seeds} seeds per rung; "
        f"errors relative, RMS over sensors, radiometric (photometric against a stored reference in lx); times: median wall time of one run; "
        f"'<=': the first rung already met the target; 1/(var*t) in 1/s; slopes of log error on log time (t, "
        f"rungs >= 10x the first rung's time) and on log samples (N)")  # fmt: skip
    for ch in charts:
        if ch.reference_rel_stderr > 0:
            log(f"{ch.config}: reference {ch.reference_kind}, its relative stderr {ch.reference_rel_stderr:.1e} "
                "(errors near it measure the reference)")  # fmt: skip
        for n in ch.notes:
            log(f"{ch.config}: {n}")
    log(f"wrote {Path(out) / 'chart.csv'} and {len(charts)} PNGs in {time.perf_counter() - t0:.1f} s")
    return 0
