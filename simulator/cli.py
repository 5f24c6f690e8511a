"""Command line: ``probesim run CONFIG.toml`` and friends.

A user mistake is one line on stderr and exit status 2; nothing is written.
"""

from __future__ import annotations

import argparse
import sys
import time

from . import __version__
from .errors import UserError

__all__ = ["main"]


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="probesim", description="Radiometric light-probe sensor simulator.")
    p.add_argument("--version", action="version", version=f"probesim {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    r = sub.add_parser("run", help="trace a config's stage and write one CSV row per sensor")
    r.add_argument("config", help="run config (.toml)")
    r.add_argument("-o", "--output", metavar="OUT.csv", help="CSV path (default: the config's [output] csv)")
    r.add_argument("--seed", type=int, help="random seed (overrides [simulation] seed)")
    r.add_argument("--samples", type=int, help="samples per sensor (overrides [simulation] samples)")
    r.add_argument("--method", help="estimator: auto, light, bsdf, mis or path")
    r.add_argument("--device", choices=("cpu", "cuda", "auto"), help="Warp device (auto: CUDA when present)")
    r.add_argument("-q", "--quiet", action="store_true", help="print no table")
    return p


def _cmd_run(args) -> int:
    from .config import apply_overrides, load_config
    from .progress import ProgressBar
    from .results import format_table
    from .run import run

    cfg = load_config(args.config)
    cfg = apply_overrides(cfg, seed=args.seed, samples=args.samples, device=args.device, csv=args.output, method=args.method)
    t0 = time.perf_counter()
    bar = ProgressBar("tracing")
    note = (lambda m: print(m, file=sys.stderr))
    try:
        out = run(cfg, progress=bar, log=note)
    finally:
        bar.close()
    wall = time.perf_counter() - t0
    rec = out.record
    if not args.quiet:
        print(format_table(out.rows))
    n = rec["sensors"]
    total = rec["samples_total"]
    trace = rec["timings_s"]["trace"]
    print(
        f"{n} sensors, {total:,} samples, method {rec['method']['used']} on {rec['device']} "
        f"({rec['threads']} threads): traced in {trace:.2f} s ({total / max(trace, 1e-9):,.0f} samples/s), "
        f"{wall:.2f} s in all"
    )
    print(f"wrote {out.csv_path} and {out.record_path.name}")
    return 0


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        if args.command == "run":
            return _cmd_run(args)
    except UserError as e:
        print(f"probesim: error: {e}", file=sys.stderr)
        return e.exit_code
    except KeyboardInterrupt:
        print("probesim: interrupted; nothing written", file=sys.stderr)
        return 130
    return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
