"""Whole-process time of small runs: what a user waits for from typing the command to its last line.

``python benchmarks/small_runs.py [CASE ...] [--repeats N] [--no-bytecode]`` (from a checkout, or
anywhere with probesim installed) runs ``python -m simulator run ...`` in a fresh process
``--repeats`` times per case (after one warm-up run, not counted, that leaves Warp's kernel cache
and Python's bytecode in place) and prints per case the median wall time, the median CPU time of
the process (user + system, all threads; a loaded machine disturbs it less than wall time), the
1-minute load average before and after, the run record's own timings (``timings_s``: stage
read, plan, tracing) and, for an adaptive run, the samples drawn per sensor against the need of
its slowest sensor (``adaptive.batches``: z²·stderr²·n/target² at the end).

Cases (default: all):

- ``point``: ``configs/point.toml``, four closed-form readings of a point light;
- ``one_sensor``: one irradiance sensor under the point light of ``stages/point.usda``;
- ``desk``: one irradiance sensor on the office's desk (``stages/office.usda``: sky, sun, six
  lamps, reflecting walls), traced: Warp, the kernels from the cache, the pilots;
- ``sphere_grid``: ``configs/integrating_sphere_grid.toml --rel-error 0.01``, 256 sensors in an
  integrating sphere of 261,120 triangles, adaptive to 1%;
- ``floor_grid``: ``configs/occluded_floor_grid.toml``, 1,024 exact readings (no Warp).

An installed package carries compiled bytecode; a checkout run with ``PYTHONDONTWRITEBYTECODE``
set compiles every module of the package again at each start (~0.1 s). The script gives its
runs a bytecode cache of their own (``PYTHONPYCACHEPREFIX``, a temporary folder) unless
``--no-bytecode`` asks for the uncompiled start.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

ONE_SENSOR = """stage = "{stage}"

[simulation]
samples = 256
seed = 1

[[sensor]]
name = "below"
kind = "irradiance"
position = [0, 0, 0]
normal = [0, 0, 1]
"""


DESK = ONE_SENSOR.replace("position = [0, 0, 0]", "position = [2.0, 2.0, 0.8]").replace('name = "below"', 'name = "desk"')


def cases(folder: Path) -> dict[str, list[str]]:
    """Each case's ``run`` arguments (the config first); ``one_sensor``'s and ``desk``'s configs are
    written to ``folder``."""
    one = folder / "one_sensor.toml"
    one.write_text(ONE_SENSOR.format(stage=(ROOT / "stages" / "point.usda").as_posix()))
    desk = folder / "desk.toml"
    desk.write_text(DESK.format(stage=(ROOT / "stages" / "office.usda").as_posix()))
    return {
        "point": [str(ROOT / "configs" / "point.toml")],
        "one_sensor": [str(one)],
        "desk": [str(desk)],
        "sphere_grid": [str(ROOT / "configs" / "integrating_sphere_grid.toml"), "--rel-error", "0.01"],
        "floor_grid": [str(ROOT / "configs" / "occluded_floor_grid.toml")],
    }


def run_once(args: list[str], out_csv: Path, env: dict) -> tuple[float, float, dict]:
    """One run in a fresh process: (wall s, CPU s of the child, its run record)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "simulator", "run", *args, "-o", str(out_csv), "-q"], env=env,
                          cwd=out_csv.parent, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)  # fmt: skip
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise SystemExit(f"run {' '.join(args)} failed ({proc.returncode}): {proc.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, json.loads(out_csv.with_suffix(".run.json").read_text())


def adaptive_line(record: dict) -> str:
    """Samples drawn per sensor against the slowest sensor's need, from the run record."""
    batches = (record.get("adaptive") or {}).get("batches") or {}
    parts = []
    n = max(1, int(record.get("sensors_read") or record.get("sensors") or 1))
    drawn = record.get("samples_total", 0) / n
    for method, b in batches.items():
        need = b.get("needed_max")
        ratio = f"{drawn / need:.2f}x" if need else "-"
        parts.append(f"{method}: first batch {b.get('first_batch')}, {drawn:.2f} per sensor drawn, "
                     f"slowest needs {need:.2f}, drawn/needed {ratio}" if need else f"{method}: first batch "
                     f"{b.get('first_batch')}, {drawn:.2f} per sensor drawn")
    return "; ".join(parts)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="*", help="cases to run (default: all)")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--no-bytecode", action="store_true", help="compile the package at every start")
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        table = cases(tmp)
        names = a.cases or list(table)
        unknown = [n for n in names if n not in table]
        if unknown:
            ap.error(f"unknown case {unknown[0]!r} (expected one of {', '.join(table)})")
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [env.get("PYTHONPATH")])])
        if a.no_bytecode:
            env["PYTHONDONTWRITEBYTECODE"] = "1"
        else:
            env.pop("PYTHONDONTWRITEBYTECODE", None)
            env["PYTHONPYCACHEPREFIX"] = str(tmp / "pycache")
        print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores, bytecode "
              f"{'off' if a.no_bytecode else 'cached'}; median of {a.repeats} runs after one warm-up")
        for name in names:
            out = tmp / f"{name}.csv"
            run_once(table[name], out, env)  # warm-up: kernel cache, bytecode
            load0 = os.getloadavg()[0]
            walls, cpus, rec = [], [], None
            for _ in range(a.repeats):
                w, c, rec = run_once(table[name], out, env)
                walls.append(w)
                cpus.append(c)
            load1 = os.getloadavg()[0]
            tim = rec.get("timings_s", {})
            inner = ", ".join(f"{k} {tim[k]:.2f}" for k in ("load", "plan", "trace", "total") if k in tim)
            print(f"{name}: wall {statistics.median(walls):.2f} s (min {min(walls):.2f}), CPU "
                  f"{statistics.median(cpus):.2f} s, load {load0:.2f}->{load1:.2f}; run record s: {inner}")
            line = adaptive_line(rec)
            if line:
                print(f"  {line}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
