"""Where the sun is: a solar position from place and time, and the direction toward it.

The stage's +Y is taken as north and +X as east (Z up), so an azimuth
measured clockwise from north gives the direction toward the sun

.. math:: \\omega = (\\sin A \\cos h,\\ \\cos A \\cos h,\\ \\sin h)

for azimuth ``A`` and elevation ``h``.

The solar position from latitude, longitude and time comes from pvlib
(``pvlib.solarposition.get_solarposition``, the NREL SPA algorithm, with
apparent elevation, i.e. refraction included), installed with the ``study``
extra: pvlib is the maintained reference implementation, and an algorithm
accurate to 0.0003° is not something to write again.

References
----------
Reda, I. and Andreas, A. (2004). Solar position algorithm for solar
radiation applications. Solar Energy 76(5), 577–589.
Holmgren, W. F., Hansen, C. W. and Mikofski, M. A. (2018). pvlib python: a
python package for modeling solar energy systems. JOSS 3(29), 884.
"""

from __future__ import annotations

import math
from datetime import datetime

import numpy as np

from simulator.errors import UserError

__all__ = ["solar_position", "sun_direction", "sun_frame"]


def solar_position(latitude_deg: float, longitude_deg: float, time_iso: str, key: str = "sun") -> tuple[float, float]:
    """``(azimuth_deg, apparent elevation_deg)`` of the sun, azimuth clockwise from north.

    Parameters
    ----------
    latitude_deg, longitude_deg : float
        Degrees, north and east positive.
    time_iso : str
        ISO 8601 time with its UTC offset, e.g. ``2026-06-21T15:00:00+02:00``.
    key : str
        Key path named in errors.
    """
    try:
        t = datetime.fromisoformat(time_iso)
    except ValueError:
        raise UserError(f"{key}.time: not an ISO 8601 time: {time_iso!r}") from None
    if t.tzinfo is None:
        raise UserError(f"{key}.time: give the UTC offset (e.g. {time_iso}+01:00); a local time without it is ambiguous")
    try:
        import pandas as pd
        from pvlib.solarposition import get_solarposition
    except ImportError:
        raise UserError(f"{key}: a solar position from place and time needs pvlib (pip install 'probesim[study]'); "
                        "or give azimuth_deg and elevation_deg") from None  # fmt: skip
    sp = get_solarposition(pd.DatetimeIndex([t]), latitude_deg, longitude_deg)
    return float(sp["azimuth"].iloc[0]), float(sp["apparent_elevation"].iloc[0])


def sun_direction(azimuth_deg: float, elevation_deg: float) -> np.ndarray:
    """Unit vector toward the sun, shape (3,), in the world frame (+Y north, +X east, +Z up)."""
    a, h = math.radians(azimuth_deg), math.radians(elevation_deg)
    return np.array([math.sin(a) * math.cos(h), math.cos(a) * math.cos(h), math.sin(h)])


def sun_frame(direction: np.ndarray) -> np.ndarray:
    """(3, 3) frame whose third column is ``direction`` (a DistantLight's +Z points at the sun)."""
    z = np.asarray(direction, float) / np.linalg.norm(direction)
    ref = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = ref - np.dot(ref, z) * z
    x /= np.linalg.norm(x)
    return np.stack([x, np.cross(z, x), z], axis=1)
