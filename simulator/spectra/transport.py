"""How many spectral channels a run needs, and why: the planner's spectral decision.

Three cases, cheapest first (docs/DESIGN.md, "Spectral transport"):

``grey``
    Every albedo is grey and every emitter has one spectral shape: one
    radiometric channel, every response post hoc (:mod:`simulator.spectra.posthoc`).
    Exact.
``per-emitter``
    Grey albedos, several emitter spectra: transport is still
    wavelength-independent, so each emitter could carry its response vector
    (one value per requested response, the generalisation of the
    (radiometric, photometric) pair), exactly. That tally is not built:
    such scenes are traced like ``spectral`` ones (unbiased, with
    wavelength noise).
``spectral``
    A coloured albedo, a measured reflectance that is not flat (or a
    coloured textured emitter) can change a reading:
    hero-wavelength transport, 4 wavelengths per path; every response is
    estimated per sample and carries the wavelength noise in its stderr.
"""

from __future__ import annotations

__all__ = ["TRANSPORTS", "HERO_WAVELENGTHS", "choose_transport"]

#: transport modes, cheapest first
TRANSPORTS = ("grey", "per-emitter", "spectral")
#: wavelengths each path carries in spectral mode (Wilkie et al. 2014)
HERO_WAVELENGTHS = 4


def choose_transport(scene, n_responses: int = 2) -> tuple[str, int, str]:
    """``(mode, channels, reason)`` for a scene.

    Parameters
    ----------
    scene : simulator.scene.model.Scene
    n_responses : int
        Responses the run reports (radiometric and photopic always: 2).

    Returns
    -------
    mode : str
        One of :data:`TRANSPORTS`.
    channels : int
        Values each path carries: 1 (grey; the photometric twin is then a
        ratio), :data:`HERO_WAVELENGTHS` otherwise.
    reason : str
        One line for ``probesim plan`` and the run record.
    """
    from simulator.spectra.posthoc import emitter_efficacies, posthoc_refusal

    why = posthoc_refusal(scene)
    if why is None:
        return "grey", 1, ("albedos are grey and every emitter has one spectrum: one channel, "
                           "responses exact post hoc")
    if why.startswith("emitters have"):
        n = len(set(round(float(k), 9) for k in emitter_efficacies(scene)))
        return "per-emitter", HERO_WAVELENGTHS, (f"albedos are grey but {n} emitter spectra differ; the exact "
                                                 f"per-emitter tally is not built: {HERO_WAVELENGTHS} hero "
                                                 "wavelengths per path")
    return "spectral", HERO_WAVELENGTHS, f"{why}; {HERO_WAVELENGTHS} hero wavelengths per path"
