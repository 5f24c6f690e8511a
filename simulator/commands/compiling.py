"""What a person sees while kernels compile: a first run's silent minute said aloud, on stderr.

:func:`simulator.engine.kernel_modules.load` reports each compile it starts
(:class:`~simulator.engine.kernel_modules.CompileProgress`); this display
writes one line naming the modules before the first one compiles, then on a
terminal a bar with the seconds elapsed, redrawn each second, elsewhere (a
log, CI) one line per module compiled. A run whose kernels are all cached
compiles nothing and shows nothing.
"""

from __future__ import annotations

import sys

from simulator.commands.progress import ProgressBar

__all__ = ["CompileDisplay", "header"]


def header(n_modules: int, device: str) -> str:
    """The line shown before a compile starts."""
    s = "" if n_modules == 1 else "s"
    return f"compiling kernels (first run only, cached afterwards): {n_modules} module{s} on {device}"


class CompileDisplay:
    """Callable fed :class:`~simulator.engine.kernel_modules.CompileProgress` reports.

    Parameters
    ----------
    stream : file, optional
        Where it writes (default ``sys.stderr``, read when called so a test's capture is honoured).
    """

    def __init__(self, stream=None):
        self._stream = stream
        self._bar: ProgressBar | None = None

    def __call__(self, p) -> None:
        out = self._stream or sys.stderr
        total = len(p.labels)
        if p.done == 0 and p.finished is None and self._bar is None:
            out.write(header(total, p.device) + ": " + ", ".join(p.labels) + "\n")
            out.flush()
            self._bar = ProgressBar("compiling", stream=out, min_interval_s=0.0)
        bar = self._bar
        if bar is None:
            return
        text = f"{p.done}/{total} modules, {p.elapsed_s:.0f} s"
        if bar.enabled:
            bar.draw(p.done, total, text)
        elif p.finished is not None:
            out.write(f"compiled {p.finished} ({p.done}/{total}, {p.elapsed_s:.1f} s)\n")
            out.flush()
        if p.done == total:
            bar.close()
            self._bar = None
