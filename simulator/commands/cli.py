"""Command line: ``probesim run CONFIG.toml`` and friends.

A user mistake is one line on stderr and exit status 2; nothing is written.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time

from simulator import __version__
from simulator.commands.startup import end_lean, lean_start, resume_collections
from simulator.engine.methods import METHODS
from simulator.errors import UserError

__all__ = ["main"]


def _stage_flags(parser: argparse.ArgumentParser) -> None:
    """The flags that change what is read from the stage (``run`` and ``plan`` read it alike)."""
    parser.add_argument("--variant", action="append", metavar="SET=VARIANT",
                        help="select a USD variant before reading, on every prim with the set, or on one prim as "
                             "/PRIM/PATH:SET=VARIANT (repeatable; overrides the config's variants)")
    parser.add_argument("--time", type=float, metavar="T",
                        help="USD time code to read the stage at (overrides the config's time; default: its earliest sample)")


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="probesim", description="Radiometric light-probe sensor simulator.")
    p.add_argument("--version", action="version", version=f"probesim {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    r = sub.add_parser("run", help="trace a config's stage and write one CSV row per sensor")
    r.add_argument("config", help="run config (.toml)")
    r.add_argument("-o", "--output", metavar="OUT.csv", help="CSV path (default: the config's [output] csv)")
    r.add_argument("--seed", type=int, help="random seed (overrides [simulation] seed)")
    r.add_argument("--samples", type=int, help="samples per sensor (overrides [simulation] samples)")
    r.add_argument("--method", help=f"estimator: {', '.join(METHODS[:-1])} or {METHODS[-1]}")
    r.add_argument("--rel-error", type=float, metavar="R", help="adaptive: stop each sensor when its confidence half-width is under R × its reading")
    _stage_flags(r)
    r.add_argument("--confidence", type=float, metavar="C", help="confidence of that interval (default 0.95; 0.999 for a guarantee over many sensors)")
    r.add_argument("--device", choices=("cpu", "cuda", "auto"), help="Warp device (auto: CUDA when present)")
    r.add_argument("--csv-columns", choices=("kinds", "full"),
                   help="CSV columns: those of the run's sensor kinds (kinds, the default) or all 32 (full); "
                        "overrides [output] csv_columns")
    r.add_argument("-q", "--quiet", action="store_true", help="print no table")

    pl = sub.add_parser("plan", help="print how each sensor of a config would be read, and why")
    pl.add_argument("config", help="run config (.toml)")
    pl.add_argument("--method", help="an explicit method instead of the config's")
    _stage_flags(pl)

    b = sub.add_parser("bench", help="speed of every estimator on the bundled stages")
    b.add_argument("configs", nargs="*", help="configs to benchmark (default: the bundled ones)")
    b.add_argument("--device", choices=("cpu", "cuda", "auto"), default="cpu")
    b.add_argument("--samples", type=int, default=4096, help="fixed budget per sensor for samples/s (default 4096)")
    b.add_argument("--reference-seconds", type=float, default=60.0, metavar="S",
                   help="configs with a stored reference: double the budget until one run takes S/2 seconds (default 60)")

    c = sub.add_parser("compare", help="error of map A against reference map B (EXR): RMS, largest error, PSNR/SSIM")
    c.add_argument("a", metavar="A.exr", help="map to judge")
    c.add_argument("b", metavar="B.exr", help="reference map")
    c.add_argument("--channel", help="channel to compare (default: grey of R, G, B, else the first common channel)")

    v = sub.add_parser("verify", help="run the reference suite: every bundled closed-form case against its expected value")
    v.add_argument("--csv", metavar="OUT.csv", help="also write the table as CSV")
    v.add_argument("--quick", action="store_true", help="looser error target and one reflectance per enclosure")
    v.add_argument("-k", metavar="TEXT", help="only the cases whose name contains TEXT")
    v.add_argument("--device", choices=("cpu", "cuda", "auto"), default="cpu", help="Warp device (default cpu)")

    ch = sub.add_parser("chart", help="error against time for every estimator on configs (log-log PNGs, CSV, summary)")
    ch.add_argument("configs", nargs="*", metavar="CONFIG", help="configs to chart (default: the bundled reference stages)")
    ch.add_argument("--out", default="out/chart", metavar="DIR", help="CSV, PNGs and cached references (default out/chart)")
    ch.add_argument("--seeds", type=int, default=4, help="independent seeds per budget (default 4)")
    ch.add_argument("--max-seconds", type=float, default=0.5, metavar="S",
                    help="stop a method's ladder once one run takes S seconds (default 0.5)")
    ch.add_argument("--device", choices=("cpu", "cuda", "auto"), default="cpu", help="Warp device (default cpu)")
    ch.add_argument("--methods", metavar="M,M", help="comma-separated curves to draw (default: every method and auto)")
    ch.add_argument("--no-adaptive", action="store_true",
                    help="skip the planner check (adaptive runs of every method to 1%%; slow on big grids)")

    st = sub.add_parser("stability", help="map where each estimator fails: methods x hard cases (CSV, heat map)")
    st.add_argument("--out", default="out/stability", metavar="DIR", help="CSVs and heat map (default out/stability)")
    st.add_argument("--quick", action="store_true", help="0.25 s per cell instead of 1 s")
    st.add_argument("--seconds", type=float, metavar="S", help="budget per cell in seconds (overrides --quick)")
    st.add_argument("--device", choices=("cpu", "cuda", "auto"), default="cpu", help="Warp device (default cpu)")

    ex = sub.add_parser("example", help="copy a bundled config and its stage into a folder, ready to run and edit")
    ex.add_argument("name", nargs="?", metavar="NAME", help="bundled example (see --list)")
    ex.add_argument("dir", nargs="?", metavar="DIR", help="folder to copy it into (created if missing)")
    ex.add_argument("--list", action="store_true", help="list the bundled examples")
    w = sub.add_parser("warmup", help="compile every kernel now (first run only; runs then load them from the cache)")
    w.add_argument("--device", choices=("cpu", "cuda", "auto"),
                   help="compile for this device only (default: the CPU, and CUDA when there is a device)")
    sn = sub.add_parser("sensor", help="a sensor model's quality indices (f1′, f2, DIN 5032-7 class, mismatch factor) "
                        "and electronics; --list: the bundled models")
    sn.add_argument("model", nargs="?", metavar="MODEL", help="a bundled model's name or a model .toml file")
    sn.add_argument("--list", action="store_true", help="list the bundled models")
    sd = sub.add_parser("study", help="placement study: candidates x scenarios, zone figures, the best K sensors (resumable, dask)")
    sd.add_argument("study", metavar="STUDY.toml", help="study file (.toml)")
    sd.add_argument("-o", "--out", metavar="DIR", help="output and chunk folder (default: the study's [output] dir)")
    sd.add_argument("--samples", type=int, help="samples per sensor (overrides [simulation] samples)")
    sd.add_argument("--seed", type=int, help="study seed, from which every chunk's derives (overrides seed)")
    sd.add_argument("--rel-error", type=float, metavar="R",
                    help="adaptive: stop each sensor when its confidence half-width is under R × its reading "
                         "(overrides [simulation] rel_error)")
    sd.add_argument("--scheduler", metavar="ADDRESS",
                    help="dask scheduler, e.g. tcp://host:8786 or tls://host:8786 (TLS from dask's distributed.comm.tls settings)")
    sd.add_argument("--local", action="store_true", help="run the chunks on a dask LocalCluster on this machine")
    sd.add_argument("--workers", type=int, metavar="N", help="LocalCluster worker processes (implies --local; default one per core)")
    return p


def _cmd_example(args) -> int:
    from simulator.commands.example import main_example

    return main_example(args.name, args.dir, args.list)


def _cmd_chart(args) -> int:
    from simulator.commands.chart import main_chart

    methods = None
    if args.methods:
        from simulator.commands.chart import METHODS

        methods = [m.strip() for m in args.methods.split(",") if m.strip()]
        unknown = [m for m in methods if m not in METHODS]
        if unknown:
            raise UserError(f"--methods: unknown method {unknown[0]!r} (expected some of {', '.join(METHODS)})")
    return main_chart(args.configs, args.out, args.seeds, args.max_seconds, args.device,
                      log=lambda m: print(m, flush=True), methods=methods, adaptive=not args.no_adaptive)  # fmt: skip


def _cmd_stability(args) -> int:
    from pathlib import Path

    from simulator.commands.stability import main_stability

    if args.seconds is not None and not (args.seconds > 0 and math.isfinite(args.seconds)):
        raise UserError(f"--seconds: must be a positive number of seconds, got {args.seconds}")
    return main_stability(Path(args.out), quick=args.quick, device=args.device, seconds=args.seconds,
                          log=lambda m: print(m, flush=True))  # fmt: skip


def _cmd_verify(args) -> int:
    from simulator.commands.verify import CASES, format_header, format_row, format_summary, run_suite, write_csv

    cases = tuple(c for c in CASES if args.k is None or args.k in c.name)
    if not cases:
        raise UserError(f"-k: no case name contains {args.k!r}")
    print(format_header(), flush=True)
    result = run_suite(
        quick=args.quick, device=args.device, cases=cases,
        on_row=lambda r: print(format_row(r), flush=True), on_skip=lambda m: print(m, flush=True),
    )  # fmt: skip
    print(format_summary(result))
    if args.csv:
        write_csv(args.csv, result.rows)
        print(f"wrote {args.csv}")
    return 0 if result.passed else 1


def _cmd_compare(args) -> int:
    from simulator.commands.compare import compare_files, format_comparison

    print(format_comparison(compare_files(args.a, args.b, channel=args.channel)))
    return 0


def _cmd_plan(args) -> int:
    from simulator.config.loader import apply_overrides, load_config
    from simulator.plan.planner import format_plan, make_plan
    from simulator.pipeline import collect_sensors, load_scene

    cfg = apply_overrides(load_config(args.config), method=args.method, variants=args.variant, time=args.time)
    scene = load_scene(cfg)
    for w in scene.warnings:
        print(f"warning: {w}", file=sys.stderr)
    sensors = [s for s in collect_sensors(cfg, scene) if s.spec.reader == "estimate"]
    plan = make_plan(scene, sensors, cfg.simulation.method, cfg.simulation.component)
    from simulator.sensor_models.readings import optics_twins

    twins = optics_twins(sensors)
    if twins:  # modelled sensors are read again through their optics
        from simulator.plan.planner import with_optics

        plan = with_optics(plan, scene, twins)
    print(format_plan(plan, max_rows=10**6))
    return 0


def _cmd_bench(args) -> int:
    from pathlib import Path

    from simulator.commands.bench import default_configs, format_bench, run_bench

    from simulator.config.overrides import check_flags

    configs = [Path(c) for c in args.configs] or default_configs()
    check_flags(samples=args.samples)  # the rule of [simulation] samples, as `probesim run --samples` obeys it
    for c in configs:
        if not c.is_file():
            raise UserError(f"{c}: config file not found")
    print(format_bench([], header=True))
    if not args.reference_seconds > 0:
        raise UserError(f"--reference-seconds: must be > 0, got {args.reference_seconds}")
    rows, info = run_bench(configs, device=args.device, samples=args.samples, reference_seconds=args.reference_seconds)
    print(f"device {info['device']} ({info['processor']}, {info['threads']} threads); "
          "time to 1%: every sensor's 95% half-width under 1% of its reading (* = cap reached first)")
    sc = info.get("scaling")
    if sc:
        print(
            f"CPU scaling, quickstart path tracing: 1 thread {sc['one_thread_samples_per_s']:,.0f} samples/s, "
            f"{sc['threads']} threads {sc['all_threads_samples_per_s']:,.0f} samples/s: {sc['speedup']:.2f}x"
        )
    return 0


def _cmd_run(args) -> int:
    from simulator.config.loader import apply_overrides, load_config
    from simulator.commands.progress import ProgressBar
    from simulator.io.glare_maps import glare_lines
    from simulator.io.results import format_table
    from simulator.pipeline import run

    cfg = load_config(args.config)
    cfg = apply_overrides(
        cfg, seed=args.seed, samples=args.samples, device=args.device, csv=args.output, method=args.method, rel_error=args.rel_error,
        confidence=args.confidence, variants=args.variant, time=args.time,
    )
    if args.csv_columns is not None:
        from dataclasses import replace

        cfg = replace(cfg, output=replace(cfg.output, csv_columns=args.csv_columns),
                      overrides={**cfg.overrides, "csv_columns": args.csv_columns})
    t0 = time.perf_counter()
    bar = ProgressBar("tracing")
    note = (lambda m: print(m, file=sys.stderr))

    def progress(p) -> None:
        resume_collections()  # tracing has begun: every module it needs is loaded
        bar(p)

    try:
        out = run(cfg, progress=progress, log=note)
    finally:
        bar.close()
    wall = time.perf_counter() - t0
    rec = out.record
    if out.interrupted:
        print(f"interrupted: wrote partial results for {rec['sensors_read']} of {rec['sensors']} sensors to {out.csv_path} "
              f"({rec['sensors_finished']} finished)", file=sys.stderr)  # fmt: skip
        return 130
    if not args.quiet:
        print(format_table(out.rows, photometric_first=cfg.light_units == "photometric"))
        from simulator.commands.sensor import format_readings

        for line in format_readings(out.rows) + glare_lines(out.rows):
            print(line)
    n = rec["sensors"]
    total = rec["samples_total"]
    trace = rec["timings_s"]["trace"]
    used = ", ".join(f"{m} ×{k}" for m, k in rec["method"]["used"].items())
    if rec["method"].get("probes"):
        used = ", ".join(x for x in (used, f"probes and glare views by {rec['method']['probes']}") if x)
    t = rec["timings_s"]
    print(
        f"{n} sensors, {rec['triangles']:,} triangles, {total:,} samples, methods {used} on {rec['device']} "
        f"({rec['threads']} threads): loaded in {t['load']:.2f} s, planned in {t['plan']:.2f} s, "
        + (f"guide learnt in {t['guide']:.2f} s ({'used' if rec['guide']['sampled'] else 'not used'}), " if rec.get("guide") else "")
        + f"traced in {trace:.2f} s ({total / max(trace, 1e-9):,.0f} samples/s), {wall:.2f} s in all"
    )
    if rec.get("emitter_pieces"):
        ep = rec["emitter_pieces"]
        tab = ep.get("table")
        print(f"emissive geometry: {ep['pieces']} pieces {'kept' if ep['kept'] else 'set aside'}: {ep['why']}"
              + (f"; picked by the table of {tab['cells']} cells of {tab['cell_m']:g} m ({tab['seconds']:.2f} s)"
                 if tab else ""))
    if rec.get("guide_skipped"):
        print(rec["guide_skipped"])
    ad = rec.get("adaptive")
    if ad:
        print(
            f"{ad['sensors_met']}/{n} sensors reached a {100 * ad['confidence']:g}% confidence half-width "
            f"of {100 * ad['rel_error']:g}% of their reading"
        )
    print(f"wrote {out.csv_path} and {out.record_path.name}")
    if rec.get("maps"):
        print(f"maps: {', '.join(rec['maps'])}")
    return 0


#: the commands that may compile kernels: they say so on stderr while they do (simulator.commands.compiling)
TRACING = ("run", "bench", "verify", "chart", "stability", "study", "warmup")


def _say_compiles() -> None:
    """Report every kernel compile of this process on stderr."""
    from simulator.commands.compiling import CompileDisplay
    from simulator.engine.kernel_modules import report_compiles_to

    report_compiles_to(CompileDisplay())


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    # a short command given on the process's own command line (argv None): start it lean, and end it so
    lean = argv is None and args.command in ("run", "plan") and lean_start()
    code = _command(args, lean)
    if lean:
        end_lean(code)  # returns only where the process must end the usual way
    return code


def _command(args, lean: bool) -> int:
    """Run the parsed command; its exit status."""
    try:
        if args.command in TRACING:
            _say_compiles()
        if lean and args.command == "run":  # a fresh process imports each kernel module once: no re-import to scan for
            from simulator.engine.device import skip_reload_scan

            skip_reload_scan()
        if args.command == "warmup":
            from simulator.commands.warmup import main_warmup

            return main_warmup(args.device)
        if args.command == "run":
            return _cmd_run(args)
        if args.command == "compare":
            return _cmd_compare(args)
        if args.command == "plan":
            return _cmd_plan(args)
        if args.command == "bench":
            return _cmd_bench(args)
        if args.command == "verify":
            return _cmd_verify(args)
        if args.command == "chart":
            return _cmd_chart(args)
        if args.command == "stability":
            return _cmd_stability(args)
        if args.command == "example":
            return _cmd_example(args)
        if args.command == "sensor":
            from simulator.commands.sensor import main_sensor

            return main_sensor(args.model, args.list)
        if args.command == "study":
            from simulator.commands.study import main_study

            return main_study(args.study, args.out, args.scheduler, workers=args.workers, local=args.local,
                              samples=args.samples, seed=args.seed, rel_error=args.rel_error)
    except UserError as e:
        print(f"probesim: error: {e}", file=sys.stderr)
        return e.exit_code
    except KeyboardInterrupt:
        print("probesim: interrupted; nothing written", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader of our output went away (`probesim verify | head`): stop
        # quietly, and keep Python from complaining while flushing stdout at exit
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    finally:
        if lean:
            resume_collections()
    return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
