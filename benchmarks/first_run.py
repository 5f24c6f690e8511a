"""A fresh install's first run, its second run, ``probesim warmup``, and a first run after warmup.

``python benchmarks/first_run.py [CONFIG] [--trees DIR ...] [--rounds N]`` (from a checkout;
CONFIG defaults to configs/quickstart.toml). Every step is the command line in a new process
with ``WARP_CACHE_PATH`` pointed at a kernel cache of its own and ``PROBESIM_CACHE_PATH`` at an
empty folder of probesim's own cache, as a fresh install has:

1. ``probesim run CONFIG`` on an empty cache (the first run: it compiles what it needs);
2. the same run again on that cache (a second run: every module cached);
3. ``probesim warmup --device cpu`` on another empty cache;
4. ``probesim run CONFIG`` on the cache warmup filled.

Each prints its wall seconds, its CPU seconds (user + system of the process and its threads, less
disturbed than wall time by other load on a shared machine), the compile's seconds as the
command reported them on stderr, and the 1-minute load average before it. ``--trees`` runs
the same steps with other checkouts' code (each on its own caches; the steps alternate
between the trees, so both see the same load), e.g. ``--trees . ../main``.
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _timed(cmd: list[str], env: dict, cwd: str) -> tuple[float, float, str]:
    """Wall and CPU seconds of one command, and its stderr."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run(cmd, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, p.stderr


def _compile_note(stderr: str) -> str:
    """What the command said of its compile: the seconds of each module (or nothing compiled)."""
    done = re.findall(r"compiled (.+?) \((\d+)/\d+, ([\d.]+) s\)", stderr)
    if not done:
        return "nothing compiled"
    return "compiled " + ", ".join(f"{label} at {secs} s" for label, _, secs in done)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("config", nargs="?", default=str(ROOT / "configs" / "quickstart.toml"))
    ap.add_argument("--trees", nargs="+", default=[str(ROOT)], metavar="DIR",
                    help="checkouts whose code to run (default: this one)")
    ap.add_argument("--rounds", type=int, default=1)
    args = ap.parse_args(argv)
    config = str(Path(args.config).resolve())
    trees = [str(Path(t).resolve()) for t in args.trees]
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.rounds):
            caches = {t: (os.path.join(tmp, f"r{r}_{i}_run"), os.path.join(tmp, f"r{r}_{i}_warm"))
                      for i, t in enumerate(trees)}
            steps = [
                ("first run", lambda t: ["run", config, "-o", os.path.join(tmp, "out")], 0),
                ("second run", lambda t: ["run", config, "-o", os.path.join(tmp, "out")], 0),
                ("warmup", lambda t: ["warmup", "--device", "cpu"], 1),
                ("first run after warmup", lambda t: ["run", config, "-o", os.path.join(tmp, "out")], 1),
            ]
            for name, command, which in steps:
                for t in trees:
                    # probesim's own cache (stage readings, kept kernel hashes) beside Warp's, as empty as it
                    env = dict(os.environ, PYTHONPATH=t, WARP_CACHE_PATH=caches[t][which],
                               PROBESIM_CACHE_PATH=caches[t][which] + "_probesim")  # fmt: skip
                    load = os.getloadavg()[0]
                    wall, cpu, err = _timed([sys.executable, "-m", "simulator", *command(t)], env, tmp)
                    where = "" if len(trees) == 1 else f" [{t}]"
                    print(f"{name:<23} {wall:6.1f} s wall, {cpu:6.1f} s CPU, load {load:4.1f}; "
                          f"{_compile_note(err)}{where}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
