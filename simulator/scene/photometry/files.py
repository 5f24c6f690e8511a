"""A photometric file read by its suffix: IES LM-63 (``.ies``) or EULUMDAT (``.ldt``).

The one module that knows both readers, so the imports run one way:
this module → :mod:`.ies`, :mod:`.ldt` → :mod:`.distribution`.
"""

from __future__ import annotations

from pathlib import Path

from simulator.errors import UserError

from .distribution import GoniometricDistribution
from .ies import read_ies
from .ldt import read_ldt

__all__ = ["read_photometry"]


def read_photometry(path) -> GoniometricDistribution:
    """Read an IES LM-63 (``.ies``) or EULUMDAT (``.ldt``, ``.eul``) file by its suffix.

    Raises
    ------
    UserError
        One line naming ``path``: an unknown suffix, or the reader's own error.
    """
    suffix = Path(path).suffix.lower()
    if suffix == ".ies":
        return read_ies(path)
    if suffix in (".ldt", ".eul"):
        return read_ldt(path)
    raise UserError(f"{path}: unknown photometric file type {suffix!r} (expected .ies or .ldt)")
