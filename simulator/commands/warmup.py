"""``probesim warmup``: compile every kernel module the tool can launch, so that no run compiles.

A fresh install has an empty kernel cache: the first run on each device
compiles the modules it needs (most of that run's time on a CPU). Warming
once, after installing or upgrading, moves that wait out of the first real
run. What is cached already is only loaded, so a second warmup is quick.
"""

from __future__ import annotations

import time

__all__ = ["devices_to_warm", "main_warmup"]


def devices_to_warm(requested: str | None) -> tuple[list[str], str | None]:
    """The devices to compile for and a note for the user (or None).

    ``None`` (no ``--device``): the CPU, and CUDA when Warp finds a device; ``cpu``: the CPU;
    ``cuda``: CUDA (a ``UserError`` where there is none, as for ``run``); ``auto``: the device
    a run with ``device = "auto"`` would use.
    """
    from simulator.engine.device import cuda_available, resolve_device

    if requested is None:
        if cuda_available():
            return ["cpu", resolve_device("cuda")], None
        return ["cpu"], "no CUDA device on this machine: CPU kernels only"
    return [resolve_device(requested)], None


def main_warmup(requested: str | None, log=print) -> int:
    """Compile (or load) :func:`~simulator.engine.kernel_modules.every_module` on each device of
    :func:`devices_to_warm`; ``log`` gets one summary line per device. Returns the exit status."""
    from simulator.engine import kernel_modules as KM

    devices, note = devices_to_warm(requested)
    if note:
        log(note)
    modules = KM.every_module()
    for device in devices:
        t0 = time.perf_counter()
        compiled = KM.load(modules, device)
        wall = time.perf_counter() - t0
        n = len(modules)
        if compiled:
            log(f"kernels ready on {device}: {n} modules, {len(compiled)} compiled, {n - len(compiled)} cached, "
                f"in {wall:.1f} s")
        else:
            log(f"kernels ready on {device}: {n} modules, all cached ({wall:.1f} s)")
    return 0
