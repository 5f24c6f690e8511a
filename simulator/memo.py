"""Values a Python process keeps for its later runs (warm runs of the API).

:class:`Kept` is the one bounded, thread-safe store behind the stage cache
(:mod:`simulator.scene.stage_cache`), the plan cache
(:mod:`simulator.plan.cache`) and the exact estimator's factors
(:mod:`simulator.engine.exact_memo`): the least recently used entry goes
first once there are more than ``max_entries`` or their sizes (bytes,
sensors: the caller's unit) add up to more than ``max_size``.
"""

from __future__ import annotations

import math
import threading
from collections import OrderedDict

__all__ = ["Kept"]


class Kept:
    """A bounded least-recently-used store; ``len()`` is the number of entries kept.

    Parameters
    ----------
    max_entries : int
        Most entries kept.
    max_size : float
        Most total size kept, in the unit of :meth:`put`'s ``size`` (no bound by default).
    """

    def __init__(self, max_entries: int, max_size: float = math.inf):
        self.max_entries = max_entries
        self.max_size = max_size
        self._entries: OrderedDict = OrderedDict()  # key -> (value, size)
        self._lock = threading.Lock()

    def get(self, key, valid=None):
        """The value kept under ``key`` (now the most recently used), or None; an entry for which
        ``valid(value)`` is false is dropped and None returned."""
        with self._lock:
            e = self._entries.get(key)
            if e is None:
                return None
            if valid is not None and not valid(e[0]):
                del self._entries[key]
                return None
            self._entries.move_to_end(key)
            return e[0]

    def put(self, key, value, size: float = 1.0) -> None:
        """Keep ``value`` under ``key``, then drop the least recently used while over a bound."""
        with self._lock:
            self._entries[key] = (value, size)
            self._entries.move_to_end(key)
            total = sum(s for _, s in self._entries.values())
            while self._entries and (len(self._entries) > self.max_entries or total > self.max_size):
                _, (_, s) = self._entries.popitem(last=False)
                total -= s

    def clear(self) -> None:
        """Forget every entry."""
        with self._lock:
            self._entries.clear()

    def __len__(self) -> int:
        return len(self._entries)
