"""``probesim study STUDY.toml``: run or resume a placement study and print its closing note."""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

from simulator.commands.progress import ProgressBar
from simulator.errors import UserError
from simulator.io.atomic import check_folder

__all__ = ["main_study", "ChunkProgress", "closing_note", "flag_overrides"]


class ChunkProgress(ProgressBar):
    """Chunks done and time left, one redrawn line on a terminal; silent otherwise."""

    def __init__(self, stream=None):
        super().__init__("chunks", stream)

    def __call__(self, done: int, total: int, elapsed_s: float) -> None:
        if not self.enabled:
            return
        if not hasattr(self, "_start"):
            self._start = done
        new = done - self._start
        left = (total - done) * elapsed_s / new if new > 0 else None
        eta = f", ~{left:.0f} s left" if left is not None and done < total else ""
        self.draw(done, total, f"{done}/{total}, {elapsed_s:.1f} s{eta}")


def _out_dir(study, path: Path, out: str | None) -> Path:
    if out:
        d = Path(out).expanduser().resolve()
    elif study.output.dir:
        d = (path.parent / study.output.dir).resolve()
    else:
        d = path.parent / f"{path.stem}.out"
    if d.exists() and not d.is_dir():
        raise UserError(f"{out or d}: not a folder")
    probe = d
    while not probe.exists():
        probe = probe.parent
    if not os.access(probe, os.W_OK):
        raise UserError(f"{out or d}: cannot write there")
    return d


def closing_note(res) -> list[str]:
    """The lines printed after a study: sizes, time, cost against a run, the chosen sensors."""
    t = res.timings_s
    ncand = len(res.candidates)
    lines = [
        f"{ncand} candidates ({', '.join(f'{s.name} {len(s.candidates)}' for s in res.sets)}), {len(res.scenarios)} scenarios "
        f"in {len(res.trace_groups)} trace group{'s' if len(res.trace_groups) != 1 else ''}, {res.chunks_total} chunks ({res.chunks_computed} computed, "
        f"{res.chunks_loaded} resumed; {res.sensor_block} sensors a chunk) {'in this process' if res.mode == 'inprocess' else f'on {res.mode} dask ({res.workers} workers)'}",
    ]
    per = t["trace_in_chunks"] / max(len(res.scenarios), 1)
    ref = res.reference
    cost = f"tracing {t['trace_in_chunks']:.2f} s, {per:.3f} s per scenario"
    if ref:
        tg0 = res.trace_groups[0]
        s0 = sum(v for k, v in res.chunk_trace_s.items() if k[0] == tg0.key)
        c0 = sum(v for k, v in res.chunk_trace_cpu_s.items() if k[0] == tg0.key)
        cpu = f", CPU time {c0 / ref['cpu_s']:.2f}x" if ref.get("cpu_s") else ""
        cost += (f" against {ref['wall_s']:.2f} s for a single run of {ref['scenario']!r} ({per / ref['wall_s']:.2f}x per scenario; "
                 f"its trace group's {len(tg0.scenarios)} scenarios {s0:.2f} s, {s0 / ref['wall_s']:.2f}x{cpu}); "
                 f"recombined vs that run: {ref['sensors_within_4_sigma']}/{ref['sensors']} sensors within 4 sigma")
    lines.append(f"wall time {t['total']:.1f} s (setup {t['setup']:.1f} s, chunks {t['chunks']:.1f} s); {cost}")
    pl = res.placement
    if pl is not None:
        from simulator.study.figures.scores import score_text

        st = lambda v, e: score_text(pl.objective, v, e)  # noqa: E731  (relative errors in percent)
        what = "mean correlation" if pl.objective == "correlation" else "relative error"
        lines.append(f"placement ({pl.objective}, target {', '.join(pl.zones)}; greedy with lazy evaluation, "
                     f"{pl.evaluations} evaluations for {pl.candidates} candidates; score ({what}) with no sensor "
                     f"{st(pl.baseline, 0.0).split(' ±')[0]}):")  # fmt: skip
        pos = {c.sensor.name: c.position for c in res.candidates}
        for s in pl.steps:
            sep = "" if s.separable else f"  (not separable from {s.runner_up}: lead {st(s.lead, s.lead_se)})"
            at = "({:.2f}, {:.2f}, {:.2f})".format(*pos[s.sensor])
            lines.append(f"  k={s.k}  {s.sensor:<16} at {at}  gain {st(s.gain, s.gain_se)}  score {st(s.score, s.score_se)}{sep}")
        lines.append("  zone -> sensor: " + ", ".join(f"{z} -> {sn}" for z, sn in pl.assignment.items()))
    tally: dict[tuple[str, str], list[int]] = {}
    for (z, _), chk in res.checks.items():
        for k, v in chk.items():
            t3 = tally.setdefault((z, k), [0, 0, 0])
            t3[("pass", "fail", "unsure").index(v)] += 1
    if tally:
        lines.append("compliance (pass/fail/unsure over scenarios): " + "; ".join(
            f"{z} {k} {p}/{f}/{u}" for (z, k), (p, f, u) in tally.items()))  # fmt: skip
    return lines


def compute_overrides(scheduler: str | None, workers: int | None, local: bool) -> tuple[str | None, int | None]:
    """``(mode, workers)`` the command line asks for (None: the study file's ``[compute]``).

    ``--scheduler`` sends the chunks to a running cluster; ``--local`` or
    ``--workers N`` start a LocalCluster here (N worker processes, default one
    per core); the two cannot be combined."""
    if scheduler is not None and "://" not in scheduler:
        raise UserError(f"--scheduler: expected an address such as tcp://host:8786, got {scheduler!r}")
    if workers is not None and workers < 1:
        raise UserError(f"--workers: expected a number of workers >= 1, got {workers}")
    if scheduler is not None and (local or workers is not None):
        raise UserError("--scheduler runs the chunks on that cluster: give --local/--workers or --scheduler, not both")
    if local or workers is not None:
        return "local", workers
    return None, None


def flag_overrides(samples: int | None = None, seed: int | None = None, rel_error: float | None = None) -> dict:
    """The study-file keys the command line sets, as :func:`simulator.study.schema.load_study` takes them.

    ``--samples`` and ``--rel-error`` are ``[simulation] samples`` and
    ``rel_error`` (so ``--rel-error`` makes the study adaptive, with
    ``samples`` as the first batch), ``--seed`` the study's top-level
    ``seed``. Chunk ids hash the settings and the seed, so a run with other
    flags never resumes another's chunks."""
    out = {}
    if samples is not None:
        out[("simulation", "samples")] = ("--samples", samples)
    if rel_error is not None:
        out[("simulation", "rel_error")] = ("--rel-error", rel_error)
    if seed is not None:
        out[("seed",)] = ("--seed", seed)
    return out


def main_study(path: str, out: str | None, scheduler: str | None, workers: int | None = None, local: bool = False,
               samples: int | None = None, seed: int | None = None, rel_error: float | None = None) -> int:
    from simulator.pipeline import _versions
    from simulator.study.annual.outputs import annual_note, write_annual_outputs
    from simulator.study.report.outputs import write_outputs
    from simulator.study.runner import run_study
    from simulator.study.schema import load_study

    mode, n_workers = compute_overrides(scheduler, workers, local)
    study, p = load_study(path, flag_overrides(samples, seed, rel_error))
    out_dir = _out_dir(study, p, out)
    check_folder(out_dir, "study folder")  # before any chunk is traced (nothing made: a later mistake writes nothing)
    bar = ChunkProgress()
    t0 = time.perf_counter()
    files = []
    if study.scenario:
        try:
            res = run_study(study, p, out_dir, scheduler=scheduler, on_chunk=bar, log=lambda m: print(m, file=sys.stderr), mode=mode,
                            workers=n_workers)  # fmt: skip
        except KeyboardInterrupt:
            bar.close()
            print(f"probesim: interrupted; finished chunks are kept in {out_dir}: run the same command again to resume", file=sys.stderr)
            return 130
        finally:
            bar.close()
        for w in res.warnings:
            print(f"warning: {w}", file=sys.stderr)
        res.timings_s["total"] = time.perf_counter() - t0
    # the year runs before any file is written, so that report.html holds the annual section too
    ares = _annual(study, p, out_dir, scheduler) if study.annual is not None else None
    if study.scenario:
        res.annual = ares
        files = write_outputs(res, _versions())
        for line in closing_note(res):
            print(line)
    if ares is not None:
        for line in annual_note(ares):
            print(line)
        files += write_annual_outputs(ares, study, out_dir, None if study.scenario else p)
    print(f"wrote {', '.join(f.name for f in files)} in {out_dir} ({time.perf_counter() - t0:.1f} s in all)")
    return 0


def _annual(study, p: Path, out_dir: Path, scheduler: str | None):
    """The study's ``[annual]`` part: run (or resume) it; its files are written by the caller."""
    from simulator.study.annual.year import run_annual

    try:
        return run_annual(study, p, out_dir, scheduler=scheduler, log=lambda m: print(m, file=sys.stderr))
    except KeyboardInterrupt:
        print(f"probesim: interrupted; finished chunks are kept in {out_dir}: run the same command again to resume", file=sys.stderr)
        raise SystemExit(130) from None
