"""Responses of a grey scene from its radiometric (or photometric) readings: exact, no spectral tracing.

Claim: when every albedo is grey and every emitter has the same spectral
shape S, each reading's spectrum is ``E_λ = E · S(λ) / ∫S dλ``. Light
transport is linear and, with grey albedos, the same at every wavelength: a
reading is ``Σ_l G_l L_l(λ)`` with geometry factors ``G_l`` (all bounces
included) that do not depend on λ, and ``L_l(λ) = c_l S(λ)``. So any
response is ``R = E · q·S/∫S`` and its standard error scales alike: the
one-channel run plus these ratios is spectrally exact (tested against a
spectral sum over lights in tests/test_spectra_posthoc.py).

With several emitter spectra the ratio differs per light, so the readings
need one tally per light (or, as the kernels will do, a response vector per
emitter instead of the (radiometric, photometric) pair); with any coloured
albedo they need spectral transport (docs/DESIGN.md, "Spectral transport").
:func:`posthoc_refusal` says which applies.

The column the stage *states* is kept: radiometric readings when
``light_units = "radiometric"``, photometric ones otherwise. When the run
declares the emitters' spectrum (``[spectra] lights``) and the stage reader
gave the lights another twin (it knows only D65, E and blackbodies), the
other column is recomputed from the declared spectrum and a note says so.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from simulator.spectra.reduce import posthoc_ratio
from simulator.spectra.sources import Spectrum

__all__ = ["BASE_COLUMNS", "PosthocResult", "emitter_efficacies", "posthoc_refusal", "apply_posthoc", "response_channels",
           "rgb_per_luminance", "run_spectrum", "finish_run"]

#: per quantity: (radiometric column, photometric column) of the CSV, in row values
BASE_COLUMNS = {
    "irradiance": ("irradiance_W_m2", "illuminance_lx"),
    "radiance": ("radiance_W_m2_sr", "luminance_cd_m2"),
    "flux": ("flux_W", "luminous_flux_lm"),
    "scalar_irradiance": ("scalar_irradiance_W_m2", "scalar_illuminance_lx"),
}

#: the stage reader's summary warning when it reduced a colour to grey
_COLOURED_WARNING = "coloured albedo/emission/light colour reduced to luminance grey"
_K_REL_TOL = 1e-9


@dataclass
class PosthocResult:
    """What :func:`apply_posthoc` did.

    Attributes
    ----------
    spectrum : str
        Name of the emitter spectrum the ratios came from.
    ratios : dict of str to float
        Response name → response per radiometric watt (µmol/J for ``par``,
        lm/W for ``photopic``, …).
    columns : list of str
        CSV columns added, value and stderr, in order.
    notes : list of str
    """

    spectrum: str
    ratios: dict[str, float]
    columns: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def to_record(self) -> dict:
        return {"path": "post-hoc (grey scene, one emitter spectrum)", "spectrum": self.spectrum,
                "per_radiometric_W": dict(self.ratios), "columns": list(self.columns), "notes": list(self.notes)}


def emitter_efficacies(scene) -> np.ndarray:
    """Photometric/radiometric ratio (lm/W) of every emitter that emits: lights, then emissive triangles."""
    em = np.asarray(scene.geometry.emission, float).reshape(-1, 2)
    pairs = np.concatenate([np.asarray([l.emission for l in scene.lights], float).reshape(-1, 2), em])
    lit = pairs[:, 0] > 0  # vectorised: a tessellated stage has 10⁵–10⁶ triangles
    return pairs[lit, 1] / pairs[lit, 0]


def _measured_curves(geometry) -> list[str]:
    """Names of the measured reflectances (``Geometry.reflectances``) some triangle uses that are not flat."""
    from simulator.spectra.reflectance import is_flat

    ids = getattr(geometry, "reflectance_id", None)
    if ids is None:
        return []
    used = np.unique(ids[ids >= 0])
    return [geometry.reflectances[i][0] for i in used if not is_flat(geometry.reflectances[i][1])]


def _coloured_surfaces(geometry) -> list[str]:
    """Materials (``Geometry.surfaces``) whose pane has a measured transmittance that is not flat, or
    whose specular workflow's ``specularColor`` is not grey."""
    from simulator.spectra.reflectance import is_flat

    out = []
    for s in getattr(geometry, "surfaces", []) or []:
        if s.pane and s.transmittance_spectrum is not None and not is_flat(s.transmittance_spectrum[1]):
            out.append(f"{s.name} (transmittance {s.transmittance_spectrum[0]})")
        elif s.glossy and s.use_specular_workflow and np.ptp(np.asarray(s.specular_color, float)) > 0:
            out.append(f"{s.name} (specularColor)")
    return out


def posthoc_refusal(scene) -> str | None:
    """Why the post-hoc path would not be exact for this scene, or None when it is.

    Not exact: a material's measured reflectance or a pane's measured transmittance is not flat, a
    specular workflow's specularColor is not grey, a colour was
    reduced to grey (the stage reader's summary warning), or the emitters have different spectra (their
    photometric/radiometric ratios differ).
    """
    measured = _measured_curves(scene.geometry)
    if measured:
        return f"measured reflectance {', '.join(measured)} is not flat: a colour can change a reading"
    surfaces = _coloured_surfaces(scene.geometry)
    if surfaces:
        return f"coloured surface {', '.join(surfaces)}: a colour can change a reading"
    coloured = [w for w in scene.warnings if w.startswith(_COLOURED_WARNING + ": ")]
    if coloured:
        where = coloured[0][len(_COLOURED_WARNING) + 2:]
        return f"coloured albedo, emission or light colour at {where}: a colour can change a reading"
    k = emitter_efficacies(scene)
    if k.size and np.ptp(k) > _K_REL_TOL * k.max():
        return (f"emitters have {len(np.unique(np.round(k, 9)))} different spectra (efficacies "
                f"{k.min():.6g}–{k.max():.6g} lm/W); responses need a tally per light")
    return None


def apply_posthoc(rows, scene, light_units: str, spectrum: Spectrum, responses) -> PosthocResult:
    """Add every response's columns to every row, from the stated column × the spectrum's ratio.

    Parameters
    ----------
    rows : list of simulator.io.results.Reading
        Changed in place: ``values`` gains ``<stem>_<unit>`` and
        ``<stem>_stderr_<unit>`` per response and quantity present; the
        twin column is rewritten when the declared spectrum disagrees with
        the stage reader's (see module docstring).
    scene : simulator.scene.model.Scene
    light_units : {"photometric", "radiometric"}
    spectrum : Spectrum
        The spectral shape every emitter shares.
    responses : iterable of Response

    Returns
    -------
    PosthocResult

    Raises
    ------
    ValueError
        :func:`posthoc_refusal` gives a reason (callers report it, or trace spectrally).
    """
    why = posthoc_refusal(scene)
    if why is not None:
        raise ValueError(why)
    responses = list(responses)
    s = spectrum.values
    k_s = spectrum.efficacy_lm_W
    ratios = {r.name: posthoc_ratio(r, s) for r in responses}
    out = PosthocResult(spectrum.name, ratios, notes=list(spectrum.notes))
    k = emitter_efficacies(scene)
    rewrite = bool(k.size) and abs(float(k[0]) - k_s) > 1e-6 * k_s
    if rewrite:
        twin = "photometric" if light_units == "radiometric" else "radiometric"
        out.notes.append(f"{twin} columns recomputed from {spectrum.name} (K = {k_s:.6g} lm/W); "
                         f"the stage reader used K = {float(k[0]):.6g} lm/W")
    stated = 0 if light_units == "radiometric" else 1
    per_stated = 1.0 if stated == 0 else 1.0 / k_s  # radiometric W per unit of the stated column
    seen: dict[str, None] = {}
    for row in rows:
        v = row.values
        for quantity, cols in BASE_COLUMNS.items():
            base = cols[stated]
            if base not in v:
                continue
            base_se = _stderr_name(base)
            watts, watts_se = v[base] * per_stated, v.get(base_se, 0.0) * per_stated
            if rewrite:
                twin_col = cols[1 - stated]
                factor = k_s if stated == 0 else 1.0
                v[twin_col], v[_stderr_name(twin_col)] = watts * factor, watts_se * factor
            for r in responses:
                col, col_se = r.columns(quantity)
                v[col], v[col_se] = watts * ratios[r.name], watts_se * ratios[r.name]
                seen[col] = seen[col_se] = None
    base_names = {c for pair in BASE_COLUMNS.values() for b in pair for c in (b, _stderr_name(b))}
    out.columns = [c for c in seen if c not in base_names]  # radiometric, photopic: the CSV's own columns
    return out


def _stderr_name(column: str) -> str:
    """``ppfd_umol_m2_s`` → ``ppfd_stderr_umol_m2_s``; for the base columns, the CSV's own names."""
    known = {
        "irradiance_W_m2": "irradiance_stderr_W_m2", "illuminance_lx": "illuminance_stderr_lx",
        "radiance_W_m2_sr": "radiance_stderr_W_m2_sr", "luminance_cd_m2": "luminance_stderr_cd_m2",
        "flux_W": "flux_stderr_W", "luminous_flux_lm": "luminous_flux_stderr_lm",
        "scalar_irradiance_W_m2": "scalar_irradiance_stderr_W_m2", "scalar_illuminance_lx": "scalar_illuminance_stderr_lx",
    }  # fmt: skip
    return known[column]


def response_channels(responses) -> list[dict]:
    """Grid-map channels of responses for :func:`simulator.io.maps.grid_outputs`.

    Each: ``{"channel", "stderr_channel", "unit", "title"}`` where the
    channels are the irradiance columns (``ppfd_umol_m2_s``, …) and the unit
    is written as in map titles (``umol/m2/s``). Radiometric and photopic
    are already in every grid map and are skipped.
    """
    out = []
    for r in responses:
        if r.name in ("radiometric", "photopic"):
            continue
        col, col_se = r.columns("irradiance")
        unit = r.units["irradiance"].replace("umol", "µmol").replace("_", "/")
        out.append({"channel": col, "stderr_channel": col_se, "unit": unit, "title": r.title, "name": r.name})
    return out


def rgb_per_luminance(spectrum: Spectrum) -> np.ndarray:
    """Linear sRGB of an emitter spectrum per unit luminance (Y = 1), shape (3,).

    ``XYZ = ∫ S (x̄, ȳ, z̄) dλ / ∫ S ȳ dλ`` (CIE 1931 2°, ȳ = V), then the
    IEC 61966-2-1 XYZ → linear sRGB matrix. In a grey scene every radiance
    has the emitters' chromaticity, so a probe's RGB lat-long map is its
    luminance map × this (D65 → (1, 1, 1) to 1e-3: sRGB's white is D65).
    """
    import colour

    from simulator.spectra import tables
    from simulator.spectra.grid import integrate

    cmfs = tables.cmfs_1931()
    xyz = integrate(spectrum.values * cmfs) / integrate(spectrum.values * cmfs[1])
    return np.asarray(colour.models.RGB_COLOURSPACE_sRGB.matrix_XYZ_to_RGB, float) @ xyz


def _shared_temperature(scene) -> float | None:
    """The one ``colorTemperature`` (kelvin) every emitting light and emissive face has, or None.

    The stage reader gives a light with ``enableColorTemperature`` (and no
    ``probesim:spectrum``) its temperature as ``Light.spectrum``, a float;
    emitters on the run's default spectrum have its name, a str. None
    unless every emitter that emits has the same float.
    """
    spectra = [l.spectrum for l in scene.lights if l.emission[0] > 0]
    g = scene.geometry
    if g.n_triangles and np.any(np.asarray(g.emission)[:, 0] > 0):
        spectra.append(g.emissive_spectrum)
    kelvin = {float(s) for s in spectra if isinstance(s, (int, float)) and not isinstance(s, bool)}
    if len(kelvin) != 1 or len(kelvin) != len(set(map(str, spectra))):
        return None
    return kelvin.pop()


def _own_spectrum(scene, declared) -> Spectrum | None:
    """The spectrum the emitters name themselves (``probesim:spectrum``) in a grey scene; None when none does.

    ``declared`` is what the other emitters have (``[spectra] lights`` or
    the run's default).

    Raises
    ------
    UserError
        The emitters' spectra differ in shape but not in efficacy (so the
        planner saw one spectrum): one channel cannot carry them.
    """
    from simulator.errors import UserError
    from simulator.spectra.sources import emitter_spectrum

    lit = [l for l in scene.lights if l.emission[0] > 0]
    own = {str(l.spectrum): l.spectrum for l in lit if l.spectrum_authored}  # as named, in order
    followers = sum(not l.spectrum_authored for l in lit)
    g = scene.geometry
    if g.n_triangles and np.any(np.asarray(g.emission)[:, 0] > 0):
        if g.emissive_spectrum_authored:
            own.setdefault(str(g.emissive_spectrum), g.emissive_spectrum)
        else:
            followers += 1
    if not own:
        return None
    shape = emitter_spectrum(next(iter(own.values())))
    if len(own) > 1 or (followers and declared.name != shape.name):
        names = list(own) + ([declared.name] if followers else [])
        raise UserError(f"{scene.path}: emitters have spectra {names} of one efficacy: responses cannot be "
                        "computed from one channel; give them one spectrum")
    return shape


def run_spectrum(settings, scene, light_units: str, radiometric_spectrum) -> Spectrum | None:
    """The emitter spectrum a run's post-hoc responses use; None when none are asked for.

    Call it once the stage is read and before tracing, so that a run that
    cannot be answered exactly stops before it starts.

    Parameters
    ----------
    settings : simulator.spectra.config.SpectraSettings
    scene : simulator.scene.model.Scene
    light_units : str
    radiometric_spectrum : str or float
        The run's (the stage reader's default spectrum in radiometric units).

    Returns
    -------
    Spectrum or None
        ``[spectra] lights`` if declared, else the spectrum the stage reader
        gave the lights: the blackbody of their one ``colorTemperature`` when
        every emitter has it, else D65 photometric, ``radiometric_spectrum``
        otherwise.

    Raises
    ------
    UserError
        The scene needs spectral or per-emitter transport
        (:func:`posthoc_refusal`), or the lights share a spectrum the run
        does not name and the scene does not tell (not a blackbody
        temperature): name it in ``[spectra] lights``.
    """
    from simulator.errors import UserError
    from simulator.spectra.sources import emitter_spectrum

    if not settings.wanted:
        return None
    why = posthoc_refusal(scene)
    if why is not None:
        raise UserError(f"{scene.path}: responses {[r.name for r in settings.responses]} cannot be computed "
                        f"from one channel: {why}")
    others = settings.lights if settings.lights is not None else emitter_spectrum(
        "D65" if light_units == "photometric" else radiometric_spectrum)
    own = _own_spectrum(scene, others)
    if own is not None:
        return own
    if settings.lights is not None:
        return settings.lights
    temperature = _shared_temperature(scene)
    if temperature is not None:  # every emitter is a blackbody at one colorTemperature
        return emitter_spectrum(temperature)
    spectrum = emitter_spectrum("D65" if light_units == "photometric" else radiometric_spectrum)
    k = emitter_efficacies(scene)
    if k.size and abs(float(k[0]) - spectrum.efficacy_lm_W) > 1e-6 * spectrum.efficacy_lm_W:
        raise UserError(f"{scene.path}: every light has efficacy {float(k[0]):.6g} lm/W, not the run's "
                        f"{spectrum.name} ({spectrum.efficacy_lm_W:.6g} lm/W): name their spectrum in "
                        "[spectra] lights (e.g. their colorTemperature)")
    return spectrum


def finish_run(rows, scene, light_units: str, spectrum: Spectrum | None, settings) -> tuple[dict | None, list[dict]]:
    """Add the response columns to a run's rows (:func:`apply_posthoc`).

    Returns
    -------
    record : dict or None
        For the run record (``"spectra"``); None when nothing was asked for.
    map_channels : list of dict
        For :func:`simulator.io.maps.grid_outputs` ``responses=``.
    """
    if spectrum is None:
        return None, []
    done = apply_posthoc(rows, scene, light_units, spectrum, settings.responses)
    return {**done.to_record(), **settings.raw}, response_channels(settings.responses)
