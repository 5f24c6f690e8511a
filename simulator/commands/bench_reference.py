"""Time to a relative RMS error against a stored reference (``probesim bench``).

A config ``configs/NAME.toml`` with a reference ``configs/references/NAME.csv``
(one row per sensor: ``sensor, illuminance_lx, illuminance_stderr_lx``, made
by a long run whose record sits beside it as ``NAME.json``) is read with the
planner's methods at doubling fixed budgets. Each budget's relative RMS error
over the sensors is

    rms² = mean_s[(x_s − r_s)² − σ_r,s²] / r_s²,

the reference's own variance σ_r² subtracted (the two runs are independent,
so E[(x − r)²] = (x − truth)² + σ_r² on average). The time to a target error
follows from the last budget by the 1/√t law of an unbiased estimator,
interpolated between budgets that bracket it when there are some. A plan
that uses ``guided`` builds its surface guide once, in the setup (its pilot
is reported there, as in a run's ``timings_s.guide``).
"""

from __future__ import annotations

import csv
import dataclasses
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.errors import UserError

__all__ = ["ReferenceCurve", "reference_path", "read_reference", "reference_curve", "format_reference_curve"]

#: the error targets reported, relative RMS
TARGETS = (0.01, 0.003)


@dataclass
class ReferenceCurve:
    config: str
    sensors: int
    device: str
    setup_s: float  #: load + plan + engine setup, measured in this process
    points: list[tuple[int, float, float]] = field(default_factory=list)  #: (samples per sensor, trace s, rms)
    methods: dict[str, int] = field(default_factory=dict)

    def seconds_to(self, target: float) -> float | None:
        """Trace seconds to reach ``target`` (None before any budget ran)."""
        if not self.points:
            return None
        pts = [(t, e) for _, t, e in self.points if e > 0 and t > 0]
        if not pts or self.points[0][2] <= target:  # met by the first budget (an exact method: error 0)
            return self.points[0][1]
        for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
            if e0 >= target >= e1:  # log-log interpolation between budgets
                a = np.log(target / e0) / np.log(e1 / e0)
                return float(np.exp(np.log(t0) + a * (np.log(t1) - np.log(t0))))
        t, e = pts[-1]
        return t * (e / target) ** 2


def reference_path(config: Path) -> Path:
    return config.parent / "references" / f"{config.stem}.csv"


def read_reference(path: Path) -> dict[str, tuple[float, float]]:
    """``sensor → (illuminance_lx, illuminance_stderr_lx)``."""
    try:
        with path.open(newline="") as f:
            rows = list(csv.DictReader(f))
        return {r["sensor"]: (float(r["illuminance_lx"]), float(r["illuminance_stderr_lx"])) for r in rows}
    except (OSError, KeyError, ValueError) as e:
        raise UserError(f"{path}: not a reference CSV (sensor, illuminance_lx, illuminance_stderr_lx): {e}") from None


def reference_curve(config: Path, device: str = "cpu", max_seconds: float = 60.0, first: int = 64, log=print) -> ReferenceCurve:
    """Doubling fixed budgets of the planned run, until one takes ``max_seconds``."""
    from simulator.config.loader import load_config
    from simulator.engine.methods import GUIDED_METHODS
    from simulator.pipeline import collect_sensors, config_engine, load_scene, run_plan
    from simulator.plan.planner import make_plan

    t0 = time.perf_counter()
    cfg = load_config(config)
    ref = read_reference(reference_path(config))
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.spec.reader == "estimate"]
    missing = [s.name for s in sensors if s.name not in ref]
    if missing:
        raise UserError(f"{reference_path(config)}: no reference for sensor {missing[0]!r} ({len(missing)} missing)")
    r = np.array([ref[s.name][0] for s in sensors])
    sr = np.array([ref[s.name][1] for s in sensors])
    use = r > 0
    plan = make_plan(scene, sensors, cfg.simulation.method, cfg.simulation.component)
    engine = config_engine(cfg, scene, sensors, device=device, threads=0)
    engine.run("path", samples=4, seed=1)  # load the kernels before timing
    guided = [ix for m, ix in plan.groups().items() if m in GUIDED_METHODS]
    if guided:  # the guide is built once per run: part of the setup, not of each budget
        engine.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
        engine.ensure_guide(cfg.simulation.seed, np.concatenate(guided), cfg.simulation.max_depth)
    curve = ReferenceCurve(config.stem, len(sensors), engine.device, time.perf_counter() - t0,
                           methods={m: len(ix) for m, ix in plan.groups().items()})  # fmt: skip
    n = first
    while True:
        sim = dataclasses.replace(cfg.simulation, samples=n, seed=1000 + n, rel_error=None)
        t = time.perf_counter()
        res = run_plan(engine, plan, sim)
        dt = time.perf_counter() - t
        x = res.mean[:, 1]
        rms2 = np.mean(((x[use] - r[use]) ** 2 - sr[use] ** 2) / r[use] ** 2)
        rms = float(np.sqrt(max(rms2, 0.0)))
        curve.points.append((n, dt, rms))
        log(f"  {config.stem}: {n} samples/sensor, {dt:.2f} s, relative RMS error {100 * rms:.2f}%")
        if dt >= max_seconds / 2 or rms < min(TARGETS) / 2 or n >= 1 << 20:
            return curve
        n *= 2


def format_reference_curve(c: ReferenceCurve) -> str:
    parts = [f"{c.config}: {c.sensors} sensors on {c.device}; methods " + ", ".join(f"{m} {k}" for m, k in c.methods.items())]
    for target in TARGETS:
        t = c.seconds_to(target)
        parts.append(f"  to {100 * target:g}% RMS: {t:.1f} s warm, {t + c.setup_s:.1f} s with load/plan/setup ({c.setup_s:.1f} s)"
                     if t is not None else f"  to {100 * target:g}% RMS: -")
    return "\n".join(parts)
