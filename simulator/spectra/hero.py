"""What hero-wavelength transport uploads: reflectance, emission and response tables on the grid.

The kernels (``simulator.kernels.estimators``, spectral mode) draw per
sample one uniform ``u`` and carry four wavelengths ``x_k = 400·frac(u +
k/4)`` nm above 380 nm (Wilkie et al. 2014), each read at its nearest grid
node ``i_k = ⌊x_k + ½⌋ ∈ {0 … 400}``. Node ``i`` is then drawn with
probability ``w_i / 400``, ``w`` the trapezoid weights (½ at the two ends,
1 inside), so a lane's estimate of a response ``Σ_i q_i f_i`` (``q`` a
quadrature vector of :mod:`simulator.spectra.responses`) is

    q_i f_i / (w_i / 400) = W_i f_i,     W = 400 · q / w,

unbiased for the grid's trapezoid integral, which every host integral
(closed forms, efficacies, post-hoc ratios) uses. The four lanes' mean is
the sample's response. Tables, one row per item, 401 columns:

- reflectance: one row per distinct surface colour, the Mallett–Yuksel
  uplift of its linear sRGB albedo (a face indexes its row), then one row
  per measured reflectance a material names (``probesim:reflectance``,
  ``Geometry.reflectances``), for the faces it covers;
- emission: one row per light record (the stage's lights, then the record
  of all emissive triangles): the light's spectral density per unit of its
  radiometric value, so that ``value[0] · row`` is the spectral density a
  sample adds. Each shape is scaled to the stage's stated column (its
  photometric value with ``light_units = "photometric"``, radiometric
  otherwise), as :func:`simulator.spectra.sources.spectral_emission` does;
  then one row per distinct coloured ``emissiveColor``
  (``Geometry.emission_rgb``): the emissive record's shape times the
  colour's uplift (:func:`simulator.spectra.sources.colour_emission`),
  scaled the same way, so a face keeps its stated value; a triangle's row
  (``face_emission``) is −1 where it uses its record's;
- response weights ``W``: radiometric and photopic first (the engine's
  two channels), then the run's other responses;
- colour weights: the ``W`` of linear sRGB luminance channels,
  ``K_m · M (x̄, ȳ, z̄)`` (CIE 1931 2°, ``M`` the IEC 61966-2-1 XYZ → linear
  sRGB matrix), so that a spectral radiance reads its colour in cd/m²
  (D65 → R = G = B = its luminance, to 1e-3); probes' RGB maps use them.

References
----------
Wilkie, A., Nawaz, S., Droske, M., Weidlich, A., Hanika, J. (2014), "Hero
Wavelength Spectral Sampling", Computer Graphics Forum 33(4) (EGSR).
docs/DESIGN.md, "Spectral transport".
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from simulator.spectra.grid import WAVELENGTHS_NM, trapezoid_weights

__all__ = ["N_LAMBDA", "HeroTables", "hero_tables", "response_weights", "colour_weights", "light_spectrum"]

#: grid nodes a lane can land on (380–780 nm at 1 nm)
N_LAMBDA = len(WAVELENGTHS_NM)
#: most distinct surface colours the reflectance table holds (then colours are rounded to 1/1024)
MAX_COLOURS = 4096


@dataclass
class HeroTables:
    """The device tables of spectral transport (float32 when uploaded).

    Attributes
    ----------
    reflectance : ndarray, shape (M, 401)
        ρ(λ) of each distinct surface colour, in [0, 1].
    face_reflectance : ndarray, shape (T,), int32
        Row of ``reflectance`` of each triangle.
    emission : ndarray, shape (L + C, 401)
        Per light record, then per distinct emissive colour: spectral density
        per unit radiometric value (nm⁻¹).
    weights : ndarray, shape (R, 401)
        Per response: the per-lane weight ``W = 400 q / w`` (see module docstring).
    responses : list of Response
        The R responses, ``radiometric`` and ``photopic`` first.
    colour : ndarray, shape (3, 401)
        Per-lane weights of linear sRGB R, G, B in cd/m² per W m⁻² sr⁻¹ nm⁻¹
        (:func:`colour_weights`).
    notes : list of str
        One line each: what spectral transport approximated (colours clipped,
        emissive triangles of several spectra).
    measured : list of str
        File names of the measured reflectance rows (the last rows of ``reflectance``).
    face_emission : ndarray, shape (T,), int32
        Row of ``emission`` of each emitting triangle with a coloured
        ``emissiveColor``; −1 elsewhere (the emissive record's row).
    surface_spectral : ndarray, shape (S, 3), int32
        Per row of ``Geometry.surfaces``: (coloured, specular row, transmittance
        row): coloured 1 when its BSDF or pane is traced per hero lane (a
        glossy row whose faces' colour is not grey, a specularColor that is
        not grey, a measured transmittance that is not flat); the rows of
        ``reflectance`` holding the uplift of its ``specularColor`` and its
        T0(λ), −1 for none (:func:`_surface_rows`). Empty without surfaces.
    """

    reflectance: np.ndarray
    face_reflectance: np.ndarray
    emission: np.ndarray
    weights: np.ndarray
    responses: list
    notes: list[str] = field(default_factory=list)
    colour: np.ndarray = field(default_factory=lambda: colour_weights())
    measured: list[str] = field(default_factory=list)
    face_emission: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int32))
    surface_spectral: np.ndarray = field(default_factory=lambda: np.zeros((0, 3), np.int32))


def response_weights(resp) -> np.ndarray:
    """``W = 400 · q / w`` of a response, shape (401,): a lane's weight at each grid node."""
    w = trapezoid_weights()
    return (WAVELENGTHS_NM[-1] - WAVELENGTHS_NM[0]) * np.asarray(resp.q, float) / w


def colour_weights() -> np.ndarray:
    """Per-lane weights (3, 401) of linear sRGB: ``400 · K_m · M (x̄, ȳ, z̄)(λ)``, so that the lanes'
    mean of ``weights · L`` estimates ``M · K_m ∫ L (x̄, ȳ, z̄) dλ`` (trapezoid rule), luminance-based
    sRGB in cd/m² (the sRGB white D65 of luminance Y reads (Y, Y, Y) to 1e-3)."""
    import colour

    from simulator.spectra import tables
    from simulator.spectra.sources import K_M_LM_W

    m = np.asarray(colour.models.RGB_COLOURSPACE_sRGB.matrix_XYZ_to_RGB, float)
    span = WAVELENGTHS_NM[-1] - WAVELENGTHS_NM[0]
    return span * K_M_LM_W * (m @ tables.cmfs_1931())


def light_spectrum(light, default, declared=None):
    """The spectral shape of one UsdLux light, times the uplift of a non-grey ``light.color``
    (:func:`simulator.spectra.sources.colour_emission`): the light's own ``probesim:spectrum``
    (``light.spectrum_authored``); else ``declared`` (``[spectra] lights``) if given; else the
    reader's (``light.spectrum``: its ``colorTemperature``, or ``default``)."""
    from simulator.spectra.sources import colour_emission, emitter_spectrum

    if getattr(light, "spectrum_authored", False):
        base = emitter_spectrum(light.spectrum)
    elif declared is not None:
        base = declared
    else:
        base = emitter_spectrum(default if light.spectrum is None else light.spectrum)
    c = np.asarray(light.color, float)
    return base if np.ptp(c) == 0.0 else colour_emission(c, base)


def _per_radiometric(shape, pair, stated: int) -> np.ndarray:
    """``shape`` scaled so that ``value[0] · row`` has the stated column ``pair[stated]``."""
    from simulator.spectra.responses import response

    r = float(pair[0])
    if r <= 0.0:
        return np.zeros(N_LAMBDA)
    s = np.asarray(shape.values, float)
    of = float(response("radiometric" if stated == 0 else "photopic").of(s))
    return s * (pair[stated] / of) / r


def _emissive_base(geometry, default_spectrum, declared):
    """The shape of the emissive-triangle record: the spectrum every emitting prim names
    (``Geometry.emissive_spectrum``; its ``probesim:spectrum`` wins over ``declared``, its
    ``colorTemperature`` does not), else ``declared``, else ``default_spectrum``."""
    from simulator.spectra.sources import emitter_spectrum

    own = getattr(geometry, "emissive_spectrum", None)
    if own is not None and (declared is None or getattr(geometry, "emissive_spectrum_authored", False)):
        return emitter_spectrum(own)
    return declared if declared is not None else emitter_spectrum(default_spectrum)


def _emissive_colour_rows(geometry, emitting, base, stated: int, first_row: int):
    """Rows and per-triangle row indices of the coloured emissive faces.

    Returns ``(rows, face_row)``: one row per distinct chromaticity of
    ``Geometry.emission_rgb`` among the ``emitting`` triangles that are not
    grey, ``colour_emission(c, base)`` scaled to the stated column of the
    first such face (:func:`_per_radiometric`; the scale of ``c`` drops out,
    so ``c`` is taken relative to its largest channel), and (T,) int32:
    ``first_row + k`` for a face of colour k, −1 for the others.
    """
    from simulator.spectra.sources import colour_emission

    n_tri = geometry.n_triangles
    face_row = np.full(n_tri, -1, np.int32)
    rgb = getattr(geometry, "emission_rgb", None)
    if rgb is None or len(rgb) != n_tri or not len(emitting):
        return [], face_row
    c = np.asarray(rgb, float)[emitting]
    top = np.max(np.abs(c), axis=1)
    coloured = np.ptp(c, axis=1) > 1e-6 * np.maximum(top, 1e-300)
    if not coloured.any():
        return [], face_row
    tris = emitting[coloured]
    key = np.round(c[coloured] / top[coloured, None], 9)
    colours, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    em = np.asarray(geometry.emission, float)
    rows = [_per_radiometric(colour_emission(col, base), em[tris[i]], stated) for col, i in zip(colours, first)]
    face_row[tris] = first_row + np.asarray(inverse, np.int32).reshape(-1)
    return rows, face_row


def hero_tables(scene, light_units: str, default_spectrum, responses=(), declared=None) -> HeroTables:
    """The tables for ``scene`` (see :class:`HeroTables`).

    Parameters
    ----------
    scene : simulator.scene.model.Scene
    light_units : {"photometric", "radiometric"}
    default_spectrum : str or float
        Spectrum of emitters the stage names none for (D65 photometric, the
        run's ``radiometric_spectrum`` otherwise).
    responses : iterable of Response
        Beyond radiometric and photopic (duplicates of those are dropped).
    declared : Spectrum, optional
        ``[spectra] lights``: every emitter's shape.
    """
    from simulator.spectra.reflectance import uplift
    from simulator.spectra.responses import response

    notes: list[str] = []
    g = scene.geometry
    n_tri = g.n_triangles
    rgb = g.albedo_rgb if g.albedo_rgb is not None and len(g.albedo_rgb) == n_tri else np.repeat(g.albedo[:, None], 3, 1)
    rgb = np.asarray(rgb, float).reshape(-1, 3)
    clipped = np.clip(rgb, 0.0, 1.0)
    if np.any(clipped != rgb):
        notes.append(f"{int(np.any(clipped != rgb, axis=1).sum())} triangle(s) with an albedo colour channel "
                     "outside [0, 1] clipped to it for the reflectance uplift")
    colours, face_row = np.unique(clipped, axis=0, return_inverse=True) if n_tri else (np.zeros((1, 3)), np.zeros(0, int))
    if len(colours) > MAX_COLOURS:
        colours, face_row = np.unique(np.round(clipped * 1024.0) / 1024.0, axis=0, return_inverse=True)
        notes.append(f"more than {MAX_COLOURS} surface colours: rounded to 1/1024 for the reflectance table")
    reflectance = uplift(colours)
    ids = getattr(g, "reflectance_id", None)
    measured_names: list[str] = []
    if ids is not None and len(ids) == n_tri and np.any(ids >= 0):
        measured = np.asarray([rho for _, rho in g.reflectances], float).reshape(-1, N_LAMBDA)
        face_row = np.where(ids >= 0, len(reflectance) + ids, face_row)
        reflectance = np.concatenate([np.asarray(reflectance, float).reshape(-1, N_LAMBDA), measured])
        measured_names = [name for name, _ in g.reflectances]
    reflectance = np.asarray(reflectance, float).reshape(-1, N_LAMBDA)
    surface_spectral, extra = _surface_rows(g, rgb, len(reflectance))
    if extra:
        reflectance = np.concatenate([reflectance, np.asarray(extra, float)])
    stated = 1 if light_units == "photometric" else 0
    rows = [_per_radiometric(light_spectrum(l, default_spectrum, declared), l.emission, stated) for l in scene.lights]
    em = np.asarray(g.emission, float).reshape(-1, 2)
    emitting = np.flatnonzero(np.any(em > 0, axis=1)) if n_tri else np.zeros(0, int)
    face_emission = np.full(n_tri, -1, np.int32)
    if len(emitting):
        base = _emissive_base(g, default_spectrum, declared)
        rows.append(_per_radiometric(base, em[emitting[0]], stated))
        coloured_rows, face_emission = _emissive_colour_rows(g, emitting, base, stated, len(rows))
        rows += coloured_rows
        k = em[emitting, 1] / np.where(em[emitting, 0] > 0, em[emitting, 0], np.inf)
        k = k[k > 0]
        if k.size and np.ptp(k) > 1e-9 * k.max():
            notes.append(f"emissive triangles of several spectra traced with one ({base.name}); "
                         "their efficacies differ")
    resp = [response("radiometric"), response("photopic")]
    resp += [r for r in responses if r.name not in ("radiometric", "photopic")]
    return HeroTables(
        reflectance=np.asarray(reflectance, float).reshape(-1, N_LAMBDA),
        face_reflectance=np.asarray(face_row, np.int32).reshape(-1),
        emission=np.asarray(rows, float).reshape(-1, N_LAMBDA) if rows else np.zeros((1, N_LAMBDA)),
        weights=np.stack([response_weights(r) for r in resp]),
        responses=resp,
        notes=notes,
        measured=measured_names,
        face_emission=face_emission,
        surface_spectral=surface_spectral,
    )


def _surface_rows(g, rgb: np.ndarray, first_row: int) -> tuple[np.ndarray, list]:
    """``(surface_spectral (S, 3), the extra reflectance rows)`` of ``Geometry.surfaces`` (see
    :class:`HeroTables`): a glossy row is coloured when any face it covers has an albedo colour that
    is not grey (its metallic F0 and F90 and its diffuse lobe then follow ρ(λ) of the face), or its
    specular workflow's ``specularColor`` is not grey (uplifted, Mallett–Yuksel, as a diffuseColor);
    a pane is coloured by a measured T0(λ) that is not flat."""
    from simulator.spectra.reflectance import is_flat, uplift

    surfaces = list(getattr(g, "surfaces", []) or [])
    out = np.full((len(surfaces), 3), -1, np.int32)
    out[:, 0] = 0
    extra: list = []
    sid = getattr(g, "surface_id", None)
    for k, s in enumerate(surfaces):
        if s.glossy:
            faces = rgb[sid == k] if sid is not None and len(sid) == len(rgb) else np.zeros((0, 3))
            if len(faces) and np.any(np.ptp(faces, axis=1) > 0):
                out[k, 0] = 1
            spec = np.asarray(s.specular_color, float)
            if s.use_specular_workflow and np.ptp(spec) > 0:
                out[k, 0], out[k, 1] = 1, first_row + len(extra)
                extra.append(uplift(np.clip(spec, 0.0, 1.0)))
        if s.pane and s.transmittance_spectrum is not None and not is_flat(s.transmittance_spectrum[1]):
            out[k, 0], out[k, 2] = 1, first_row + len(extra)
            extra.append(np.asarray(s.transmittance_spectrum[1], float))
    return out, extra
