"""One run, start to finish: config → stage → plan → engine → CSV and run record."""

from __future__ import annotations

import hashlib
import platform
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from . import __version__
from .config import RunConfig
from .errors import UserError
from .plan import choose_method
from .results import Reading, readings_from, write_outputs
from .scene.model import Scene, Sensor

__all__ = ["RunOutput", "load_scene", "collect_sensors", "run"]


@dataclass
class RunOutput:
    rows: list[Reading]
    csv_path: Path
    record_path: Path
    record: dict
    scene: Scene


def load_scene(cfg: RunConfig) -> Scene:
    from .scene.usd import load_stage  # the only module that imports pxr

    return load_stage(cfg.stage, light_units=cfg.light_units, radiometric_spectrum=cfg.radiometric_spectrum)


def collect_sensors(cfg: RunConfig, scene: Scene) -> list[Sensor]:
    """Config sensors, then those authored in the stage; names must be unique."""
    sensors = list(cfg.sensors) + list(scene.sensors)
    if not sensors:
        raise UserError(
            f"{cfg.path}: no sensors: add [[sensor]] or [[grid]] tables, or author prims with "
            f"probesim:sensor:kind in {cfg.stage.name}"
        )
    seen: dict[str, str] = {}
    for s in sensors:
        if s.name in seen:
            raise UserError(f"{cfg.path}: sensor name {s.name!r} is used twice ({seen[s.name]} and {s.source})")
        seen[s.name] = s.source
    return sensors


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _versions() -> dict:
    import numpy
    import warp

    try:
        from pxr import Usd

        usd = ".".join(map(str, Usd.GetVersion()))
    except Exception:  # pragma: no cover - version lookup only
        usd = "unknown"
    return {
        "probesim": __version__,
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "warp": warp.config.version,
        "usd": usd,
    }


def run(cfg: RunConfig, progress=None, log=print) -> RunOutput:
    """Run a validated config and write its CSV and run record.

    Parameters
    ----------
    cfg : RunConfig
    progress : callable, optional
        Receives :class:`simulator.engine.Progress` after each batch.
    log : callable
        Where one-line notes (warnings, the chosen method) go.
    """
    from .engine import Engine  # imports warp

    t0 = time.perf_counter()
    scene = load_scene(cfg)
    sensors = collect_sensors(cfg, scene)
    sim = cfg.simulation
    method, reason = choose_method(scene, sensors, sim.method, sim.component)
    for w in scene.warnings:
        log(f"warning: {w}")
    t_load = time.perf_counter()
    engine = Engine(scene, sensors, device=sim.device, threads=sim.threads)
    t_setup = time.perf_counter()
    res = engine.run(
        method,
        samples=sim.samples,
        seed=sim.seed,
        rel_error=sim.rel_error,
        abs_error=sim.abs_error,
        max_samples=sim.sample_cap,
        time_limit_s=sim.time_limit_s,
        max_depth=sim.max_depth,
        component=sim.component,
        progress=progress,
    )
    for w in res.warnings:
        log(f"warning: {w}")
    rows = readings_from(sensors, res.mean, res.stderr, res.samples, res.seconds, res.method, res.target_met)
    t_end = time.perf_counter()
    record = {
        "config_path": str(cfg.path),
        "config": cfg.raw,
        "overrides": getattr(cfg, "overrides", {}),
        "stage": {"path": str(cfg.stage), "sha256": _sha256(cfg.stage), "meters_per_unit": scene.meters_per_unit, "up_axis": scene.up_axis},
        "seed": sim.seed,
        "samples_requested": sim.samples,
        "samples_total": int(res.samples.sum()),
        "method": {"requested": sim.method, "used": res.method, "reason": reason},
        "component": sim.component,
        "device": res.device,
        "threads": engine.threads,
        "host": {"platform": platform.platform(), "machine": platform.machine(), "processor": platform.processor(), "python": sys.version.split()[0]},
        "versions": _versions(),
        "timings_s": {"load": t_load - t0, "setup": t_setup - t_load, "trace": res.wall_s, "total": t_end - t0},
        "sensors": len(sensors),
        "warnings": list(scene.warnings) + list(res.warnings),
        "non_finite_samples": int(res.non_finite.sum()),
    }
    record_path = write_outputs(cfg.output.csv, rows, record)
    return RunOutput(rows, cfg.output.csv, record_path, record, scene)
