"""The glazed office against the open one, each read with its default estimator.

Reads the office's 1,464 work-plane and wall sensors (configs/office_bench.toml)
with the stage's ``window`` variant ``open`` (an open opening, all matte) beside
``pane`` (a pane of ior 1.52 in the opening) and ``glazed`` (the pane and a GGX floor
of roughness 0.4),
each with the plan's estimator (``auto``: both ``guided``), at a fixed budget
and seed. For each it prints the RMS relative standard error of the
illuminance over the sensors, the CPU seconds of the run (the guide's pilot
included; process CPU time, so other load on the machine does not count),
and two load-free figures of the cost of a given error:

- CPU seconds to 1% RMS: CPU s × (RMS relative stderr / 1%)² (the error
  falls as 1/√samples), and the same with the guide's pilot counted once
  (pilot CPU s + trace CPU s × (RMS / 1%)²: the pilot is a fixed cost,
  :data:`simulator.engine.guide.PILOT_SAMPLES` per sensor, whatever the
  target);
- relative variance × rays: mean over the sensors of stderr²·n/mean², times
  the rays traced per sample (a separate counted run).

and the ratio of each to the open window's. ``--path`` also reads the glazed office
with plain paths. ``--fixed-k K`` instead times each window's samples at one split K
(CPU µs per sample, relative variance per sample, rays tallied per sample), beside the
open window traced with the surface-model kernels; ``--perf DIR`` adds where the time
goes, per kernel function (Linux ``perf``), and ``--lines`` per source line (the kernels
compiled with line tables, in their own cache under DIR; the Python lines of probesim's
kernels and the lines of Warp's headers they inline, such as its BVH traversal), with
each glazed window's lines against the open window's. ``--queries`` times single ray queries
from the work plane toward the window and in cosine directions, open and pane.

    PYTHONPATH=. python benchmarks/glazed_office.py --samples 256 --seed 1
    PYTHONPATH=. python benchmarks/glazed_office.py --fixed-k 7 --samples 128 --perf out/perf
    PYTHONPATH=. python benchmarks/glazed_office.py --fixed-k 7 --samples 64 --windows pane --perf out/perf --lines
"""

from __future__ import annotations

import argparse
import dataclasses
import re
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def measure(window: str, samples: int, seed: int, method: str = "auto") -> dict:
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, config_engine, load_scene, run_plan
    from simulator.plan.planner import make_plan
    from simulator.scene.model import SensorKind

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    cfg = dataclasses.replace(cfg, variants={**cfg.variants, "window": window})
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE]
    plan = make_plan(scene, sensors, method)
    sim = dataclasses.replace(cfg.simulation, samples=samples, seed=seed, rel_error=None)
    config_engine(cfg, scene, sensors[:4]).run(plan.sensors[0].method, samples=32, seed=seed)  # compile, warm caches
    engine = config_engine(cfg, scene, sensors)
    t0 = time.process_time()
    if any(sp.method == "guided" for sp in plan.sensors):  # the pilot alone (the run then reuses its guide)
        engine.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
        engine.ensure_guide(seed, np.arange(len(sensors)), sim.max_depth)
    pilot_s = time.process_time() - t0
    res = run_plan(engine, plan, sim)
    cpu_s = time.process_time() - t0
    mean, se = res.mean[:, 1], res.stderr[:, 1]
    rel = se / mean
    rms = float(np.sqrt(np.mean(rel**2)))
    relvar = float(np.mean(rel**2 * res.samples))
    counted = config_engine(cfg, scene, sensors)
    n_count = max(32, samples // 8)
    methods = sorted({sp.method for sp in plan.sensors})
    rays = 0.0
    for m in methods:
        ids = np.array([i for i, sp in enumerate(plan.sensors) if sp.method == m])
        counted.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
        counted.run(m, samples=n_count, seed=seed + 7, sensor_ids=ids, count_rays=True)
        rays += counted.rays_traced
    rays_per_sample = rays / (n_count * len(sensors))
    return {"window": window, "methods": "+".join(methods), "rms": rms, "cpu_s": cpu_s,
            "cpu_to_1pct_s": cpu_s * (rms / 0.01) ** 2, "pilot_once_s": pilot_s + (cpu_s - pilot_s) * (rms / 0.01) ** 2,
            "relvar": relvar, "rays": rays_per_sample,
            "relvar_rays": relvar * rays_per_sample}  # fmt: skip


def per_sample(window: str, samples: int, k: int, perf_dir: Path | None = None, lines: bool = False) -> dict:
    """CPU µs per irradiance sample at a fixed split K (``guided``, its guide built first), the relative
    variance per sample and the rays tallied per sample. ``open+surfaces`` reads the open window with the
    kernels compiled with the surface model (docs/DESIGN.md §Trace variants), so that it and ``pane`` run
    the same machine code. With ``perf_dir``, ``perf record`` samples the timed run and the kernels'
    functions are named from their object files' symbol tables (``perf-PID.map``); with ``lines`` too,
    each sample in the trace module is put on its source line (:func:`_line_shares`)."""
    from simulator.config.loader import load_config
    from simulator.pipeline import collect_sensors, config_engine, load_scene
    from simulator.plan.planner import make_plan
    from simulator.scene.model import SensorKind

    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    cfg = dataclasses.replace(cfg, variants={**cfg.variants, "window": window.split("+")[0]})
    scene = load_scene(cfg)
    sensors = [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE]
    plan = make_plan(scene, sensors, "guided")
    engine = config_engine(cfg, scene, sensors)
    engine.split_indirect = k
    if window.endswith("+surfaces"):
        forced = property(lambda self: self._K.trace_for(1))  # this engine only
        engine.__class__ = type("SurfaceKernelsEngine", (type(engine),), {"trace_variant": forced})
    engine.set_light_mask(plan.light_mask([l.name for l in scene.lights]))
    engine.ensure_guide(1, np.arange(len(sensors)), -1)
    engine.run("guided", samples=16, seed=1)  # kernels loaded, pilots done
    rec = _perf_start(window, perf_dir) if perf_dir else None
    t0 = time.process_time()
    res = engine.run("guided", samples=samples, seed=2)
    cpu_s = time.process_time() - t0
    breakdown = _perf_stop(rec, cpu_s / (samples * len(sensors)) * 1e6, lines) if rec else None
    rel = res.stderr[:, 1] / res.mean[:, 1]
    engine.run("guided", samples=32, seed=9, count_rays=True)
    return {"window": window, "us": cpu_s / (samples * len(sensors)) * 1e6, "relvar": float(np.mean(rel**2 * res.samples)),
            "rays": engine.rays_traced / (32 * len(sensors)), "perf": breakdown}  # fmt: skip


def _perf_start(window: str, perf_dir: Path):
    """Write this process's perf map of the loaded CPU kernel modules and start ``perf record`` on it."""
    import gc
    import os
    import re
    import subprocess

    import warp as wp

    runtime = wp._src.context.runtime
    lines = []
    trace = None  # the trace module's object file and where it was loaded (for --lines)
    for o in gc.get_objects():
        if type(o).__name__ != "ModuleExec" or o.device.is_cuda or not o.binary_path:
            continue
        nm = subprocess.run(["nm", "-C", "-S", str(o.binary_path)], capture_output=True, text=True).stdout.splitlines()
        for name in list(o.kernel_hooks):
            addr = runtime.llvm.wp_lookup(o.handle.encode(), (name + "_cpu_forward").encode())
            entry = [ln for ln in nm if ln.endswith(name + "_cpu_forward")]
            if not addr or not entry:
                continue
            base = addr - int(entry[0].split()[0], 16)
            if (".trace_matte" if window == "open" else ".trace_surfaces") in Path(o.binary_path).name:  # the one it runs
                trace = (Path(o.binary_path), base)
            for ln in nm:
                m = re.match(r"([0-9a-f]+) ([0-9a-f]+) [tT] (\S+?)\(", ln)
                if m:
                    lines.append(f"{base + int(m.group(1), 16):x} {int(m.group(2), 16):x} {m.group(3)}")
            break
    # perf names code it cannot find in a file from this map, at the fixed place it reads (its JIT convention)
    Path(f"/tmp/perf-{os.getpid()}.map").write_text("\n".join(lines) + "\n")
    perf_dir.mkdir(parents=True, exist_ok=True)
    data = perf_dir / f"{window}.data"
    proc = subprocess.Popen(["perf", "record", "-F", "999", "-o", str(data), "-p", str(os.getpid())],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)  # fmt: skip
    time.sleep(1.0)
    return proc, data, trace


def _perf_stop(rec, us_per_sample: float, lines: bool = False) -> list[tuple[str, float]] | dict[str, float]:
    """Stop ``perf record``; the functions' shares of the timed run as µs per sample (largest first), or
    with ``lines`` every source line's (:func:`_line_shares`)."""
    import signal
    import subprocess

    proc, data, trace = rec
    proc.send_signal(signal.SIGINT)
    proc.wait()
    if lines:
        return _line_shares(data, trace, us_per_sample)
    out = subprocess.run(["perf", "report", "-i", str(data), "--no-children", "--sort", "symbol", "--stdio"],
                         capture_output=True, text=True).stdout  # fmt: skip
    rows = []
    for ln in out.splitlines():
        m = re.match(r"\s+([0-9.]+)%\s+\[[.k]\]\s+(\S+)", ln) if not ln.startswith("#") else None
        if m:
            rows.append((m.group(2)[:48], float(m.group(1)) / 100.0 * us_per_sample))
    return rows[:8]


def _line_tables(perf_dir: Path) -> None:
    """Have the kernels compiled with line tables, in a Warp cache of their own under ``perf_dir``: Warp's
    C++ then carries ``#line`` directives to the Python source (``lineinfo``) and clang keeps them
    (its front end's ``-debug-info-kind=line-tables-only``); the code is otherwise the same."""
    import warp as wp

    import simulator.engine.device as device

    wp.config.lineinfo = True
    wp.config.kernel_cache_dir = str(perf_dir / "kernels")
    flags = device.cpu_compiler_flags
    device.cpu_compiler_flags = lambda default: f"{flags(default) or ''} -debug-info-kind=line-tables-only -dwarf-version=4"


def _line_shares(data: Path, trace, us_per_sample: float) -> dict[str, float]:
    """µs per sample on each source line of the trace module (``file:line``; ``?`` where the line tables
    name none), from ``perf script``'s sampled addresses put back in its object file (``addr2line``)."""
    import collections
    import subprocess

    ips = collections.Counter(subprocess.run(["perf", "script", "-i", str(data), "-F", "ip"], capture_output=True,
                                             text=True).stdout.split())  # fmt: skip
    total = sum(ips.values())
    obj, base = trace
    here = collections.Counter()
    for ip, n in ips.items():
        off = int(ip, 16) - base
        if 0 <= off < obj.stat().st_size:
            here[off] += n
    offs = sorted(here)
    where = subprocess.run(["addr2line", "-e", str(obj), *map(hex, offs)], capture_output=True, text=True).stdout.split("\n")
    out = collections.Counter()
    for off, w in zip(offs, where):
        w = w.split(" (")[0]
        w = re.sub(r"^.*/(simulator/kernels|warp/native)/", r"\1/", w)
        out[w] += here[off] / total * us_per_sample
    out["(outside the trace module)"] = (total - sum(here.values())) / total * us_per_sample
    return dict(out)


def _print_lines(rows: list[dict], top: int = 12) -> None:
    """Each window's busiest source lines, then each glazed window's lines against the open window's with the
    same kernels (``open+surfaces``), by file and by line, largest differences first."""
    for r in rows:
        print(f"{r['window']}: the busiest lines, µs per sample")
        for w, us in sorted(r["perf"].items(), key=lambda t: -t[1])[:top]:
            print(f"    {us:6.2f}  {w}")
    ref = next(r["perf"] for r in rows if r["window"] == "open+surfaces")
    for r in rows:
        if r["window"] in ("open", "open+surfaces"):
            continue
        for by, key in (("file", lambda w: w.rsplit(":", 1)[0]), ("line", lambda w: w)):
            diff: dict[str, list[float]] = {}
            for side, shares in enumerate((ref, r["perf"])):
                for w, us in shares.items():
                    diff.setdefault(key(w), [0.0, 0.0])[side] += us
            print(f"{r['window']} against open+surfaces, by {by}: µs per sample (open+surfaces, {r['window']}, difference)")
            for w, (a, b) in sorted(diff.items(), key=lambda t: -abs(t[1][1] - t[1][0]))[:top]:
                print(f"    {a:6.2f} {b:6.2f} {b - a:+6.2f}  {w}")


def query_costs(window: str, n: int = 400_000) -> list[tuple[str, float, float]]:
    """CPU ns per ray query (``first_hit`` and the BVH query alone, least of 5 launches, one worker) of
    n rays to infinity from the work plane (z 0.8 m): toward points uniform in the window opening, and
    in cosine directions; with the share of them that meet a face."""
    from simulator.config.loader import load_config
    from simulator.engine.ray_profile import cast, time_queries
    from simulator.pipeline import collect_sensors, config_engine, load_scene
    from simulator.scene.model import SensorKind

    rng = np.random.default_rng(1)
    o = np.c_[rng.uniform(0.5, 5.5, n), rng.uniform(0.5, 3.5, n), np.full(n, 0.8)]
    to_window = np.c_[np.zeros(n), rng.uniform(0.6, 3.4, n), rng.uniform(0.9, 2.3, n)] - o
    to_window /= np.linalg.norm(to_window, axis=1)[:, None]
    u1, u2 = rng.random(n), rng.random(n)
    cosine = np.c_[np.sqrt(u1) * np.cos(2 * np.pi * u2), np.sqrt(u1) * np.sin(2 * np.pi * u2), np.sqrt(1 - u1)]
    cfg = load_config(ROOT / "configs" / "office_bench.toml")
    cfg = dataclasses.replace(cfg, variants={**cfg.variants, "window": window})
    scene = load_scene(cfg)
    engine = config_engine(cfg, scene, [s for s in collect_sensors(cfg, scene) if s.kind != SensorKind.PROBE][:4])
    out = []
    for name, d in (("toward the window", to_window), ("cosine", cosine)):
        t = np.full(n, 1e30)
        first_hit_s, bvh_s = time_queries(engine, o, d, t, repeats=5)
        out.append((name, first_hit_s / n * 1e9, float(np.mean(cast(engine, o, d, t).face >= 0))))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=256)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--path", action="store_true", help="also read the glazed office with plain paths")
    ap.add_argument("--windows", nargs="+", default=["pane", "glazed"], choices=["pane", "glazed"],
                    help="the variants read beside the open window (default: both)")  # fmt: skip
    ap.add_argument("--fixed-k", type=int, metavar="K",
                    help="instead: CPU µs per sample at split K, the open window also with the surface-model kernels")
    ap.add_argument("--perf", type=Path, metavar="DIR", help="with --fixed-k: perf record each timed run into DIR "
                    "and print where its time goes (needs Linux perf)")  # fmt: skip
    ap.add_argument("--lines", action="store_true", help="with --perf: per source line instead of per function (the "
                    "kernels compiled with line tables in DIR/kernels; needs addr2line)")  # fmt: skip
    ap.add_argument("--queries", action="store_true", help="instead: CPU ns per ray query, open and pane windows")
    a = ap.parse_args()
    if a.lines:
        if not (a.perf and a.fixed_k):
            ap.error("--lines needs --fixed-k and --perf")
        _line_tables(a.perf)
    if a.queries:
        for w in ("open", "pane"):
            for name, ns, hit in query_costs(w):
                print(f"{w:<6} rays {name:<18} {ns:6.1f} CPU ns per query, {hit:.1%} meet a face")
        return
    if a.fixed_k:
        rows = [per_sample(w, a.samples, a.fixed_k, a.perf, a.lines) for w in ["open", "open+surfaces", *a.windows]]
        print(f"split K = {a.fixed_k}, {a.samples} samples per sensor, 1,464 sensors, guided")
        for r in rows:
            print(f"{r['window']:<14} {r['us']:6.1f} CPU µs per sample, relative variance {r['relvar']:.4f}, "
                  f"{r['rays']:.2f} rays tallied per sample, relvar × µs {r['relvar'] * r['us']:.2f}")  # fmt: skip
            for name, us in [] if a.lines else r["perf"] or []:
                print(f"    {us:6.2f} µs  {name}")
        if a.lines:
            _print_lines(rows)
        return
    rows = [measure(w, a.samples, a.seed) for w in ["open", *a.windows]]
    if a.path:
        rows.append(measure("glazed", a.samples, a.seed, "path"))
    print(f"{'window':<8} {'method':<8} {'RMS se':>8} {'CPU s':>8} {'CPU s to 1%':>12} {'pilot once':>11} {'relvar':>8} "
          f"{'rays':>7} {'relvar×rays':>12}")  # fmt: skip
    for r in rows:
        print(f"{r['window']:<8} {r['methods']:<8} {r['rms']:>8.2%} {r['cpu_s']:>8.2f} {r['cpu_to_1pct_s']:>12.1f} "
              f"{r['pilot_once_s']:>11.1f} {r['relvar']:>8.3f} {r['rays']:>7.2f} {r['relvar_rays']:>12.3f}")  # fmt: skip
    o = rows[0]
    for g in rows[1 : 1 + len(a.windows)]:
        print(f"{g['window']} / open ({a.samples} samples, seed {a.seed}): {g['cpu_to_1pct_s'] / o['cpu_to_1pct_s']:.2f}x CPU "
              f"seconds to 1% RMS ({g['pilot_once_s'] / o['pilot_once_s']:.2f}x with the pilot once), "
              f"{g['relvar_rays'] / o['relvar_rays']:.2f}x relative variance x rays, "
              f"{g['cpu_s'] / o['cpu_s']:.2f}x CPU seconds per run")  # fmt: skip


if __name__ == "__main__":
    main()
