"""Units, spectra and photometry.

Where materials are grey, light transport is the same at every wavelength and
a reading needs only two integrals of each emitter's spectrum: its
radiometric total (W) and its photometric total (lm). This module turns a
light's stated value into that pair (scenes with colour are traced with hero
wavelengths, :mod:`simulator.spectra.hero`, from the same pair and the
emitter's spectral shape).

Notes
-----
Luminous efficacy of radiation of a spectrum S(λ) over 380–780 nm:

    K(S) = K_m · ∫ V(λ) S(λ) dλ / ∫ S(λ) dλ,   K_m = 683.002 lm/W,

with V the CIE 1924 photopic luminous efficiency function, integrated at
1 nm with the trapezoid rule. K_m is the CIE's (CIE 018:2019): the SI fixes
683 lm/W at 540 THz (555.016 nm in standard air), where V is 0.999997, so
the peak of K_m·V at 555 nm is 683/V(555.016 nm) = 683.002 lm/W; 683 for
K_m would put every lumen 2.9e-6 low against the SI. For CIE Illuminant D65 K ≈ 205.15 lm/W; for an
equal-energy spectrum K ≈ 182.46 lm/W.

References
----------
CIE 15:2004 Colorimetry; CIE 018:2019 (photometry); the CIE 1924 V(λ) and D65
tables as published by the ``colour-science`` package. docs/REFERENCES.md §Photometry.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

__all__ = [
    "K_CD",
    "K_M",
    "SPECTRA",
    "luminous_efficacy",
    "efficacy_from_tables",
    "NAMED_EFFICACY",
    "emission_pair",
    "luminance_grey",
]

#: luminous efficacy of monochromatic radiation of 540 × 10¹² Hz, lm/W (exact: the SI's K_cd)
K_CD = 683.0
#: maximum luminous efficacy of radiation for photopic vision, lm/W: K_cd / V(555.016 nm), the CIE's
#: K_m (CIE 018:2019); docs/REFERENCES.md §Photometry
K_M = 683.002

#: spectrum names accepted in configs
SPECTRA = ("D65", "E")

_WAVELENGTHS_NM = np.arange(380.0, 781.0, 1.0)

# Rec. 709 / linear sRGB luminance weights (ITU-R BT.709), the colour space
# UsdLux and UsdPreviewSurface colours are authored in by default. They sum to
# 1 exactly as decimals, but not as the nearest doubles; see luminance_grey.
_REC709_Y = np.array([0.2126, 0.7152, 0.0722])


def _spectrum_values(spectrum: str | float) -> np.ndarray:
    import colour  # lazy: ~1 s import, only needed once per run

    if isinstance(spectrum, str):
        if spectrum == "E":
            return np.ones_like(_WAVELENGTHS_NM)
        if spectrum == "D65":
            return np.asarray(colour.SDS_ILLUMINANTS["D65"][_WAVELENGTHS_NM], float)
        raise ValueError(f"unknown spectrum {spectrum!r}; expected one of {SPECTRA} or a temperature in K")
    shape = colour.SpectralShape(380, 780, 1)
    return np.asarray(colour.sd_blackbody(float(spectrum), shape).values, float)


#: K(S) of the named spectra, lm/W, from the tables as in :func:`efficacy_from_tables`
#: (kept as numbers so a run need not import colour-science, ~0.9 s; a test
#: checks them against the tables)
NAMED_EFFICACY = {"D65": 205.15264670605671, "E": 182.457836057514}


def luminous_efficacy(spectrum: str | float) -> float:
    """Luminous efficacy of radiation of a spectrum, lm/W.

    Parameters
    ----------
    spectrum : {"D65", "E"} or float
        A named spectrum, or a blackbody temperature in kelvin.

    Returns
    -------
    float
        K(S) in lm/W over 380–780 nm (see module Notes).
    """
    if isinstance(spectrum, str) and spectrum in NAMED_EFFICACY:
        return NAMED_EFFICACY[spectrum]
    return efficacy_from_tables(spectrum)


@lru_cache(maxsize=64)
def efficacy_from_tables(spectrum: str | float) -> float:
    """Luminous efficacy of radiation computed from the CIE tables (V(λ),
    D65, Planck's law via colour-science), lm/W.

    Parameters
    ----------
    spectrum : {"D65", "E"} or float
        A named spectrum, or a blackbody temperature in kelvin.

    Returns
    -------
    float
        K(S) in lm/W over 380–780 nm (see module Notes).
    """
    import colour

    v = np.asarray(
        colour.colorimetry.SDS_LEFS_PHOTOPIC["CIE 1924 Photopic Standard Observer"][_WAVELENGTHS_NM],
        float,
    )
    s = _spectrum_values(spectrum)
    return K_M * float(np.trapezoid(v * s, _WAVELENGTHS_NM) / np.trapezoid(s, _WAVELENGTHS_NM))


def emission_pair(value: float, light_units: str, spectrum: str | float) -> tuple[float, float]:
    """Turn a stated emission value into ``(radiometric, photometric)``.

    Parameters
    ----------
    value : float
        The number the stage states (after intensity·2^exposure·grey(color)/sizeFactor).
    light_units : {"photometric", "radiometric"}
        ``photometric``: ``value`` is photometric (cd/m², cd or lx);
        ``radiometric``: it is radiometric (W m⁻² sr⁻¹, W/sr or W/m²).
    spectrum : str or float
        Spectral shape of the emitter (see :func:`luminous_efficacy`).

    Returns
    -------
    (float, float)
        Radiometric value and its photometric twin.
    """
    k = luminous_efficacy(spectrum)
    if light_units == "photometric":
        return value / k, value
    if light_units == "radiometric":
        return value, value * k
    raise ValueError(f"light_units must be 'photometric' or 'radiometric', not {light_units!r}")


def luminance_grey(rgb):
    """Luminance-weighted grey of linear Rec. 709 colours (BT.709 Y weights).

    Parameters
    ----------
    rgb : array_like, shape (3,) or (..., 3)
        Linear Rec. 709 colours, any units.

    Returns
    -------
    float or numpy.ndarray, shape (...)
        Y = 0.2126·R + 0.7152·G + 0.0722·B, a float for one colour.

    Notes
    -----
    Evaluated as deviations from the green component,

        Y = G + 0.2126·(R − G) + 0.0722·(B − G),

    which equals the weighted sum because the weights sum to 1. Written this
    way the sum of the weights is never formed in floating point: an exactly
    grey colour (R = G = B = g) returns g itself (the plain dot product gives
    0.9·0.2126 + 0.9·0.7152 + 0.9·0.0722 = 0.8999999999999999), a near-grey
    one stays within its components' spread of g (R − G and B − G are exact
    for close components), and a scene's grey albedo or emission is read as
    authored, whatever the BLAS or summation order.

    References
    ----------
    ITU-R BT.709-6 (2015), item 3.2; docs/REFERENCES.md §Luminance of a colour.
    """
    c = np.asarray(rgb, dtype=np.float64)
    if c.shape[-1:] != (3,):
        raise ValueError(f"luminance_grey: expected colours of shape (..., 3), got {c.shape}")
    r, g, b = c[..., 0], c[..., 1], c[..., 2]
    y = g + _REC709_Y[0] * (r - g) + _REC709_Y[2] * (b - g)
    return float(y) if y.ndim == 0 else y
