"""Ctrl-C as a request to stop: a flag polled between batches.

While :func:`sigint_deferred` is active (main thread only), SIGINT sets
``StopFlag.requested`` instead of raising ``KeyboardInterrupt``, so an
interrupt never lands inside a batch's merge or a file write; the batch
loop (:func:`simulator.engine.adaptive.run_batches`) checks the flag after
each batch and the run writes what it has measured.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager
from typing import Iterator

__all__ = ["StopFlag", "sigint_deferred"]


class StopFlag:
    """Set once a stop has been asked for (by SIGINT or by a caller)."""

    def __init__(self) -> None:
        self.requested = False

    def request(self, *_args) -> None:
        """Ask for a stop; usable as a signal handler."""
        self.requested = True


@contextmanager
def sigint_deferred(flag: StopFlag | None = None) -> Iterator[StopFlag]:
    """Within the block, SIGINT sets ``flag.requested`` (every further one too)
    instead of raising; the previous handler is back afterwards.

    Outside the main thread signal handlers cannot be set: the block then
    runs with SIGINT as it was, and the flag is only set by callers.
    """
    flag = StopFlag() if flag is None else flag
    if threading.current_thread() is not threading.main_thread():
        yield flag
        return
    previous = signal.signal(signal.SIGINT, flag.request)
    try:
        yield flag
    finally:
        # None: a handler not set from Python, which cannot be put back; the default stands in
        signal.signal(signal.SIGINT, signal.SIG_DFL if previous is None else previous)
