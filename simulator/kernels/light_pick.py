"""Next-event estimation by one light per vertex, picked by its estimated share.

Sampling every light at every path vertex costs one shadow ray per light
that can reach the vertex, most of them wasted where a light is blocked
(the sky and sun seen through a window from the back of a room). Instead,
one light ``li`` is picked with probability

    P(li | x) = (1 − α)·w_li(x) / Σ_l w_l(x) + α·c_li(x) / Σ_l c_l(x),

    w_l(x) = ê_l(x) · f_l,

where ê_l(x) ≥ 0 is a cheap deterministic estimate of light l's
unoccluded irradiance at the vertex (:func:`light_estimate`), f_l a
learned factor (the ratio of its shadowed sample values to ê over a pilot
run, so mostly the fraction of its light that is not blocked; one row for
each sensor's own vertex, one for all later vertices: :func:`pick_factor`,
learnt by ``Engine._prepare_pick``), and c_l ∈ {0, 1}
whether light l can reach the vertex at all (1 unless it is provably
behind the vertex, or masked for the sensor). The uniform share α keeps
every light that can give light at a probability ≥ α/L, so no light is
starved by a pilot that saw it blocked; when every w is 0 the pick is
uniform over the c (α = 1). The light's sample is then divided by P, and
multiple importance sampling uses the strategy's real density
P(li | x)·pdf_light(ω) (Veach 1997 §9.2; pbrt-v4's light samplers,
Pharr, Jakob, Humphreys 2023, §12.6, pick ∝ power in the same way).

Where the pick applies is ``TraceParams.pick_light``: never, at every
vertex, or past the sensor's own vertex (what paths use; see
``engine.methods.light_pick_rule`` for the measurements).

Delta lights (point lights, distant lights of angle 0) are not picked:
they are still sampled at every vertex, so readings that are exact today
(a lone point light) stay exact; the pick is among the lights with area.

The pick is drawn in one pass over the lights (weighted reservoir
sampling, one uniform per candidate: the running choice is replaced by
light l with probability m_l / Σ_{k ≤ l} m_k), so each estimate is formed
once; :func:`pick_probability` recomputes P for a light that a cosine
direction happened to hit at the same vertex, from the totals the pick kept.

References
----------
docs/REFERENCES.md §Light selection
"""

import warp as wp

from simulator.scene.model import LightKind

from .lights import LightRec, SceneRec
from .lights.emissive import elem_piece, piece_estimate, piece_power, piece_probability, piece_totals
from .guide import patch_at
from .records import TraceParams
from .sampling import PI

#: the uniform share α of the pick (see the module docstring); on the
#: office's paths, variance per sample 2.07, 2.10 and 2.31 at α = 0.03, 0.1
#: and 0.3: a small share costs little, and bounds the weight 1/P by L/α
PICK_UNIFORM = wp.constant(0.1)
#: lm → W near 555 nm (1/683): the pick weighs a light by W + lm/683, so a
#: light with either channel counts (a weight that only steers the pick, not
#: the photometric constant K_m = 683.002 lm/W of simulator.units)
LM_TO_W = wp.constant(1.0 / 683.0)

_POINT = wp.constant(int(LightKind.POINT))
_SPHERE = wp.constant(int(LightKind.SPHERE))
_RECT = wp.constant(int(LightKind.RECT))
_DISK = wp.constant(int(LightKind.DISK))
_DISTANT = wp.constant(int(LightKind.DISTANT))
_DOME = wp.constant(int(LightKind.DOME))
_CYLINDER = wp.constant(int(LightKind.CYLINDER))
_EMISSIVE = wp.constant(int(LightKind.EMISSIVE))


@wp.func
def is_delta(l: LightRec) -> bool:
    """A point light, or a distant light of angle 0: no direction sample can hit it."""
    return l.kind == _POINT or (l.kind == _DISTANT and l.one_minus_cos <= 0.0)


@wp.func
def importance(v: wp.vec2) -> float:
    """One number for a (W, lm) pair: W + lm/683."""
    return wp.max(v[0], 0.0) + LM_TO_W * wp.max(v[1], 0.0)


@wp.func
def below_horizon(h: float, reach: float, d: float) -> bool:
    """Whether a light whose centre lies ``h`` above the receiver's plane and
    which reaches at most ``reach`` from it across that plane lies wholly
    below it (by more than float32 rounding of the distance d)."""
    return h + reach < -1.0e-6 * d


@wp.func
def cos_above(h: float, reach: float, d: float) -> float:
    """The mean of max(0, cosθ) over a light whose heights above the
    receiver's plane spread uniformly over h ± reach, at distance d: h/d when
    it lies wholly above, (h + reach)²/(4·reach·d) when it straddles the
    horizon (so a light cut by the horizon keeps an estimate of its upper part), 0 below."""
    if h >= reach:
        return wp.min(h / d, 1.0)
    if h + reach <= 0.0:
        return 0.0
    return wp.min((h + reach) * (h + reach) / (4.0 * reach * d), 1.0)


@wp.func
def light_estimate(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3) -> wp.vec2:
    """(ê, c) of light ``li`` at the vertex (p, n): ê a cheap estimate of its
    unoccluded irradiance as :func:`importance` (W/m²), c = 0 when it
    provably cannot reach the vertex (it lies wholly below the vertex's
    horizon, or the vertex is behind a one-sided light), else 1.

    Notes
    -----
    An estimate only steers the pick (any keeps the readings unbiased), so
    it is the light seen as a small source from its centre, at d and at
    cosines θ (receiver) and θl (light), capped by πL (a whole hemisphere of
    radiance L); cosθ is :func:`cos_above`, so a light the horizon cuts keeps
    the share above it (a sun straddling the horizon got P = α/2 from cosθ
    of its centre, 0, and its reading 19× the variance): rect and disk L·A·cosθl·cosθ/d²; sphere πL·(r/d)²·cosθ;
    cylinder L·2rℓ·sinγ·cosθ/d² (γ between its axis and the view); distant
    cone πL·sin²σ·cosθ; dome πL (a textured dome's map scale is left to the
    learned factor); emissive triangles in pieces (lights/emissive.py) the
    sum of the pieces' own estimates × their learned factors (the record's
    factor then stays 1), a lone piece 1 W/m² scaled by the learned factor. The closed forms would be better guesses near a large light,
    but cost more than they save on the CPU (measured on the quickstart:
    Lambert's formula for its two rect lights at every vertex made a sample
    ~40% slower for the same variance).
    A shaped light's estimate is its unshaped one: its learned factor takes
    in the share the shaping sends toward the vertices that need it.
    """
    l = scene.lights[li]
    le = importance(l.emission)
    cap = PI * le
    if l.kind == _DOME:
        return wp.vec2(cap, 1.0)
    if l.kind == _DISTANT:
        s2 = l.one_minus_cos * (2.0 - l.one_minus_cos)  # sin²σ
        cos_r = wp.dot(l.ez, n)
        sin_s = wp.sqrt(s2)
        if below_horizon(cos_r, sin_s, 1.0):
            return wp.vec2(0.0, 0.0)
        return wp.vec2(cap * s2 * cos_above(cos_r, sin_s, 1.0), 1.0)
    if l.kind == _EMISSIVE and scene.n_pieces > 1:
        tot = piece_totals(scene, p, n)
        return wp.vec2(tot[0], wp.where(tot[1] > 0.0, 1.0, 0.0))
    if l.kind != _RECT and l.kind != _DISK and l.kind != _SPHERE and l.kind != _CYLINDER:
        return wp.vec2(1.0, 1.0)  # emissive triangles
    d = l.position - p
    d2 = wp.length_sq(d)
    if d2 <= 0.0:
        return wp.vec2(cap, 1.0)
    dist = wp.sqrt(d2)
    w = d / dist
    h = wp.dot(d, n)
    e = float(0.0)
    if l.kind == _RECT or l.kind == _DISK:
        if wp.dot(p - l.position, l.ez) >= 0.0:
            return wp.vec2(0.0, 0.0)  # behind the one-sided emitter
        ax = wp.abs(wp.dot(l.ex, n))
        ay = wp.abs(wp.dot(l.ey, n))
        reach = wp.where(l.kind == _RECT, 0.5 * (l.width * ax + l.height * ay), l.radius * wp.sqrt(ax * ax + ay * ay))
        if below_horizon(h, reach, dist):
            return wp.vec2(0.0, 0.0)
        e = le * l.area * wp.max(wp.dot(w, l.ez), 0.0) * cos_above(h, reach, dist) / d2  # cosθl = (p − c)·(−ez)/d
    elif l.kind == _SPHERE:
        if d2 <= l.radius * l.radius:
            return wp.vec2(cap, 1.0)  # inside: it emits outward only, but let the sampler say so
        if below_horizon(h, l.radius, dist):
            return wp.vec2(0.0, 0.0)
        e = cap * (l.radius * l.radius / d2) * cos_above(h, l.radius, dist)
    else:  # cylinder: its side, radius r and length ℓ along ex
        reach = l.radius + 0.5 * l.length * wp.abs(wp.dot(l.ex, n))
        if below_horizon(h, reach, dist):
            return wp.vec2(0.0, 0.0)
        e = le * 2.0 * l.radius * l.length * wp.length(wp.cross(w, l.ex)) * cos_above(h, reach, dist) / d2
    return wp.vec2(wp.min(e, cap), 1.0)


@wp.func
def pick_factor(scene: SceneRec, row: int, patch: int, li: int) -> float:
    """The learned factor f_li of the pick (row 0: every vertex past the
    first; row 1 + s: sensor s's first vertex), or, where the pilot learnt
    them per surface patch (``patch`` ≥ 0: a vertex past the first), its patch's."""
    if patch >= 0:
        return scene.patch_pick_factor[patch * scene.n_lights + li]
    return scene.pick_factor[row * scene.n_lights + li]


@wp.struct
class LightPick:
    li: int  # the picked light, −1 when none (no light with area may reach the vertex)
    prob: float  # P(li | x)
    sum_w: float  # Σ w_l over the candidates
    sum_c: float  # Σ c_l
    row: int  # the factor row used at this vertex
    patch: int  # the surface patch whose factors it uses, −1: the row's
    rng: wp.uint32  # the caller's random state after the pick's draws


@wp.func
def pick_mix(sum_w: float) -> float:
    """The uniform share α actually used: 1 when no light has weight."""
    return wp.where(sum_w > 0.0, PICK_UNIFORM, 1.0)


@wp.func
def pick_weights(scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, row: int, patch: int, masked: bool) -> wp.vec2:
    """(w_li, c_li) at the vertex; (0, 0) for delta lights and masked ones."""
    l = scene.lights[li]
    if masked or is_delta(l):
        return wp.vec2(0.0, 0.0)
    ec = light_estimate(scene, li, p, n)
    return wp.vec2(ec[0] * pick_factor(scene, row, patch, li), ec[1])


@wp.func
def light_masked(scene: SceneRec, mask_row: int, depth: int, li: int) -> bool:
    """Whether light ``li`` is not sampled at the sensor (first vertex only): the plan proved it
    wholly behind the sensor (mask 0), or its direct light there is computed on the host (mask 2,
    :func:`computed_at`)."""
    if depth == 0 and mask_row >= 0:
        return scene.light_mask[mask_row * scene.n_lights + li] != 1
    return False


@wp.func
def computed_at(scene: SceneRec, mask_row: int, depth: int, li: int) -> bool:
    """Whether light ``li``'s direct light at the sensor is computed on the host, not sampled (mask
    2: exact direct light, docs/DESIGN.md §Direct light computed in reflecting rooms): at the
    sensor's own vertex neither its light sample nor a direction that meets it counts; paths go on
    from there, and every later vertex counts it as before."""
    if depth == 0 and mask_row >= 0 and li >= 0:
        return scene.light_mask[mask_row * scene.n_lights + li] == 2
    return False


@wp.func
def pick_light_at(scene: SceneRec, p: wp.vec3, n: wp.vec3, mask_row: int, depth: int, face: int, rng: wp.uint32) -> LightPick:
    """Draw one light with area for the vertex (p, n) with P(li | x) (module
    docstring), by two reservoirs in one pass: one over the weights w, one
    over the c, the mixture then chosen with probability α.

    The vertex lies on triangle ``face`` (−1: a sensor); past the first vertex, where the pilot
    learnt factors per patch (``scene.n_patch_pick``), its patch's factors steer the pick."""
    pk = LightPick()
    pk.li = -1
    pk.prob = 0.0
    pk.sum_w = 0.0
    pk.sum_c = 0.0
    pk.row = wp.where(depth == 0 and mask_row >= 0, 1 + mask_row, 0)
    pk.patch = -1
    if scene.n_patch_pick > 0 and depth > 0 and face >= 0:
        pk.patch = patch_at(scene, face, p)
    pick_w = int(-1)
    pick_c = int(-1)
    w_of_w = float(0.0)
    c_of_w = float(0.0)
    w_of_c = float(0.0)
    c_of_c = float(0.0)
    state = rng
    pk.rng = rng
    for li in range(scene.n_lights):
        wc = pick_weights(scene, li, p, n, pk.row, pk.patch, light_masked(scene, mask_row, depth, li))
        if wc[0] > 0.0:
            pk.sum_w += wc[0]
            if wp.randf(state) * pk.sum_w < wc[0]:
                pick_w = li
                w_of_w = wc[0]
                c_of_w = wc[1]
        if wc[1] > 0.0:
            pk.sum_c += wc[1]
            if wp.randf(state) * pk.sum_c < wc[1]:
                pick_c = li
                w_of_c = wc[0]
                c_of_c = wc[1]
    u = wp.randf(state)
    pk.rng = state
    if pk.sum_c <= 0.0 and pk.sum_w <= 0.0:
        return pk
    a = pick_mix(pk.sum_w)
    if u < a and pick_c >= 0:
        pk.li = pick_c
        pk.prob = mixed_probability(w_of_c, c_of_c, pk.sum_w, pk.sum_c)
    elif pick_w >= 0:
        pk.li = pick_w
        pk.prob = mixed_probability(w_of_w, c_of_w, pk.sum_w, pk.sum_c)
    else:
        pk.li = pick_c
        pk.prob = mixed_probability(w_of_c, c_of_c, pk.sum_w, pk.sum_c)
    return pk


@wp.func
def pick_light(scene: SceneRec, p: wp.vec3, n: wp.vec3, mask_row: int, depth: int, rng: wp.uint32) -> LightPick:
    """:func:`pick_light_at` with the factors of the rows only (no patch)."""
    return pick_light_at(scene, p, n, mask_row, depth, -1, rng)


@wp.func
def mixed_probability(w: float, c: float, sum_w: float, sum_c: float) -> float:
    """(1 − α)·w/Σw + α·c/Σc, with α = :func:`pick_mix` (Σ = 0 terms dropped)."""
    a = pick_mix(sum_w)
    prob = float(0.0)
    if sum_w > 0.0:
        prob += (1.0 - a) * w / sum_w
    if sum_c > 0.0:
        prob += a * c / sum_c
    return prob


@wp.func
def pick_probability(scene: SceneRec, pk: LightPick, li: int, p: wp.vec3, n: wp.vec3, mask_row: int, depth: int) -> float:
    """P(li | x) of :func:`pick_light` at the same vertex (its totals in
    ``pk``); 1 for delta lights, which are always sampled."""
    if is_delta(scene.lights[li]):
        return 1.0
    wc = pick_weights(scene, li, p, n, pk.row, pk.patch, light_masked(scene, mask_row, depth, li))
    return mixed_probability(wc[0], wc[1], pk.sum_w, pk.sum_c)


@wp.func
def picks_at(params: TraceParams, depth: int) -> bool:
    """Whether the vertex at ``depth`` picks one light (pick_light 1: every
    vertex; 2: every vertex past the sensor's own)."""
    return params.pick_light == 1 or (params.pick_light == 2 and depth > 0)


@wp.func
def pick_scale(
    scene: SceneRec, params: TraceParams, pk: LightPick, li: int, p: wp.vec3, n: wp.vec3, depth: int
) -> float:
    """P(li | vertex) of the light pick, 1 when every light is sampled: the
    factor on pdf_light that makes it the next-event strategy's density."""
    if not picks_at(params, depth):
        return 1.0
    return pick_probability(scene, pk, li, p, n, params.mask_row, depth)


@wp.func
def piece_moments(v: float, r: float, w: float) -> wp.vec2:
    """What a light sample x of the emitter pieces tells of the second moment of the vertex's two-sample
    MIS estimate with the pieces' pick and with a pick ∝ power, (S₁, S₀): over x drawn with the
    pieces' pdf p, the means of S₁ and S₀ are those second moments (importance reweighting).

    v = f/p is the sample's unweighted contribution, r = p₀/p = π_k/P(k | x) the power pick's pdf
    over the pieces' at x (the triangle and point picks are the same), and w = p²/(p² + b²) its power
    heuristic weight against the BSDF's pdf b, so q = b/p = √(1/w − 1) (q = 0 without MIS, w = 1).
    The light term E_p[(w f/p)²] is v²·w² and the BSDF term E_b[(w_b f/b)²] = E_p[v²·w_b²/q],
    w_b = q²/(1 + q²); with p₀ = r·p the weights are r²/(r² + q²) and q²/(r² + q²), so

        S₁ = v²·(1 + q³)/(1 + q²)²,   S₀ = v²·(r³ + q³)/(r² + q²)²

    (the light term of S₀: E_p[(w₀ f/p₀)²·p₀/p] = v²·w₀²/r). Without MIS, S₀ = v²/r.
    """
    if w <= 1.0e-12 or v <= 0.0:
        return wp.vec2(0.0, 0.0)
    q2 = wp.max(1.0 / w - 1.0, 0.0)
    q3 = q2 * wp.sqrt(q2)
    a = 1.0 + q2
    b = r * r + q2
    return wp.vec2(v * v * (1.0 + q3) / (a * a), v * v * (r * r * r + q3) / (b * b))


@wp.func
def tally_pick(
    scene: SceneRec, params: TraceParams, li: int, p: wp.vec3, n: wp.vec3, depth: int, weight: float, got: wp.vec2,
    elem: int, mis_w: float,
):
    """A pilot's sums for light ``li``'s pick factor (light_pick.py): the
    path weight × its estimate ê, and × the value its shadowed sample gave;
    slot 0 for a sensor's first vertex, 1 for the rest. A sample of emissive
    element ``elem`` (≥ 0, kernels/lights/emissive.py) of piece k also adds to k's sums (one row for
    all vertices): weight × ê_k and weight × value × P(k | x), the piece's
    shadowed irradiance (the value was divided by P(k | x)), and for the
    pieces' choice (engine.driver.Engine._choose_pieces) :func:`piece_moments`.
    ``mis_w`` is the sample's MIS weight (1 without MIS)."""
    if is_delta(scene.lights[li]):
        return
    pc = int(-1)
    if scene.lights[li].kind == _EMISSIVE and elem >= 0 and scene.n_pieces > 1:
        pc = elem_piece(scene, elem)
    if pc >= 0:
        pr = piece_probability(scene, pc, p, n, piece_totals(scene, p, n))
        j = params.thread * scene.n_pieces + pc
        ek = piece_estimate(scene, pc, p, n)
        v = weight * importance(got)
        mo = piece_moments(v, piece_power(scene, pc) / wp.max(pr, 1.0e-30), mis_w)
        # the first two as weight × (ê_k, value × P): the factors' sums as they were before the moments
        got_k = weight * (importance(got) * pr)
        scene.piece_tally[j] = scene.piece_tally[j] + wp.vec4(weight * ek[0], got_k, mo[0], mo[1])
    slot = wp.where(depth == 0 and params.mask_row >= 0, 0, 1)
    k = (params.thread * 2 + slot) * scene.n_lights + li
    e = light_estimate(scene, li, p, n)
    scene.pick_tally[k] = scene.pick_tally[k] + weight * wp.vec2(e[0], importance(got))


@wp.func
def tally_patch_pick(scene: SceneRec, li: int, face: int, p: wp.vec3, n: wp.vec3, weight: float, got: wp.vec2):
    """A one-worker pilot's sums for light ``li``'s factor at the patch of the vertex p on triangle
    ``face`` (a vertex past the first): weight × ê, weight × the shadowed value, and one visit.
    Warp's CPU atomics are not atomic across workers, so the pilot runs on one (its sums are then
    the same whatever the run's thread count)."""
    if is_delta(scene.lights[li]) or face < 0:
        return
    e = light_estimate(scene, li, p, n)
    k = patch_at(scene, face, p) * scene.n_lights + li
    scene.patch_pick_tally[k] = scene.patch_pick_tally[k] + wp.vec3(weight * e[0], weight * importance(got), 1.0)

