"""A one-line progress display on stderr for long runs.

Shown only when stderr is a terminal, so logs and CI output stay clean.
"""

from __future__ import annotations

import sys
import time

__all__ = ["ProgressBar"]


class ProgressBar:
    """Callable fed :class:`simulator.engine.driver.Progress` updates.

    Other progress lines (a study's chunks) subclass it and call :meth:`draw`
    with their own counts and text.
    """

    #: characters in the bar
    WIDTH = 24

    def __init__(self, label: str, stream=None, min_interval_s: float = 0.2):
        self.label = label
        self.stream = stream or sys.stderr
        self.enabled = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.min_interval_s = min_interval_s
        self._last = 0.0
        self._drawn = False

    def __call__(self, p) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        final = p.sensors_done == p.sensors_total
        if not final and now - self._last < self.min_interval_s:
            return
        self._last = now
        eta = "" if p.eta_s is None or final else f", ~{p.eta_s:.0f} s left"
        self.draw(
            p.sensors_done, p.sensors_total,
            f"{p.sensors_done}/{p.sensors_total} sensors done, {p.samples:,} samples, {p.elapsed_s:.1f} s{eta}",
        )  # fmt: skip

    def draw(self, done: int, total: int, text: str) -> None:
        """Redraw the line: the label, a bar filled ``done / total``, then ``text``."""
        bar = "#" * int(round(done / max(total, 1) * self.WIDTH))
        self.stream.write(f"\r{self.label} [{bar:<{self.WIDTH}}] {text}   ")
        self.stream.flush()
        self._drawn = True

    def close(self) -> None:
        if self._drawn:
            self.stream.write("\n")
            self.stream.flush()
