"""Annual daylight metrics of a zone from its sensors' hourly illuminances.

For hourly work-plane illuminances E[h, i] (lux) of a zone's N sensors:

DA300 (daylight autonomy, IES LM-83-12 §2.2.1)
    Per sensor, the fraction of occupied hours with E ≥ 300 lx; the zone's
    figure is the mean over its sensors.
sDA300/50% (spatial daylight autonomy, LM-83-12 §2.2)
    The fraction of sensors whose DA300 is at least 50%. With ``[shading]``
    the hours are those of the shades as their rule operated them (LM-83-12
    §2.2.7: closed where more than 2% of the sensors see over 1000 lx of
    direct sun; :mod:`simulator.study.annual.shading`), otherwise as the
    stage is.
ASE1000/250h (annual sunlight exposure, LM-83-12 §2.3)
    The fraction of sensors that see more than 1000 lx of *direct sun only*
    (no interreflection, no sky) for more than 250 occupied hours, shades up
    (the first shading state); the direct sun is exact
    (:mod:`simulator.study.annual.sunlight`), so ASE has no variance.
UDI (useful daylight illuminance, Nabil and Mardaljevic 2005)
    Per sensor, the fractions of occupied hours below 100 lx (fell short),
    from 100 to 2000 lx (useful) and above 2000 lx (exceeded); zone means.
    The band edges are settings (``udi_lx``).
EN 17037 daylight provision (EN 17037:2018 §5.1, Table A.1, minimum level)
    Of the daylight hours (the sun above the horizon at the hour's centre,
    about half the year), the fraction in which at least 50% of the sensors
    see E ≥ 300 lx (target), and the fraction in which at least 95% see
    E ≥ 100 lx (minimum target); the zone meets the minimum level when both
    fractions are at least 50%.
Daylight factor (CIE overcast sky)
    DF = E / E_h × 100% with E_h the sky's unobstructed horizontal
    illuminance; the zone's figure is the mean over its sensors.

Occupied hours are 08:00–18:00 local standard time by default
(LM-83-12's 10 hours a day, 3650 a year), each hour counted by its centre.

Uncertainty: the hourly readings of one sensor share their daylight
coefficients, so their errors are correlated across hours; each metric's
standard error is the standard deviation of the metric over replicates of the
whole year recombined from coefficients redrawn from their covariance
(:func:`simulator.study.annual.year.replicate_years`).

References
----------
IES LM-83-12 (2012). Approved method: IES spatial daylight autonomy (sDA)
and annual sunlight exposure (ASE). Illuminating Engineering Society.
Nabil, A. and Mardaljevic, J. (2005). Useful daylight illuminance: a new
paradigm for assessing daylight in buildings. Lighting Research and
Technology 37(1), 41–59.
EN 17037:2018 Daylight in buildings. CEN.
docs/REFERENCES.md §Annual daylight metrics.
"""

from __future__ import annotations

import numpy as np

__all__ = ["METRICS", "zone_metrics"]

#: metric -> (unit, one-line definition) in output order
METRICS = {
    "DA": ("%", "mean over sensors of the share of occupied hours with E >= da_lx"),
    "sDA": ("%", "share of sensors with DA >= 50% (LM-83-12, no blind operation)"),
    "ASE": ("%", "share of sensors with direct sun >= ase_lx for more than ase_hours occupied hours"),
    "UDI_fell_short": ("%", "mean share of occupied hours with E < udi_lx[0]"),
    "UDI_useful": ("%", "mean share of occupied hours with udi_lx[0] <= E <= udi_lx[1]"),
    "UDI_exceeded": ("%", "mean share of occupied hours with E > udi_lx[1]"),
    "EN17037_target": ("%", "share of daylight hours with >= 50% of sensors at E >= en17037_lx[0]"),
    "EN17037_minimum": ("%", "share of daylight hours with >= 95% of sensors at E >= en17037_lx[1]"),
    "EN17037_pass": ("0/1", "1 when both EN 17037 shares are >= 50% (minimum level)"),
    "DF": ("%", "mean daylight factor under the CIE overcast sky"),
}


def zone_metrics(e: np.ndarray, direct: np.ndarray, occupied: np.ndarray, daylight: np.ndarray, df: np.ndarray, cfg,
                 hour_weight: float = 1.0) -> dict[str, float]:  # fmt: skip
    """Every metric of :data:`METRICS` for one zone.

    Parameters
    ----------
    e, direct : ndarray, shape (H, N)
        Hourly illuminance and its direct-sun part, lux.
    occupied, daylight : ndarray of bool, shape (H,)
        The analysis hours of LM-83 and UDI, and of EN 17037.
    df : ndarray, shape (N,)
        Daylight factors (fractions).
    cfg : AnnualSpec-like
        ``da_lx, ase_lx, ase_hours, udi_lx, en17037_lx``.
    hour_weight : float
        Hours each row stands for (``step_h``): ASE counts hours.
    """
    eo = e[occupied]
    n_occ = max(len(eo), 1)
    da = np.sum(eo >= cfg.da_lx, axis=0) / n_occ
    ase_hours = np.sum(direct[occupied] >= cfg.ase_lx, axis=0) * hour_weight
    lo, hi = cfg.udi_lx
    ed = e[daylight]
    n_day = max(len(ed), 1)
    tgt = np.mean(ed >= cfg.en17037_lx[0], axis=1) >= 0.5 if len(ed) else np.zeros(0, bool)
    mn = np.mean(ed >= cfg.en17037_lx[1], axis=1) >= 0.95 if len(ed) else np.zeros(0, bool)
    t_share, m_share = float(np.sum(tgt)) / n_day, float(np.sum(mn)) / n_day
    return {
        "DA": 100.0 * float(np.mean(da)),
        "sDA": 100.0 * float(np.mean(da >= 0.5)),
        "ASE": 100.0 * float(np.mean(ase_hours > cfg.ase_hours)),
        "UDI_fell_short": 100.0 * float(np.mean(np.sum(eo < lo, axis=0) / n_occ)),
        "UDI_useful": 100.0 * float(np.mean(np.sum((eo >= lo) & (eo <= hi), axis=0) / n_occ)),
        "UDI_exceeded": 100.0 * float(np.mean(np.sum(eo > hi, axis=0) / n_occ)),
        "EN17037_target": 100.0 * t_share,
        "EN17037_minimum": 100.0 * m_share,
        "EN17037_pass": float(t_share >= 0.5 and m_share >= 0.5),
        "DF": 100.0 * float(np.mean(df)),
    }
