"""A year of weather: EPW and TMY3 files read with pvlib, the sun at each hour's centre, units checked against the data.

A climate file gives, per hour, the direct-normal and diffuse-horizontal
irradiances (W/m²) and, usually, the matching illuminances (lx). Both formats
label each row with the *end* of its hour, local standard time (TMY3 and EPW
hour 1 is 00:00–01:00); the hour's value is a mean over it, so the sun is
placed at the hour's centre, 30 minutes before the label
(:attr:`Weather.centre`), with pvlib's solar position (NREL SPA, apparent
elevation: refraction included, as :mod:`simulator.study.inputs.sun`).

Units are checked against the data, not the header: the global-horizontal
illuminance over the global-horizontal irradiance is daylight's luminous
efficacy, about 100–130 lm/W. Where the file's ratio has a median near 1 the
illuminance fields hold units of 100 lx (pvlib's bundled ``723170TYA.CSV``
does, whatever its header says: its median is 1.07), and they are scaled by
100, which the run says; a median outside both ranges is refused.

References
----------
Wilcox, S. and Marion, W. (2008). Users manual for TMY3 data sets.
NREL/TP-581-43156 (fields; hour ending).
U.S. DOE, EnergyPlus Auxiliary Programs: weather file (EPW) format.
docs/REFERENCES.md §Climate files.
"""

from __future__ import annotations


import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from simulator.errors import UserError

__all__ = ["Weather", "read_weather", "check_illuminance_units", "derive_tmy3_lux", "EFFICACY_LUX_RANGE", "EFFICACY_HLUX_RANGE"]

#: plausible median GH illuminance / GHI when the fields are in lux (lm/W)
EFFICACY_LUX_RANGE = (50.0, 250.0)
#: ... and when they are in units of 100 lx
EFFICACY_HLUX_RANGE = (0.5, 2.5)
#: hours with GHI above this (W/m²) take part in the units check
_CHECK_GHI_W_M2 = 50.0


@dataclass
class Weather:
    """One climate file's hours (every row), in SI units.

    Attributes
    ----------
    site : str
    latitude_deg, longitude_deg, altitude_m, tz_h : float
        Degrees north and east; metres; the file's standard-time offset from UTC, hours.
    end : pandas.DatetimeIndex
        Each row's label, the end of its hour (local standard time, with the offset).
    centre : pandas.DatetimeIndex
        Each hour's centre, ``end − 30 min``: where the sun is placed.
    dni_w_m2, dhi_w_m2, ghi_w_m2 : ndarray, shape (N,)
        Direct-normal, diffuse-horizontal and global-horizontal irradiance.
    dni_lx, dhi_lx, ghi_lx : ndarray or None
        The matching illuminances in lux (None: the file has none).
    dew_c : ndarray, shape (N,)
        Dew-point temperature, °C (precipitable water of the efficacy model).
    sun_azimuth_deg, sun_elevation_deg : ndarray, shape (N,)
        The sun at each hour's centre: azimuth clockwise from north, apparent elevation.
    notes : list of str
        What was read and how (unit scaling), for the record.
    """

    path: str
    site: str
    latitude_deg: float
    longitude_deg: float
    altitude_m: float
    tz_h: float
    end: object
    centre: object
    dni_w_m2: np.ndarray
    dhi_w_m2: np.ndarray
    ghi_w_m2: np.ndarray
    dni_lx: np.ndarray | None
    dhi_lx: np.ndarray | None
    ghi_lx: np.ndarray | None
    dew_c: np.ndarray
    sun_azimuth_deg: np.ndarray = field(default_factory=lambda: np.zeros(0))
    sun_elevation_deg: np.ndarray = field(default_factory=lambda: np.zeros(0))
    notes: list = field(default_factory=list)

    def __len__(self) -> int:
        return len(self.dni_w_m2)


def check_illuminance_units(ghi_w_m2: np.ndarray, ghi_illum: np.ndarray, label: str) -> float | None:
    """Factor that turns the file's illuminance fields into lux (1 or 100), None when it has none.

    The median of illuminance / irradiance over hours with GHI > 50 W/m² is
    read as a luminous efficacy: 50–250 means lux, 0.5–2.5 units of 100 lx.
    Raises UserError for anything else."""
    m = (ghi_w_m2 > _CHECK_GHI_W_M2) & np.isfinite(ghi_illum)
    if not m.any() or not (ghi_illum[m] > 0).any():
        return None
    r = float(np.median(ghi_illum[m] / ghi_w_m2[m]))
    if EFFICACY_LUX_RANGE[0] <= r <= EFFICACY_LUX_RANGE[1]:
        return 1.0
    if EFFICACY_HLUX_RANGE[0] <= r <= EFFICACY_HLUX_RANGE[1]:
        return 100.0
    raise UserError(f"{label}: global horizontal illuminance over irradiance has a median of {r:.3g}: neither lux "
                    "(about 100 lm/W) nor units of 100 lx (about 1); cannot tell the file's illuminance units")  # fmt: skip


def _float(df, col, missing: float = 9999.0) -> np.ndarray | None:
    """A column as float64, EPW's "missing" codes (9999 for radiation, 999999 for illuminance) and negatives as NaN."""
    if col not in df.columns:
        return None
    v = np.asarray(df[col], np.float64)
    return np.where((v >= missing) | (v < 0), np.nan, v)


def read_weather(path: str | os.PathLike, key: str = "weather") -> Weather:
    """Read an EPW (``.epw``) or TMY3 (``.csv``) file with pvlib and place the sun at each hour's centre.

    Raises
    ------
    UserError
        A missing or unreadable file, one pvlib cannot parse, or illuminance
        units the data contradict; ``key`` names the setting in messages.
    """
    p = Path(path)
    label = f"{key}: {p}"
    if not p.is_file():
        raise UserError(f"{label}: weather file not found")
    try:
        import pandas as pd
        from pvlib import iotools
        from pvlib.solarposition import get_solarposition
    except ImportError:
        raise UserError(f"{key}: reading a climate file needs pvlib (pip install 'probesim[study]')") from None
    ext = p.suffix.lower()
    try:
        if ext == ".epw":
            df, meta = iotools.read_epw(str(p))
            cols = {"ghi_lx": "global_hor_illum", "dni_lx": "direct_normal_illum", "dhi_lx": "diffuse_horizontal_illum", "dew": "temp_dew"}
            site = f"{meta.get('city', '')}, {meta.get('country', '')}".strip(", ")
            tz, alt = float(meta["TZ"]), float(meta.get("altitude", 0.0))
        elif ext == ".csv":
            df, meta = iotools.read_tmy3(str(p), map_variables=True)
            cols = {"ghi_lx": "GH illum (lx)", "dni_lx": "DN illum (lx)", "dhi_lx": "DH illum (lx)", "dew": "temp_dew"}
            site = str(meta.get("Name", "")).strip('"')
            tz, alt = float(meta["TZ"]), float(meta.get("altitude", 0.0))
        else:
            raise UserError(f"{label}: expected an EPW (.epw) or TMY3 (.csv) file")
    except UserError:
        raise
    except Exception as exc:  # pvlib's parse errors are of many kinds
        raise UserError(f"{label}: cannot read it as {'EPW' if ext == '.epw' else 'TMY3'}: {type(exc).__name__}: {exc}") from None
    need = [c for c in ("ghi", "dni", "dhi") if c not in df.columns]
    if need:
        raise UserError(f"{label}: no {', '.join(need)} column")
    ghi, dni, dhi = (np.nan_to_num(_float(df, c), nan=0.0) for c in ("ghi", "dni", "dhi"))
    gl, nl, dl = (_float(df, cols[c], 999999.0) for c in ("ghi_lx", "dni_lx", "dhi_lx"))
    notes = [f"{'EPW' if ext == '.epw' else 'TMY3'} file {p.name}: {site}, latitude {float(meta['latitude']):.3f}, "
             f"longitude {float(meta['longitude']):.3f}, {len(df)} hours; rows label the end of each hour, the sun is placed at its centre"]  # fmt: skip
    scale = check_illuminance_units(ghi, gl, label) if gl is not None else None
    if scale is None:
        gl = nl = dl = None
        notes.append("no illuminance fields")
    else:
        gl, nl, dl = (None if a is None else np.nan_to_num(a * scale, nan=0.0) for a in (gl, nl, dl))
        if scale != 1.0:
            notes.append(f"illuminance fields read as units of {scale:g} lx (median GH illuminance / GHI of the file "
                         f"{float(np.median(gl[ghi > _CHECK_GHI_W_M2] / ghi[ghi > _CHECK_GHI_W_M2]) / scale):.3f}), scaled to lux")  # fmt: skip
    dew = _float(df, cols["dew"])
    dew = np.full(len(df), 11.0) if dew is None else np.nan_to_num(dew, nan=11.0)
    end = df.index
    centre = end - pd.Timedelta(minutes=30)
    lat, lon = float(meta["latitude"]), float(meta["longitude"])
    sp = get_solarposition(centre, lat, lon, altitude=alt)
    return Weather(str(p), site, lat, lon, alt, tz, end, centre, dni, dhi, ghi, nl, dl, gl, dew,
                   np.asarray(sp["azimuth"], np.float64), np.asarray(sp["apparent_elevation"], np.float64), notes)  # fmt: skip


def derive_tmy3_lux(src: str | os.PathLike, dst: str | os.PathLike | None = None) -> str:
    """A small TMY3 file from a full one: its first line, then date, time, the radiation and
    illuminance columns and the dew point, illuminances scaled to lux (×100, see the module's Notes) and zenith
    luminance to cd/m² (×10) where the data say they are in those units. Returns the text; writes ``dst`` if given.

    This is how ``stages/weather/greensboro_tmy3_lux.csv`` was made from
    pvlib's ``pvlib/data/723170TYA.CSV`` (Greensboro, NC, TMY3)."""
    import pandas as pd

    lines = Path(src).read_text().splitlines()
    df = pd.read_csv(src, skiprows=1, header=0, dtype=str)
    keep = ["Date (MM/DD/YYYY)", "Time (HH:MM)", "GHI (W/m^2)", "DNI (W/m^2)", "DHI (W/m^2)", "GH illum (lx)", "DN illum (lx)",
            "DH illum (lx)", "Zenith lum (cd/m^2)", "Dew-point (C)"]  # fmt: skip
    out = df[keep].copy()
    ghi = out["GHI (W/m^2)"].astype(float).to_numpy()
    scale = check_illuminance_units(ghi, out["GH illum (lx)"].astype(float).to_numpy(), str(src)) or 1.0
    for c in ("GH illum (lx)", "DN illum (lx)", "DH illum (lx)"):
        out[c] = (out[c].astype(float) * scale).round().astype(int).astype(str)
    if scale == 100.0:  # the same file stores zenith luminance in units of 10 cd/m²
        out["Zenith lum (cd/m^2)"] = (out["Zenith lum (cd/m^2)"].astype(float) * 10.0).round().astype(int).astype(str)
    text = lines[0] + "\n" + out.to_csv(index=False, lineterminator="\n")
    if dst is not None:
        Path(dst).write_text(text)
    return text


def daylight_mask(w: Weather) -> np.ndarray:
    """Hours with daylight: the sun above the horizon at the hour's centre, or any diffuse light."""
    return (w.sun_elevation_deg > 0.0) | (w.dhi_w_m2 > 0.0)


def hour_of_day(w: Weather) -> np.ndarray:
    """Local standard time of each hour's centre, hours (0.5 … 23.5)."""
    c = w.centre
    return np.asarray(c.hour + c.minute / 60.0, np.float64)



