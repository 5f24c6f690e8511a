"""What a run costs in a Python process that has run before (a parametric study's loop).

``python benchmarks/warm_runs.py [CONFIG] [--runs N] [--profile K]`` (from a checkout, or anywhere
with probesim installed; CONFIG defaults to configs/occluded_floor_grid.toml, the 1,024-sensor
exact grid) runs, in one process, one cold ``simulator.run(cfg)`` (imports, first stage read,
first plan), then N warm runs writing the outputs (CSV, run record, maps, into a temporary
folder) and N warm runs with ``write=False``; and N warm runs of a light-intensity study (the
config's ``--intensity-of`` light's ``inputs:intensity`` scaled in a copy of the stage between
runs: a fresh stage read and plan each time, the exact estimator's geometric factors kept), and
N warm runs with every sensor moved (a new plan and new exact geometry each run). It
prints the median wall and CPU time (``time.process_time``: all threads, less disturbed by a
loaded machine than wall time) per run, and the 1-minute load average. ``--profile K``: a
cProfile of K warm writing runs, the top entries by cumulative time.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:  # run from a checkout: the package sits beside this folder
    sys.path.insert(0, str(ROOT))


def _timed(fn, runs: int) -> tuple[float, float]:
    """Median wall and CPU seconds of ``fn()`` over ``runs`` calls."""
    wall, cpu = [], []
    for _ in range(runs):
        w0, c0 = time.perf_counter(), time.process_time()
        fn()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
    return statistics.median(wall), statistics.median(cpu)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("config", nargs="?", default=str(ROOT / "configs" / "occluded_floor_grid.toml"))
    ap.add_argument("--runs", type=int, default=20)
    ap.add_argument("--profile", type=int, default=0, metavar="K")
    ap.add_argument("--intensity-of", default="Lamp", help="light prim name whose intensity the study scales")
    args = ap.parse_args(argv)

    import simulator
    from simulator.config.overrides import apply_overrides

    quiet = lambda *a: None  # noqa: E731
    with tempfile.TemporaryDirectory() as tmp:
        cfg = apply_overrides(simulator.load_config(args.config), csv=os.path.join(tmp, "out.csv"))
        w0, c0 = time.perf_counter(), time.process_time()
        simulator.run(cfg, log=quiet)
        cold = (time.perf_counter() - w0, time.process_time() - c0)
        written = _timed(lambda: simulator.run(cfg, log=quiet), args.runs)
        bare = _timed(lambda: simulator.run(cfg, log=quiet, write=False), args.runs)
        study = _intensity_study(cfg, Path(tmp), args.intensity_of, args.runs, quiet)
        moved = _moved_sensors(cfg, args.runs, quiet)
        if args.profile:
            import cProfile
            import pstats

            prof = cProfile.Profile()
            prof.enable()
            for _ in range(args.profile):
                simulator.run(cfg, log=quiet)
            prof.disable()
            pstats.Stats(prof).sort_stats("cumulative").print_stats(25)
    n = len(cfg.sensors)
    print(f"{Path(args.config).name}: {n} config sensors; load average {os.getloadavg()[0]:.2f}")
    print(f"cold run (imports, first read and plan): wall {cold[0] * 1e3:.0f} ms, CPU {cold[1] * 1e3:.0f} ms")
    print(f"warm run, writing outputs:     median wall {written[0] * 1e3:.1f} ms, CPU {written[1] * 1e3:.1f} ms")
    print(f"warm run, write=False:         median wall {bare[0] * 1e3:.1f} ms, CPU {bare[1] * 1e3:.1f} ms")
    if study is not None:
        print(f"intensity study, write=False:  median wall {study[0] * 1e3:.1f} ms, CPU {study[1] * 1e3:.1f} ms "
              "(stage edited between runs: read and planned afresh)")
    print(f"sensors moved, write=False:    median wall {moved[0] * 1e3:.1f} ms, CPU {moved[1] * 1e3:.1f} ms "
          "(every sensor 1 mm higher each run: planned and read afresh)")
    return 0


def _moved_sensors(cfg, runs: int, quiet):
    """Median (wall, CPU) of runs whose sensors all rise by 1 mm each run (a new plan and new exact geometry)."""
    import dataclasses

    import simulator

    k = iter(range(1, 10**9))

    def one():
        dz = 1e-3 * next(k)
        sensors = [dataclasses.replace(s, position=s.position + [0.0, 0.0, dz]) for s in cfg.sensors]
        simulator.run(dataclasses.replace(cfg, sensors=sensors, grids=[]), log=quiet, write=False)

    return _timed(one, runs)


def _intensity_study(cfg, folder: Path, light: str, runs: int, quiet):
    """Median (wall, CPU) of runs of a copy of the stage whose light ``light`` gets a new intensity each run."""
    import dataclasses
    import re

    import simulator

    text = cfg.stage.read_text()
    pattern = re.compile(r'(def \w+ "' + re.escape(light) + r'"[^{]*\{[^}]*?float inputs:intensity = )([0-9.eE+-]+)')
    if not pattern.search(text):
        return None
    stage = folder / cfg.stage.name
    for p in cfg.stage.parent.iterdir():  # the stage's neighbours (sublayers, textures) beside the copy
        if p.is_file() and p.name != stage.name and not (folder / p.name).exists():
            shutil.copy(p, folder / p.name)
    study = dataclasses.replace(cfg, stage=stage)
    k = iter(range(1, 10**9))

    def one():
        stage.write_text(pattern.sub(lambda m: m.group(1) + f"{1000 + next(k)}", text, count=1))
        simulator.run(study, log=quiet, write=False)

    return _timed(one, runs)


if __name__ == "__main__":
    raise SystemExit(main())
