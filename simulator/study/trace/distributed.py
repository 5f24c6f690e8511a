"""Running chunks: in this process, on a dask LocalCluster, or on a scheduler's cluster.

``mode = "auto"`` runs in this process when the machine has two cores or
fewer or the study has at most two chunks to compute (a cluster's start-up,
seconds per worker importing the tracer, would cost more than it saves),
and otherwise starts a ``LocalCluster`` of one single-threaded-tracing
worker process per core. A scheduler address (``--scheduler`` or
``[compute] scheduler``) sends the chunks to that cluster instead. Failed
tasks are retried ``retries`` times by dask. Results come back in
completion order; the caller stores each as it arrives.
"""

from __future__ import annotations

import os
from dataclasses import replace
from typing import Callable, Iterator

from simulator.errors import UserError
from simulator.study.trace.chunks import ChunkSpec, compute_chunk

__all__ = ["QUIET_CLUSTER", "choose_mode", "run_chunks"]


def choose_mode(mode: str, scheduler: str | None, n_chunks: int, workers: int) -> tuple[str, int]:
    """``(mode, workers)`` actually used: ``inprocess``, ``local`` or ``scheduler``."""
    if scheduler:
        return "scheduler", 0
    cores = os.cpu_count() or 1
    n = workers if workers > 0 else cores
    if mode == "auto":
        mode = "inprocess" if cores <= 2 or n_chunks <= 2 or n <= 1 else "local"
    return mode, (n if mode == "local" else 1)


#: dask settings a tls:// scheduler needs (``distributed.comm.tls.*``, or DASK_DISTRIBUTED__COMM__TLS__... variables)
TLS_KEYS = ("distributed.comm.tls.ca-file", "distributed.comm.tls.client.cert")


def scheduler_security(address: str):
    """The client's :class:`distributed.Security` for ``address``: None for tcp (dask's default),
    and for ``tls://`` the one dask's configuration describes (``distributed.comm.tls.ca-file``,
    ``.client.cert``, ``.client.key``), checked here so that a missing setting is one line."""
    if not address.startswith("tls://"):
        return None
    import dask
    from distributed import Security

    missing = [k for k in TLS_KEYS if not dask.config.get(k, None)]
    if missing:
        env = ", ".join("DASK_" + k.upper().replace(".", "__").replace("-", "_") for k in missing)
        raise UserError(f"--scheduler {address}: a tls:// scheduler needs dask's {', '.join(missing)} (in dask's config file, or {env})")
    for k in ("distributed.comm.tls.ca-file", "distributed.comm.tls.client.cert", "distributed.comm.tls.client.key"):
        f = dask.config.get(k, None)
        if f and not os.path.isfile(f):
            raise UserError(f"--scheduler {address}: {k} = {f}: no such file")
    return Security(require_encryption=True)


#: a LocalCluster's options here: no dashboard, its scheduler's HTTP routes (health, metrics) on a free port
#: rather than 8787, which another cluster on the machine may hold (dask then warns and moves), quiet logs
QUIET_CLUSTER = {"dashboard_address": None, "scheduler_kwargs": {"dashboard_address": ":0"}, "silence_logs": 40}


def run_chunks(specs: list[ChunkSpec], mode: str, workers: int, scheduler: str | None, retries: int,
               log: Callable[[str], None] = print) -> Iterator[dict]:  # fmt: skip
    """Compute ``specs``, yielding each chunk's result as it finishes."""
    if not specs:
        return
    if mode == "inprocess":
        for s in specs:
            yield compute_chunk(s)
        return
    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError:
        raise UserError("a dask cluster needs dask[distributed] (pip install 'dask[distributed]'), or set [compute] mode = \"inprocess\"") from None
    cluster = None
    if mode == "scheduler":
        try:
            client = Client(scheduler, timeout="20s", security=scheduler_security(scheduler))
        except (OSError, TimeoutError) as exc:
            raise UserError(f"dask scheduler {scheduler}: cannot reach it: {exc}") from None
    else:
        cores = os.cpu_count() or 1
        threads = max(1, cores // max(workers, 1))
        specs = [replace(s, threads=threads) for s in specs]
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, **QUIET_CLUSTER)
        client = Client(cluster)
    try:
        futures = [client.submit(compute_chunk, s, key=f"probesim-chunk-{s.id}", pure=False, retries=retries) for s in specs]
        for fut in as_completed(futures):
            try:
                result = fut.result()
            except ImportError as exc:  # a worker without probesim, or without a package a chunk needs
                where = f"dask scheduler {scheduler}" if mode == "scheduler" else "dask LocalCluster"
                raise UserError(f"{where}: a worker cannot import what a chunk needs ({exc}): install the study's "
                                "probesim, the same build, on every worker") from None  # fmt: skip
            yield result
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
