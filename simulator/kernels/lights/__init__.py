"""Light sampling and evaluation: one file per light kind, dispatch generated.

Warp has no virtual dispatch, so each light is a :class:`LightRec` with a
kind integer (:class:`simulator.scene.model.LightKind`). Every kind file in
this package (``point.py``, ``sphere.py``, ...) declares its ``@wp.func``
hooks in one :class:`~simulator.kernels.lights.base.LightKernel` named
``KERNEL``; this module finds them, checks that every ``LightKind`` has
exactly one, and generates :func:`sample_light`, :func:`pdf_light`,
:func:`hit_light`, :func:`escaped_radiance`, :func:`light_within`,
:func:`analytic_light` and :func:`analytic_patch_light` as unrolled
``if kind == k`` chains over the declared hooks (``wp.static``), and the
host upload :func:`light_record`.

Each sampler returns the light's *unshadowed* contribution to irradiance on
a receiver at ``p`` with normal ``n``,

    value = L(ωi) · cosθ / pdf(ωi),

together with the direction, the shadow-ray length and the solid-angle pdf
(0 for delta lights, which no direction sample can hit). The caller traces
the shadow ray and applies multiple-importance weights.

=============  =====================================================  ==================
kind           strategy                                               pdf(ω)
=============  =====================================================  ==================
POINT          exact direction (delta)                                0
SPHERE         uniform in the subtended cone                          1/(2π(1−cosθmax))
RECT           uniform in the subtended spherical rectangle           1/Ω (area if Ω tiny)
DISK           uniform in area                                        d²/(A·cosθl)
DISTANT        exact (angle 0, delta) or uniform in its cone          1/(2π(1−cosθmax))
DOME           cosine lobe about the receiver normal                  cosθ/π
DOME (map)     texel ∝ value·sinθ, uniform in (u, v) inside it        pdf_uv/(2π² sinθ)
CYLINDER       uniform in area on the side, front-facing points       d²/(A·cosθl)
EMISSIVE       triangle ∝ its power, then uniform in area             P(tri)·d²/(A·|cosθl|)
=============  =====================================================  ==================
"""

import importlib
import pkgutil

import numpy as np
import warp as wp

from simulator.scene.model import Light, LightKind

from .base import RAY_INF, GuideRec, LightKernel, LightRec, LightSample, SceneRec, empty_sample, tri_emitted, tri_vertex

__all__ = [
    "KERNELS", "RAY_INF", "GuideRec", "LightKernel", "LightRec", "LightSample", "SceneRec",
    "analytic_light", "analytic_patch_light", "emissive_record", "escaped_radiance", "hit_light",
    "light_record", "light_within", "pdf_light", "sample_light", "tri_emitted", "tri_vertex",
]  # fmt: skip


def _find_kernels() -> tuple[LightKernel, ...]:
    """Every kind file's ``KERNEL``, in ``LightKind`` order; one per kind."""
    found: dict[LightKind, LightKernel] = {}
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        if info.name == "base":
            continue
        k = getattr(importlib.import_module(f"{__name__}.{info.name}"), "KERNEL", None)
        if not isinstance(k, LightKernel):
            continue
        if k.kind in found:
            raise ImportError(f"light kind {k.kind.name} is declared twice (kernels/lights/{info.name}.py)")
        found[k.kind] = k
    missing = [k.name for k in LightKind if k not in found]
    if missing:
        raise ImportError(f"light kinds without a kind file in simulator/kernels/lights: {', '.join(missing)}")
    return tuple(found[k] for k in LightKind)


#: the declared kinds, indexed by ``LightKind``
KERNELS = _find_kernels()


def _hooks(name: str) -> tuple[tuple[int, object], ...]:
    """(kind integer, hook) of every kind that declares hook ``name``."""
    return tuple((int(k.kind), getattr(k, name)) for k in KERNELS if getattr(k, name) is not None)


_SAMPLE = _hooks("sample")
_PDF = _hooks("pdf")
_HIT = _hooks("hit")
_ESCAPED = _hooks("escaped")
_NEAR = _hooks("near")
_ANALYTIC = _hooks("analytic")
_ANALYTIC_PATCH = _hooks("analytic_patch")


@wp.func
def sample_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    """Sample light ``li`` for a receiver at ``p`` facing ``n``."""
    l = scene.lights[li]
    for i in range(wp.static(len(_SAMPLE))):
        if l.kind == wp.static(_SAMPLE[i][0]):
            return wp.static(_SAMPLE[i][1])(scene, l, p, n, u)
    return empty_sample()


@wp.func
def pdf_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    """Solid-angle pdf with which :func:`sample_light` would pick direction
    ``wi`` from ``p``, given that ``wi`` hits the light at distance ``t``
    (on triangle ``tri`` for emissive geometry)."""
    l = scene.lights[li]
    for i in range(wp.static(len(_PDF))):
        if l.kind == wp.static(_PDF[i][0]):
            return wp.static(_PDF[i][1])(scene, l, p, n, wi, t, tri)
    return 0.0


@wp.func
def hit_light(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    """Distance along the ray (o, d) to the emitting side of a light with a
    surface, or −1 if it is missed, lies beyond ``t_max``, or the light has
    no surface. UsdLux lights neither block nor reflect: a ray that hits one
    goes on to whatever lies behind."""
    for i in range(wp.static(len(_HIT))):
        if l.kind == wp.static(_HIT[i][0]):
            return wp.static(_HIT[i][1])(l, o, d, t_max)
    return -1.0


@wp.func
def escaped_radiance(l: LightRec, d: wp.vec3) -> wp.vec2:
    """Radiance from an infinitely distant light along a ray that left the scene."""
    for i in range(wp.static(len(_ESCAPED))):
        if l.kind == wp.static(_ESCAPED[i][0]):
            return wp.static(_ESCAPED[i][1])(l, d)
    return wp.vec2(0.0, 0.0)


@wp.func
def light_within(l: LightRec, d: wp.vec3, reach: float) -> bool:
    """True if the light's surface lies within ``reach`` of the point at
    offset d from its centre (or the point is inside a sphere light)."""
    for i in range(wp.static(len(_NEAR))):
        if l.kind == wp.static(_NEAR[i][0]):
            return wp.static(_NEAR[i][1])(l, d, reach)
    return False


@wp.func
def analytic_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """Unoccluded irradiance on (p, n) from light ``li`` in closed form (the
    host has checked that the closed form applies; see plan.analytic_refusal)."""
    l = scene.lights[li]
    for i in range(wp.static(len(_ANALYTIC))):
        if l.kind == wp.static(_ANALYTIC[i][0]):
            return wp.static(_ANALYTIC[i][1])(scene, l, p, n)
    return wp.vec2(0.0, 0.0)


@wp.func
def analytic_patch_light(l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float) -> wp.vec2:
    """Mean unoccluded irradiance on the w × h patch (centre c, normal n,
    axes right and up) in closed form, for kinds that have one (point)."""
    for i in range(wp.static(len(_ANALYTIC_PATCH))):
        if l.kind == wp.static(_ANALYTIC_PATCH[i][0]):
            return wp.static(_ANALYTIC_PATCH[i][1])(l, c, n, right, up, w, h)
    return wp.vec2(0.0, 0.0)


# ---------------------------------------------------------------- host upload


def light_record(light: Light, keep: list) -> LightRec:
    """The device record of one light: the common fields, then its kind's ``upload``.

    Parameters
    ----------
    light : Light
    keep : list
        Device arrays the record points to are appended (keep them alive).
    """
    r = LightRec()
    r.kind = int(light.kind)
    r.position = wp.vec3(*map(float, light.position))
    f = np.asarray(light.frame, float)
    r.ex = wp.vec3(*map(float, f[:, 0]))
    r.ey = wp.vec3(*map(float, f[:, 1]))
    r.ez = wp.vec3(*map(float, f[:, 2]))
    r.emission = wp.vec2(float(light.emission[0]), float(light.emission[1]))
    r.width, r.height, r.radius = float(light.width), float(light.height), float(light.radius)
    r.one_minus_cos = 0.0
    r.area = 0.0
    r.length = float(light.length)
    upload = KERNELS[light.kind].upload
    if upload is not None:
        upload(r, light, keep)
    if light.shaping is not None:
        _upload_shaping(r, light.shaping, keep)
    return r


def _upload_shaping(r: LightRec, sh, keep: list) -> None:
    """UsdLuxShapingAPI on the record (a modifier of any kind's emission; see
    ``estimators.shaping_factor``); an IES table goes in ``map`` (rows θ, columns φ)."""
    r.shaped = 1
    r.shaping = wp.vec4(float(sh.cone_angle_rad), float(sh.cone_softness), float(sh.focus), float(sh.focus_tint))
    if sh.ies is not None:
        _, _, table = sh.ies.regular_table()
        t = np.ascontiguousarray(table.T, np.float32)  # (θ rows, φ columns)
        r.map_h, r.map_w = int(t.shape[0]), int(t.shape[1])
        r.map = wp.array(t.ravel(), dtype=float)
        r.ies_scale = float(sh.ies_scale)
        keep.append(r.map)


def emissive_record() -> LightRec:
    """The one record that stands for all emissive triangles (see emissive.py)."""
    r = LightRec()
    r.kind = int(LightKind.EMISSIVE)
    return r

