"""Reference readings of the stability (hard) cases, ``configs/stability/``.

Each case stresses one way an estimator can fail (grazing receivers, near
fields, tiny and delta sources, leaks, self-intersection, a 0.99 furnace,
high dynamic range, degenerate faces). Besides the expected reading, a case
whose truth is a shadow's 0 has a *scale*, the unoccluded reading, that the
stability verdict's error floors are relative to. Signatures as in
:mod:`simulator.reference.cases.direct`; the stages are read in radiometric
units (channel 0).
"""

from __future__ import annotations

import math

import numpy as np

from simulator.reference import closed_forms as cf
from simulator.reference.cases.context import CaseContext
from simulator.scene.model import Light, LightKind, Scene, Sensor, SensorKind

#: emissiveColor of the leak stage's /World/Looks/Emitter (radiometric, W m⁻² sr⁻¹)
LEAK_EMITTER = 1000.0
#: the degenerate stage's emissive square: radiance (W m⁻² sr⁻¹), centre height and side (m)
DEGENERATE_LAMP = (100.0, 2.0, 1.0)
#: on_surface: albedo of the 10 km plane
ON_SURFACE_ALBEDO = 0.5
#: furnace99: emitted radiance of the walls (W m⁻² sr⁻¹) and their albedo
FURNACE99 = (1.0, 0.99)


def light_irradiance(l: Light, p: np.ndarray, n: np.ndarray, ch: int = 0) -> float:
    """Unoccluded irradiance on (p, n) from one UsdLux light, channel ``ch``.

    Point: E = I·cosξ/d²; sphere: the straddling-sphere formula (0 inside: a
    SphereLight emits outward only); rect: Lambert's contour formula on its
    one-sided rectangle; distant: E⊥·cosξ for a delta light, and for a cone
    of half-angle σ the sphere formula with a unit sphere of radius sin σ at
    distance 1 (closed_forms).
    """
    L = l.emission[ch]
    if l.kind == LightKind.POINT:
        return float(cf.point_irradiance(L, l.position, p, n))
    if l.kind == LightKind.SPHERE:
        if np.linalg.norm(p - l.position) < l.radius:
            return 0.0  # inside: a SphereLight emits outward only
        return float(cf.sphere_irradiance(L, l.position, l.radius, p, n))
    if l.kind == LightKind.RECT:
        v = cf.rect_light_vertices(l.position, l.frame[:, 0], l.frame[:, 1], l.width, l.height)
        return float(cf.polygon_irradiance(L, v, p, n, one_sided_normal=-l.frame[:, 2]))
    if l.kind == LightKind.DISTANT:
        toward = l.frame[:, 2]
        if l.half_angle == 0.0:
            return float(L * max(0.0, float(np.dot(toward, n))))
        # a cone of half-angle σ at infinity is a unit sphere of radius sin σ at distance 1
        return float(cf.sphere_irradiance(L, p + toward, math.sin(l.half_angle), p, n))
    raise ValueError(f"no closed form here for a {l.kind.name} light")


def lights_irradiance(scene: Scene, p, n, ch: int = 0) -> float:
    """Sum of :func:`light_irradiance` over the scene's lights (nothing blocks)."""
    return sum(light_irradiance(l, np.asarray(p, float), np.asarray(n, float), ch) for l in scene.lights)


def _square(cx: float, cy: float, z: float, size: float) -> np.ndarray:
    h = size / 2
    return np.array([[cx - h, cy - h, z], [cx + h, cy - h, z], [cx + h, cy + h, z], [cx - h, cy + h, z]])


def lights(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Sum of every light's closed form; nothing blocks (grazing, near field,
    tiny source, delta lights, high dynamic range)."""
    return lights_irradiance(ctx.scene, s.position, s.normal, ch)


def leak(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """0: every receiver is under a black tray that hides the lamps."""
    return 0.0


def leak_scale(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """What both lamps would give unoccluded: the rect light's closed form plus
    the emissive 1 m square at (1, 0, 1), facing down (Lambert's contour formula)."""
    panel = _square(1.0, 0.0, 1.0, 1.0)
    return lights_irradiance(ctx.scene, s.position, s.normal, ch) + float(
        cf.polygon_irradiance(LEAK_EMITTER, panel, s.position, s.normal, one_sided_normal=(0, 0, -1)))


def on_surface(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Unshadowed lamps for receivers on the plane; the meter looking straight
    down at the origin reads L = ρ/π·E(origin) (the plane is lit by the lamps
    only: a plane cannot light itself)."""
    if s.kind == SensorKind.RADIANCE:
        origin = next(x for x in ctx.sensors if x.name == "origin")
        return ON_SURFACE_ALBEDO / math.pi * lights_irradiance(ctx.scene, origin.position, origin.normal, ch)
    return lights_irradiance(ctx.scene, s.position, s.normal, ch)


def furnace99(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """E = π·L_e/(1 − ρ) anywhere inside, any orientation (L_e = 1, ρ = 0.99)."""
    return float(cf.furnace_irradiance(*FURNACE99))


def degenerate_unoccluded(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """The one emissive 1 m square at z = 2 (L = 100, facing down), by Lambert's
    contour formula: a surface modelled twice emits as one."""
    radiance, z, side = DEGENERATE_LAMP
    return float(cf.polygon_irradiance(radiance, _square(0.0, 0.0, z, side), s.position, s.normal, one_sided_normal=(0, 0, -1)))


def degenerate(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """:func:`degenerate_unoccluded`, and 0 under the blocker (x > 1.5)."""
    return 0.0 if s.position[0] > 1.5 else degenerate_unoccluded(ctx, s, ch)


def glossy(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """A glossy floor (its one material's UsdPreviewSurface lobes) under a uniform sky of radiance L:
    a meter looking down at θ reads L·A(cos θ), A the directional albedo; a down-facing irradiance
    sensor 2πL ∫ A(μ) μ dμ (simulator.reference.microfacet, an implementation independent of the
    kernels; Gauss–Legendre, 24 nodes in μ)."""
    from simulator.reference.microfacet import directional_albedo, preview_lobes

    g = ctx.scene.geometry
    row = g.surfaces[int(g.surface_id[0])]
    lobes = preview_lobes(float(g.albedo[0]), row.roughness, row.metallic, row.ior,
                          row.specular_grey if row.use_specular_workflow else None, row.clearcoat,
                          row.clearcoat_roughness)
    (dome,) = [l for l in ctx.scene.lights if l.kind == LightKind.DOME]
    big_l = dome.emission[ch]
    if s.kind == SensorKind.RADIANCE:
        return big_l * directional_albedo(lobes, abs(float(s.normal[2])))
    x, w = np.polynomial.legendre.leggauss(24)
    mu, w = 0.5 * (x + 1.0), 0.5 * w
    return 2.0 * math.pi * big_l * float(sum(wk * mk * directional_albedo(lobes, mk, 256, 128) for mk, wk in zip(mu, w)))
