"""The plan: which estimator reads each sensor, and why.

``method = "auto"`` models no more of the scene than a reading needs. Per
sensor, in order:

1. **closed form** (``analytic``) when no surface can block any light the
   sensor sees (a conservative geometric proof, :func:`analytic_refusal`)
   and every surface in front of it is black, so no reflected light reaches
   it either;
2. **direct light** when no surface the sensor can see reflects (albedo 0,
   or no geometry in front of it): bounces would add nothing. ``light``
   samples each light once, and is cheapest for small and delta lights;
   ``mis`` adds a cosine-weighted direction, worth its extra ray when a light
   covers a large part of the sensor's sky (a dome, a near panel):
   ``LARGE_SOURCE_SR`` decides (measured with ``probesim chart``); and
   ``mis`` wherever a DomeLight with portals reaches the sensor, since light
   sampling draws such a dome only through its portals and the cosine
   directions count the sky seen past them. Before
   either, ``exact`` — each RectLight's visible part in closed form, so
   penumbrae carry no noise — when every light it sees is a RectLight and
   few triangles stand in the way (:mod:`simulator.plan.exact_rule`);
3. **paths** otherwise: interreflection is part of the reading. ``auto``
   reads them with ``guided`` paths (``path`` plus a surface guide learnt by
   a pilot, :mod:`simulator.engine.guide`) when :data:`AUTO_GUIDED` is set
   and the stage can be cut into patches within the cap
   (:func:`simulator.scene.patches.patch_layout`); else ``path``. Panes,
   cut-outs and glossy faces keep the guide: its segments pass them at
   their transmittance and glossy vertices mix it with their lobes, so a
   glazed room is guided like an open one.

Lights wholly behind a sensor's plane contribute nothing to it and are not
sampled for it. The plan says which transport the scene needs and why
(:func:`simulator.spectra.transport.choose_transport`): ``grey`` traces one
channel (with its radiometric and photometric totals), exact; ``spectral``
(a colour can change a reading) and ``per-emitter`` (several emitter
spectra; its exact per-emitter tally is not built) trace 4 hero wavelengths
per sample. An explicit method overrides the plan for every sensor.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from simulator.errors import UserError
from simulator.plan.exact_rule import EMISSIVE, exact_plan_refusal, exact_plan_refusals, hybrid_records
from simulator.engine.methods import HYBRID_METHODS, METHOD_FLAGS, MC_METHODS, light_pick_rule, rr_threshold_rule, sampled_method
from simulator.plan.bounds import FrontIndex
from simulator.scene.model import LightKind, Scene, Sensor, SensorKind, patch_width_axis

__all__ = ["MC_METHODS", "SensorPlan", "Plan", "SceneBounds", "make_plan", "probe_method", "analytic_refusal", "scene_bounds",
           "lights_behind", "lights_behind_many", "cull_mask", "closed_form_refusal", "format_plan", "with_optics"]

#: a light subtending more than this solid angle (sr) from a direct-lit
#: sensor makes `mis` the plan: its cosine-weighted direction then lands on
#: the light often, and on the dome stage reached 1% 1.1× faster than `light`
#: (`probesim chart`), while on small sources (point, 1 mm sphere) the extra
#: ray cost 2–6× the time of `light`.
LARGE_SOURCE_SR = 1.0

#: whether ``auto`` reads interreflecting sensors with ``guided`` paths (see
#: docs/DESIGN.md, "Surface guide", for the measurements behind the choice)
AUTO_GUIDED = True


def probe_method(scene: Scene, requested: str, component: str = "total") -> tuple[str, str]:
    """``(method, reason)`` for the run's probes, which look in every direction
    and have no closed form: paths if any surface reflects (or for the
    indirect component), else direct light sampling; an explicit Monte Carlo
    method as asked (``analytic`` falls back to this choice)."""
    reflects = scene.geometry.n_triangles > 0 and bool(np.any(scene.geometry.reflecting()))
    if requested in ("auto", "analytic", "exact"):
        if component == "indirect":
            return "path", "the indirect component is light reflected on the way: paths"
        if reflects:
            return "path", "surfaces reflect (albedo > 0), so interreflection needs paths"
        return "light", "no surface reflects, so direct light sampling"
    if requested in MC_METHODS:
        note = ""
        if requested == "light" and reflects and (portal_dome := _portal_dome(scene, [])):
            note = f"; light samples the DomeLight {portal_dome} only through its portals: sky seen past them is not counted"
        if not METHOD_FLAGS[requested][3] and reflects:
            return requested, f"as requested; direct light only: interreflection is ignored ({requested} does not bounce){note}"
        return requested, "as requested"
    raise UserError(f"simulation.method: {requested!r} is not a method (use auto, analytic, exact, light, bsdf, mis or path)")


@dataclass
class SceneBounds:
    """What the planner's geometric tests need of a scene, computed once.

    Attributes
    ----------
    index : FrontIndex or None
        The triangles (None without geometry), with the subsets ``all``,
        ``suspect`` (those that may block a light: all, or, when every light
        is a one-sided rect or disk and nothing emits, those not wholly behind
        every light's emitting plane), ``opaque`` (not emissive) and
        ``reflecting`` (albedo > 0).
    emissive : bool
        Some triangle emits.
    coplanar_emitters : bool
        Every emissive triangle lies in one plane (emitters cannot shadow one another).
    """

    index: FrontIndex | None
    emissive: bool = False
    coplanar_emitters: bool = False
    _last: tuple = (None, None)
    _known: dict = field(default_factory=dict)

    def first_in_front(self, sensor: Sensor) -> dict[str, int]:
        """:meth:`FrontIndex.first_in_front` for the sensor's plane (the last answer is kept:
        the refusal and the reflection test ask about the same sensor in turn; :meth:`prime`
        answers many at once)."""
        key = (sensor.position.tobytes(), sensor.normal.tobytes())
        if (known := self._known.get(key)) is not None:
            return known
        if self._last[0] != key:
            self._last = (key, self.index.first_in_front(sensor.position, sensor.normal))
        return self._last[1]

    def prime(self, sensors: list[Sensor]) -> None:
        """Answer :meth:`first_in_front` for the planar sensors' planes in one stacked scan
        (:meth:`FrontIndex.first_in_front_many`; nothing where the scene is too big for that)."""
        planar = [s for s in sensors if s.kind in (SensorKind.IRRADIANCE, SensorKind.PATCH)]
        if self.index is None or not planar:
            return
        found = self.index.first_in_front_many(np.array([s.position for s in planar], float),
                                               np.array([s.normal for s in planar], float))  # fmt: skip
        if found is None:
            return
        names = self.index.names
        for s, row in zip(planar, found.tolist()):
            self._known[(s.position.tobytes(), s.normal.tobytes())] = dict(zip(names, row))


def scene_bounds(scene: Scene) -> SceneBounds:
    """Build the :class:`SceneBounds` of a scene (O(T log T), once per plan)."""
    g = scene.geometry
    if g.n_triangles == 0:
        return SceneBounds(None)
    pts = g.points[g.triangles]  # (T, 3, 3)
    # vertices within float64 rounding of the sensor's plane (a floor under a
    # sensor lying on it) count as behind it, not in front
    tol = 1e-9 * max(1.0, float(pts.max()), -float(pts.min()))
    emissive = np.any(g.emission > 0, axis=1)
    suspect = np.ones(len(pts), bool)
    planar = [l for l in scene.lights if l.kind in (LightKind.RECT, LightKind.DISK)]
    if len(planar) == len(scene.lights) and not emissive.any():
        behind_all = np.ones(len(pts), bool)
        for l in planar:  # wholly on the non-emitting side of the light's plane
            behind_all &= np.all((pts - l.position) @ l.frame[:, 2] >= -tol, axis=1)
        suspect = ~behind_all
    coplanar = False
    if emissive.any():
        e = pts[emissive]
        with np.errstate(invalid="ignore", divide="ignore"):  # a degenerate first emitter: not coplanar
            n0 = np.cross(e[0, 1] - e[0, 0], e[0, 2] - e[0, 0])
            n0 /= np.linalg.norm(n0)
            coplanar = bool(np.all(np.abs((e - e[0, 0]) @ n0) <= tol))
    subsets = {"all": np.ones(len(pts), bool), "suspect": suspect, "opaque": ~emissive, "reflecting": g.reflecting()}
    return SceneBounds(FrontIndex(pts, subsets, tol), bool(emissive.any()), coplanar)


def analytic_refusal(scene: Scene, sensor: Sensor, bounds: SceneBounds | None = None) -> str | None:
    """Why the closed form cannot give this sensor's reading, or None if it can.

    Conservative: a triangle that is not wholly behind the sensor's plane may
    block a light unless it is wholly behind that light's emitting plane (rect
    and disk lights, which emit to one side only); any such triangle refuses
    the closed form. Patches have a closed form for point lights only, radiance
    meters and probes none. ``bounds``: the scene's :func:`scene_bounds`
    (built here when not given).
    """
    if sensor.kind == SensorKind.PATCH:
        if any(l.kind != LightKind.POINT for l in scene.lights):
            return "a patch has a closed form for point lights only"
    elif sensor.kind in (SensorKind.CYLINDRICAL, SensorKind.SEMICYLINDRICAL):
        # E = I(ω)·sinθ·(1 + cos φ)/(π d²) (whole cylinder: 1/π in place of (1 + cos φ)/π); it looks all round,
        # so any triangle may block a light
        if any(l.kind != LightKind.POINT for l in scene.lights):
            return f"a {sensor.kind.name.lower()} sensor has a closed form for point lights only"
        if scene.geometry.n_triangles:
            return f"a {sensor.kind.name.lower()} sensor looks all round: any surface may block a light"
        return None
    elif sensor.kind != SensorKind.IRRADIANCE:
        return f"no closed form for a {sensor.kind.name.lower()} sensor"
    g = scene.geometry
    for l in scene.lights:
        if l.kind == LightKind.CYLINDER:
            return f"no closed form for the CylinderLight {l.name}"
        if l.shaping is not None and (l.kind != LightKind.POINT or sensor.kind == SensorKind.PATCH):
            return f"no closed form for the shaped light {l.name} (only a point light's E = I(ω)·cosψ/d²)"
        if l.kind == LightKind.DOME and l.texture:
            return f"no closed form for the textured DomeLight {l.name}"
        if l.kind == LightKind.DISK and sensor.kind == SensorKind.IRRADIANCE:
            n = sensor.normal
            a, b = l.frame[:, 0] @ n, l.frame[:, 1] @ n
            if (l.position - sensor.position) @ n - l.radius * np.hypot(a, b) <= 0 and (l.position - sensor.position) @ l.frame[:, 2] > 0:
                return f"the DiskLight {l.name} straddles the sensor's horizon"
    if g.n_triangles == 0:
        return None
    bounds = bounds or scene_bounds(scene)
    first = bounds.first_in_front(sensor)  # a patch is planar too
    if first["all"] < 0:
        return None
    if bounds.emissive and first["opaque"] < 0 and bounds.coplanar_emitters and len(scene.lights) == 0:
        return None  # only emitters in front: coplanar ones cannot shadow one another
    if first["suspect"] >= 0:
        name = g.prim_names[g.prim[first["suspect"]]] if g.prim_names else "a surface"
        return f"{name} may block a light"
    return None


# ---------------------------------------------------------------- per-sensor plans


@dataclass
class SensorPlan:
    """How one sensor is read.

    Attributes
    ----------
    name, kind : str
    method : str
    bounces : bool
        Whether paths follow reflections for this sensor.
    reason : str
    lights : list of str
        Lights that can reach the sensor (sampled for it).
    culled : list of str
        Lights wholly behind its plane: not sampled for it.
    geometry : str
        What of the scene matters: ``none``, ``black occluders`` or
        ``reflecting surfaces`` in front of the sensor.
    computed : list of str
        A hybrid's lights whose direct light is computed on the host (``emissive surfaces``: the
        emissive triangles); empty for every other method.
    """

    name: str
    kind: str
    method: str
    bounces: bool
    reason: str
    lights: list[str] = field(default_factory=list)
    culled: list[str] = field(default_factory=list)
    geometry: str = "none"
    computed: list[str] = field(default_factory=list)

    def to_record(self) -> dict:
        """``dataclasses.asdict`` of the plan, written out (asdict's deep copy took ~0.1 s of a
        warm 1,024-sensor run)."""
        return {"name": self.name, "kind": self.kind, "method": self.method, "bounces": self.bounces,
                "reason": self.reason, "lights": list(self.lights), "culled": list(self.culled),
                "geometry": self.geometry} | ({"computed": list(self.computed)} if self.computed else {})  # fmt: skip


@dataclass
class Plan:
    requested: str
    component: str
    channels: int
    channel_reason: str
    sensors: list[SensorPlan]
    #: transport the scene needs (:data:`simulator.spectra.transport.TRANSPORTS`)
    transport: str = "grey"
    #: per Monte Carlo method used: how next-event estimation samples the lights, and why
    light_sampling: dict[str, str] = field(default_factory=dict)
    #: one line per surface beyond Lambert: what it needs and why (:func:`surface_needs`); empty: all matte
    surfaces: list[str] = field(default_factory=list)
    #: sensors from this index on are optics twins of modelled sensors (:func:`with_optics`), run after the
    #: others; None: there are none
    optics_from: int | None = None

    def run_order(self) -> list[tuple[str, np.ndarray]]:
        """``(method, sensor indices)`` in the order a run reads them: :meth:`groups`, the optics twins'
        groups after every other sensor's (so naming a model changes no ideal reading)."""
        groups = self.groups()
        if self.optics_from is None:
            return list(groups.items())
        n = self.optics_from
        return ([(m, ix[ix < n]) for m, ix in groups.items() if np.any(ix < n)]
                + [(m, ix[ix >= n]) for m, ix in groups.items() if np.any(ix >= n)])

    def groups(self) -> dict[str, np.ndarray]:
        """Sensor indices per method, in first-use order."""
        out: dict[str, list[int]] = {}
        for i, sp in enumerate(self.sensors):
            out.setdefault(sp.method, []).append(i)
        return {m: np.asarray(ix, np.int64) for m, ix in out.items()}

    def light_mask(self, light_names: list[str]) -> np.ndarray:
        """(S, L) int32: 1 where light l is sampled for sensor s at its first vertex."""
        mask = np.ones((len(self.sensors), len(light_names)), np.int32)
        col = {n: j for j, n in enumerate(light_names)}
        for i, sp in enumerate(self.sensors):
            for n in sp.culled:
                mask[i, col[n]] = 0
        return mask

    def computed_mask(self, light_names: list[str]) -> np.ndarray | None:
        """(S, L + 1) bool: the hybrids' computed direct light per sensor and light record (the lights
        named, then the emissive triangles); None where no sensor has any."""
        if not any(sp.computed for sp in self.sensors):
            return None
        col = {n: j for j, n in enumerate(light_names)}
        col[EMISSIVE] = len(light_names)
        out = np.zeros((len(self.sensors), len(light_names) + 1), bool)
        for i, sp in enumerate(self.sensors):
            for n in sp.computed:
                out[i, col[n]] = True
        return out

    def record_json(self) -> str:
        """:meth:`to_record` as the run record's JSON writes it (``indent=2``, sorted keys), made once per
        plan: a kept plan (:mod:`simulator.plan.cache`) is not encoded again, and a plan is not changed
        after :func:`make_plan`. Python's JSON encoder runs in pure Python with ``indent``: ~40 ms for
        1,024 sensors."""
        text = self.__dict__.get("_record_json")
        if text is None:
            import json

            text = self.__dict__["_record_json"] = json.dumps(self.to_record(), indent=2, sort_keys=True)
        return text

    def to_record(self) -> dict:
        return {
            "requested": self.requested,
            "component": self.component,
            "transport": self.transport,
            "channels": self.channels,
            "channel_reason": self.channel_reason,
            "methods": {m: len(ix) for m, ix in self.groups().items()},
            "light_sampling": dict(self.light_sampling),
            "sensors": [sp.to_record() for sp in self.sensors],
        } | ({"surfaces": list(self.surfaces)} if self.surfaces else {})


def surface_needs(scene: Scene) -> list[str]:
    """One line per row of ``Geometry.surfaces`` its faces use: the prim that first uses it, how many
    triangles, what the kernels model (coverage, dielectric slab) and why, and what is read but not
    modelled. Empty when every face is matte (the matte kernels run unchanged)."""
    g = scene.geometry
    if not g.has_surfaces:
        return []
    out = []
    counts = np.bincount(g.surface_id[g.surface_id >= 0], minlength=len(g.surfaces))
    for k, s in enumerate(g.surfaces):
        if counts[k] == 0:
            continue
        if s.pane:
            why = (f"probesim:transmittance {s.transmittance:g}" if s.transmittance is not None
                   else f"opacity {s.opacity:g} in {s.opacity_mode} mode")
            if g.solid_side is not None and (closed := int(np.count_nonzero((g.surface_id == k) & (g.solid_side != 0)))):
                why += f"; {closed} on closed meshes, read as slabs entered once"
        elif s.opacity_texture >= 0:
            tex = g.coverage_textures[s.opacity_texture]
            read = int(np.count_nonzero((g.surface_id == k) & (g.texture_id >= 0))) if g.texture_id is not None else 0
            why = (f"opacity from {tex.name}, {tex.opacity.shape[1]} x {tex.opacity.shape[0]} texels, "
                   f"{read} triangle(s) with primvars:{tex.primvar}")
        elif s.coverage < 1.0:
            why = (f"opacity {s.opacity:g} in presence mode" if s.opacity_threshold == 0
                   else f"opacity {s.opacity:g} against opacityThreshold {s.opacity_threshold:g}")
        else:
            why = "specular inputs authored away from their fallbacks"
        line = f"{s.name}: {counts[k]} triangle(s): {'; '.join(s.lobes())} ({why})"
        if s.unmodelled:
            line += f"; read, not modelled: {', '.join(s.unmodelled)}"
        out.append(line)
    from simulator.scene.surfaces import curved_mirrors, glint_pairs, shaded_faces

    for plane, alpha, li in glint_pairs(g, scene.lights):
        n, d = plane[:3], plane[3]
        out.append(f"glints: {scene.lights[li].name} reflected in the glossy plane n = ({n[0]:.3g}, {n[1]:.3g}, "
                   f"{n[2]:.3g}), n·x = {d:.4g} m (GGX α {alpha:.3g}), sampled at matte vertices that face it")
    shaded = shaded_faces(g)
    if shaded is not None:
        prims = sorted({g.prim_names[i] for i in np.unique(g.prim[shaded])})
        curves = curved_mirrors(g, shaded)
        out.append(f"smooth normals: {int(shaded.sum())} glossy or mirror triangle(s) of {', '.join(prims[:3])}"
                   f"{' ...' if len(prims) > 3 else ''} reflect about their interpolated normals"
                   + (f"; {curves.n} curved mirror(s): point lights and the sun solved for their reflection point"
                      if curves.n else ""))
    return out


def lights_behind(scene: Scene, sensor: Sensor) -> list[str]:
    """Lights that cannot reach the sensor's front side: wholly behind the
    plane through it (irradiance and patch sensors), or emitting away from it."""
    if sensor.kind not in (SensorKind.IRRADIANCE, SensorKind.PATCH):
        return []
    p, n = sensor.position, sensor.normal
    out = []
    for l in scene.lights:
        behind = False
        if l.kind == LightKind.POINT:
            behind = (l.position - p) @ n <= 0
        elif l.kind == LightKind.SPHERE:
            behind = (l.position - p) @ n <= -l.radius
        elif l.kind in (LightKind.RECT, LightKind.DISK):
            ex, ey, ez = l.frame[:, 0], l.frame[:, 1], l.frame[:, 2]
            if l.kind == LightKind.RECT:
                hx, hy = 0.5 * l.width * ex, 0.5 * l.height * ey
                corners = l.position + np.array([-hx - hy, hx - hy, hx + hy, -hx + hy])
                wholly = np.all((corners - p) @ n <= 0)
            else:
                wholly = (l.position - p) @ n + l.radius * np.hypot(ex @ n, ey @ n) <= 0
            # one-sided: a receiver on the light's back side sees nothing of it
            # (a patch is planar, so the test at its centre holds for all of it
            # only when the light is wholly on one side: test its corners too)
            pts = [p] if sensor.kind == SensorKind.IRRADIANCE else _patch_corners(sensor)
            back = all((q - l.position) @ ez >= 0 for q in pts)
            behind = bool(wholly or back)
        elif l.kind == LightKind.DISTANT:
            # the cone of directions toward the light, half-angle θ, around +ez
            behind = l.frame[:, 2] @ n <= -np.sin(l.half_angle) if l.half_angle > 0 else l.frame[:, 2] @ n <= 0
        if behind:
            out.append(l.name)
    return out


def lights_behind_many(scene: Scene, sensors: list[Sensor]) -> list[list[str]]:
    """:func:`lights_behind` of each sensor: irradiance sensors' tests stacked over the sensors (the
    same products per sensor, by numpy's stacked ``matmul``, so the same answers), the others' one
    by one."""
    out = [[] for _ in sensors]
    irr = [i for i, s in enumerate(sensors) if s.kind == SensorKind.IRRADIANCE]
    for i, s in enumerate(sensors):
        if s.kind == SensorKind.PATCH:
            out[i] = lights_behind(scene, s)
    if not irr or not scene.lights:
        return out
    P = np.array([sensors[i].position for i in irr], float)  # (S, 3)
    N = np.array([sensors[i].normal for i in irr], float)

    def dot_n(v: np.ndarray) -> np.ndarray:
        """(S, k): row s of ``v`` (S, k, 3) dotted with sensor s's normal, as ``v[s] @ n``."""
        return (v @ N[:, :, None])[..., 0]

    behind = np.zeros((len(irr), len(scene.lights)), bool)
    for j, l in enumerate(scene.lights):
        if l.kind == LightKind.POINT:
            behind[:, j] = dot_n((l.position - P)[:, None, :])[:, 0] <= 0
        elif l.kind == LightKind.SPHERE:
            behind[:, j] = dot_n((l.position - P)[:, None, :])[:, 0] <= -l.radius
        elif l.kind in (LightKind.RECT, LightKind.DISK):
            ex, ey, ez = l.frame[:, 0], l.frame[:, 1], l.frame[:, 2]
            if l.kind == LightKind.RECT:
                hx, hy = 0.5 * l.width * ex, 0.5 * l.height * ey
                corners = l.position + np.array([-hx - hy, hx - hy, hx + hy, -hx + hy])
                wholly = np.all(dot_n(corners[None] - P[:, None, :]) <= 0, axis=1)
            else:
                a = dot_n(np.broadcast_to(ex, P.shape)[:, None, :])[:, 0]
                b = dot_n(np.broadcast_to(ey, P.shape)[:, None, :])[:, 0]
                wholly = dot_n((l.position - P)[:, None, :])[:, 0] + l.radius * np.hypot(a, b) <= 0
            back = ((P - l.position)[:, None, :] @ ez)[:, 0] >= 0  # (p − c)·ez per sensor
            behind[:, j] = wholly | back
        elif l.kind == LightKind.DISTANT:
            c = dot_n(np.broadcast_to(l.frame[:, 2], P.shape)[:, None, :])[:, 0]
            behind[:, j] = c <= -np.sin(l.half_angle) if l.half_angle > 0 else c <= 0
    names = [l.name for l in scene.lights]
    for i, row in zip(irr, behind.tolist()):
        out[i] = [n for n, b in zip(names, row) if b]
    return out


def closed_form_refusal(method: str, scene: Scene, sensor: Sensor) -> str | None:
    """For the commands that try every method: why ``method`` (``analytic`` or
    ``exact``) cannot read ``sensor``, or None if it can."""
    if method == "analytic":
        return analytic_refusal(scene, sensor)
    return exact_plan_refusal(scene, sensor, lights_behind(scene, sensor))


def cull_mask(scene: Scene, sensors: list[Sensor]) -> np.ndarray:
    """(S, L) int32: 1 where a light can reach the sensor (see :func:`lights_behind`),
    the mask a run's plan gives the engine."""
    names = [l.name for l in scene.lights]
    return np.array([[n not in lights_behind(scene, s) for n in names] for s in sensors], np.int32).reshape(len(sensors), len(names))


def _largest_solid_angle(scene: Scene, sensor: Sensor, culled: list[str]) -> float:
    """Largest solid angle (sr, at most 2π) any light not culled subtends
    from the sensor: a rough size (area·|cos|/d² for panels), enough to tell
    a sky or a near panel from a small source."""
    best = 0.0
    p = sensor.position
    for l in scene.lights:
        if l.name in culled:
            continue
        d2 = float(np.sum((l.position - p) ** 2))
        if l.kind == LightKind.DOME:
            omega = 2 * np.pi
        elif l.kind == LightKind.DISTANT:
            omega = 2 * np.pi * (1 - np.cos(l.half_angle))
        elif l.kind == LightKind.SPHERE:
            omega = 2 * np.pi if d2 <= l.radius**2 else 2 * np.pi * (1 - np.sqrt(1 - l.radius**2 / d2))
        elif l.kind in (LightKind.RECT, LightKind.DISK, LightKind.CYLINDER):
            area = {LightKind.RECT: l.width * l.height, LightKind.DISK: np.pi * l.radius**2}.get(l.kind, 2 * l.radius * l.length)
            cos_l = abs((p - l.position) @ l.frame[:, 2]) / np.sqrt(d2) if d2 > 0 and l.kind != LightKind.CYLINDER else 1.0
            omega = area * cos_l / d2 if d2 > 0 else 2 * np.pi
        else:
            omega = 0.0
        best = max(best, min(omega, 2 * np.pi))
    return best


def _portal_dome(scene: Scene, culled: list[str]) -> str | None:
    """The first DomeLight with portals that reaches the sensor (not culled), or None."""
    return next((l.name for l in scene.lights if l.kind == LightKind.DOME and l.portals and l.name not in culled), None)


def _patch_corners(s: Sensor) -> list[np.ndarray]:
    right = patch_width_axis(s.up, s.normal)
    hx, hy = 0.5 * s.size[0] * right, 0.5 * s.size[1] * s.up
    return [s.position + a * hx + b * hy for a in (-1, 1) for b in (-1, 1)]


def _reflecting_in_front(scene: Scene, sensor: Sensor, bounds: SceneBounds) -> tuple[str, bool]:
    """(geometry label, whether any surface the sensor can see reflects)."""
    g = scene.geometry
    if g.n_triangles == 0:
        return "none", False
    if sensor.kind in (SensorKind.IRRADIANCE, SensorKind.PATCH):
        first = bounds.first_in_front(sensor)
        if first["all"] < 0:
            return "none", False
        reflects = first["reflecting"] >= 0
    else:  # meters and probes look everywhere
        reflects = bool(np.any(g.reflecting()))
    return ("reflecting surfaces" if reflects else "black occluders"), reflects


def make_plan(scene: Scene, sensors: list[Sensor], requested: str = "auto", component: str = "total",
              hybrid: bool = True) -> Plan:
    """Plan how each sensor is read (see the module docstring for the rules).

    An explicit ``requested`` method applies to every sensor (``analytic``
    raises :class:`UserError` naming a sensor it cannot read). ``hybrid``
    False: no hybrid (a light-group pass tallies every light on its paths).
    """
    transport, channels, channel_reason = _transport(scene)
    bounds = scene_bounds(scene)
    bounds.prime(sensors)
    paths, paths_why = _path_method(scene)
    # the per-sensor tests, stacked over the sensors where they are numpy products
    culled_of = lights_behind_many(scene, sensors)
    seen, refusals = [], []  # per sensor in turn: both ask for its plane's first triangle (kept once)
    for s in sensors:
        seen.append(_reflecting_in_front(scene, s, bounds))
        refusals.append(analytic_refusal(scene, s, bounds) if requested == "auto" else None)
    direct_only = [not reflects or component == "direct" for _, reflects in seen]
    asks_exact = [requested == "exact" or (requested == "auto" and component != "indirect" and d
                                           and not (r is None and d)) for r, d in zip(refusals, direct_only)]  # fmt: skip
    ask = [i for i, a in enumerate(asks_exact) if a]
    exact_why = dict(zip(ask, exact_plan_refusals(scene, [sensors[i] for i in ask], [culled_of[i] for i in ask])))
    # the hybrid: direct light computed for irradiance sensors that need paths (grey transport; auto)
    hyb = {}
    if hybrid and requested == "auto" and component == "total" and transport == "grey":
        need = [i for i, (_, reflects) in enumerate(seen)
                if reflects and sensors[i].kind == SensorKind.IRRADIANCE and getattr(sensors[i], "optics", None) is None]
        names = [l.name for l in scene.lights] + [EMISSIVE]
        for i, (recs, why) in zip(need, hybrid_records(scene, [sensors[i] for i in need], [culled_of[i] for i in need])):
            if recs:
                hyb[i] = ([names[r] for r in recs], why)
    plans = []
    for i, s in enumerate(sensors):
        culled = culled_of[i]
        lights = [l.name for l in scene.lights if l.name not in culled]
        if bounds.emissive:
            lights.append("emissive surfaces")
        geometry, reflects = seen[i]
        kind = s.kind.name.lower()
        if requested != "auto":
            if requested == "analytic" and (why := analytic_refusal(scene, s, bounds)) is not None:
                raise UserError(f"method analytic cannot read sensor {s.name!r}: {why} (use light, mis, path or auto)")
            if requested == "exact" and (why := exact_why[i]) is not None:
                raise UserError(f"method exact cannot read sensor {s.name!r}: {why} (use light, mis, path or auto)")
            bounces = bool(METHOD_FLAGS[requested][3]) if requested in METHOD_FLAGS else False
            reason = "as requested" + ("" if bounces or not reflects else f"; {requested} ignores the interreflection this sensor sees")
            if requested == "light" and (portal_dome := _portal_dome(scene, culled)):
                reason += (f"; light samples the DomeLight {portal_dome} only through its portals: "
                           "sky seen past them is not counted (mis and path count it)")
            plans.append(SensorPlan(s.name, kind, requested, bounces, reason, lights, culled, geometry))
            continue
        refusal = refusals[i]
        if component == "indirect":
            method, reason = paths, "indirect light has been reflected on the way: paths" + paths_why
        elif refusal is None and (not reflects or component == "direct"):
            method, reason = "analytic", "nothing can block its lights" + ("" if component == "direct" else " and nothing in front of it reflects: closed form")
        elif (not reflects or component == "direct") and exact_why[i] is None:
            method = "exact"
            reason = f"no surface it sees reflects ({refusal}): each light's visible part in closed form, penumbrae exact"
        elif not reflects or component == "direct":
            why = refusal or "no closed form"
            big = _largest_solid_angle(scene, s, culled)
            if big > LARGE_SOURCE_SR and s.kind in (SensorKind.IRRADIANCE, SensorKind.PATCH):
                method = "mis"
                reason = f"no surface it sees reflects ({why}); a light covers {big:.2g} sr of its sky: light and cosine sampling combined"
            elif portal_dome := _portal_dome(scene, culled):
                method = "mis"
                reason = (f"no surface it sees reflects ({why}); the DomeLight {portal_dome} is light-sampled through its "
                          "portals only: cosine directions count the sky seen past them")
            else:
                method, reason = "light", f"no surface it sees reflects, so direct light is all ({why}): light sampling"
        elif i in hyb:
            method = "exact+" + paths
            reason = "surfaces it sees reflect: paths read the reflected light" + paths_why + "; " + hyb[i][1]
        else:
            method, reason = paths, "surfaces it sees reflect: interreflection needs paths" + paths_why
        plans.append(SensorPlan(s.name, kind, method, bool(METHOD_FLAGS.get(sampled_method(method), (0, 0, 0, False))[3]),
                                reason, lights, culled, geometry, hyb[i][0] if method in HYBRID_METHODS else []))  # fmt: skip
    return Plan(requested, component, channels, channel_reason, plans, transport, _light_sampling(scene, plans),
                surface_needs(scene))


def with_optics(plan: Plan, scene: Scene, twins: list[Sensor]) -> Plan:
    """``plan`` with the optics twins of its modelled sensors appended (:mod:`simulator.sensor_models.readings`).

    A twin is planned as its sensor is, except that a head's angular response has no closed form:
    where the plan would read it by ``analytic`` or ``exact`` (light straight from emitters) it takes
    ``mis`` when a light covers more than :data:`LARGE_SOURCE_SR` of its sky or a portal dome reaches
    it (directions drawn by the response pay there), else ``light``; an explicit closed-form method
    likewise. The plan given is not changed (a kept plan is shared)."""
    requested = plan.requested if plan.requested not in ("analytic", "exact") else "auto"
    twin_plan = make_plan(scene, twins, requested, plan.component, hybrid=False)  # a computed part reads the cosine
    extra = []
    for s, sp in zip(twins, twin_plan.sensors):
        if sp.method in ("analytic", "exact"):
            big = _largest_solid_angle(scene, s, sp.culled)
            mis = big > LARGE_SOURCE_SR or _portal_dome(scene, sp.culled) is not None
            sp = SensorPlan(sp.name, sp.kind, "mis" if mis else "light", False,
                            "a sensor model's angular response has no closed form: " +
                            ("light samples and directions drawn by the response, combined" if mis else "light sampling"),
                            sp.lights, sp.culled, sp.geometry)  # fmt: skip
        extra.append(sp)
    sensors = plan.sensors + extra
    light_sampling = dict(plan.light_sampling)
    for m, how in _light_sampling(scene, extra).items():
        light_sampling.setdefault(m, how)
    return Plan(plan.requested, plan.component, plan.channels, plan.channel_reason, sensors, plan.transport,
                light_sampling, list(plan.surfaces), optics_from=len(plan.sensors))


def _light_sampling(scene: Scene, plans: list[SensorPlan]) -> dict[str, str]:
    """How each Monte Carlo method of the plan samples lights at a vertex
    (:func:`simulator.engine.methods.light_pick_rule`)."""
    out = {}
    for m in dict.fromkeys(sp.method for sp in plans):
        b = sampled_method(m)
        if b in MC_METHODS and b != "bsdf":
            mode, why = light_pick_rule(b, scene)
            how = {"off": "every light at each vertex", "every": "one light per vertex",
                   "after_first": "every light at the sensor and one light at each later vertex"}[mode]
            out[m] = f"{how} ({why})"
            if b != m:
                out[m] += "; at the sensor, the lights whose direct light is computed are left out"
            if METHOD_FLAGS[b][3]:  # paths: their roulette threshold
                out[m] += "; " + rr_threshold_rule(scene)[1]
    if out and scene.geometry.n_triangles and np.any(scene.geometry.emission > 0):
        from simulator.scene.emitters import pieces_note

        note = pieces_note(scene.geometry)
        for m in out:
            out[m] += "; " + note
    return out


def _diffuse_faces(g) -> np.ndarray:
    """Per triangle: whether it has a diffuse lobe the surface guide can stand in for, shape (T,):
    albedo > 0 and neither a pane (which only reflects, passes or absorbs; a translucent layer keeps its
    matte share) nor a metal (metallic 1: no diffuse lobe)."""
    out = g.albedo > 0
    if g.has_surfaces:
        for k, s in enumerate(g.surfaces):
            if (s.pane and not s.layered) or (s.glossy and s.metallic >= 1.0):
                out &= g.surface_id != k
    return out


def _path_method(scene: Scene) -> tuple[str, str]:
    """``(method, note)`` for the sensors that need paths: ``guided`` when
    :data:`AUTO_GUIDED` and the stage has a patch layout, else ``path``; the
    note (appended to the reason) says which and why."""
    from simulator.scene.patches import patch_layout

    if not AUTO_GUIDED:
        return "path", ""
    lay = patch_layout(scene.geometry.points, scene.geometry.triangles)
    if not lay.usable:
        return "path", f" ({lay.reason})"
    surf = ""
    if scene.geometry.has_surfaces:  # the guide's segments pass panes and cut-outs, glossy lobes join its mixture
        if not np.any(_diffuse_faces(scene.geometry)):
            return "path", " (no face reflects diffusely: the surface guide, a strategy for diffuse lobes, has nothing to do)"
        surf = "; its segments cross panes and cut-outs at their transmittance, glossy vertices mix it with their lobes"
    return "guided", f", guided by a {lay.reason} (learnt by a pilot{surf})"


def _transport(scene: Scene) -> tuple[str, int, str]:
    """``(transport, channels traced, reason)``: grey is one channel, exact; the others trace hero wavelengths."""
    from simulator.spectra.transport import choose_transport

    return choose_transport(scene)


def format_plan(plan: Plan, max_rows: int = 40) -> str:
    """The plan as a terminal table, one line per sensor (long lists summarised)."""
    lines = [f"{'sensor':<24} {'kind':<10} {'method':<9} {'lights':>6} {'culled':>6}  {'geometry':<20} reason"]
    for sp in plan.sensors[:max_rows]:
        lines.append(f"{sp.name[:24]:<24} {sp.kind:<10} {sp.method:<9} {len(sp.lights):>6} {len(sp.culled):>6}  {sp.geometry:<20} {sp.reason}")
    if len(plan.sensors) > max_rows:
        lines.append(f"... {len(plan.sensors) - max_rows} more sensors")
    counts = ", ".join(f"{m}: {len(ix)}" for m, ix in plan.groups().items())
    for m, how in plan.light_sampling.items():
        lines.append(f"{m} samples {how}")
    lines.append(f"methods: {counts}; component {plan.component}; transport {plan.transport}, channels: {plan.channels} ({plan.channel_reason})")
    lines += [f"surface {line}" for line in plan.surfaces]
    return "\n".join(lines)
