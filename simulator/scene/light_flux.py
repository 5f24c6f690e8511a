"""The flux a light emits as traced, and the emission that gives a stated flux.

A light's emission value E (:attr:`simulator.scene.model.Light.emission`:
radiance, or a point light's intensity) and its shaping factor f(ω)
(:meth:`simulator.scene.model.LightShaping.factor`, θ from the light's −Z
axis) give its total flux Φ = E · G, with G a geometric integral per kind:

====================  =====================================  =========================
kind                  emits                                   G (m²·sr, or sr)
====================  =====================================  =========================
point                 intensity E·f(ω)                        ∫_S² f dω
sphere (radius r)     radiance E·f(ω), outward                π r² ∫_S² f dω
rect (w × h), disk    radiance E·f(ω), one side (−Z)          A ∫_{θ<90°} f cosθ dω
cylinder (r, ℓ)       radiance E outward from its side        π · 2π r ℓ (no shaping)
====================  =====================================  =========================

(a sphere's intensity toward ω is E·f(ω) times its projected area π r², whatever
ω; a flat light's radiance is weighted by cosθ over its hemisphere). Unshaped,
∫_S² f dω = 4π and ∫ f cosθ dω = π, the familiar Φ = 4π I, 4π² r² L and π A L.
Distant and dome lights have no finite flux (None).

The integrals are exact for the kernels' interpolant: the IES table is
bilinear in (θ, φ) on :meth:`~simulator.scene.photometry.GoniometricDistribution.regular_table`
(the table the kernels read), so its φ-integral is the trapezoid rule over
the φ nodes, and the rest (linear in θ within a cell, times focus, cone and
sinθ or sinθ cosθ, smooth between the break points) is integrated by
Gauss–Legendre on every segment between table nodes, cone edges and 90°.
"""

from __future__ import annotations

import math

import numpy as np

from simulator.scene.model import Light, LightKind, LightShaping

__all__ = ["FLUX_KINDS", "flux_per_emission", "emitted_flux", "shaping_integral"]

#: kinds with a finite flux (after a SphereLight of radius 0 or treatAsPoint becomes POINT)
FLUX_KINDS = (LightKind.POINT, LightKind.SPHERE, LightKind.RECT, LightKind.DISK, LightKind.CYLINDER)
#: Gauss–Legendre nodes per smooth segment of θ
_GL_NODES = 16


def shaping_integral(shaping: LightShaping | None, one_sided: bool) -> float:
    """∫ f dω over the sphere (``one_sided`` False) or ∫ f cosθ dω over the −Z hemisphere (True), sr.

    Parameters
    ----------
    shaping : LightShaping or None
        None: f = 1 (4π, or π one-sided).
    one_sided : bool
        A flat light (rect, disk): cosine-weighted over θ ∈ [0°, 90°].
    """
    if shaping is None:
        return math.pi if one_sided else 4.0 * math.pi
    top = math.pi / 2 if one_sided else math.pi
    breaks = {0.0, top}
    if shaping.ies is None:
        cut = min(shaping.cone_angle_rad, math.pi)
        breaks |= {cut, cut * (1.0 - min(max(shaping.cone_softness, 0.0), 1.0))}
        col_theta = None
    else:
        th_deg, ph_deg, table = shaping.ies.regular_table()
        col_theta = np.radians(th_deg)
        # φ-integral of each θ node (the interpolant is linear in φ within a cell: the trapezoid is exact)
        col = np.sum(0.5 * (table[1:] + table[:-1]) * np.diff(np.radians(ph_deg))[:, None], axis=0)
        breaks |= set(col_theta.tolist())
    edges = np.array(sorted(b for b in breaks if 0.0 <= b <= top))
    x, w = np.polynomial.legendre.leggauss(_GL_NODES)
    a, b = edges[:-1, None], edges[1:, None]
    theta = (0.5 * (b - a) * x + 0.5 * (b + a)).ravel()
    weight = (0.5 * (b - a) * w).ravel()
    # f without its IES part, times the φ-integral of the IES part (2π where it has none)
    if col_theta is None:
        f_phi = shaping.factor(theta, np.zeros_like(theta)) * 2.0 * math.pi
    else:
        bare = LightShaping(cone_angle_rad=math.pi, focus=shaping.focus, focus_tint=shaping.focus_tint)  # no cone
        f_phi = bare.factor(theta, np.zeros_like(theta)) * shaping.ies_scale * np.interp(theta, col_theta, col)
    jac = np.sin(theta) * (np.cos(theta) if one_sided else 1.0)
    return float(np.sum(weight * f_phi * jac))


def flux_per_emission(light: Light) -> float | None:
    """G = Φ / E of a light (m²·sr for radiance, sr for a point light's intensity); None: no finite flux.

    See the module docstring for each kind's G.
    """
    kind = light.kind
    if kind == LightKind.POINT:
        return shaping_integral(light.shaping, one_sided=False)
    if kind == LightKind.SPHERE:
        return math.pi * light.radius**2 * shaping_integral(light.shaping, one_sided=False)
    if kind == LightKind.RECT:
        return light.width * light.height * shaping_integral(light.shaping, one_sided=True)
    if kind == LightKind.DISK:
        return math.pi * light.radius**2 * shaping_integral(light.shaping, one_sided=True)
    if kind == LightKind.CYLINDER:
        return math.pi * 2.0 * math.pi * light.radius * light.length
    return None


def emitted_flux(light: Light) -> tuple[float, float] | None:
    """``(W, lm)`` the light emits as traced (its emission pair × G); None for distant and dome lights."""
    g = flux_per_emission(light)
    if g is None:
        return None
    return (float(light.emission[0] * g), float(light.emission[1] * g))


def _emission_unit(light: Light) -> tuple[str, str]:
    """(radiometric, photometric) units of ``light.emission``."""
    if light.kind == LightKind.POINT:
        return "W/sr", "cd"
    if light.kind == LightKind.DISTANT and light.half_angle == 0.0:
        return "W/m²", "lx"
    return "W/(m²·sr)", "cd/m²"


def lights_record(lights) -> list[dict]:
    """The run record's ``lights``: per UsdLux light, what the stage stated of its output, the emission
    derived from it (radiance, or a point light's intensity) and the flux it emits as traced.

    Returns
    -------
    list of dict
        ``{"prim", "kind", "authored", "emission": {"radiometric", "photometric", "units"},
        "flux_lm", "flux_W"}``; the flux is None for distant and dome lights (no finite flux).
    """
    out = []
    for light in lights:
        flux = emitted_flux(light)
        shaping = light.shaping
        out.append({
            "prim": light.name,
            "kind": light.kind.name.lower(),
            "authored": dict(getattr(light, "authored", {}) or {}),
            "shaping": None if shaping is None else ("ies" if shaping.ies is not None else "cone/focus"),
            "emission": {"radiometric": float(light.emission[0]), "photometric": float(light.emission[1]),
                         "units": list(_emission_unit(light))},
            "flux_lm": None if flux is None else flux[1],
            "flux_W": None if flux is None else flux[0],
        })
    return out
