"""The Warp modules a run compiles, whether Warp's kernel cache holds them, and loading them.

Warp compiles a module (C++ generated from its kernels and every function
they call, then clang) the first time one of its kernels is launched, and
keeps the object file in its kernel cache (``wp.config.kernel_cache_dir``)
under the module's content hash, so later processes only load it. That
first compile is most of a first run's time on a CPU (tens of seconds);
:func:`load` therefore tells beforehand which modules the cache lacks and
reports the compile (:class:`CompileProgress`, to the reporter of
:func:`report_compiles_to`), and compiles the missing ones in parallel.

The modules (docs/DESIGN.md §Kernel modules):

- one per trace variant (``kernels.estimators.trace_module``): the
  estimator kernel and the probe kernel of the all-matte variant, or of the
  one with the surface model. A run loads its stage's only;
- ``kernels.estimators``: the closed-form (analytic) kernel, loaded by a
  run that reads a sensor in closed form;
- ``kernels.ray_replay``: ray queries alone, for profiling.
"""

from __future__ import annotations

import os
import threading
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass
from typing import Callable

from . import kernel_hashes
from .device import resolve_device, warp

__all__ = ["KernelModule", "CompileProgress", "trace_module", "analytic_module", "every_module", "is_cached",
           "load", "report_compiles_to"]


@dataclass(frozen=True)
class KernelModule:
    """One Warp module and the name a person reads for it.

    Attributes
    ----------
    label : str
        What it is, e.g. ``"trace (all-matte stages)"``.
    module : warp Module
    """

    label: str
    module: object


@dataclass(frozen=True)
class CompileProgress:
    """What the reporter is told while kernels compile.

    Attributes
    ----------
    labels : tuple of str
        The modules being compiled (those the cache lacked), in order.
    done : int
        How many of them are compiled so far (0 at the start, ``len(labels)`` at the end).
    elapsed_s : float
        Seconds since the compile began.
    finished : str or None
        The module just compiled (None for the start, and for a tick while nothing finished).
    device : str
    """

    labels: tuple
    done: int
    elapsed_s: float
    finished: str | None
    device: str


_reporter: Callable[[CompileProgress], None] | None = None


def report_compiles_to(reporter: Callable[[CompileProgress], None] | None) -> None:
    """Send every later compile's :class:`CompileProgress` to ``reporter`` (None: compile silently).
    The command line sets one for the whole process (``simulator.commands.compiling``)."""
    global _reporter
    _reporter = reporter


def trace_module(surfaces: bool) -> KernelModule:
    """The module of one trace variant: estimator and probe kernels (``kernels.estimators.make_trace``,
    ``kernels.probe.make_probe_kernel``). Both are built here on first use, before the module can be
    hashed, so the module's hash (and its cache entry) is the same whether or not the run reads a
    probe; the other variant is not built (docs/DESIGN.md §Start-up of a small run)."""
    wp = warp()
    from simulator.kernels import estimators as K
    from simulator.kernels import probe as KP

    KP.make_probe_kernel(bool(surfaces))  # and with it the variant's trace (make_trace)
    label = "trace (surface model)" if surfaces else "trace (all-matte stages)"
    return KernelModule(label, wp.get_module(K.trace_module(surfaces)))


def analytic_module() -> KernelModule:
    """The module of the closed-form kernel (``kernels.estimators.analytic_kernel``)."""
    from simulator.kernels import estimators as K

    return KernelModule("closed forms", K.analytic_kernel.module)


def ray_replay_module() -> KernelModule:
    """The ray-query kernels of the profiler (``kernels.ray_replay``)."""
    from simulator.kernels import ray_replay as R

    return KernelModule("ray queries (profiling)", R.closest_hit_kernel.module)


def every_module() -> list[KernelModule]:
    """Every module the tool can launch a kernel of (what ``probesim warmup`` compiles)."""
    return [trace_module(False), trace_module(True), analytic_module(), ray_replay_module()]


def _device(device: str):
    """The Warp device for a requested name (``cpu``, ``cuda``, ``auto``) or a resolved one (``cuda:0``)."""
    wp = warp()
    return wp.get_device(resolve_device(device) if device in ("cpu", "cuda", "auto") else device)


def _variant(module, dev) -> int:
    """The block size a launch on ``dev`` loads the module with (Warp's default: 1 on the CPU, the
    module's on CUDA), as Warp resolves it where its private helper is there."""
    try:
        from warp._src.context import _resolve_launch_block_dim
    except ImportError:  # another Warp layout: its documented defaults
        return 1 if dev.is_cpu else int(module.options["block_dim"])
    return _resolve_launch_block_dim(dev, None)


def is_cached(km: KernelModule, device: str = "cpu", use_kept: bool = True) -> bool:
    """Whether loading ``km`` on ``device`` needs no compile: already loaded in this process, or its
    object file and metadata are in Warp's kernel cache under its current hash (the test
    ``Module.load`` makes before compiling; hashing the module is its first step anyway). The hash
    is the one a former process kept for exactly this code and configuration where there is one
    (:mod:`.kernel_hashes`; not with ``use_kept`` False), and only if its object file is there: else
    Warp's own."""
    wp = warp()
    dev = _device(device)
    m = km.module
    dim = _variant(m, dev)
    # the hash a former process computed for this very code, if kept (nothing where Warp hashed it already)
    restored = use_kept and wp.config.cache_kernels and kernel_hashes.restore(m, dim)
    if (dev.context, dim) in m.execs and m.execs[(dev.context, dim)].module_hash == m.get_module_hash(dim):
        return True
    if not wp.config.cache_kernels:
        return False
    try:
        files = _cache_files(m, dev, dim)
    except (AttributeError, TypeError):  # a Warp whose Module names its files otherwise: say nothing, Warp still compiles
        if restored:
            kernel_hashes.forget(m)
        return True
    if all(os.path.exists(f) for f in files):
        if not restored:
            kernel_hashes.keep(m, dim)
        return True
    if restored:  # nothing is compiled under a kept hash: Warp hashes the module itself
        kernel_hashes.forget(m)
        return is_cached(km, device, use_kept=False)
    return False


def _cache_files(m, dev, dim: int) -> tuple[str, str]:
    """The object file and the metadata ``Module.load`` looks for in the kernel cache (Warp 1.19's naming)."""
    wp = warp()
    folder = os.path.join(wp.config.kernel_cache_dir, m.get_module_identifier(dim))
    return os.path.join(folder, m._get_compile_output_name(dev, block_dim=dim)), os.path.join(folder, m._get_meta_name(dim))


#: seconds between reports while a compile runs and no module has finished (a ticking display)
TICK_S = 1.0


def load(modules: list[KernelModule], device: str = "cpu", workers: int | None = None) -> tuple[str, ...]:
    """Load ``modules`` on ``device``, compiling those the kernel cache lacks; returns their labels.

    The missing ones are compiled ``workers`` at a time (default: one per CPU core, at most
    their number): Warp generates each module's C++ under a lock and runs clang outside it, so
    two modules compile in about the wall time of the larger on two cores. While they compile,
    the reporter (:func:`report_compiles_to`) is told at the start, each second, and as each
    module finishes. Nothing is reported when every module is cached.
    """
    dev = _device(device)
    name = str(dev)
    missing = [km for km in modules if not is_cached(km, name)]
    for km in modules:
        if km not in missing:
            km.module.load(dev, _variant(km.module, dev))
    if not missing:
        return ()
    labels = tuple(km.label for km in missing)
    reporter = _reporter
    t0 = time.perf_counter()
    state = {"done": 0}
    lock = threading.Lock()
    stop = threading.Event()

    def report(finished: str | None, tick: bool = False) -> None:
        with lock:
            if finished is not None:
                state["done"] += 1
                if state["done"] == len(labels):
                    stop.set()  # no tick after the last report
            elif tick and stop.is_set():
                return
            if reporter is not None:
                reporter(CompileProgress(labels, state["done"], time.perf_counter() - t0, finished, name))

    report(None)

    def tick() -> None:
        while not stop.wait(TICK_S):
            report(None, tick=True)

    ticker = threading.Thread(target=tick, daemon=True)
    ticker.start()
    try:
        n_workers = workers or min(len(missing), os.cpu_count() or 1)
        if n_workers <= 1:
            for km in missing:
                km.module.load(dev, _variant(km.module, dev))
                report(km.label)
        else:
            with ThreadPoolExecutor(max_workers=n_workers) as pool:
                futures = {pool.submit(km.module.load, dev, _variant(km.module, dev)): km for km in missing}
                for f in as_completed(futures):
                    f.result()
                    report(futures[f].label)
    finally:
        stop.set()
        ticker.join()
    for km in missing:  # compiled under the hash Warp computed: kept for later processes
        kernel_hashes.keep(km.module, _variant(km.module, dev))
    return labels
