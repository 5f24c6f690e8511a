"""A year of weather: EPW and TMY3 files read with pvlib, the sun at each hour's centre, units checked against the data.

A climate file gives, per hour, the direct-normal and diffuse-horizontal
irradiances (W/m²) and, usually, the matching illuminances (lx). Both formats
label each row with the *end* of its hour, local standard time (TMY3 and EPW
hour 1 is 00:00–01:00); the hour's value is a mean over it, so the sun is
placed at the hour's centre, 30 minutes before the label
(:attr:`Weather.centre`), with pvlib's solar position (NREL SPA, apparent
elevation: refraction included, as :mod:`simulator.study.inputs.sun`).

pvlib does not index the two formats alike: ``read_tmy3`` gives each row its
label (the hour's end; 24:00 as 00:00 of the next day), ``read_epw`` the
label's hour less one (``hour − 1``: the hour's *start*). The end is therefore
pvlib's index plus one hour for EPW, and for TMY3 the row's own date and time
(pvlib's index but for one row: it moves any 29 February timestamp to 1 March,
so a leap year's "02/28 24:00" would end a day late), so the same hour of data
gets the same end, centre and sun from either file. Radiance reads an
hourly EPW record the same way (``loadEPW``: time ``hour − 1 + 0.5``).

Closure. Global horizontal G, diffuse horizontal D and direct normal N of one
hour satisfy G = D + N·cos z (z the sun's zenith angle at the hour's centre).
On the hours with the sun at least :data:`CLOSURE_MIN_ELEVATION_DEG` up and G
above :data:`CLOSURE_MIN_GHI_W_M2` (or 100 times that in lux) the relative
error |G − D − N cos z| / G is read, for the irradiances and, where given,
the illuminances. An hour does not close beyond :data:`CLOSURE_HOUR_TOL`; a
year with more than :data:`CLOSURE_YEAR_FRACTION` of its hours so gets a
one-line warning (file, count, worst hour). Where the file's own assignment
has a median error above the hour tolerance and another assignment of the
three columns to (G, D, N) closes with a median below a third of it and below
:data:`CLOSURE_SWAPPED_MEDIAN`, the columns are taken as swapped and the file
is refused. Why these figures: the bundled TMY3 year (Greensboro) closes with
a median of 0.14% (irradiance) and 0.07% (illuminance), its worst hour 3.6%;
the hourly mean of N·cos z differs from N times the cosine at the hour's
centre by a few per cent only near sunrise and sunset, which the 5° floor
leaves out; pyranometer and pyrheliometer errors (a few per cent each) stay
well inside 10%. The same year with N and D swapped has a median error of
34%, and the swapped assignment closes at 0.14%.

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

__all__ = ["Weather", "read_weather", "check_illuminance_units", "check_closure", "derive_tmy3_lux", "EFFICACY_LUX_RANGE",
           "EFFICACY_HLUX_RANGE", "CLOSURE_HOUR_TOL", "CLOSURE_YEAR_FRACTION", "CLOSURE_SWAPPED_MEDIAN"]  # fmt: skip

#: plausible median GH illuminance / GHI when the fields are in lux (lm/W)
EFFICACY_LUX_RANGE = (50.0, 250.0)
#: ... and when they are in units of 100 lx
EFFICACY_HLUX_RANGE = (0.5, 2.5)
#: hours with GHI above this (W/m²) take part in the units check
_CHECK_GHI_W_M2 = 50.0

#: closure is read on hours with the sun at least this high at the hour's centre (degrees)
CLOSURE_MIN_ELEVATION_DEG = 5.0
#: ... and the global horizontal irradiance above this (W/m²; 100 × this in lux for illuminances)
CLOSURE_MIN_GHI_W_M2 = 50.0
#: an hour does not close when |G − D − N cos z| / G exceeds this
CLOSURE_HOUR_TOL = 0.10
#: a year warns when more than this share of its checked hours do not close
CLOSURE_YEAR_FRACTION = 0.01
#: another column assignment whose median error is below this (and a third of the file's) means swapped columns
CLOSURE_SWAPPED_MEDIAN = 0.05


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
    warnings : list of str
        Doubts about the data (components that do not close), one line each.
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
    warnings: list = field(default_factory=list)

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


#: the three columns' roles, as permutations of (G, D, N) a swapped file may have
_ROLE_NAMES = ("global horizontal", "diffuse horizontal", "direct normal")


def check_closure(g: np.ndarray, d: np.ndarray, n: np.ndarray, elevation_deg: np.ndarray, end, label: str, what: str,
                  min_g: float) -> str | None:  # fmt: skip
    """Whether an hour's global horizontal equals its diffuse plus its direct normal times cos z.

    Parameters
    ----------
    g, d, n : ndarray, shape (N,)
        Global horizontal, diffuse horizontal and direct normal, as the file's columns give them
        (W/m² or lx; NaN for missing).
    elevation_deg : ndarray, shape (N,)
        The sun's elevation at each hour's centre.
    end : pandas.DatetimeIndex
        Each hour's end (named in messages).
    label, what : str
        The file (``key: path``) and the quantity ("irradiance", "illuminance") named in messages.
    min_g : float
        Hours with a smaller global horizontal value are not read (the relative error of a dim hour says little).

    Returns
    -------
    str or None
        A one-line warning when more than :data:`CLOSURE_YEAR_FRACTION` of the hours read miss by more
        than :data:`CLOSURE_HOUR_TOL`, else None.

    Raises
    ------
    UserError
        When the columns look swapped: the file's assignment has a median error above the hour
        tolerance and another closes with a median below a third of it and below
        :data:`CLOSURE_SWAPPED_MEDIAN`.
    """
    import itertools

    cos_z = np.sin(np.radians(np.asarray(elevation_deg, np.float64)))
    up = np.asarray(elevation_deg, np.float64) >= CLOSURE_MIN_ELEVATION_DEG
    cols = [np.nan_to_num(np.asarray(c, np.float64), nan=0.0) for c in (g, d, n)]

    def errors(perm):
        gg, dd, nn = (cols[i] for i in perm)
        m = up & (gg > min_g)
        with np.errstate(divide="ignore", invalid="ignore"):
            r = np.abs(gg - dd - nn * cos_z) / np.where(m, gg, 1.0)
        return m, r

    m, r = errors((0, 1, 2))
    if m.sum() < 24:  # under a day of bright hours: nothing to judge
        return None
    median = float(np.median(r[m]))
    if median > CLOSURE_HOUR_TOL:
        best, best_median = None, median
        for perm in itertools.permutations(range(3)):
            mp, rp = errors(perm)
            if perm != (0, 1, 2) and mp.sum() >= 24 and (md := float(np.median(rp[mp]))) < best_median:
                best, best_median = perm, md
        if best is not None and best_median < min(CLOSURE_SWAPPED_MEDIAN, median / 3.0):
            moved = [f"the {_ROLE_NAMES[i]} column reads as {_ROLE_NAMES[k]}" for k, i in enumerate(best) if i != k]
            raise UserError(f"{label}: the {what} columns look swapped: as given, global horizontal = diffuse + direct normal "
                            f"x cos(zenith) misses by a median of {median:.0%} over {int(m.sum())} daylight hours; with "
                            f"{' and '.join(moved)} it closes to {best_median:.1%}; correct the file")  # fmt: skip
    bad = m & (r > CLOSURE_HOUR_TOL)
    if bad.sum() <= CLOSURE_YEAR_FRACTION * m.sum():
        return None
    k = int(np.argmax(np.where(m, r, -1.0)))
    gk, dk, nk = (float(c[k]) for c in cols)
    return (f"{label}: the {what} columns do not close: global horizontal differs from diffuse + direct normal x cos(zenith) by more "
            f"than {CLOSURE_HOUR_TOL:.0%} in {int(bad.sum())} of {int(m.sum())} daylight hours (sun above {CLOSURE_MIN_ELEVATION_DEG:g} deg; "
            f"median {median:.1%}); worst the hour ending {end[k]}: global {gk:.0f}, diffuse {dk:.0f} + direct {nk:.0f} x {cos_z[k]:.3f} "
            f"= {dk + nk * cos_z[k]:.0f} ({r[k]:.0%} off)")  # fmt: skip


def _float(df, col, missing: float = 9999.0) -> np.ndarray | None:
    """A column as float64, EPW's "missing" codes (9999 for radiation, 999999 for illuminance) and negatives as NaN."""
    if col not in df.columns:
        return None
    v = np.asarray(df[col], np.float64)
    return np.where((v >= missing) | (v < 0), np.nan, v)


def _tmy3_end(df, pd):
    """Each TMY3 row's end from its own ``Date`` and ``Time`` (24:00 is 00:00 of the next day), in pvlib's time zone.

    pvlib's ``read_tmy3`` moves every timestamp that falls on 29 February to 1 March (TMY years have no
    leap day), so the row "02/28/1996 24:00" (the hour 23:00–24:00 of 28 February) would end a day late."""
    date = pd.to_datetime(df["Date (MM/DD/YYYY)"], format="%m/%d/%Y")
    hm = df["Time (HH:MM)"].str.split(":")
    t = pd.to_timedelta(hm.str[0].astype(int), unit="h") + pd.to_timedelta(hm.str[1].astype(int), unit="min")
    return pd.DatetimeIndex(date + t).tz_localize(df.index.tz)


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
    if not df.index.is_unique:
        raise UserError(f"{label}: rows repeat an hour (a sub-hourly file?): only hourly EPW and TMY3 files are read")
    # pvlib's index: EPW the label's hour − 1 (its start); TMY3 the label (the hour's end), but for a
    # "02/28 24:00" row of a leap year, which it moves on to 1 March 00:00: the end is taken from the file's
    # own date and time there (see the module's notes)
    end = df.index + pd.Timedelta(hours=1) if ext == ".epw" else _tmy3_end(df, pd)
    centre = end - pd.Timedelta(minutes=30)
    lat, lon = float(meta["latitude"]), float(meta["longitude"])
    sp = get_solarposition(centre, lat, lon, altitude=alt)
    az, el = np.asarray(sp["azimuth"], np.float64), np.asarray(sp["apparent_elevation"], np.float64)
    warnings = [check_closure(ghi, dhi, dni, el, end, label, "irradiance", CLOSURE_MIN_GHI_W_M2)]
    if gl is not None and dl is not None and nl is not None:  # the illuminances, 100 lm/W to the irradiances' floor
        warnings.append(check_closure(gl, dl, nl, el, end, label, "illuminance", 100.0 * CLOSURE_MIN_GHI_W_M2))
    warnings = [w for w in warnings if w is not None]
    return Weather(str(p), site, lat, lon, alt, tz, end, centre, dni, dhi, ghi, nl, dl, gl, dew, az, el, notes, warnings)


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



