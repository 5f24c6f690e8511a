"""A one-line progress display on stderr for long runs.

Shown only when stderr is a terminal, so logs and CI output stay clean.
"""

from __future__ import annotations

import sys
import time

__all__ = ["ProgressBar"]


class ProgressBar:
    """Callable fed :class:`simulator.engine.driver.Progress` updates."""

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
        frac = p.sensors_done / max(p.sensors_total, 1)
        width = 24
        bar = "#" * int(round(frac * width))
        eta = "" if p.eta_s is None or final else f", ~{p.eta_s:.0f} s left"
        self.stream.write(
            f"\r{self.label} [{bar:<{width}}] {p.sensors_done}/{p.sensors_total} sensors done, "
            f"{p.samples:,} samples, {p.elapsed_s:.1f} s{eta}   "
        )
        self.stream.flush()
        self._drawn = True

    def close(self) -> None:
        if self._drawn:
            self.stream.write("\n")
            self.stream.flush()
