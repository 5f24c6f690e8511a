"""One kernel launch spread over CPU worker threads.

Warp's CPU launches release the GIL, so ``threads`` Python threads each
launching a slice of the kernel threads run in parallel; one launch runs
its kernel threads one after another, in index order. Every kernel
thread's result depends only on its global index (``offset + tid``), never
on how the launch was cut, and state shared by a chunk of kernel threads
stays on one worker (``align``). The workers are always joined before
:func:`fan_out` returns or raises, so no launch outlives its batch.
"""

from __future__ import annotations

import threading
from typing import Callable

import numpy as np

__all__ = ["fan_out"]


def fan_out(threads: int, run: Callable[[int, int], None], n: int, align: int = 1) -> None:
    """Run ``run(offset, dim)`` over n kernel threads, cut into at most
    ``threads`` contiguous slices, one CPU worker each (1 on a GPU: one launch).

    Parameters
    ----------
    threads : int
        CPU workers.
    run : callable
        ``run(offset, dim)`` launches kernel threads ``[offset, offset + dim)``.
    n : int
        Kernel threads in all.
    align : int
        Slices start at multiples of ``align``: kernel threads that share
        state in chunks of ``align`` (a guide pilot's tally blocks) then
        always run on one worker, in order, so the chunk's sums do not
        depend on ``threads``.
    """
    align = max(1, int(align))
    units = -(-n // align)
    parts = min(threads, units)
    if parts <= 1:
        run(0, n)
        return
    cuts = np.minimum(np.linspace(0, units, parts + 1).astype(int) * align, n)
    workers = [threading.Thread(target=run, args=(int(a), int(b - a))) for a, b in zip(cuts[:-1], cuts[1:])]
    interrupted = None
    try:
        for w in workers:
            w.start()
    finally:
        for w in workers:
            while w.is_alive():
                try:
                    w.join()
                except KeyboardInterrupt as e:  # keep joining: the workers write into the batch's arrays
                    interrupted = e
    if interrupted is not None:
        raise interrupted
