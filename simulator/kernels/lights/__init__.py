"""Light sampling and evaluation: one file per light kind, dispatch generated.

Warp has no virtual dispatch, so each light is a :class:`LightRec` with a
kind integer (:class:`simulator.scene.model.LightKind`). Every kind file in
this package (``point.py``, ``sphere.py``, ...) declares its ``@wp.func``
hooks in one :class:`~simulator.kernels.lights.base.LightKernel` named
``KERNEL``; this module finds them, checks that every ``LightKind`` has
exactly one, and generates :func:`sample_light`, :func:`pdf_light`,
:func:`hit_light`, :func:`escaped_radiance`, :func:`light_within`,
:func:`analytic_light` and :func:`analytic_patch_light` as unrolled
``if kind == k`` chains over the declared hooks (:func:`kind_chain`), and the
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
DOME (portal)  portal ∝ projected solid angle Π, then uniform in it   Σ_k (Π_k/ΣΠ)/Ω_k through portals, 0 elsewhere
CYLINDER       uniform in area on the side, front-facing points       d²/(A·cosθl)
EMISSIVE       piece by estimate × visibility, triangle ∝ power, area  P(k|x)·P(tri|k)·d²/(A·|cosθl|)
=============  =====================================================  ==================
"""

import importlib
import pkgutil

import numpy as np
import warp as wp

from simulator.scene.model import Light, LightKind

from .base import RAY_INF, GuideRec, LightKernel, LightRec, LightSample, SceneRec, empty_sample, tri_emitted, tri_params, tri_vertex

__all__ = [
    "KERNELS", "RAY_INF", "GuideRec", "LightKernel", "LightRec", "LightSample", "SceneRec",
    "analytic_light", "analytic_patch_light", "emissive_record", "escaped_radiance", "hit_light", "kind_chain",
    "light_record", "light_within", "pdf_light", "sample_light", "tri_emitted", "tri_params", "tri_vertex",
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


def kind_chain(entries, link, fallback):
    """An unrolled ``if kind == k`` chain over ``entries`` ((kind integer,
    hook) pairs): ``link(k, hook, rest)`` returns a ``@wp.func`` that calls
    ``hook`` when the kind is ``k`` and ``rest`` otherwise; ``fallback``
    ends the chain.

    Each link's ``wp.static`` names only its closure's ``k``, ``hook`` and
    ``rest``, so Warp resolves them where the link is declared. A loop over
    a table (``wp.static(table[i])``) would leave them to be resolved by
    building the whole module, which Warp does to hash it before every
    cached load (0.45 s of a one-sensor run's start-up)."""
    f = fallback
    for k, hook in reversed(entries):
        f = link(k, hook, f)
    return f


# The links of the sample and pdf chains, and the two entry points, are inlined wherever they are called (as
# rays.unoccluded): each takes the scene record by value, and a link left out of line by the compiler's own
# inlining decision would copy the whole record at every light sample (10-15% of a sample's time)
def _sample_link(k, hook, rest):
    @wp.func(inline=True)
    def sample_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
        if l.kind == wp.static(k):
            return wp.static(hook)(scene, l, p, n, u)
        return wp.static(rest)(scene, l, p, n, u)

    return sample_kind


@wp.func(inline=True)
def _no_sample(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    return empty_sample()


def _pdf_link(k, hook, rest):
    @wp.func(inline=True)
    def pdf_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
        if l.kind == wp.static(k):
            return wp.static(hook)(scene, l, p, n, wi, t, tri)
        return wp.static(rest)(scene, l, p, n, wi, t, tri)

    return pdf_kind


@wp.func(inline=True)
def _no_pdf(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    return 0.0


def _hit_link(k, hook, rest):
    @wp.func
    def hit_kind(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
        if l.kind == wp.static(k):
            return wp.static(hook)(l, o, d, t_max)
        return wp.static(rest)(l, o, d, t_max)

    return hit_kind


@wp.func
def _no_hit(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    return -1.0


def _escaped_link(k, hook, rest):
    @wp.func
    def escaped_kind(l: LightRec, d: wp.vec3) -> wp.vec2:
        if l.kind == wp.static(k):
            return wp.static(hook)(l, d)
        return wp.static(rest)(l, d)

    return escaped_kind


@wp.func
def _no_escape(l: LightRec, d: wp.vec3) -> wp.vec2:
    return wp.vec2(0.0, 0.0)


def _near_link(k, hook, rest):
    @wp.func
    def near_kind(l: LightRec, d: wp.vec3, reach: float) -> bool:
        if l.kind == wp.static(k):
            return wp.static(hook)(l, d, reach)
        return wp.static(rest)(l, d, reach)

    return near_kind


@wp.func
def _not_near(l: LightRec, d: wp.vec3, reach: float) -> bool:
    return False


def _analytic_link(k, hook, rest):
    @wp.func
    def analytic_kind(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
        if l.kind == wp.static(k):
            return wp.static(hook)(scene, l, p, n)
        return wp.static(rest)(scene, l, p, n)

    return analytic_kind


@wp.func
def _no_analytic(scene: SceneRec, l: LightRec, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    return wp.vec2(0.0, 0.0)


def _analytic_patch_link(k, hook, rest):
    @wp.func
    def analytic_patch_kind(
        l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float
    ) -> wp.vec2:
        if l.kind == wp.static(k):
            return wp.static(hook)(l, c, n, right, up, w, h)
        return wp.static(rest)(l, c, n, right, up, w, h)

    return analytic_patch_kind


@wp.func
def _no_analytic_patch(l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float) -> wp.vec2:
    return wp.vec2(0.0, 0.0)


_sample_chain = kind_chain(_hooks("sample"), _sample_link, _no_sample)
_pdf_chain = kind_chain(_hooks("pdf"), _pdf_link, _no_pdf)
_hit_chain = kind_chain(_hooks("hit"), _hit_link, _no_hit)
_escaped_chain = kind_chain(_hooks("escaped"), _escaped_link, _no_escape)
_near_chain = kind_chain(_hooks("near"), _near_link, _not_near)
_analytic_chain = kind_chain(_hooks("analytic"), _analytic_link, _no_analytic)
_analytic_patch_chain = kind_chain(_hooks("analytic_patch"), _analytic_patch_link, _no_analytic_patch)


@wp.func(inline=True)
def sample_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, u: wp.vec3) -> LightSample:
    """Sample light ``li`` for a receiver at ``p`` facing ``n``."""
    return _sample_chain(scene, scene.lights[li], p, n, u)


@wp.func(inline=True)
def pdf_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, wi: wp.vec3, t: float, tri: int) -> float:
    """Solid-angle pdf with which :func:`sample_light` would pick direction
    ``wi`` from ``p``, given that ``wi`` hits the light at distance ``t``
    (on triangle ``tri`` for emissive geometry)."""
    return _pdf_chain(scene, scene.lights[li], p, n, wi, t, tri)


@wp.func
def hit_light(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> float:
    """Distance along the ray (o, d) to the emitting side of a light with a
    surface, or −1 if it is missed, lies beyond ``t_max``, or the light has
    no surface. UsdLux lights neither block nor reflect: a ray that hits one
    goes on to whatever lies behind."""
    return _hit_chain(l, o, d, t_max)


@wp.func
def escaped_radiance(l: LightRec, d: wp.vec3) -> wp.vec2:
    """Radiance from an infinitely distant light along a ray that left the scene."""
    return _escaped_chain(l, d)


@wp.func
def light_within(l: LightRec, d: wp.vec3, reach: float) -> bool:
    """True if the light's surface lies within ``reach`` of the point at
    offset d from its centre (or the point is inside a sphere light)."""
    return _near_chain(l, d, reach)


@wp.func
def analytic_light(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """Unoccluded irradiance on (p, n) from light ``li`` in closed form (the
    host has checked that the closed form applies; see plan.analytic_refusal)."""
    return _analytic_chain(scene, scene.lights[li], p, n)


@wp.func
def analytic_patch_light(l: LightRec, c: wp.vec3, n: wp.vec3, right: wp.vec3, up: wp.vec3, w: float, h: float) -> wp.vec2:
    """Mean unoccluded irradiance on the w × h patch (centre c, normal n,
    axes right and up) in closed form, for kinds that have one (point)."""
    return _analytic_patch_chain(l, c, n, right, up, w, h)


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

