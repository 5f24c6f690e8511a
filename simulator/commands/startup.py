"""The start-up of a short command (``probesim run``, ``probesim plan``) in a fresh process.

Most of a small run's time is loading modules (numpy, the config schema,
USD, Warp and the kernels' functions), not tracing. Two things make that
start-up longer without doing anything for the run:

- Python's cyclic garbage collector: loading modules allocates hundreds of
  thousands of long-lived objects (functions, classes, ASTs, schema
  tables) and frees few, so each collection walks them all and finds
  nothing (8–12% of a one-sensor run's CPU time). :func:`lean_start` pauses
  collections; :func:`resume_collections` moves what was loaded out of their
  way (``gc.freeze``) and resumes them once tracing has begun.
- OpenBLAS's thread pool: started when numpy loads, it spins on the other
  core after each matrix product; a run's host arithmetic is small products
  (3 × 3 maps of many points), and on a 2-core machine the spinning threads
  take CPU time from the stage reader and from Warp's worker threads. A
  fresh process starts with one BLAS thread unless ``OPENBLAS_NUM_THREADS``
  is set (the products compute every element the same way on one thread).

And one thing makes its end longer: tearing the interpreter down frees every
object those modules made, one by one (about 0.03 s of a one-sensor run,
after its files are written). :func:`end_lean` ends such a process at once
instead, once its output is flushed and what would run at exit has run.
"""

from __future__ import annotations

import atexit
import gc
import os
import sys
import threading

__all__ = ["lean_start", "resume_collections", "end_lean"]


def lean_start() -> bool:
    """In a fresh process (numpy not loaded yet: it reads the variable when it loads), ask for one
    BLAS thread and pause garbage collection; returns whether it did. A caller that has loaded the
    modules already (a test calling the command line in-process) has nothing to gain and is left as it is."""
    if "numpy" in sys.modules or not gc.isenabled():
        return False
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    gc.disable()
    return True


def resume_collections() -> None:
    """Resume garbage collection, the objects loaded so far left out of it (they live as long as the process)."""
    if not gc.isenabled():
        gc.freeze()
        gc.enable()


def end_lean(code: int) -> None:
    """End a process :func:`lean_start` started, with exit status ``code``, without tearing the interpreter
    down: standard output and error are flushed and the functions registered to run at exit are run, as
    a normal exit would, then the process ends (the system reclaims its memory at once). Returns, so
    that the caller exits the usual way, where that could lose anything: a thread other than the main
    one still running and not a daemon (a normal exit waits for it), output that cannot be flushed, or
    a Python without the exit hook to call."""
    run_exit_functions = getattr(atexit, "_run_exitfuncs", None)
    if run_exit_functions is None:
        return
    main = threading.main_thread()
    if threading.current_thread() is not main or any(t is not main and t.is_alive() and not t.daemon
                                                     for t in threading.enumerate()):
        return
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except (OSError, ValueError):  # a closed or broken stream: the usual exit reports it as it always did
        return
    run_exit_functions()
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    finally:
        os._exit(code)
