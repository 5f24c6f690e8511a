"""A year's daylight coefficients and their recombination into hourly readings.

:class:`Coefficients` holds, per sensor, the photometric daylight
coefficients of the sky's 146 patch slots (direct and interreflected) and of
the lamp groups, each with its covariance; :func:`hourly` recombines them
with each hour's patch levels into readings and standard errors (the method
is in :mod:`simulator.study.annual.year`'s Notes); :func:`replicate_years`
redraws them from N(ĉ, C) for the annual figures' bootstrap. Apart from
:mod:`.year` so that the sensor heads (:mod:`.heads`) can recombine a year
without importing the study that calls them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Coefficients", "hourly", "replicate_years"]


@dataclass
class Coefficients:
    """Per sensor, the photometric daylight coefficients of the sky's patches (146 slots) and of the lamp groups.

    ``dir``/``ind`` (S, 146) with covariances (S, 146, 146); ``lamp`` (S, G) with (S, G, G)."""

    dir: np.ndarray
    dir_cov: np.ndarray
    ind: np.ndarray
    ind_cov: np.ndarray
    lamp: np.ndarray
    lamp_cov: np.ndarray
    lamp_names: list
    samples: np.ndarray
    sun: np.ndarray | None = None  #: (S, B) traced sun per bin less its exact direct part, for the authored sun
    sun_var: np.ndarray | None = None  #: (S, B) its variance


def hourly(co: Coefficients, d: np.ndarray, q: np.ndarray, sun_direct: np.ndarray, stderr: bool = True,
           sun_bin: np.ndarray | None = None, sun_scale: np.ndarray | None = None, cone: np.ndarray | None = None):  # fmt: skip
    """Hourly readings (H, S) and their standard errors (see the module's Notes).

    ``cone`` (S,) marks cone photosensors: their *direct* coefficients hold
    the surfaces they see lit directly (the engine's direct component of a
    radiance meter is its first hit's light), so the sun in patches ``q``
    enters their direct coefficients too (and ``sun_direct`` holds only a
    sun inside the cone). With ``sun_bin`` (H,) and ``sun_scale`` (H,): the
    sun's light apart from ``sun_direct`` is the traced bin's coefficient
    times the hour's E_n over the authored sun's (``q`` is then 0)."""
    dq = d + q
    mean = d @ co.dir.T + dq @ co.ind.T + sun_direct
    if cone is not None and cone.any():
        mean[:, cone] += q @ co.dir[cone].T
    traced = sun_bin is not None and co.sun is not None
    if traced:
        on = sun_bin >= 0
        mean[on] += co.sun[:, sun_bin[on]].T * sun_scale[on, None]
    if not stderr:
        return mean, None
    var = np.zeros_like(mean)
    for s in range(co.dir.shape[0]):
        dd = dq if (cone is not None and cone[s]) else d
        var[:, s] = np.sum((dd @ co.dir_cov[s]) * dd, axis=1) + np.sum((dq @ co.ind_cov[s]) * dq, axis=1)
    if traced:
        var[on] += co.sun_var[:, sun_bin[on]].T * sun_scale[on, None] ** 2
    return mean, np.sqrt(np.maximum(var, 0.0))


def _sqrt_psd(c: np.ndarray) -> np.ndarray:
    """A with A Aᵀ = c for a covariance (negative eigenvalues from rounding set to 0), per leading index."""
    w, v = np.linalg.eigh(c)
    return v * np.sqrt(np.maximum(w, 0.0))[..., None, :]


def replicate_years(co: Coefficients, replicates: int, seed: int):
    """Yield ``replicates`` coefficient sets redrawn from N(ĉ, C) per sensor (a fixed seed)."""
    rng = np.random.default_rng(seed)
    ad, ai = _sqrt_psd(co.dir_cov), _sqrt_psd(co.ind_cov)
    al = _sqrt_psd(co.lamp_cov) if co.lamp.shape[1] else None
    for _ in range(replicates):
        zd = rng.standard_normal(co.dir.shape)
        zi = rng.standard_normal(co.ind.shape)
        zl = rng.standard_normal(co.lamp.shape)
        lamp = co.lamp + (np.einsum("sgk,sk->sg", al, zl) if al is not None else 0.0)
        sun = None if co.sun is None else co.sun + np.sqrt(np.maximum(co.sun_var, 0.0)) * rng.standard_normal(co.sun.shape)
        yield Coefficients(co.dir + np.einsum("spk,sk->sp", ad, zd), co.dir_cov, co.ind + np.einsum("spk,sk->sp", ai, zi), co.ind_cov,
                           lamp, co.lamp_cov, co.lamp_names, co.samples, sun, co.sun_var)  # fmt: skip
