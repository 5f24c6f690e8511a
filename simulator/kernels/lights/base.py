"""What every light kind shares: the device records, the sample record and
the declaration a kind file fills in.

A light on the device is one :class:`LightRec`: the common fields (kind,
position, frame, emission) and a few *shape slots* (width, height, radius,
length, cone, area, a lat-long map) that each kind reads as it needs. A new
kind uses these slots; a new slot is added here.

A kind file (``point.py``, ``sphere.py``, ...) writes its ``@wp.func``s with
the signatures below and declares them in one :class:`LightKernel`; the
package (:mod:`simulator.kernels.lights`) generates the dispatch from those
declarations. A hook a kind leaves ``None`` gets the neutral answer: pdf 0
(a delta light), never hit, nothing escaped, not near, no closed form.

=================  ================================================================  ===========
hook               signature                                                         default
=================  ================================================================  ===========
``sample``         ``(scene, l, p, n, u: vec3) -> LightSample``                      (required)
``pdf``            ``(scene, l, p, n, wi, t, tri) -> float``: solid-angle pdf        0
``hit``            ``(l, o, d, t_max) -> float``: distance to the emitting side      −1
``escaped``        ``(l, d) -> vec2``: radiance along a ray that left the scene      0
``near``           ``(l, d = p − position, reach) -> bool``: surface within reach    False
``analytic``       ``(scene, l, p, n) -> vec2``: unoccluded irradiance, closed form  0
``analytic_patch`` ``(l, c, n, right, up, w, h) -> vec2``: mean over a patch         0
``upload``         host: ``(rec, light, keep)`` fills the kind's slots               none
=================  ================================================================  ===========
"""

from dataclasses import dataclass
from typing import Any, Callable

import warp as wp

from simulator.scene.model import LightKind

from ..optics import OpticsRec
from ..surface_rec import GlintRec, SurfRec, TexRec

#: length of a ray that leaves the scene, metres
RAY_INF = wp.constant(1.0e30)


@wp.struct
class PortalRec:
    """One UsdLux PortalLight of a dome (:class:`simulator.scene.model.Portal`):
    the rectangle ``corner + [0, width]·ex + [0, height]·ey``, passing the
    dome's light toward −ez."""

    corner: wp.vec3
    ex: wp.vec3
    ey: wp.vec3
    ez: wp.vec3
    width: float
    height: float


@wp.struct
class LightRec:
    """One light on the device (see :class:`simulator.scene.model.Light`)."""

    kind: int
    position: wp.vec3
    ex: wp.vec3
    ey: wp.vec3
    ez: wp.vec3  # rect/disk emit toward −ez; a distant light lies toward +ez
    emission: wp.vec2  # (radiometric, photometric)
    width: float
    height: float
    radius: float
    one_minus_cos: float  # distant light: 1 − cos(half-angle); 0 = delta
    area: float
    length: float  # cylinder length along ex (its axis)
    # textured dome: lat-long map in the frame (ex, ey = pole, ez = lat 0, lon 0)
    has_map: int  # 1: radiance = emission × map[texel]; 0: uniform
    map_w: int
    map_h: int
    map: wp.array(dtype=float)  # map_h × map_w values, row 0 at the pole ey
    map_marg: wp.array(dtype=float)  # map_h + 1: marginal CDF over rows
    map_cond: wp.array(dtype=float)  # map_h × (map_w + 1): conditional CDFs over columns
    # UsdLuxShapingAPI (estimators.shaping_factor): shaped = 1 multiplies emission toward ω by the factor
    shaped: int
    shaping: wp.vec4  # (cone half-angle rad, cone softness, focus, focus tint)
    ies_scale: float  # > 0: × ies_scale·I(θ, φ), I bilinear in map (map_h rows θ 0…180°, map_w columns φ 0…360°)
    # dome with UsdLux PortalLights (dome.py): sampled through them where they face the receiver
    n_portals: int
    portals: wp.array(dtype=PortalRec)


@wp.struct
class GuideRec:
    """The surface guide of guided paths (estimators: ``sample_guide``):
    every triangle cut into m × m patches (:mod:`simulator.scene.patches`),
    patch j drawn with probability P_j from a pilot's tallies, one table per
    source row (row 0: a path's first vertex; a surface vertex: its prim's)."""

    tri_m: wp.array(dtype=wp.int32)  # per triangle: subdivisions per edge (m² patches)
    tri_offset: wp.array(dtype=wp.int32)  # per triangle: index of its first patch
    patch_tri: wp.array(dtype=wp.int32)  # per patch: its triangle
    tri_row: wp.array(dtype=wp.int32)  # per triangle: the source row a vertex on it samples
    n_rows: int
    density: wp.array(dtype=float)  # (n_rows × n_patches): P_j / A_j (m⁻²), the guide's area pdf
    ids: wp.array(dtype=wp.int32)  # per row, its patches with P_j > 0, concatenated
    cdf: wp.array(dtype=float)  # per row, the inclusive CDF over its ids (last = 1), concatenated
    row_start: wp.array(dtype=wp.int32)  # (n_rows + 1): row r's entries are [row_start[r], row_start[r + 1])
    n: int  # len(ids); 0: no guide (guided paths are plain paths)
    n_patches: int  # 0: no layout (nothing is tallied)
    tally: wp.array(dtype=wp.vec2)  # pilot: (workers × n_rows × n_patches) next-event contributions


@wp.struct
class SceneRec:
    """Geometry, materials and lights on the device."""

    mesh: wp.uint64
    has_mesh: int
    points: wp.array(dtype=wp.vec3)
    tris: wp.array(dtype=wp.int32)  # 3 per triangle
    albedo: wp.array(dtype=float)
    emission: wp.array(dtype=wp.vec2)  # front-face radiance per triangle
    two_sided: wp.array(dtype=wp.int32)
    # surfaces beyond Lambert (kernels.surfaces); all unread while ``surfaces`` is 0 (an all-matte stage)
    surfaces: int  # 1: some face has a row of surf (coverage, panes)
    surf_id: wp.array(dtype=wp.int32)  # per triangle: its row of surf, −1 for a matte face
    surf_side: wp.array(dtype=wp.int32)  # per triangle: 0 open pane (thin slab); ±1 closed pane mesh, front out / in
    surf: wp.array(dtype=SurfRec)
    # glint pairs (kernels.glints): flat glossy planes × distant lights, whose reflection matte vertices sample
    n_glints: int
    glints: wp.array(dtype=GlintRec)
    # opacity textures read per texel (kernels.coverage); unread unless a row of surf is textured
    tex_id: wp.array(dtype=wp.int32)  # per triangle: its texture, −1: its row's coverage
    tex_uv: wp.array(dtype=wp.vec2)  # 3 per triangle: st at its corners
    tex: wp.array(dtype=TexRec)
    texels: wp.array(dtype=float)  # the textures' opacities, concatenated
    n_mirror_planes: int  # flat planes of mirror faces (kernels.mirrors), 0 for none
    mirror_planes: wp.array(dtype=wp.vec4)  # (n, d): n·x = d
    face_mirror: wp.array(dtype=wp.int32)  # per triangle: its mirror plane, −1 for none
    plane_mirror: wp.array(dtype=wp.int32)  # per mirror plane: 1 when a face of it is a mirror, 0 for panes alone
    # shading normals of glossy and mirror faces (kernels.glossy.shading_normal); unread while n_shaded is 0
    n_shaded: int
    shade_id: wp.array(dtype=wp.int32)  # per triangle: its corners are shade_n[3·id …], −1: its face normal
    shade_n: wp.array(dtype=wp.vec3)  # unit corner normals, on the front face's side
    # curved mirrors (kernels.curved): pieces of shaded mirror faces, each with its vertices' bounding sphere
    n_curves: int
    face_curve: wp.array(dtype=wp.int32)  # per triangle: its curved mirror, −1 for none
    curve_sphere: wp.array(dtype=wp.vec4)  # per curved mirror: (centre, radius), the seed of its Newton solve
    # emissive geometry in pieces (kernels/lights/emissive.py reads these through its accessors): every table
    # in one int and one float array, so that the record (copied into every function that takes it) stays small
    n_pieces: int
    n_emit_tris: int  # T: the triangles (every one has an entry)
    n_elems: int  # E: the elements, m² sub-triangles of each emitting triangle cut m × m (m = 1: the triangle)
    n_cells: int  # C: cells of the pieces' table (engine.piece_table); 0: no table
    cell_dims: wp.vec3i  # its grid's voxels along x, y, z (G = 6·nx·ny·nz slots)
    # ints: per triangle its first element (−1: emits nothing) [T] and its cut m [T]; per element its triangle
    # [E] and piece [E]; the elements grouped by piece [E]; per piece its first entry there [K] and count [K];
    # the grid's slots, each its cell or −1 [G]
    emit_ints: wp.array(dtype=wp.int32)
    # floats: per element its share of its piece's power [E]; per piece the inclusive CDF over its elements in
    # that order [E]; per piece its learned factor [K] and share of all power [K]; per piece centre (3), mean
    # front normal (3), area, radiance (W + lm/683), reach, two-sided [10K]; the grid's lowest corner and
    # 1/spacing [4]; per cell its CDF over the pieces [C·K] and Σ_k of its shadowed estimates [C]
    emit_floats: wp.array(dtype=float)
    piece_tally: wp.array(dtype=wp.vec4)  # (threads × n_pieces): a pilot's sums, light_pick.tally_pick
    lights: wp.array(dtype=LightRec)
    n_lights: int
    eps: float  # ray-origin offset relative to max(1 m, |p|∞)
    ray_counts: wp.array(dtype=wp.int32)  # two per kernel thread (path, shadow rays), when TraceParams.count_rays
    light_mask: wp.array(dtype=wp.int32)  # (sensors × n_lights): 0 = light culled for that sensor
    # hero-wavelength transport (TraceParams.spectral; tables of simulator.spectra.hero, 401 grid nodes)
    spectral_reflectance: wp.array2d(dtype=float)  # (colours × 401): ρ(λ)
    spectral_face: wp.array(dtype=wp.int32)  # per triangle: its row of spectral_reflectance
    spectral_emission: wp.array2d(dtype=float)  # (light records × 401): density per unit radiometric value
    spectral_face_emission: wp.array(dtype=wp.int32)  # per triangle: its coloured row of spectral_emission, −1: its record's
    response_weights: wp.array2d(dtype=float)  # (responses × 401): a lane's weight 400·q/w
    response_lanes: wp.array(dtype=wp.vec4)  # per kernel thread: this sample's spectral density per hero lane
    colour_weights: wp.array2d(dtype=float)  # (3 × 401): a lane's weight of linear sRGB (cd/m²), for probe maps
    # per row of surf: (coloured, specular row, transmittance row) of spectral_reflectance (kernels.spectral_surfaces)
    spectral_surface: wp.array(dtype=wp.vec3i)
    spectral_panes: int  # 1: some pane has a measured T0(λ) (shadow and path rays then weigh it per lane)
    light_group: wp.array(dtype=wp.int32)  # per light record: its light group, −1 for none (TraceParams.group_tally)
    patch_base: wp.array(dtype=wp.int32)  # per light record: first group of its sky patches (a split dome), −1 when not split
    guide: GuideRec  # surface patches for guided paths
    pick_factor: wp.array(dtype=float)  # ((1 + sensors) × n_lights): learned factors of the light pick (light_pick.py)
    pick_tally: wp.array(dtype=wp.vec2)  # (threads × 2 × n_lights): a pilot's Σ(ê, shadowed value), TraceParams.tally_pick
    # the light pick's factors per surface patch (guide layout) for vertices past the first; n_patch_pick 0: row 0 serves all
    n_patch_pick: int
    patch_pick_factor: wp.array(dtype=float)  # (n_patches × n_lights), when n_patch_pick > 0
    patch_pick_tally: wp.array(dtype=wp.vec3)  # (n_patches × n_lights): a one-worker pilot's Σ(w·ê, w·value, 1), tally_pick 2
    optics: wp.array(dtype=OpticsRec)  # sensor models' angular responses (SensorRec.optics − 1 indexes it; kernels.optics)


@wp.struct
class LightSample:
    wi: wp.vec3  # unit direction from the receiver toward the light
    dist: float  # shadow-ray length
    value: wp.vec2  # unshadowed L·cosθ/pdf (W/m², lx)
    pdf: float  # solid-angle pdf; 0 for delta lights
    tri: int  # sampled emissive triangle, −1 otherwise
    elem: int  # its element (kernels/lights/emissive.py), −1 otherwise


@dataclass(frozen=True)
class LightKernel:
    """One light kind's device code and upload: ``kind`` is the integer the
    kernels switch on; ``sample`` … ``analytic_patch`` are ``@wp.func`` hooks
    (None: the neutral answer, see the module docstring); ``upload(rec,
    light, keep)`` fills the kind's slots of the :class:`LightRec` from the
    :class:`~simulator.scene.model.Light` (device arrays the record points to
    go on the list ``keep``)."""

    kind: LightKind
    sample: Any
    pdf: Any = None
    hit: Any = None
    escaped: Any = None
    near: Any = None
    analytic: Any = None
    analytic_patch: Any = None
    upload: Callable | None = None


@wp.func
def empty_sample() -> LightSample:
    s = LightSample()
    s.wi = wp.vec3(0.0, 0.0, 1.0)
    s.dist = 0.0
    s.value = wp.vec2(0.0, 0.0)
    s.pdf = 0.0
    s.tri = -1
    s.elem = -1
    return s


@wp.func
def tri_vertex(scene: SceneRec, tri: int, k: int) -> wp.vec3:
    return scene.points[scene.tris[3 * tri + k]]


@wp.func
def tri_params(scene: SceneRec, face: int, y: wp.vec3) -> wp.vec2:
    """(s, t) of the point y on triangle ``face``: y = a + s·(b − a) + t·(c − a)
    (least squares, so a point off the plane by rounding projects onto it); (0, 0) on a degenerate one."""
    a = tri_vertex(scene, face, 0)
    e1 = tri_vertex(scene, face, 1) - a
    e2 = tri_vertex(scene, face, 2) - a
    d = y - a
    d00 = wp.dot(e1, e1)
    d01 = wp.dot(e1, e2)
    d11 = wp.dot(e2, e2)
    d20 = wp.dot(d, e1)
    d21 = wp.dot(d, e2)
    den = d00 * d11 - d01 * d01
    if den <= 0.0:
        return wp.vec2(0.0, 0.0)
    return wp.vec2((d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den)


@wp.func
def tri_emitted(scene: SceneRec, tri: int, wo_dot_ng: float) -> wp.vec2:
    """Radiance a triangle emits toward a viewer on the side where
    dot(toward viewer, geometric normal) = ``wo_dot_ng``."""
    if wo_dot_ng > 0.0 or scene.two_sided[tri] != 0:
        return scene.emission[tri]
    return wp.vec2(0.0, 0.0)


@wp.func
def area_sample(l: LightRec, p: wp.vec3, n: wp.vec3, q: wp.vec3, nl: wp.vec3) -> LightSample:
    """A point q drawn uniformly on the light's area A (pdf 1/A), whose
    emitting normal there is nl, as a direction sample from p: solid-angle
    pdf d²/(A·cosθl); nothing when q faces away from p."""
    s = empty_sample()
    d = q - p
    dist = wp.length(d)
    if dist <= 0.0:
        return s
    wi = d / dist
    cos_l = -wp.dot(wi, nl)
    if cos_l <= 0.0:
        return s
    s.wi = wi
    s.dist = dist
    s.pdf = dist * dist / (l.area * cos_l)
    cos_r = wp.dot(wi, n)
    if cos_r > 0.0:
        s.value = l.emission * (cos_r / s.pdf)
    return s


@wp.func
def area_pdf(l: LightRec, cos_l: float, t: float) -> float:
    """Solid-angle pdf of :func:`area_sample` for a hit at distance t whose
    emitting side makes cosine ``cos_l`` with the ray: t²/(A·cosθl), 0 from behind."""
    return wp.where(cos_l > 0.0, t * t / (l.area * cos_l), 0.0)


@wp.func
def near_box(l: LightRec, d: wp.vec3, reach: float, thickness: float) -> bool:
    """True if d (from the light's centre) lies within ``reach`` of the
    light's bounding box: half-extent the largest of its shape slots across
    ex and ey, ``thickness`` along ez (cheap and sufficient)."""
    ext = wp.max(wp.max(0.5 * l.width, 0.5 * l.height), wp.max(l.radius, 0.5 * l.length))
    if wp.abs(wp.dot(d, l.ex)) <= ext + reach and wp.abs(wp.dot(d, l.ey)) <= ext + reach:
        if wp.abs(wp.dot(d, l.ez)) <= thickness + reach:
            return True
    return False


@wp.func
def near_planar(l: LightRec, d: wp.vec3, reach: float) -> bool:
    """``near`` of a flat light (rect, disk): :func:`near_box` of no thickness."""
    return near_box(l, d, reach, 0.0)


@wp.func
def behind(l: LightRec, p: wp.vec3) -> bool:
    """Whether p lies on the dark side of a one-sided planar light (or in its plane)."""
    return wp.dot(p - l.position, l.ez) >= 0.0


@wp.func
def plane_hit(l: LightRec, o: wp.vec3, d: wp.vec3, t_max: float) -> wp.vec3:
    """Where the ray (o, d) crosses the plane of a one-sided planar light
    from its emitting side: (t, x, y) with (x, y) in the light's frame, or
    t = −1 when it does not before ``t_max``."""
    denom = wp.dot(d, l.ez)
    if denom <= 0.0:
        return wp.vec3(-1.0, 0.0, 0.0)  # seen from behind: one-sided
    t = wp.dot(l.position - o, l.ez) / denom
    if t <= 0.0 or t >= t_max:
        return wp.vec3(-1.0, 0.0, 0.0)
    q = o + t * d - l.position
    return wp.vec3(t, wp.dot(q, l.ex), wp.dot(q, l.ey))


@wp.func
def hit_inside(h: wp.vec3, inside: bool) -> float:
    """The ``hit`` of a one-sided planar light from its :func:`plane_hit`
    ``h = (t, x, y)``: t when the plane is crossed (t > 0) at a point
    ``inside`` the light's outline, else −1."""
    if h[0] > 0.0 and inside:
        return h[0]
    return -1.0
