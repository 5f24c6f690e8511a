"""``probesim bench``: speed of every estimator on the bundled stages.

For each config and each estimator that applies it measures, after a warm-up
(so kernel compilation is not timed):

- samples per second and rays per second at a fixed budget;
- the time to reach 1%: an adaptive run with ``rel_error = 0.01`` until every
  sensor's 95% half-width is under 1% of its reading (or the cap).

for a config with a stored reference (``configs/references/NAME.csv``), the
time to 1% and 0.3% relative RMS error of the planned run against it
(:mod:`simulator.commands.bench_reference`); and finally the CPU speed-up of
all cores over one thread on the quickstart stage. Figures are printed with the device and processor they came from.
"""

from __future__ import annotations

import os
import platform
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from simulator.bundled import bundled_configs
from simulator.config.loader import load_config
from simulator.engine.methods import METHOD_FLAGS
from simulator.plan.planner import MC_METHODS
from simulator.pipeline import collect_sensors, config_engine, load_scene

__all__ = ["BenchRow", "default_configs", "run_bench", "format_bench", "processor_name"]

#: the bundled configs benchmarked by default (those present are used)
DEFAULT_CONFIGS = (
    "point", "sphere", "rect", "disk", "distant_occluder", "dome", "quickstart",
    "furnace", "integrating_sphere", "cie171_5_8", "occluded_floor_grid", "office_bench",
)  # fmt: skip


@dataclass
class BenchRow:
    config: str
    method: str
    sensors: int
    samples_per_s: float | None
    rays_per_s: float | None
    seconds_to_1pct: float | None
    reached: bool
    note: str = ""


def processor_name() -> str:
    """The CPU model as the OS reports it."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.lower().startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def default_configs() -> list[Path]:
    """The bundled configs benchmarked by default."""
    return bundled_configs(DEFAULT_CONFIGS, "bench")


def _bench_one(engine, scene, sensors, method: str, samples: int, cap: int) -> BenchRow:
    name = ""
    if method == "bsdf" and any(l.is_delta for l in scene.lights):
        return BenchRow(name, method, len(sensors), None, None, None, False, "blind: point/distant lights")
    # fixed budget, rays counted in a separate short run so counting does not perturb timing
    engine.run(method, samples=min(samples, 64), seed=1)  # warm caches
    t0 = time.perf_counter()
    fixed = engine.run(method, samples=samples, seed=2)
    dt = time.perf_counter() - t0
    n = int(fixed.samples.sum())
    counted = engine.run(method, samples=max(32, samples // 8), seed=3, count_rays=True)
    rays_per_sample = engine.rays_traced / max(1, int(counted.samples.sum()))
    t0 = time.perf_counter()
    ad = engine.run(method, samples=256, seed=4, rel_error=0.01, abs_error=1e-12, max_samples=cap)
    t1 = time.perf_counter() - t0
    reached = bool(ad.target_met.all())
    return BenchRow(name, method, len(sensors), n / dt, n / dt * rays_per_sample, t1, reached)


def run_bench(configs: list[Path], device: str = "cpu", samples: int = 4096, cap: int = 1 << 20, log=print,
              reference_seconds: float = 60.0) -> tuple[list[BenchRow], dict]:
    """Benchmark each config with each applicable estimator.

    Returns the rows and a dict with the device, processor, threads and the
    1-thread vs all-threads speed-up.
    """
    rows: list[BenchRow] = []
    info: dict = {"processor": processor_name(), "cores": os.cpu_count()}
    for path in configs:
        cfg = load_config(path)
        scene = load_scene(cfg)
        sensors = collect_sensors(cfg, scene)
        sensors = [s for s in sensors if s.spec.reader == "estimate"]
        engine = config_engine(cfg, scene, sensors, device=device, threads=0)
        info["device"] = engine.device
        info["threads"] = engine.threads
        from simulator.commands.bench_reference import reference_path
        from simulator.plan.planner import closed_form_refusal

        if reference_path(path).is_file():
            continue  # measured against its reference below
        reflects = scene.geometry.n_triangles > 0 and bool(np.any(scene.geometry.albedo > 0))
        closed = [m for m in ("analytic", "exact") if all(closed_form_refusal(m, scene, s) is None for s in sensors)]
        methods = closed[:1] + list(MC_METHODS)
        if closed[:1] == ["exact"]:
            from simulator.plan.planner import cull_mask

            engine.set_light_mask(cull_mask(scene, sensors))
        for m in methods:
            if m in METHOD_FLAGS and not METHOD_FLAGS[m][3] and reflects:
                row = BenchRow(path.stem, m, len(sensors), None, None, None, False, "biased: ignores interreflection")
            elif m in ("analytic", "exact"):
                engine.run(m, samples=1, seed=1)  # warm-up: importing Warp and loading the kernels is not timed
                t0 = time.perf_counter()
                engine.run(m, samples=1, seed=1)
                dt = time.perf_counter() - t0
                row = BenchRow(path.stem, m, len(sensors), None, None, dt, True, "exact (closed form)")
            else:
                row = _bench_one(engine, scene, sensors, m, samples, cap)
                row.config = path.stem
            rows.append(row)
            log(format_bench([row], header=False))
    # time to a relative RMS error against a stored reference, where there is one
    from simulator.commands.bench_reference import format_reference_curve, reference_curve, reference_path

    info["reference_curves"] = []
    for path in configs:
        if reference_path(path).is_file():
            curve = reference_curve(path, device=device, max_seconds=reference_seconds, log=log)
            info["reference_curves"].append(curve)
            log(format_reference_curve(curve))
    # CPU scaling: the quickstart's path tracing on one thread and on all
    qs = [p for p in configs if p.stem == "quickstart"]
    if qs and info.get("device") == "cpu" and (os.cpu_count() or 1) > 1:
        cfg = load_config(qs[0])
        scene = load_scene(cfg)
        sensors = [s for s in collect_sensors(cfg, scene) if s.spec.reader == "estimate"]
        rates = {}
        for threads in (1, os.cpu_count() or 1):
            eng = config_engine(cfg, scene, sensors, device="cpu", threads=threads)
            eng.run("path", samples=64, seed=1)
            t0 = time.perf_counter()
            r = eng.run("path", samples=2048, seed=2)
            rates[threads] = int(r.samples.sum()) / (time.perf_counter() - t0)
        one, all_ = rates[1], rates[max(rates)]
        info["scaling"] = {"threads": max(rates), "one_thread_samples_per_s": one, "all_threads_samples_per_s": all_, "speedup": all_ / one}
    return rows, info


def _f(x, fmt: str) -> str:
    return "-" if x is None else format(x, fmt)


def format_bench(rows: list[BenchRow], header: bool = True) -> str:
    lines = []
    if header:
        lines.append(f"{'config':<20} {'method':<9} {'sensors':>7} {'samples/s':>12} {'rays/s':>12} {'time to 1%':>11}  note")
    for r in rows:
        t = "-" if r.seconds_to_1pct is None else f"{r.seconds_to_1pct:.3f} s" + ("" if r.reached else "*")
        lines.append(
            f"{r.config:<20} {r.method:<9} {r.sensors:>7} {_f(r.samples_per_s, ',.0f'):>12} {_f(r.rays_per_s, ',.0f'):>12} {t:>11}  {r.note}"
        )
    return "\n".join(lines)
