"""Spectral or per-band estimates → every requested response, each with its standard error.

A response is linear in the spectrum (:class:`~simulator.spectra.responses.Response`),
so an estimate's standard error maps through the same weights:

* On the grid, ``R = q · x`` and ``Var R = qᵀ Σ q``, Σ the covariance of the
  estimate ``x`` (shape (401, 401)). With only per-wavelength standard
  errors σ the grid values must be independent (``Var R = Σ q_i² σ_i²``).
* Per band (Monte Carlo with one path carrying every band), the bands of a
  sample are correlated: they share the path. ``R = w · X`` with
  :func:`band_weights` ``w`` and ``Var R = wᵀ Σ_b w``, Σ_b the band
  covariance of the mean. A kernel can instead project each sample onto
  ``w`` and keep one running sum and sum of squares per response: the same
  variance without an n × n covariance.

Notes
-----
Band weights for an emitter spectrum S: a band b carries ``X_b = ∫_b f dλ``
of the spectral quantity f. If within the band f ∝ S (true for one emitter
in a scene whose reflectances are constant over the band),
``∫_b q f dλ = X_b · ∫_b q S dλ / ∫_b S dλ``, so
``w_b = ∫_b q S / ∫_b S`` (q as a density: the response's weighting).
This is exact for grey scenes and for reflectances that are flat within
each band; the error elsewhere is measured in docs/DESIGN.md "Spectral
transport".
"""

from __future__ import annotations

import numpy as np

from simulator.spectra.grid import Bands, trapezoid_weights

__all__ = ["reduce_grid", "band_weights", "reduce_bands", "posthoc_ratio"]


def reduce_grid(responses, mean: np.ndarray, cov: np.ndarray | None = None,
                stderr: np.ndarray | None = None) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Responses of spectral estimates on the grid with their standard errors.

    Parameters
    ----------
    responses : iterable of Response
    mean : ndarray, shape (..., 401)
        Spectral density estimates (e.g. W m⁻² nm⁻¹).
    cov : ndarray, shape (..., 401, 401), optional
        Covariance of ``mean`` (of the mean, not of one sample).
    stderr : ndarray, shape (..., 401), optional
        Per-wavelength standard errors of independent estimates; ignored when
        ``cov`` is given. Neither: standard errors are 0 (an exact spectrum).

    Returns
    -------
    dict of str to (ndarray, ndarray)
        Response name → ``(value, stderr)``, shapes (...).
    """
    mean = np.asarray(mean, float)
    out = {}
    for r in responses:
        v = mean @ r.q
        if cov is not None:
            var = np.einsum("...i,...ij,...j->...", np.broadcast_to(r.q, mean.shape), np.asarray(cov, float),
                            np.broadcast_to(r.q, mean.shape))
        elif stderr is not None:
            var = (np.asarray(stderr, float) ** 2) @ (r.q ** 2)
        else:
            var = np.zeros_like(v)
        out[r.name] = (v, np.sqrt(np.maximum(var, 0.0)))
    return out


def band_weights(response, bands: Bands, emitter: np.ndarray) -> np.ndarray:
    """Per-band weights ``w_b = ∫_b q S dλ / ∫_b S dλ`` of a response under an emitter (see Notes).

    Parameters
    ----------
    response : Response
    bands : Bands
    emitter : ndarray, shape (401,)
        The emitter's spectral shape S (only its shape within each band matters).

    Returns
    -------
    ndarray, shape (n,)
        The response per W in each band; 0 for a band where S is 0. For a
        spectrum ∝ S, ``w · bands.integrate(f) == q · f`` to rounding: a grid
        point on a band edge gives each side its trapezoid half.
    """
    b = bands.matrix()                      # (n, 401): trapezoid weights of each band
    share = b / trapezoid_weights()         # fraction of grid point i's weight that lies in band b
    s = np.asarray(emitter, float)
    num = share @ (response.q * s)          # ∫_b q S dλ, splitting q's weight at shared edge points
    den = b @ s                             # ∫_b S dλ
    return np.divide(num, den, out=np.zeros_like(num), where=den > 0)


def reduce_bands(weights: dict[str, np.ndarray], mean: np.ndarray,
                 cov: np.ndarray | None = None) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Responses of per-band estimates: ``R = w · X``, ``stderr = sqrt(wᵀ Σ_b w)``.

    Parameters
    ----------
    weights : dict of str to ndarray, shape (n,)
        Response name → :func:`band_weights`.
    mean : ndarray, shape (..., n)
        Band integrals (e.g. W m⁻² in each band).
    cov : ndarray, shape (..., n, n), optional
        Covariance of ``mean`` between bands (None: exact, stderr 0).

    Returns
    -------
    dict of str to (ndarray, ndarray)
    """
    mean = np.asarray(mean, float)
    out = {}
    for name, w in weights.items():
        v = mean @ w
        var = np.zeros_like(v) if cov is None else np.einsum("i,...ij,j->...", w, np.asarray(cov, float), w)
        out[name] = (v, np.sqrt(np.maximum(var, 0.0)))
    return out


def posthoc_ratio(response, emitter: np.ndarray) -> float:
    """Response per radiometric watt of an emitter spectrum: ``q · S / ∫ S dλ`` (380–780 nm).

    In a grey scene whose emitters share one spectral shape S, every
    spectral reading is ``E_λ = E · S(λ)/∫S`` (grey transport scales every
    wavelength alike), so ``R = E · posthoc_ratio`` and ``stderr_R = stderr_E
    · posthoc_ratio``, exactly.
    """
    s = np.asarray(emitter, float)
    return float(response.q @ s / (trapezoid_weights() @ s))

