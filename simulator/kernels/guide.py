"""The surface guide of ``guided`` paths: patches, their sampler and its pdf twin.

Host side: :mod:`simulator.scene.patches` (the layout) and
:mod:`simulator.engine.guide` (the pilot and the tables).
"""

import functools

import warp as wp

from .lights import SceneRec, tri_params, tri_vertex
from .rays import first_hit, offset_length
from .records import TraceParams
from .sampling import INV_PI, patch_index, patch_point  # noqa: F401  (patch_point: the guide's sampler below)
from .coverage import coverage_at
from .surfaces import pass_factor, transmittance_along


# ---------------------------------------------------------------- surface guide
#
# Guided paths (method ``guided``) add a second way to pick the next vertex y
# from x: a patch j of the stage's surfaces with probability P_j (from a
# pilot's tallies of the light each patch passed on to the sensors), then a
# point uniform on it, area pdf P_j/A_j. It is mixed with the cosine
# direction by one-sample MIS (balance heuristic: divide by the mixture pdf,
# in area measure, Veach 1997 §9.2.4; docs/REFERENCES.md §One-sample MIS);
# see vertex_irradiance. The idea of
# learning where light comes from with a pilot and sampling it is path
# guiding's (Vorba et al. 2014, Müller et al. 2017), here on surface patches.


@wp.func
def patch_at(scene: SceneRec, face: int, y: wp.vec3) -> int:
    """The patch (global index) holding the point y of triangle ``face``."""
    st = tri_params(scene, face, y)
    return scene.guide.tri_offset[face] + patch_index(st[0], st[1], scene.guide.tri_m[face])


@wp.struct
class GuideSample:
    y: wp.vec3  # the point drawn
    face: int  # its triangle
    density: float  # area pdf P_j/A_j there (m⁻²)


@wp.func
def guide_row(scene: SceneRec, depth: int, face: int) -> int:
    """The guide table a vertex samples from: row 0 at a path's first
    vertex, else its triangle's (see GuideRec)."""
    if depth == 0 or face < 0:
        return 0
    return scene.guide.tri_row[face]


@wp.func
def sample_guide(scene: SceneRec, row: int, u: wp.vec3) -> GuideSample:
    """A patch j with row ``row``'s probability P_j (binary search of its
    CDF: P_j = cdf[k] − cdf[k−1]), then a point uniform on it: area pdf
    P_j/A_j. Twin of :func:`pdf_guide`. Needs the row to be non-empty."""
    lo = scene.guide.row_start[row]
    hi = scene.guide.row_start[row + 1] - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if scene.guide.cdf[mid] <= u[0]:
            lo = mid + 1
        else:
            hi = mid
    j = scene.guide.ids[lo]
    face = scene.guide.patch_tri[j]
    st = patch_point(j - scene.guide.tri_offset[face], scene.guide.tri_m[face], wp.vec2(u[1], u[2]))
    a = tri_vertex(scene, face, 0)
    g = GuideSample()
    g.y = a + st[0] * (tri_vertex(scene, face, 1) - a) + st[1] * (tri_vertex(scene, face, 2) - a)
    g.face = face
    g.density = scene.guide.density[row * scene.guide.n_patches + j]
    return g


@wp.func
def pdf_guide(scene: SceneRec, row: int, face: int, y: wp.vec3) -> float:
    """Area pdf (m⁻²) with which :func:`sample_guide` draws the point y of
    triangle ``face``: row ``row``'s P_j/A_j of its patch, 0 where that row
    never goes."""
    if scene.guide.n == 0:
        return 0.0
    return scene.guide.density[row * scene.guide.n_patches + patch_at(scene, face, y)]


@wp.func
def guide_fraction(scene: SceneRec, params: TraceParams, depth: int, row: int) -> float:
    """c: the probability of the guide strategy at a vertex of this depth
    that samples guide row ``row`` (0: cosine only). None where the row is
    empty, outside [guide_first, guide_depth), or at the last vertex a
    bounce limit allows (the next one would add nothing)."""
    if params.guide_c <= 0.0 or scene.guide.n == 0:
        return 0.0
    if scene.guide.row_start[row + 1] <= scene.guide.row_start[row]:
        return 0.0
    if depth < params.guide_first or (params.guide_depth >= 0 and depth >= params.guide_depth):
        return 0.0
    if params.bounces >= 0 and depth >= params.bounces:
        return 0.0
    return params.guide_c


@wp.func
def mixture_factor(c: float, pdf_guide_area: float, pdf_cos_area: float) -> float:
    """p_cos,A(y) / p_mix(y), p_mix = c·p_guide,A + (1 − c)·p_cos,A: what a
    vertex reached by either strategy multiplies the path's throughput by
    (besides ρ; it is 1 for c = 0 and at most 1/(1 − c)).

    Notes
    -----
    Light leaving y toward x contributes L(y) = ρ/π·E(y) to E(x) through
    ∫ L G dA_y with G = cosθx·cosθy/r²; one-sample MIS with the balance
    heuristic estimates it by L·G/p_mix(y) whichever strategy drew y (Veach
    1997, §9.2.4). Since p_cos,A = cosθx·cosθy/(π r²) = G/π, the next
    vertex's weight is weight·ρ·G/(π·p_mix) = weight·ρ·p_cos,A/p_mix."""
    den = c * pdf_guide_area + (1.0 - c) * pdf_cos_area
    if den <= 0.0:
        return 0.0
    return pdf_cos_area / den


@wp.struct
class GuideStep:
    y: wp.vec3  # the next vertex
    n: wp.vec3  # its normal, facing the previous vertex
    face: int  # its triangle; −1: the strategy gave nothing (the path ends)
    factor: float  # p_cos,A / p_mix at y (see mixture_factor), × share
    wi: wp.vec3  # unit direction from the vertex toward y
    jac: float  # cosθy / r² (m⁻²): a solid-angle pdf times it is the area pdf at y
    density: float  # the guide's area pdf P_j/A_j at y (m⁻²)
    share: float  # what the segment passes and y scatters: T(x → y)·s(y) (1 on matte stages)


@wp.func
def scatter_share(scene: SceneRec, face: int, d: wp.vec3, ng: wp.vec3, p: wp.vec3) -> float:
    """The probability that a path ray along ``d`` meeting ``face`` at p scatters
    there (the SCATTER event of :func:`.surfaces.surface_event`): 1 on a
    matte face, 1 − (what passes) = the coverage c on a cut-out (its
    texture's at p where one drives it), 0 on a pane (a pane reflects,
    passes or absorbs, it never scatters diffusely), the matte share c on
    a translucent layer (pane 2, whose gap is the slab)."""
    sid = scene.surf_id[face]
    if sid < 0:
        return 1.0
    s = scene.surf[sid]
    if s.pane == 2:
        return coverage_at(scene, s, face, p)
    if s.pane != 0:
        return 0.0
    return 1.0 - pass_factor(scene, face, d, ng, p)


@wp.func
def glossy_mixture_factor(c: float, pdf_guide_area: float, pdf_dir_area: float) -> float:
    """p_dir,A / (p_dir,A + c·p_guide,A) at a glossy vertex, where p_dir,A
    (the density of its lobe sampling, chosen with probability 1 − c,
    already times 1 − c) and the guide's p_guide,A are both area densities
    at y: what a next vertex drawn by the lobes takes besides f·cosθ/p_dir
    (one-sample MIS, balance heuristic; 1 for c = 0)."""
    den = pdf_dir_area + c * pdf_guide_area
    if den <= 0.0:
        return 0.0
    return pdf_dir_area / den


@functools.cache
def make_guided_step(surfaces: bool):
    """:func:`guided_step` of one trace variant (:func:`.estimators.make_trace`): with
    ``surfaces`` False its tests of ``scene.surfaces`` fold to the all-matte branch and the
    pane and cut-out code is left out of the generated code."""

    @wp.func
    def guided_step(scene: SceneRec, row: int, o: wp.vec3, n: wp.vec3, c: float, u: wp.vec3) -> GuideStep:
        """The guide strategy at a vertex with ray origin o and normal n: a point
        y from :func:`sample_guide`, kept when it faces o, o sees its side, and
        the segment o → y first meets y's triangle (within the ray offset of y:
        a coplanar neighbour met at y by rounding does not block it).

        On a stage with panes or cut-outs (``scene.surfaces``) the segment is not
        blocked by what passes light: it takes the share T(x → y)·s(y), T the
        product of the pass factors on it (:func:`.surfaces.transmittance_along`,
        as a shadow ray) and s(y) the probability that a ray meeting y's face
        scatters there (:func:`scatter_share`). A cosine ray reaches y as a
        scattering vertex with probability T·s and weight 1, so both strategies
        estimate the same ∫ L·G·T·s dA; their one-sample MIS weights
        (:func:`mixture_factor`) depend on y alone and still sum to 1, so the
        pair stays unbiased (Veach 1997 §9.2.4 needs no more than that)."""
        g = GuideStep()
        g.face = -1
        gs = sample_guide(scene, row, u)
        d = gs.y - o
        dist = wp.length(d)
        if dist <= 0.0:
            return g
        wi = d / dist
        cos_x = wp.dot(wi, n)
        a = tri_vertex(scene, gs.face, 0)
        ng = wp.cross(tri_vertex(scene, gs.face, 1) - a, tri_vertex(scene, gs.face, 2) - a)
        if cos_x <= 0.0 or wp.length(ng) <= 0.0:
            return g
        ng = wp.normalize(ng)
        cos_y = -wp.dot(wi, ng)
        if cos_y < 0.0:
            ng = -ng
            cos_y = -cos_y
        if cos_y <= 0.0:
            return g
        off = offset_length(scene, gs.y)
        share = float(1.0)
        if (scene.surfaces != 0) if wp.static(surfaces) else False:
            share = scatter_share(scene, gs.face, wi, ng, gs.y)
            if share > 0.0 and dist > off:
                share = share * transmittance_along(scene, o, wi, dist - off, -1)
            if share <= 0.0:
                return g
        else:
            h = first_hit(scene, o, wi, dist + off)
            if h.face >= 0 and h.face != gs.face and h.t < dist - off:
                return g
        g.y = gs.y
        g.n = ng
        g.face = gs.face
        g.factor = mixture_factor(c, gs.density, cos_x * cos_y * INV_PI / (dist * dist))
        if (scene.surfaces != 0) if wp.static(surfaces) else False:
            g.factor = g.factor * share
        g.wi = wi
        g.jac = cos_y / (dist * dist)
        g.density = gs.density
        g.share = share
        return g

    return guided_step


@wp.func
def tally_patch(scene: SceneRec, params: TraceParams, row: int, face: int, y: wp.vec3, value: wp.vec2):
    """Pilot: add a next-event contribution made at the vertex y of triangle
    ``face``, reached from a vertex sampling guide row ``row``, to that
    row's tally of y's patch, in the block of the kernel thread's chunk
    (``params.thread // params.tally_chunk``). A chunk's kernel threads run
    on one CPU worker, in order (the engine cuts launches at chunk bounds),
    so each block's float32 sums come out the same whatever the worker
    count: Warp's CPU atomics are not atomic across threads, and a float
    sum depends on its order."""
    if scene.guide.n_patches > 0 and face >= 0:
        block = params.thread // params.tally_chunk
        k = (block * scene.guide.n_rows + row) * scene.guide.n_patches + patch_at(scene, face, y)
        wp.atomic_add(scene.guide.tally, k, value)
