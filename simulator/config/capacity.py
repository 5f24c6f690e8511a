"""Whether a config's sensors fit in memory, decided before any is built.

A ``[[grid]]`` of 0.1 mm cells over a floor is billions of sensors; built
one by one they fill the memory until the system kills the process, with
no word of why. The grid's cell count is known from its size and spacing
alone, so the loader checks the memory a run of that many sensors needs
against the machine's before expanding a single cell.
"""

from __future__ import annotations

import os

__all__ = ["SENSOR_BYTES", "physical_memory_bytes", "memory_needed_bytes", "format_bytes", "too_many_sensors"]

#: peak memory of a run per sensor (bytes): the sensor, its device record,
#: running statistics, plan entry, CSV row and map pixel. Measured as the
#: peak resident size of ``probesim run`` (method light, one point light) on
#: a 400 × 500 grid against a 10 × 500 one: 845 MB more for 195,000 more
#: cells, 4.3 KB a cell; rounded up.
SENSOR_BYTES = 4500


def physical_memory_bytes() -> int | None:
    """The machine's physical memory in bytes, None where the system does not say."""
    try:
        return int(os.sysconf("SC_PAGE_SIZE")) * int(os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):
        return None


def memory_needed_bytes(n_sensors: int) -> int:
    """Estimated peak memory (bytes) of a run of ``n_sensors`` sensors: ``n_sensors`` × :data:`SENSOR_BYTES`."""
    return int(n_sensors) * SENSOR_BYTES


def format_bytes(n: float) -> str:
    """``n`` bytes in binary units, three figures (``4.1 TiB``; past PiB, whole PiB: ``40,000 PiB``)."""
    if n < 1024:
        return f"{int(n)} B"
    for unit in ("KiB", "MiB", "GiB", "TiB", "PiB"):
        n /= 1024.0
        if n < 1000 or unit == "PiB":
            return f"{n:.3g} {unit}" if n < 1000 else f"{n:,.0f} {unit}"
    raise AssertionError("unreachable")


def too_many_sensors(n_sensors: int, memory: int | None = None) -> str | None:
    """Why a run of ``n_sensors`` sensors cannot fit, or None when it can.

    Parameters
    ----------
    n_sensors : int
        Sensors of the run (its grids' cells included).
    memory : int, optional
        Bytes available; default :func:`physical_memory_bytes` (no check
        where that is unknown).
    """
    memory = physical_memory_bytes() if memory is None else memory
    need = memory_needed_bytes(n_sensors)
    if memory is None or need <= memory:
        return None
    return f"{n_sensors:,} sensors would need about {format_bytes(need)} of memory, more than this machine's {format_bytes(memory)}"
