"""Clang's time on the trace modules, and the trace's CPU time, at LLVM inlining thresholds.

``python benchmarks/compile_flags.py [--thresholds 9000:3000 3000:1000] [--rounds 3]`` (from a
checkout). Each threshold pair (call site : cold call site, ``simulator.engine.device.INLINE_THRESHOLDS``;
9000:3000 is Warp's own) gets a kernel cache of its own in a temporary folder. First, in a child
process per pair, the two trace modules are compiled into it one after the other
(``kernel_modules.load``), and the process CPU seconds of each load (Warp's code generation and
clang, on one core) and the size of its object file are printed. Then, round by round, each bundled
case (the quickstart, the furnace, the office at 128 samples and the glazed office at 64) runs once
per pair in a fresh process, the pairs alternated within the round; the CPU seconds of
``simulator.run`` (all threads: less disturbed than wall time by other load on a shared machine)
and its trace seconds are printed per run, then the median CPU seconds per case and pair.
Readings do not depend on the thresholds (the same bytes); only time does.
"""

from __future__ import annotations

import argparse
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:  # run from a checkout: the package sits beside this folder
    sys.path.insert(0, str(ROOT))

#: (label, config, extra command-line overrides)
CASES = (
    ("quickstart", "configs/quickstart.toml", {}),
    ("furnace", "configs/furnace.toml", {}),
    ("office 128", "configs/office_bench.toml", {"samples": 128}),
    ("glazed office 64", "configs/office_bench.toml", {"samples": 64, "variants": ["window=glazed"]}),
)


def _set_thresholds(pair: str) -> None:
    from simulator.engine import device

    site, cold = (int(x) for x in pair.split(":"))
    device.INLINE_THRESHOLDS = (site, cold)


def _child_compile(pair: str) -> dict:
    """CPU seconds and object bytes of loading each trace module into the (empty) kernel cache."""
    _set_thresholds(pair)
    from simulator.engine import kernel_modules as KM
    from simulator.engine.device import warp

    wp = warp()
    out = {"flags": wp.config.cpu_compiler_flags}
    for surfaces in (False, True):
        km = KM.trace_module(surfaces)
        c0 = time.process_time()
        KM.load([km], "cpu")
        cpu = time.process_time() - c0
        objs = glob.glob(os.path.join(wp.config.kernel_cache_dir, "*", f"*{km.module.name}*.o"))
        out[km.label] = {"cpu_s": cpu, "object_bytes": sum(os.path.getsize(f) for f in objs)}
    return out


def _child_run(pair: str, case: int) -> dict:
    """CPU and trace seconds of one run of ``CASES[case]`` (its modules already in the cache)."""
    _set_thresholds(pair)
    import simulator
    from simulator.config.overrides import apply_overrides

    label, config, overrides = CASES[case]
    cfg = apply_overrides(simulator.load_config(ROOT / config), **overrides)
    c0, w0 = time.process_time(), time.perf_counter()
    res = simulator.run(cfg, log=lambda *a: None, write=False)
    return {"cpu_s": time.process_time() - c0, "wall_s": time.perf_counter() - w0,
            "trace_s": res.record["timings_s"]["trace"]}


def _spawn(args: list[str], cache: str) -> dict:
    env = dict(os.environ, WARP_CACHE_PATH=cache, PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, __file__, *args], env=env, capture_output=True, text=True, check=True)
    return json.loads(p.stdout.strip().splitlines()[-1])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--thresholds", nargs="+", default=["9000:3000", "5000:1700"], metavar="SITE:COLD")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--cases", nargs="+", choices=[c[0].split()[0] for c in CASES], help="only these cases (first word)")
    ap.add_argument("--no-compile", action="store_true", help="leave out the compile step (an untimed run fills the caches)")
    ap.add_argument("--child-compile", metavar="SITE:COLD", help=argparse.SUPPRESS)
    ap.add_argument("--child-run", nargs=2, metavar=("SITE:COLD", "CASE"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child_compile:
        print(json.dumps(_child_compile(args.child_compile)))
        return 0
    if args.child_run:
        print(json.dumps(_child_run(args.child_run[0], int(args.child_run[1]))))
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        caches = {t: os.path.join(tmp, t.replace(":", "_")) for t in args.thresholds}
        cases = [i for i, c in enumerate(CASES) if args.cases is None or c[0].split()[0] in args.cases]
        for t in [] if args.no_compile else args.thresholds:
            load = os.getloadavg()[0]
            got = _spawn(["--child-compile", t], caches[t])
            print(f"inlining {t} ({got.pop('flags')}), load {load:.1f}:")
            for label, v in got.items():
                print(f"  compile {label}: {v['cpu_s']:.2f} s CPU, object {v['object_bytes'] / 1e3:.0f} kB")
        if args.no_compile:  # each case once first, untimed: its modules compiled into each cache
            for i in cases:
                for t in args.thresholds:
                    _spawn(["--child-run", t, str(i)], caches[t])
        cpu: dict[tuple[str, str], list[float]] = {}
        for r in range(args.rounds):
            for i in cases:
                label = CASES[i][0]
                for t in args.thresholds:
                    load = os.getloadavg()[0]
                    got = _spawn(["--child-run", t, str(i)], caches[t])
                    cpu.setdefault((label, t), []).append(got["cpu_s"])
                    print(f"round {r + 1} {label:<17} inlining {t:<10} {got['cpu_s']:6.2f} s CPU, trace "
                          f"{got['trace_s']:6.2f} s, load {load:.1f}")
        print("median CPU seconds of a run:")
        for label in (CASES[i][0] for i in cases):
            cells = [f"{t}: {statistics.median(cpu[(label, t)]):.2f}" for t in args.thresholds]
            print(f"  {label:<17} " + ", ".join(cells))
    return 0


if __name__ == "__main__":
    sys.exit(main())
