"""Where a traced one-sensor run's start-up goes: the CPU time of each piece, in fresh processes.

``python benchmarks/startup_pieces.py [--repeats N]`` (from a checkout) starts a new Python process
per repeat and way, and in it takes, in a run's order and with a run's start (collections paused,
one BLAS thread), the CPU seconds (``time.process_time``) of:

- ``numpy``: importing numpy;
- ``config``: importing the config schema (pydantic and the models);
- ``stage``: the office stage's reading (``stages/office.usda``): read by the stage reader (importing
  ``pxr`` and the reader is part of it) or taken from the disk cache;
- ``warp``: importing and initialising Warp;
- ``kernel functions``: defining the trace functions and kernels: both variants with Warp's
  re-import scan (before), or the all-matte variant alone without it (now,
  ``engine.kernel_modules.trace_module``);
- ``module hash``: the trace module's hash, computed by Warp or restored from the kept entry;
- ``module load``: loading its object file from Warp's kernel cache.

Two ways are compared, each in its own processes, alternated: ``before`` (the disk caches off,
both trace variants defined, the scan on: what a run did before) and ``now`` (a run's way: the caches
in a temporary folder, filled by one warm-up process, one variant, the scan skipped). It prints the median of each
piece and of their sum, with the 1-minute load average before and after. Warp's kernel cache must
hold the trace module already (any earlier run does that).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

CHILD = r"""
import gc, json, os, sys, time
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
gc.disable()
now = sys.argv[1] == "now"
out = {}
def took(name, t0):
    out[name] = time.process_time() - t0
t = time.process_time(); import numpy; took("numpy", t)
t = time.process_time(); import simulator.config; took("config", t)
from simulator.config.loader import load_config
from simulator.pipeline import cached_scene
cfg = load_config(sys.argv[2])
t = time.process_time(); cached_scene(cfg); took("stage", t)
from simulator.engine import device
if now:
    device.skip_reload_scan()
t = time.process_time(); device.warp(); took("warp", t)
from simulator.engine import kernel_hashes, kernel_modules
t = time.process_time()
km = kernel_modules.trace_module(False)
if not now:  # both variants, as every run defined them before they were built on first use
    from simulator.kernels import probe
    probe.make_probe_kernel(True)
took("kernel functions", t)
m = km.module
t = time.process_time()
if not kernel_hashes.restore(m, 1):
    m.get_module_hash(1)
    kernel_hashes.keep(m, 1)
took("module hash", t)
t = time.process_time(); m.load(device.warp().get_device("cpu"), 1); took("module load", t)
from simulator.scene import stage_cache
out["stage from disk"] = stage_cache.stats()["disk_hits"]
out["hash restored"] = kernel_hashes.restored(m, 1)
print(json.dumps(out))
"""

PIECES = ("numpy", "config", "stage", "warp", "kernel functions", "module hash", "module load")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        cfg = Path(tmp) / "desk.toml"
        cfg.write_text(f'stage = "{(ROOT / "stages" / "office.usda").as_posix()}"\n\n[simulation]\nsamples = 256\nseed = 1\n\n'
                       '[[sensor]]\nname = "desk"\nkind = "irradiance"\nposition = [2.0, 2.0, 0.8]\nnormal = [0, 0, 1]\n')  # fmt: skip
        base = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])]),
                    PYTHONPYCACHEPREFIX=str(Path(tmp) / "pycache"))  # fmt: skip
        base.pop("PYTHONDONTWRITEBYTECODE", None)
        envs = {"before": dict(base, PROBESIM_CACHE_PATH=""), "now": dict(base, PROBESIM_CACHE_PATH=str(Path(tmp) / "cache"))}

        def child(way: str) -> dict:
            proc = subprocess.run([sys.executable, "-c", CHILD, way, str(cfg)], env=envs[way], capture_output=True,
                                  text=True, cwd=tmp)  # fmt: skip
            if proc.returncode != 0:
                raise SystemExit(f"{way}: {proc.stderr.strip()}")
            return json.loads(proc.stdout.strip().splitlines()[-1])

        for way in envs:  # warm-up: bytecode, and for "now" the caches
            child(way)
        load0 = os.getloadavg()[0]
        got = {way: [] for way in envs}
        for _ in range(a.repeats):
            for way in envs:
                got[way].append(child(way))
        load1 = os.getloadavg()[0]
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores; median CPU s of {a.repeats} fresh processes "
          f"per way, load {load0:.2f}->{load1:.2f}")
    print(f"{'piece':18s} {'before':>8s} {'now':>8s}")
    for piece in (*PIECES, "sum"):
        med = {way: statistics.median(sum(r[p] for p in PIECES) if piece == "sum" else r[piece] for r in rows)
               for way, rows in got.items()}  # fmt: skip
        print(f"{piece:18s} {med['before']:8.3f} {med['now']:8.3f}")
    now = got["now"][-1]
    print(f"now: stage from disk {bool(now['stage from disk'])}, module hash restored {now['hash restored']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
