"""How many sensors a chunk holds when ``[compute] sensor_block = "auto"``: from the study's size alone.

Notes
-----
A chunk builds its own engine, so each pays the pilots a run pays once
(their samples are discarded): the surface guide's pilot draws
``max(PILOT_SAMPLES · b, PILOT_MIN_TOTAL)`` paths for a block of ``b``
sensors (32 per sensor, at least 16,384 in all), the roulette threshold's
at least ``RR_PILOT_TOTAL`` and the light pick's ``PICK_PILOT_SAMPLES`` per
sensor. In path samples, a trace group of ``S`` sensors at ``N`` samples
each split into blocks ``b_1 … b_n`` costs

.. math:: C(n) = \\sum_i \\bigl[\\max(32 b_i, 16384) + 256 + (16 + N)\\,b_i\\bigr],

and one run of the same sensors ``C(1)``. The rule takes the smallest block, so the
most chunks (finer resume, more parallel work), whose ``C(n) ≤ BUDGET · C(1)``, with
``BUDGET = 1.2`` (under the 1.3 the cost is held to, leaving room for the
per-chunk setup the model leaves out: the scene's upload, launches), and no
block above :data:`MAX_BLOCK` sensors (memory of the group tallies). ``N`` is
``[simulation] samples``: with an adaptive target the pass draws at least
that many, so the real ratio is lower. The figures come from constants of
the engine, not from timing, so the block, and with it every chunk's seed and
bytes, is the same on every machine, worker count and mode.

Measured (the bundled office study, 54 sensors at 512 samples, CPU time of
the first trace group against one run of its hardest scenario, 2-core
machine under a load average of ~7): blocks of 8 (7 chunks) 4.5×, of 32 (2
chunks) 1.66×, of all 54 1.05×.
"""

from __future__ import annotations

__all__ = ["auto_block", "pass_cost", "BUDGET", "MAX_BLOCK"]

#: a study's trace group may cost at most this many times one run (in the model's path samples)
BUDGET = 1.2
#: the largest automatic block, sensors
MAX_BLOCK = 1024


def _pilots() -> tuple[int, int, int, int]:
    from simulator.engine.driver import PICK_PILOT_SAMPLES, RR_PILOT_TOTAL
    from simulator.engine.guide import PILOT_MIN_TOTAL, PILOT_SAMPLES

    return PILOT_SAMPLES, PILOT_MIN_TOTAL, RR_PILOT_TOTAL, PICK_PILOT_SAMPLES


def pass_cost(n_sensors: int, samples: int, block: int) -> float:
    """Path samples a trace group of ``n_sensors`` at ``samples`` each costs in blocks of ``block`` (see Notes)."""
    per, floor, rr, pick = _pilots()

    def chunk(b: int) -> float:
        return max(per * b, floor) + rr + (pick + samples) * b

    full, rest = divmod(n_sensors, block)
    return full * chunk(block) + (chunk(rest) if rest else 0.0)


def auto_block(n_sensors: int, samples: int) -> int:
    """The smallest block (the most chunks) whose cost stays within :data:`BUDGET` of one run, at most
    :data:`MAX_BLOCK` (see Notes)."""
    if n_sensors <= 0:
        return 1
    top = min(n_sensors, MAX_BLOCK)
    one = pass_cost(n_sensors, samples, n_sensors)
    for b in range(1, top + 1):
        if pass_cost(n_sensors, samples, b) <= BUDGET * one:
            return b
    return top
