"""The Perez all-weather sky, hour by hour, as Tregenza patch luminances; the Perez luminous efficacy model.

From an hour's diffuse-horizontal irradiance ``I_dh`` and direct-normal
irradiance ``I_n`` (W/m²) at solar zenith angle Z (radians), Perez et al.
(1990) define the sky's clearness and brightness

.. math:: \\varepsilon = \\frac{(I_{dh} + I_n)/I_{dh} + \\kappa Z^3}{1 + \\kappa Z^3},\\quad \\kappa = 1.041,
          \\qquad \\Delta = I_{dh}\\, m / I_0,

with m the relative optical air mass (Kasten 1966,
m = 1/(cos Z + 0.15 (93.885 − Z°)^−1.253)) and I_0 the extraterrestrial
normal irradiance of the day (pvlib). ε falls in one of 8 bins
(1, 1.065, 1.23, 1.5, 1.95, 2.8, 4.5, 6.2, ∞). The all-weather model (Perez,
Seals and Michalsky 1993, eqn. 1) gives the relative luminance at zenith
angle ζ and angular distance γ from the sun

.. math:: l(\\zeta, \\gamma) = [1 + a\\,e^{b/\\cos\\zeta}]\\,[1 + c\\,e^{d\\gamma} + e\\cos^2\\gamma],

with each of a…e = x₁ + x₂Z + Δ(x₃ + x₄Z) from the bin's row of
:data:`PEREZ_1993` (Table 1), except in the first bin, where
c = exp((Δ(c₁ + c₂Z))^c₃) − c₄ and d = −exp(Δ(d₁ + d₂Z)) + d₃ + Δd₄
(eqns. 7 and 8).

Normalisation. The model's luminance is relative; each hour's patch
luminances are scaled so the sky's unobstructed horizontal illuminance,
Σ_p L_p ∫_p cosθ dω, equals the hour's diffuse horizontal illuminance E_dh:
the file's illuminance field (``illuminance = "file"``, the default), or
E_dh = I_dh · K_d from the Perez (1990) diffuse luminous efficacy (Table 4,
eqn. 7: K_d = a + bW + c cos Z + d ln Δ lm/W, W = exp(0.07 T_d − 0.075) cm
of precipitable water from the dew point T_d in °C) with the direct
normal illuminance from eqn. 8 (K_n = max(0, a + bW + c e^{5.73Z − 5} + dΔ)).
Each patch's luminance is the model's mean over the patch (the midpoint rule
of :func:`simulator.study.inputs.sky_patches.patch_means`).

Where the model's inputs leave its range the hour is clamped to the range
the coefficients were fitted on, as Radiance's ``gendaymtx`` does
(:data:`CLEARNESS_RANGE`, :data:`BRIGHTNESS_RANGE`): 1 ≤ ε ≤ 12 (Perez 1990
Table 1's bins start at 1 and its clear bin holds ε ≥ 6.2; gendaymtx stops ε
at 11.9 from irradiances and 12 from illuminances, the same bin either way)
and 0.01 ≤ Δ ≤ 0.6 on both sides (and Δ ≥ 0.2 for 1.065 < ε < 2.8, as
gendaymtx's parameter routine), the sun's elevation for the sky's shape
within 0°…87° (a sun below the horizon at the hour's centre shapes a
twilight sky as if on the horizon; its direct light is 0), negative
luminances 0. Without the upper bound on Δ a bright diffuse hour at a low
sun (air mass ~36 at the horizon, so Δ of 5 and more) drives a…e far out
of the fitted range and the whole sky negative; the bound keeps it a sky.
Should a sky still have no positive luminance, it is made uniform (as
gendaymtx does), so an hour's diffuse light is never lost.

References
----------
Perez, R., Ineichen, P., Seals, R., Michalsky, J. and Stewart, R. (1990).
Modeling daylight availability and irradiance components from direct and
global irradiance. Solar Energy 44(5), 271–289.
Perez, R., Seals, R. and Michalsky, J. (1993). All-weather model for sky
luminance distribution — preliminary configuration and validation. Solar
Energy 50(3), 235–245; erratum 51(5), 423.
Kasten, F. (1966). A new table and approximation formula for the relative
optical air mass. Arch. Meteorol. Geophys. Bioklimatol. B14, 206–223.
docs/REFERENCES.md §Perez sky and efficacy.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from simulator.study.inputs import sky_patches as SP

__all__ = ["PEREZ_1993", "EPSILON_BINS", "CLEARNESS_RANGE", "BRIGHTNESS_RANGE", "DIFFUSE_EFFICACY", "DIRECT_EFFICACY", "air_mass",
           "clearness_brightness", "epsilon_bin", "perez_parameters", "relative_luminance", "efficacies", "HourSkies", "hour_skies"]  # fmt: skip

#: upper edges of the clearness bins (Perez 1990 Table 1); the last is open
EPSILON_BINS = (1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200)

#: Perez, Seals and Michalsky (1993) Table 1: per ε bin, (a1 a2 a3 a4, b1…b4, c1…c4, d1…d4, e1…e4)
PEREZ_1993 = np.array([
    [1.3525, -0.2576, -0.2690, -1.4366, -0.7670, 0.0007, 1.2734, -0.1233, 2.8000, 0.6004, 1.2375, 1.0000,
     1.8734, 0.6297, 0.9738, 0.2809, 0.0356, -0.1246, -0.5718, 0.9938],
    [-1.2219, -0.7730, 1.4148, 1.1016, -0.2054, 0.0367, -3.9128, 0.9156, 6.9750, 0.1774, 6.4477, -0.1239,
     -1.5798, -0.5081, -1.7812, 0.1080, 0.2624, 0.0672, -0.2190, -0.4285],
    [-1.1000, -0.2515, 0.8952, 0.0156, 0.2782, -0.1812, -4.5000, 1.1766, 24.7219, -13.0812, -37.7000, 34.8438,
     -5.0000, 1.5218, 3.9229, -2.6204, -0.0156, 0.1597, 0.4199, -0.5562],
    [-0.5484, -0.6654, -0.2672, 0.7117, 0.7234, -0.6219, -5.6812, 2.6297, 33.3389, -18.3000, -62.2500, 52.0781,
     -3.5000, 0.0016, 1.1477, 0.1062, 0.4659, -0.3296, -0.0876, -0.0329],
    [-0.6000, -0.3566, -2.5000, 2.3250, 0.2937, 0.0496, -5.6812, 1.8415, 21.0000, -4.7656, -21.5906, 7.2492,
     -3.5000, -0.1554, 1.4062, 0.3988, 0.0032, 0.0766, -0.0656, -0.1294],
    [-1.0156, -0.3670, 1.0078, 1.4051, 0.2875, -0.5328, -3.8500, 3.3750, 14.0000, -0.9999, -7.1406, 7.5469,
     -3.4000, -0.1078, -1.0750, 1.5702, -0.0672, 0.4016, 0.3017, -0.4844],
    [-1.0000, 0.0211, 0.5025, -0.5119, -0.3000, 0.1922, 0.7023, -1.6317, 19.0000, -5.0000, 1.2438, -1.9094,
     -4.0000, 0.0250, 0.3844, 0.2656, 1.0468, -0.3788, -2.4517, 1.4656],
    [-1.0500, 0.0289, 0.4260, 0.3590, -0.3250, 0.1156, 0.7781, 0.0025, 31.0625, -14.5000, -46.1148, 55.3750,
     -7.2312, 0.4050, 13.3500, 0.6234, 1.5000, -0.6426, 1.8564, 0.5636],
])  # fmt: skip

#: Perez et al. (1990) Table 4, diffuse luminous efficacy (a, b, c, d) per ε bin, lm/W (eqn. 7)
DIFFUSE_EFFICACY = np.array([
    [97.24, -0.46, 12.00, -8.91], [107.22, 1.15, 0.59, -3.95], [104.97, 2.96, -5.53, -8.77], [102.39, 5.59, -13.95, -13.90],
    [100.71, 5.94, -22.75, -23.74], [106.42, 3.83, -36.15, -28.83], [141.88, 1.90, -53.24, -14.03], [152.23, 0.35, -45.27, -7.98],
])  # fmt: skip
#: ... direct-normal luminous efficacy (a, b, c, d), lm/W (eqn. 8)
DIRECT_EFFICACY = np.array([
    [57.20, -4.55, -2.98, 117.12], [98.99, -3.46, -1.21, 12.38], [109.83, -4.90, -1.71, -8.81], [110.34, -5.84, -1.99, -4.56],
    [106.36, -3.97, -1.75, -6.16], [107.19, -1.25, -1.51, -26.73], [105.75, 0.77, -1.26, -34.44], [101.18, 1.58, -1.10, -8.29],
])  # fmt: skip

_KAPPA = 1.041
#: sky clearness ε and brightness Δ are clamped to these (the model's fitted range, as gendaymtx clamps them)
CLEARNESS_RANGE = (1.0, 12.0)
BRIGHTNESS_RANGE = (0.01, 0.6)
#: the sun's elevation range that shapes the sky (degrees), as gendaymtx clamps it
SKY_SUN_ELEVATION_DEG = (0.0, 87.0)


def air_mass(zenith_rad: np.ndarray) -> np.ndarray:
    """Relative optical air mass (Kasten 1966), zenith angle in radians (≤ 90°)."""
    z = np.asarray(zenith_rad, np.float64)
    return 1.0 / (np.cos(z) + 0.15 * np.power(93.885 - np.degrees(z), -1.253))


def clearness_brightness(dhi_w_m2, dni_w_m2, zenith_rad, dni_extra_w_m2) -> tuple[np.ndarray, np.ndarray]:
    """Perez sky clearness ε and brightness Δ, clamped to :data:`CLEARNESS_RANGE` and :data:`BRIGHTNESS_RANGE`
    on both sides; the lower bounds where I_dh = 0."""
    dhi = np.asarray(dhi_w_m2, np.float64)
    z3 = np.asarray(zenith_rad, np.float64) ** 3
    with np.errstate(divide="ignore", invalid="ignore"):
        eps = np.where(dhi > 0, ((dhi + dni_w_m2) / np.where(dhi > 0, dhi, 1.0) + _KAPPA * z3) / (1.0 + _KAPPA * z3), 1.0)
    delta = dhi * air_mass(zenith_rad) / np.asarray(dni_extra_w_m2, np.float64)
    return np.clip(eps, *CLEARNESS_RANGE), np.clip(delta, *BRIGHTNESS_RANGE)


def epsilon_bin(eps: np.ndarray) -> np.ndarray:
    """Bin index 0…7 of each clearness."""
    return np.searchsorted(np.asarray(EPSILON_BINS), np.asarray(eps, np.float64), side="right")


def perez_parameters(eps, delta, zenith_rad) -> np.ndarray:
    """(a, b, c, d, e) of the all-weather model, shape (N, 5)."""
    k = epsilon_bin(eps)
    z = np.asarray(zenith_rad, np.float64)
    delta = np.asarray(delta, np.float64)
    delta = np.where((eps > 1.065) & (eps < 2.8), np.maximum(delta, 0.2), delta)
    x = PEREZ_1993[k].reshape(-1, 5, 4)
    p = x[..., 0] + x[..., 1] * z[:, None] + delta[:, None] * (x[..., 2] + x[..., 3] * z[:, None])
    first = k == 0
    if first.any():
        xf, zf, df = x[first], z[first], delta[first]
        p[first, 2] = np.exp(np.power(df * (xf[:, 2, 0] + xf[:, 2, 1] * zf), xf[:, 2, 2])) - xf[:, 2, 3]
        p[first, 3] = -np.exp(df * (xf[:, 3, 0] + xf[:, 3, 1] * zf)) + xf[:, 3, 2] + df * xf[:, 3, 3]
    return p


def relative_luminance(params: np.ndarray, dirs: np.ndarray, sun: np.ndarray) -> np.ndarray:
    """l(ζ, γ) of eqn. 1 for N hours at M directions, shape (N, M), negatives 0.

    ``params`` (N, 5); ``dirs`` (M, 3) unit, above the horizon; ``sun`` (N, 3) unit."""
    a, b, c, d, e = (params[:, i : i + 1] for i in range(5))
    cos_z = np.clip(dirs[:, 2], 0.01, 1.0)[None, :]  # gendaymtx's floor at the horizon
    cos_g = np.clip(sun @ dirs.T, -1.0, 1.0)
    g = np.arccos(cos_g)
    lum = (1.0 + a * np.exp(b / cos_z)) * (1.0 + c * np.exp(d * g) + e * cos_g * cos_g)
    return np.maximum(lum, 0.0)


def efficacies(eps, delta, zenith_rad, dew_c) -> tuple[np.ndarray, np.ndarray]:
    """Diffuse and direct-normal luminous efficacy, lm/W (Perez 1990 eqns. 7, 8)."""
    k = epsilon_bin(eps)
    w = np.exp(0.07 * np.asarray(dew_c, np.float64) - 0.075)
    z = np.asarray(zenith_rad, np.float64)
    dc, nc = DIFFUSE_EFFICACY[k], DIRECT_EFFICACY[k]
    kd = dc[:, 0] + dc[:, 1] * w + dc[:, 2] * np.cos(z) + dc[:, 3] * np.log(delta)
    kn = np.maximum(nc[:, 0] + nc[:, 1] * w + nc[:, 2] * np.exp(5.73 * z - 5.0) + nc[:, 3] * delta, 0.0)
    return kd, kn


def _patch_grid(n_sub: int) -> tuple[np.ndarray, np.ndarray]:
    """Cell centres of every patch (patch_means' grid): directions (145·n², 3) and each cell's patch."""
    u = (np.arange(n_sub) + 0.5) / n_sub
    dirs, owner = [], []
    for p in range(SP.N_PATCHES):
        b = int(np.searchsorted(np.asarray(SP.BAND_START), p, side="right") - 1)
        a0, a1 = (math.radians(x) for x in SP.band_edges_deg(b))
        n = SP.BAND_COUNTS[b]
        s = math.sin(a0) + u * (math.sin(a1) - math.sin(a0))
        w = 2 * math.pi / n
        az = w * (p - SP.BAND_START[b]) + (u - 0.5) * w
        ss, aa = np.meshgrid(s, az, indexing="ij")
        cc = np.sqrt(np.maximum(1.0 - ss**2, 0.0))
        dirs.append(np.stack([np.sin(aa) * cc, np.cos(aa) * cc, ss], axis=-1).reshape(-1, 3))
        owner.append(np.full(n_sub * n_sub, p))
    return np.concatenate(dirs), np.concatenate(owner)


@dataclass
class HourSkies:
    """Each hour's sky and sun, in lux and cd/m².

    Attributes
    ----------
    patch_cd_m2 : ndarray, shape (N, 145)
        Tregenza patch luminances of the Perez sky (0 where there is no diffuse light).
    dhi_lx, dni_lx : ndarray, shape (N,)
        Diffuse horizontal illuminance the sky is scaled to; direct normal
        illuminance of the sun (0 where it is below the horizon at the hour's centre).
    sun_dir : ndarray, shape (N, 3)
        Unit direction toward the sun (world frame, +Y north).
    epsilon, delta : ndarray, shape (N,)
    """

    patch_cd_m2: np.ndarray
    dhi_lx: np.ndarray
    dni_lx: np.ndarray
    sun_dir: np.ndarray
    sun_up: np.ndarray
    epsilon: np.ndarray
    delta: np.ndarray

    @property
    def global_lx(self) -> np.ndarray:
        """The unobstructed horizontal illuminance these skies and suns are built to: E_dh + E_n sin h."""
        return self.dhi_lx + self.dni_lx * np.maximum(self.sun_dir[:, 2], 0.0)


def hour_skies(w, hours: np.ndarray, illuminance: str = "file", n_sub: int = 8, block: int = 256) -> HourSkies:
    """Perez skies and suns of the rows ``hours`` of a :class:`~simulator.study.annual.climate.Weather`.

    ``illuminance``: "file" (the file's diffuse and direct illuminance fields)
    or "efficacy" (the Perez 1990 efficacy model on its irradiances)."""
    from simulator.study.inputs.sun import sun_direction

    hours = np.asarray(hours, np.int64)
    az, el = w.sun_azimuth_deg[hours], w.sun_elevation_deg[hours]
    up = el > 0.0
    el_sky = np.clip(el, *SKY_SUN_ELEVATION_DEG)
    zen = np.radians(90.0 - el_sky)
    sun = np.stack([sun_direction(a, e) for a, e in zip(az, el)]) if len(hours) else np.zeros((0, 3))
    sun_sky = np.stack([sun_direction(a, e) for a, e in zip(az, el_sky)]) if len(hours) else np.zeros((0, 3))
    dhi, dni = w.dhi_w_m2[hours], np.where(up, w.dni_w_m2[hours], 0.0)
    import pandas as pd
    from pvlib.irradiance import get_extra_radiation

    i0 = np.asarray(get_extra_radiation(np.asarray(pd.DatetimeIndex(w.centre[hours]).day_of_year, np.float64)), np.float64)
    eps, delta = clearness_brightness(dhi, dni, zen, i0)
    if illuminance == "file":
        if w.dhi_lx is None or w.dni_lx is None:
            raise ValueError("the weather file has no illuminance fields: use illuminance = \"efficacy\"")
        e_dh, e_dn = w.dhi_lx[hours].copy(), np.where(up, w.dni_lx[hours], 0.0)
    else:
        kd, kn = efficacies(eps, delta, zen, w.dew_c[hours])
        e_dh, e_dn = dhi * kd, dni * kn
    e_dh = np.where(dhi > 0, np.maximum(e_dh, 0.0), 0.0)
    e_dn = np.maximum(e_dn, 0.0)
    params = perez_parameters(eps, delta, zen)
    dirs, owner = _patch_grid(n_sub)
    proj = np.array([SP.patch_projected_solid_angle(p) for p in range(SP.N_PATCHES)])
    out = np.zeros((len(hours), SP.N_PATCHES))
    for lo in range(0, len(hours), block):
        sl = slice(lo, lo + block)
        lum = relative_luminance(params[sl], dirs, sun_sky[sl])
        rel = lum.reshape(lum.shape[0], SP.N_PATCHES, n_sub * n_sub).mean(axis=2)
        h = rel @ proj
        flat = h <= 0.0  # no positive luminance left: a uniform sky keeps the hour's diffuse light (gendaymtx does the same)
        rel[flat], h[flat] = 1.0, proj.sum()
        with np.errstate(divide="ignore", invalid="ignore"):
            out[sl] = np.where(h[:, None] > 0, rel * (e_dh[sl] / np.where(h > 0, h, 1.0))[:, None], 0.0)
    del owner
    return HourSkies(out, e_dh, e_dn, sun, up, eps, delta)
