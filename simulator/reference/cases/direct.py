"""Expected readings of the direct-light reference cases: one emitter (and
black occluders), closed forms from :mod:`simulator.reference.closed_forms`
evaluated with the light, surface and sensor parameters the stage reader
produced. Each function names its formula and source.

Every expected-value function has the signature ``(ctx, sensor, channel) ->
float`` (:data:`simulator.reference.cases.context.ExpectedFn`); a receiver
without a closed form raises :class:`simulator.errors.UserError`.
"""

from __future__ import annotations

import math

import numpy as np

from simulator.errors import UserError
from simulator.reference import closed_forms as cf
from simulator.reference.cases.context import CaseContext, no_closed_form, one_light
from simulator.reference.geometry import (
    cone_lands_inside, patch_vertices, points_in_polygon_2d, ray_hits_triangles, ray_triangles,
)
from simulator.reference.texture import bilinear_at
from simulator.scene.model import Light, LightKind, Scene, Sensor, SensorKind


def _patch(s: Sensor) -> np.ndarray:
    """Corners of a patch sensor, counter-clockwise about its normal, metres."""
    return patch_vertices(s.position, s.normal, s.up, s.size)


def _cone_lands(s: Sensor, plane_point, plane_normal, inside) -> bool:
    """Whether every ray of a radiance meter's cone lands where ``inside`` holds."""
    return cone_lands_inside(s.position, s.normal, s.half_angle, plane_point, plane_normal, inside)


def point(ctx: CaseContext, s: Sensor, ch: int, scene: Scene | None = None) -> float:
    """Isotropic point source. Irradiance: E = I·cosξ/d² (inverse-square cosine
    law, docs/REFERENCES.md §Point source). Patch: flux Φ = I·Ω with Ω the patch's
    solid angle (Van Oosterom & Strackee), over its area."""
    l = one_light(scene or ctx.scene, LightKind.POINT)
    intensity = l.emission[ch]
    if s.kind == SensorKind.PATCH:
        return float(cf.point_flux_through_polygon(intensity, l.position, _patch(s))) / (s.size[0] * s.size[1])
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.point_irradiance(intensity, l.position, s.position, s.normal))
    raise no_closed_form(ctx, s, "a radiance meter cannot see a point light")


def point_cm_yup(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """The same stage authored in centimetres with Y up must read exactly what
    point.usda (metres, Z up) reads: the closed form of :func:`point`
    evaluated with the light of point.toml's stage."""
    return point(ctx, s, ch, scene=ctx.reference_scene("point.toml"))


def sphere(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Uniform sphere light: E = π·L·sin²σ·cosθ above the horizon, the
    straddling formula across it (Howell's catalogue;
    docs/REFERENCES.md §Uniform sphere). A radiance meter whose cone lies inside the sphere's disc reads L."""
    l = one_light(ctx.scene, LightKind.SPHERE)
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.sphere_irradiance(l.emission[ch], l.position, l.radius, s.position, s.normal))
    if s.kind == SensorKind.RADIANCE:
        to_c = l.position - s.position
        d = np.linalg.norm(to_c)
        angle = math.acos(np.clip(np.dot(to_c / d, s.normal), -1.0, 1.0))
        if angle + s.half_angle <= math.asin(min(1.0, l.radius / d)):
            return l.emission[ch]
        raise no_closed_form(ctx, s, "the meter's cone is not inside the sphere's disc")
    raise no_closed_form(ctx, s, "patch")


def rect(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Rect light. A receiver parallel to it and facing it: corner rectangles
    (Howell's catalogue, parallel rectangle from above a corner, added and
    subtracted; docs/REFERENCES.md §Parallel rectangle). Any other receiver:
    Lambert's contour formula after clipping to its upper hemisphere
    (docs/REFERENCES.md §Lambert's polygon formula). A meter whose cone lands inside the
    rectangle reads L."""
    l = one_light(ctx.scene, LightKind.RECT)
    L = l.emission[ch]
    ex, ey, ez = l.frame[:, 0], l.frame[:, 1], l.frame[:, 2]
    if s.kind == SensorKind.IRRADIANCE:
        rel = l.position - s.position
        height = float(rel @ ez)
        if np.dot(s.normal, ez) > 1.0 - 1e-12 and height > 0:  # parallel, facing the light
            cx, cy = float(rel @ ex), float(rel @ ey)
            return float(cf.rect_irradiance_parallel(L, cx - l.width / 2, cx + l.width / 2, cy - l.height / 2, cy + l.height / 2, height))
        verts = cf.rect_light_vertices(l.position, ex, ey, l.width, l.height)
        return float(cf.polygon_irradiance(L, verts, s.position, s.normal, one_sided_normal=-ez))
    if s.kind == SensorKind.RADIANCE:

        def inside(q):
            r = q - l.position
            return (np.abs(r @ ex) <= l.width / 2) & (np.abs(r @ ey) <= l.height / 2)

        if np.dot(s.normal, ez) > 0 and _cone_lands(s, l.position, ez, inside):
            return L
        raise no_closed_form(ctx, s, "the meter's cone does not land inside the rectangle")
    raise no_closed_form(ctx, s, "patch")


#: sides of the polygons that bracket a disk light (see :func:`disk`)
DISK_POLYGON_SIDES = 8192


def _disk_polygon(l: Light, circumscribed: bool) -> np.ndarray:
    phi = 2 * np.pi * np.arange(DISK_POLYGON_SIDES) / DISK_POLYGON_SIDES
    r = l.radius / math.cos(math.pi / DISK_POLYGON_SIDES) if circumscribed else l.radius
    return l.position + r * (np.cos(phi)[:, None] * l.frame[:, 0] + np.sin(phi)[:, None] * l.frame[:, 1])


def disk_bracket(l: Light, s: Sensor, ch: int) -> tuple[float, float]:
    """(inscribed, circumscribed) polygon irradiance of a disk light. The
    integrand cos⁺θ is ≥ 0 and inscribed ⊂ disk ⊂ circumscribed, so the two
    bracket the disk's irradiance: E_in ≤ E ≤ E_out."""
    ez = l.frame[:, 2]
    e = [
        float(cf.polygon_irradiance(l.emission[ch], _disk_polygon(l, c), s.position, s.normal, one_sided_normal=-ez))
        for c in (False, True)
    ]
    return e[0], e[1]


def disk(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Disk light. On its axis: E = π·L·R²/(R²+h²)·cosω (Howell's catalogue,
    coaxial disk, element tilted). Parallel, off the axis: E = π·L·F with the
    offset-disk configuration factor (Howell; docs/REFERENCES.md §Parallel disk).
    Any other receiver (perpendicular, or with the disk partly below its
    horizon): Lambert's contour formula on the inscribed and circumscribed
    8192-gons, which bracket the exact value (their relative gap is about
    (π/8192)² ≈ 1.5e-7); the midpoint is used."""
    l = one_light(ctx.scene, LightKind.DISK)
    if s.kind != SensorKind.IRRADIANCE:
        raise no_closed_form(ctx, s, "only irradiance receivers")
    ez = l.frame[:, 2]
    rel = l.position - s.position
    h = float(rel @ ez)
    offset = float(np.linalg.norm(rel - h * ez))
    if h > 0 and offset < 1e-12 * max(1.0, h):
        tilt = math.acos(float(np.clip(np.dot(s.normal, ez), -1.0, 1.0)))
        if tilt <= 0.5 * math.pi - math.atan2(l.radius, h):  # disk wholly above the horizon
            return float(cf.disk_irradiance_on_axis(l.emission[ch], l.radius, h, tilt=tilt))
    if h > 0 and np.dot(s.normal, ez) > 1.0 - 1e-12:
        return float(cf.disk_irradiance_parallel(l.emission[ch], l.radius, h, offset))
    lo, hi = disk_bracket(l, s, ch)
    return 0.5 * (lo + hi)


def disk_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    l = one_light(ctx.scene, LightKind.DISK)
    ez = l.frame[:, 2]
    rel = l.position - s.position
    h = float(rel @ ez)
    if h > 0 and (np.linalg.norm(rel - h * ez) < 1e-12 * max(1.0, h) or np.dot(s.normal, ez) > 1.0 - 1e-12):
        return ""
    lo, hi = disk_bracket(l, s, ch)
    return f"polygon bracket ±{0.5 * (hi - lo) / max(abs(hi), 1e-300):.1e}" if hi > 0 else ""


def distant_occluder(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Delta distant light: E = E⊥·cosξ where the ray toward the light is
    clear, 0 where the stage's geometry blocks it (docs/REFERENCES.md, point
    source with I/d² → E⊥). The shadow test is a float64 Möller–Trumbore over
    every triangle of the stage, independent of the engine's BVH."""
    l = one_light(ctx.scene, LightKind.DISTANT)
    if l.half_angle != 0.0 or s.kind != SensorKind.IRRADIANCE:
        raise no_closed_form(ctx, s, "a delta distant light and irradiance receivers only")
    g = ctx.scene.geometry
    toward = l.frame[:, 2]
    if ray_hits_triangles(s.position, toward, g.points[g.triangles]):
        return 0.0
    return l.emission[ch] * max(0.0, float(np.dot(s.normal, toward)))


def _ground_is_black_plane(scene: Scene) -> bool:
    g = scene.geometry
    return g.n_triangles > 0 and bool(np.all(g.points[:, 2] == 0.0)) and bool(np.all(g.albedo == 0))


def dome(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Uniform sky over a black ground: E = π·L·(1 + cos β)/2 for a receiver
    tilted β from the zenith (docs/REFERENCES.md §Uniform environment); a meter
    whose cone is wholly above the horizon reads L. The ground is 20 km across,
    so from 1 m up the sky seen past its edge is below 1e-4 rad of elevation."""
    l = one_light(ctx.scene, LightKind.DOME)
    if not _ground_is_black_plane(ctx.scene):
        raise UserError(f"{ctx.scene.path}: the dome case expects a black ground at z = 0 and nothing else")
    if s.position[2] < 0:
        raise no_closed_form(ctx, s, "below the ground")
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.dome_irradiance(l.emission[ch], math.acos(float(np.clip(s.normal[2], -1.0, 1.0)))))
    if s.kind == SensorKind.RADIANCE and math.acos(float(np.clip(s.normal[2], -1.0, 1.0))) + s.half_angle < 0.5 * math.pi:
        return l.emission[ch]
    raise no_closed_form(ctx, s, "radiance meter looking at the ground")


def sensor_heads(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """A sensor head's reading ∫ L r dω (docs/REFERENCES.md §Sensor models): under a uniform sky over a
    black ground, facing up, 2π·L/(n + 1) for r = cosⁿ θ and L·∫r dω for a table (its integral, exact
    for r linear between rows); under a delta distant light of normal irradiance E arriving θ off the
    normal, E·r(θ) where the ray toward it is clear (the shadow test of :func:`distant_occluder`), r
    interpolated from the model's table by numpy."""
    resp = getattr(s, "optics", None)
    if resp is None:
        raise no_closed_form(ctx, s, "not a sensor model's optics")
    kinds = {l.kind for l in ctx.scene.lights}
    if kinds == {LightKind.DOME}:
        l = one_light(ctx.scene, LightKind.DOME)
        if not _ground_is_black_plane(ctx.scene) or s.normal[2] < 1.0 - 1e-12:
            raise no_closed_form(ctx, s, "needs a head facing up over a black ground")
        if resp.kind == "power":
            return float(cf.cos_power_dome_reading(l.emission[ch], resp.exponent))
        return l.emission[ch] * resp.integral_sr()
    l = one_light(ctx.scene, LightKind.DISTANT)
    if l.half_angle != 0.0:
        raise no_closed_form(ctx, s, "a delta distant light only")
    g = ctx.scene.geometry
    toward = l.frame[:, 2]
    if ray_hits_triangles(s.position, toward, g.points[g.triangles]):
        return 0.0
    cos_t = float(np.clip(np.dot(s.normal, toward), -1.0, 1.0))
    if cos_t <= 0.0:
        return 0.0
    theta = math.degrees(math.acos(cos_t))
    if resp.kind == "power":
        return l.emission[ch] * cos_t ** resp.exponent
    if not resp.symmetric:
        raise no_closed_form(ctx, s, "a symmetric head only")
    r = float(np.interp(theta, resp.theta_deg, resp.values[0])) if theta <= resp.theta_deg[-1] else 0.0
    return l.emission[ch] * r


def cylindrical(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Cylindrical and semi-cylindrical receivers. Under an isotropic point source:
    E_z = I·sinθ/(π·d²), E_sc = I·sinθ·(1 + cos φ)/(π·d²); under a uniform sky over a
    black ground, vertical axis: πL/2 for both (docs/REFERENCES.md §Cylindrical illuminance)."""
    if s.kind not in (SensorKind.CYLINDRICAL, SensorKind.SEMICYLINDRICAL):
        raise no_closed_form(ctx, s, "not a cylindrical receiver")
    kinds = {l.kind for l in ctx.scene.lights}
    if kinds == {LightKind.DOME}:
        l = one_light(ctx.scene, LightKind.DOME)
        if not _ground_is_black_plane(ctx.scene) or s.position[2] <= 0 or abs(abs(s.up[2]) - 1.0) > 1e-12:
            raise no_closed_form(ctx, s, "needs a vertical axis above a black ground")
        return float(cf.dome_cylindrical_irradiance(l.emission[ch]))
    l = one_light(ctx.scene, LightKind.POINT)
    if s.kind == SensorKind.CYLINDRICAL:
        return float(cf.cylindrical_point_irradiance(l.emission[ch], l.position, s.position, s.up))
    return float(cf.semicylindrical_point_irradiance(l.emission[ch], l.position, s.position, s.normal, s.up))


def _overcast_rows(ctx: CaseContext) -> tuple:
    """(dome light, its map's row values) for a sky map uniform in azimuth,
    whose lat-long pole the stage turned to the zenith (+Z)."""
    l = one_light(ctx.scene, LightKind.DOME)
    m = l.texture_map
    if m is None or ctx.scene.geometry.n_triangles:
        raise UserError(f"{ctx.scene.path}: the overcast case expects one textured DomeLight and no geometry")
    if not np.allclose(m, m[:, :1]) or float(l.frame[2, 1]) < 1.0 - 1e-9:
        raise UserError(f"{ctx.scene.path}: the overcast case expects a map uniform in azimuth with its pole at +Z")
    return l, m[:, 0].astype(float)


def overcast(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """The CIE standard overcast sky stored as lat-long rows (each the exact
    solid-angle mean of L_z(1 + 2cosθ)/3): horizontal and vertical receivers
    read the row-exact sums of ∫L·cosγ dω
    (closed_forms.latlong_rows_illuminance); a meter whose cone lies inside the
    top row reads that row's luminance."""
    l, rows = _overcast_rows(ctx)
    if s.kind == SensorKind.IRRADIANCE and abs(abs(s.normal[2]) - 1.0) < 1e-12 and s.normal[2] > 0:
        return l.emission[ch] * cf.latlong_rows_illuminance(rows)
    if s.kind == SensorKind.IRRADIANCE and abs(s.normal[2]) < 1e-12:
        return l.emission[ch] * cf.latlong_rows_illuminance(rows, vertical=True)
    if s.kind == SensorKind.RADIANCE and s.normal[2] > 0 and math.acos(min(1.0, s.normal[2])) + s.half_angle < math.pi / len(rows):
        return l.emission[ch] * rows[0]
    raise no_closed_form(ctx, s, "only horizontal, vertical and zenith receivers")


def overcast_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    l, rows = _overcast_rows(ctx)
    if s.kind != SensorKind.IRRADIANCE:
        return ""
    vertical = abs(s.normal[2]) < 1e-12
    sky = l.emission[ch] * rows[0] / float(cf.cie_overcast_row_means(1.0, len(rows))[0])  # L_z
    cont = cf.cie_overcast_illuminance(sky, vertical=vertical)
    return f"continuous CIE sky {cont:.5g} (map {overcast(ctx, s, ch) / cont - 1.0:+.2%})"


def _emissive_polygon(scene: Scene) -> tuple[np.ndarray, np.ndarray, tuple[float, float]]:
    """(vertices in authored order, front-face normal, emitted radiance pair)
    of a stage whose only geometry is one emissive, albedo-0 polygon."""
    g = scene.geometry
    if len(g.prim_names) != 1 or g.n_triangles == 0:
        raise UserError(f"{scene.path}: the polygon case expects exactly one emissive Mesh")
    if np.any(g.albedo != 0) or np.any(g.two_sided) or np.ptp(g.emission, axis=0).max() != 0:
        raise UserError(f"{scene.path}: the polygon must be one-sided, black (albedo 0) and uniformly emissive")
    verts = g.points  # one prim: its points in authored (face) order
    newell = 0.5 * np.cross(verts, np.roll(verts, -1, axis=0)).sum(axis=0)  # area vector along the winding
    return verts, newell / np.linalg.norm(newell), (float(g.emission[0, 0]), float(g.emission[0, 1]))


def polygon(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Emissive polygon, front face only: Lambert's contour formula,
    E = (L/2)·|Σ γ_i n·û_i|, after Sutherland–Hodgman clipping to the
    receiver's upper hemisphere (Lambert 1760; Arvo 1995; docs/REFERENCES.md
    "Uniform polygon"). A meter whose cone lands inside the polygon reads L."""
    verts, front, emission = _emissive_polygon(ctx.scene)
    L = emission[ch]
    if s.kind == SensorKind.IRRADIANCE:
        return float(cf.polygon_irradiance(L, verts, s.position, s.normal, one_sided_normal=front))
    if s.kind == SensorKind.RADIANCE:
        a = verts[1] - verts[0]
        a /= np.linalg.norm(a)
        b = np.cross(front, a)
        poly2 = np.column_stack([(verts - verts[0]) @ a, (verts - verts[0]) @ b])

        def inside(q):
            r = q - verts[0]
            return points_in_polygon_2d(np.column_stack([r @ a, r @ b]), poly2)

        if np.dot(s.normal, front) < 0 and _cone_lands(s, verts[0], front, inside):
            return L
        raise no_closed_form(ctx, s, "the meter's cone does not land on the polygon's front")
    raise no_closed_form(ctx, s, "patch")


def radiance_floor(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """A Lambertian floor (f = ρ/π) under a delta sun: E = E⊥·cosξ, and the
    floor's radiance, the same toward every direction, is L = ρ·E/π
    (f = ρ/π in docs/REFERENCES.md §Reflection equation). The floor is the only
    surface, so no other light reaches it or the meters."""
    l = one_light(ctx.scene, LightKind.DISTANT)
    g = ctx.scene.geometry
    if l.half_angle != 0.0 or g.n_triangles == 0 or np.ptp(g.albedo) != 0 or np.any(g.points[:, 2] != 0.0):
        raise UserError(f"{ctx.scene.path}: the radiance-floor case expects one flat floor at z = 0 and a delta sun")
    toward = l.frame[:, 2]
    e_floor = l.emission[ch] * max(0.0, float(toward[2]))
    if s.kind == SensorKind.IRRADIANCE:
        return l.emission[ch] * max(0.0, float(np.dot(s.normal, toward)))
    if s.kind == SensorKind.RADIANCE:
        lo, hi = g.points.min(axis=0), g.points.max(axis=0)

        def on_floor(q):
            return np.all((q[:, :2] >= lo[:2]) & (q[:, :2] <= hi[:2]), axis=1)

        if _cone_lands(s, np.zeros(3), np.array([0.0, 0.0, 1.0]), on_floor):
            return float(g.albedo[0]) * e_floor / math.pi
        raise no_closed_form(ctx, s, "the meter's cone does not land on the floor")
    raise no_closed_form(ctx, s, "patch")


#: the CIE 171:2006 case 5.2 source is modelled by a small disk; its exact
#: irradiance must stay this close to the point-source value (relative)
CIE171_5_2_MODEL_LIMIT = 2e-7


def _cie171_disk(ctx: CaseContext) -> tuple[Light, cf.CIE171PointSourceGrid]:
    l = one_light(ctx.scene, LightKind.DISK)
    grid = cf.cie171_point_source_grid()
    if not np.allclose(l.position, grid.source, atol=1e-9) or l.frame[2, 2] < 1.0 - 1e-12:
        raise UserError(f"{ctx.scene.path}: the CIE 171 5.2 source must sit at {tuple(grid.source)} m facing down")
    return l, grid


def _cie171_index(ctx: CaseContext, s: Sensor, grid) -> int:
    if s.name not in grid.names:
        raise no_closed_form(ctx, s, f"not one of the CIE 171 5.2 receivers {', '.join(grid.names)}")
    i = grid.names.index(s.name)
    if not np.allclose(s.position, grid.positions[i], atol=1e-12) or s.normal[2] < 1.0 - 1e-12:
        raise UserError(f"{ctx.cfg.path}: sensor {s.name} must sit at {tuple(grid.positions[i])} facing up")
    return i


def cie171_5_2(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """CIE 171:2006 case 5.2, exact: E = I0·h²/d⁴ for a Lambertian point
    source I(θ) = I0·cosθ (closed_forms.cie171_point_source_grid), scaled by
    the stage's I0 = L·πr² over the case's 1000 cd (so that radiometric mode,
    where the same numbers are W/sr, is checked too). The stage's 1 mm disk
    departs from a point by at most (r/h)² ≈ 1.1e-7 (the exact offset-disk
    factor, Howell; checked against CIE171_5_2_MODEL_LIMIT here)."""
    l, grid = _cie171_disk(ctx)
    i = _cie171_index(ctx, s, grid)
    i0 = l.emission[ch] * math.pi * l.radius**2  # on-axis intensity of a flat Lambertian emitter: L·A
    e_point = grid.exact_lx[i] * i0 / grid.intensity_cd
    e_disk = float(cf.disk_irradiance_parallel(l.emission[ch], l.radius, grid.height_m, np.linalg.norm(grid.offsets[i])))
    if abs(e_disk / e_point - 1.0) > CIE171_5_2_MODEL_LIMIT:
        raise UserError(
            f"{ctx.scene.path}: the disk that models the CIE 171 5.2 point source is too large: "
            f"it departs from a point by {e_disk / e_point - 1.0:.1e} at {s.name}"
        )
    return e_point


def cie171_5_2_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    l, grid = _cie171_disk(ctx)
    i = _cie171_index(ctx, s, grid)
    e_disk = float(cf.disk_irradiance_parallel(l.emission[ch], l.radius, grid.height_m, np.linalg.norm(grid.offsets[i])))
    e_point = grid.exact_lx[i] * l.emission[ch] * math.pi * l.radius**2 / grid.intensity_cd
    return f"CIE table {grid.published_lx[i]:g}; disk/point {e_disk / e_point - 1.0:+.1e}"


def shaped_point(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """Shaped point lights (spot cone, focus, IES profile): E = Σ I(ω)·cosψ/d²
    with I(ω) = emission × LightShaping.factor(θ, φ), θ from the light's −Z
    axis, φ from its +X toward +Y (the numpy twin of the kernel's factor:
    cone with smoothstep softness, focus, the IES file's bilinear
    interpolation; OpenUSD user guide, "ShapingAPI")."""
    if s.kind != SensorKind.IRRADIANCE:
        raise no_closed_form(ctx, s, "only irradiance sensors")
    total = 0.0
    for l in ctx.scene.lights:
        if l.kind != LightKind.POINT:
            raise UserError(f"{ctx.scene.path}: the shaped-luminaire case expects point lights only, found {l.kind.name}")
        d = s.position - l.position
        dist = float(np.linalg.norm(d))
        w = d / dist
        cos_psi = float(-w @ s.normal)
        if cos_psi <= 0:
            continue
        f = 1.0
        if l.shaping is not None:
            ex, ey, ez = l.frame[:, 0], l.frame[:, 1], l.frame[:, 2]
            theta = math.acos(float(np.clip(-w @ ez, -1.0, 1.0)))
            phi = math.atan2(float(w @ ey), float(w @ ex))
            f = float(l.shaping.factor(theta, phi))
        total += l.emission[ch] * f * cos_psi / dist**2
    return total


def cie171_5_2_ies_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    grid = cf.cie171_point_source_grid()
    if s.name not in grid.names or ch != 1:
        return ""
    i = grid.names.index(s.name)
    return f"CIE table {grid.published_lx[i]:g}; exact cosine {grid.exact_lx[i]:.5f}"


def flush_note(ctx: CaseContext, s: Sensor, ch: int) -> str:
    return "Lambert (flush light)"


def glazing(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """A delta sun through a sheet 1 m above the receiver (stages/glazing.usda): E = E⊥·cosθ·T(θ),
    T the unpolarised thin-slab transmittance of the sheet's pane (closed_forms.thin_slab: clear, or
    the datasheet's 0.70 at normal incidence), 0.7 under the presence mesh of opacity 0.3
    (docs/REFERENCES.md §Thin slab and §Coverage). Which sheet: the surface row of the triangle
    straight above the receiver."""
    l = one_light(ctx.scene, LightKind.DISTANT)
    if l.half_angle != 0.0 or s.kind != SensorKind.IRRADIANCE:
        raise no_closed_form(ctx, s, "a delta distant light and irradiance receivers only")
    g = ctx.scene.geometry
    toward = l.frame[:, 2]
    c = max(0.0, float(np.dot(s.normal, toward)))
    p = g.points[g.triangles]
    above = [t for t in range(g.n_triangles) if ray_hits_triangles(s.position, toward, p[t:t + 1])]
    rows = {int(g.surface_id[t]) for t in above} if g.surface_id is not None else set()
    if len(rows) != 1 or min(rows) < 0:  # (a ray along a sheet's diagonal meets both its triangles)
        raise no_closed_form(ctx, s, "one glazing sheet above the receiver")
    row = g.surfaces[rows.pop()]
    cos_sheet = abs(float(toward[2]))
    if row.pane:
        t = float(cf.thin_slab(cos_sheet, row.ior, row.transmittance)[1])
        if row.layered:  # a translucent layer: the slab over the share 1 − opacity
            t *= 1.0 - row.coverage
    else:
        t = 1.0 - row.coverage
    return l.emission[ch] * c * t


def cutout(ctx: CaseContext, s: Sensor, ch: int) -> float:
    """A delta sun through a sheet whose opacity is read per texel (stages/cutout.usda): E = E⊥·cosθ·(1 − c),
    c the coverage where the sun's ray from the receiver crosses the sheet: the texture's bilinear value o
    at that point's st (presence), or 1 where o ≥ opacityThreshold and 0 below (docs/REFERENCES.md
    §Coverage; :func:`simulator.reference.texture.bilinear_at`, the crossing's barycentric weights by
    Möller–Trumbore)."""
    l = one_light(ctx.scene, LightKind.DISTANT)
    if l.half_angle != 0.0 or s.kind != SensorKind.IRRADIANCE:
        raise no_closed_form(ctx, s, "a delta distant light and irradiance receivers only")
    g = ctx.scene.geometry
    toward = l.frame[:, 2]
    c = max(0.0, float(np.dot(s.normal, toward)))
    t, u, v, ok = ray_triangles(s.position, toward, g.points[g.triangles])
    hit = np.flatnonzero(ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0))
    if len(hit) == 0 or g.surface_id is None or g.texture_id is None or g.texture_id[hit[0]] < 0:
        raise no_closed_form(ctx, s, "one textured cut-out sheet above the receiver")
    k = int(hit[0])
    row = g.surfaces[int(g.surface_id[k])]
    tex = g.coverage_textures[int(g.texture_id[k])]
    st = (1 - u[k] - v[k]) * g.texture_uv[k, 0] + u[k] * g.texture_uv[k, 1] + v[k] * g.texture_uv[k, 2]
    o = min(max(bilinear_at(tex.opacity.astype(np.float64), st, tex.wrap, tex.border), 0.0), 1.0)
    cover = (1.0 if o >= row.opacity_threshold else 0.0) if row.opacity_threshold > 0 else o
    return l.emission[ch] * c * (1.0 - cover)
