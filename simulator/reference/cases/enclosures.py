"""Expected readings of the enclosure (interreflection) reference cases:
furnaces, the integrating sphere and CIE 171:2006 case 5.8, from
:mod:`simulator.reference.closed_forms`. Signature as in
:mod:`simulator.reference.cases.direct`.
"""

from __future__ import annotations

import math

import numpy as np

from simulator.errors import UserError
from simulator.reference import closed_forms as cf
from simulator.reference.cases.context import CaseContext, no_closed_form, one_light
from simulator.reference.cases.direct import _patch
from simulator.scene.model import LightKind, Scene, Sensor, SensorKind


def _uniform_surface(scene: Scene) -> tuple[float, tuple[float, float]]:
    g = scene.geometry
    if g.n_triangles == 0 or np.ptp(g.albedo) != 0:
        raise UserError(f"{scene.path}: the enclosure case expects surfaces of one albedo")
    return float(g.albedo[0]), (float(g.emission[:, 0].max()), float(g.emission[:, 1].max()))


def furnace(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Closed furnace, every wall emitting L_e with albedo ρ: L = L_e/(1 − ρ)
    everywhere and E = π·L_e/(1 − ρ) (docs/REFERENCES.md §Furnace)."""
    rho, emission = _uniform_surface(ctx.scene)
    if np.ptp(ctx.scene.geometry.emission[:, ch]) != 0:
        raise UserError(f"{ctx.scene.path}: the furnace case expects every wall to emit the same radiance")
    component = ctx.cfg.simulation.component
    total_l = float(cf.furnace_radiance(emission[ch], rho))
    l_value = {"total": total_l, "direct": emission[ch], "indirect": total_l - emission[ch]}[component]
    if s.kind == SensorKind.RADIANCE:
        return l_value
    if s.kind in (SensorKind.IRRADIANCE, SensorKind.PATCH):
        return math.pi * l_value
    raise no_closed_form(ctx, s, "unknown sensor kind")


def integrating_sphere(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Integrating sphere of albedo ρ with an isotropic point source (flux
    Φ = 4π·I) inside: the light reflected at least once reaches every wall
    point alike, ρΦ/((1 − ρ)·S) with S the wall area (docs/REFERENCES.md
    §Integrating sphere: Φ/(4πR²)·ρ/(1 − ρ) for S = 4πR²; the surface mean is
    exact for any closed enclosure, closed_forms.cie171_indirect_illuminance,
    and uniform on a sphere). The direct part is the point source's own
    E = I·cosξ/d² at the receiver (a patch: I·Ω/area), which equals Φ/(4πR²)
    on the wall of an ideal sphere with the source at its centre."""
    rho, _ = _uniform_surface(ctx.scene)
    l = one_light(ctx.scene, LightKind.POINT)
    g = ctx.scene.geometry
    p = g.points[g.triangles]
    area = float(0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum())
    flux = 4.0 * math.pi * l.emission[ch]
    reflected = float(cf.cie171_indirect_illuminance(flux, rho, area))
    if s.kind == SensorKind.IRRADIANCE:
        direct = float(cf.point_irradiance(l.emission[ch], l.position, s.position, s.normal))
    elif s.kind == SensorKind.PATCH:
        direct = float(cf.point_flux_through_polygon(l.emission[ch], l.position, _patch(s))) / (s.size[0] * s.size[1])
    else:
        raise no_closed_form(ctx, s, "irradiance and patch receivers only")
    return {"total": direct + reflected, "indirect": reflected, "direct": direct}[ctx.cfg.simulation.component]


def cie171_5_8(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """CIE 171:2006 case 5.8: in a closed room of uniform reflectance ρ and
    total area S_T, the mean indirect illuminance over all surfaces is
    E_ind = ρΦ/((1 − ρ)S_T) (closed_forms.cie171_indirect_illuminance). The
    room is a cube with the source at its centre, so by symmetry each of the
    six faces receives the same indirect flux, and a patch covering one whole
    face reads E_ind itself. Φ = 4π·I from the stage's source; S_T from its
    triangles."""
    rho, _ = _uniform_surface(ctx.scene)
    l = one_light(ctx.scene, LightKind.POINT)
    g = ctx.scene.geometry
    p = g.points[g.triangles]
    area = float(0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum())
    if s.kind != SensorKind.PATCH or abs(s.size[0] * s.size[1] * 6.0 / area - 1.0) > 1e-9:
        raise no_closed_form(ctx, s, "only patches covering one whole face of the cube")
    if ctx.cfg.simulation.component != "indirect":
        raise no_closed_form(ctx, s, "the case's closed form is the indirect component")
    flux = 4.0 * math.pi * l.emission[ch]
    return float(cf.cie171_indirect_illuminance(flux, rho, area))


def cie171_5_8_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    rho, _ = _uniform_surface(ctx.scene)
    table = cf.CIE171_5_8_TABLE_LX.get(round(rho, 2))
    return f"ρ = {rho:g}; CIE table {table:g}" if table is not None and ch == 1 else f"ρ = {rho:g}"


def rho_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    return f"ρ = {_uniform_surface(ctx.scene)[0]:g}"
