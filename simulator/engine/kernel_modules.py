"""The Warp modules a run compiles, whether Warp's kernel cache holds them, and loading them.

Warp compiles a module (C++ generated from its kernels and every function
they call, then clang) the first time one of its kernels is launched, and
keeps the object file in its kernel cache (``wp.config.kernel_cache_dir``)
under the module's content hash, so later processes only load it. That
first compile is most of a first run's time on a CPU (tens of seconds);
:func:`load` therefore tells beforehand which modules the cache lacks and
reports the compile (:class:`CompileProgress`, to the reporter of
:func:`report_compiles_to`), and compiles the missing ones in parallel.
:func:`start` begins a compile early, on a thread of its own, so that it
runs beside the host's work (a run's spectral tables, the scene's upload)
on the other core; the :func:`load` that needs the module then waits for it.

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
from concurrent.futures import Future, ThreadPoolExecutor, as_completed
from dataclasses import dataclass
from typing import Callable

from .device import resolve_device, warp

__all__ = ["KernelModule", "CompileProgress", "trace_module", "analytic_module", "every_module", "is_cached",
           "load", "start", "in_flight", "report_compiles_to"]


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
    ``kernels.probe.make_probe_kernel``). Both kernels are defined before the module is hashed: the
    probe module is imported here, so the module's hash (and its cache entry) is the same whether or
    not the run reads a probe."""
    wp = warp()
    from simulator.kernels import estimators as K
    from simulator.kernels import probe as KP  # noqa: F401  (defines the variant's probe kernel in its module)

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


def is_cached(km: KernelModule, device: str = "cpu") -> bool:
    """Whether loading ``km`` on ``device`` needs no compile: already loaded in this process, or its
    object file and metadata are in Warp's kernel cache under its current hash (the test
    ``Module.load`` makes before compiling; hashing the module is its first step anyway)."""
    wp = warp()
    dev = _device(device)
    m = km.module
    dim = _variant(m, dev)
    if (dev.context, dim) in m.execs and m.execs[(dev.context, dim)].module_hash == m.get_module_hash(dim):
        return True
    if not wp.config.cache_kernels:
        return False
    try:
        files = _cache_files(m, dev, dim)
    except (AttributeError, TypeError):  # a Warp whose Module names its files otherwise: say nothing, Warp still compiles
        return True
    return all(os.path.exists(f) for f in files)


def _cache_files(m, dev, dim: int) -> tuple[str, str]:
    """The object file and the metadata ``Module.load`` looks for in the kernel cache (Warp 1.19's naming)."""
    wp = warp()
    folder = os.path.join(wp.config.kernel_cache_dir, m.get_module_identifier(dim))
    return os.path.join(folder, m._get_compile_output_name(dev, block_dim=dim)), os.path.join(folder, m._get_meta_name(dim))


#: seconds between reports while a compile runs and no module has finished (a ticking display)
TICK_S = 1.0


@dataclass(frozen=True)
class _Started:
    """A compile :func:`start` began: the module, when, and its outcome (set by the compiling thread)."""

    km: KernelModule
    t0: float
    done: Future


#: compiles begun by :func:`start` and not yet taken up by a :func:`load`, by (module, device name)
_started: dict[tuple[int, str], _Started] = {}
#: every compile :func:`start` began in this process (:func:`in_flight`)
_begun: list[_Started] = []
_started_lock = threading.Lock()


def start(modules: list[KernelModule], device: str = "cpu") -> tuple[str, ...]:
    """Begin compiling, on one thread of its own, those of ``modules`` the kernel cache lacks on
    ``device``; returns their labels (empty when all are cached: nothing is started).

    Nothing is reported here: the :func:`load` of a started module waits for its compile and
    reports it as its own (the seconds counted from this start), so a run's display and log are
    those of a compile :func:`load` ran itself, only shorter by what overlapped. The thread is not
    a daemon: a process that stops early (a user error, Ctrl-C) finishes the compile, and caches
    it, before it exits, rather than tear clang's libraries down under it or leave Warp's build
    folder behind (:func:`in_flight` names it meanwhile). Called with every module cached, or with
    modules already started, it does nothing for them.
    """
    dev = _device(device)
    name = str(dev)
    with _started_lock:
        missing = [km for km in modules if (id(km.module), name) not in _started and not is_cached(km, name)]
        if not missing:
            return ()
        t0 = time.perf_counter()
        jobs = [_Started(km, t0, Future()) for km in missing]
        for job in jobs:
            _started[(id(job.km.module), name)] = job
        _begun.extend(jobs)

    def compile_all() -> None:
        for job in jobs:
            if not job.done.set_running_or_notify_cancel():
                continue
            try:
                job.km.module.load(dev, _variant(job.km.module, dev))
            except BaseException as e:  # noqa: BLE001  (handed to the load that waits for it)
                job.done.set_exception(e)
            else:
                job.done.set_result(None)

    threading.Thread(target=compile_all, name="probesim-compile", daemon=False).start()
    return tuple(km.label for km in missing)


def in_flight() -> tuple[str, ...]:
    """The modules whose compile :func:`start` began and that are still compiling (the process
    waits for them before it exits)."""
    with _started_lock:
        return tuple(job.km.label for job in _begun if not job.done.done())


def _take_started(km: KernelModule, name: str) -> _Started | None:
    """The compile :func:`start` began for ``km`` on device ``name``, handed to one :func:`load` only."""
    with _started_lock:
        return _started.pop((id(km.module), name), None)


def load(modules: list[KernelModule], device: str = "cpu", workers: int | None = None) -> tuple[str, ...]:
    """Load ``modules`` on ``device``, compiling those the kernel cache lacks; returns their labels.

    The missing ones are compiled ``workers`` at a time (default: one per CPU core, at most
    their number): Warp generates each module's C++ under a lock and runs clang outside it, so
    two modules compile in about the wall time of the larger on two cores. A module whose
    compile :func:`start` began is waited for, and counts as compiled here. While they compile,
    the reporter (:func:`report_compiles_to`) is told at the start, each second, and as each
    module finishes. Nothing is reported when every module is cached.
    """
    dev = _device(device)
    name = str(dev)
    started = {id(km.module): job for km in modules if (job := _take_started(km, name)) is not None}
    missing = [km for km in modules if id(km.module) not in started and not is_cached(km, name)]
    for km in modules:
        if km not in missing and id(km.module) not in started:
            km.module.load(dev, _variant(km.module, dev))
    waited = list(started.values())
    if not missing and not waited:
        return ()
    labels = tuple(job.km.label for job in waited) + tuple(km.label for km in missing)
    reporter = _reporter
    t0 = min([job.t0 for job in waited] + [time.perf_counter()])
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
        for job in waited:  # begun by start(): its thread compiles them one after the other
            job.done.result()
            job.km.module.load(dev, _variant(job.km.module, dev))  # loaded there already: a lookup
            report(job.km.label)
        n_workers = workers or min(len(missing), os.cpu_count() or 1)
        if n_workers <= 1:
            for km in missing:
                km.module.load(dev, _variant(km.module, dev))
                report(km.label)
        elif missing:
            with ThreadPoolExecutor(max_workers=n_workers) as pool:
                futures = {pool.submit(km.module.load, dev, _variant(km.module, dev)): km for km in missing}
                for f in as_completed(futures):
                    f.result()
                    report(futures[f].label)
    finally:
        stop.set()
        ticker.join()
    return labels
