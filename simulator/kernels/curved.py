"""Lights seen in curved mirrors: the reflection point found by Newton's method, as ``@wp.func``.

A point light, an angle-0 distant light or the sun's disc reflected by a
curved mirror (a piece of mirror faces with shading normals,
``SceneRec.face_curve``: a chrome ball, a polished cylinder) reaches a
receiver x along the few directions d whose reflection about the shading
normal at the point m they meet leads to the light. No sampled direction
meets them (a delta meets a delta; the sun's image in a ball is ~10⁻⁹ sr);
the flat planes' image source (:mod:`.mirrors`) does not apply. So each
curved mirror k is solved for m, as manifold next-event estimation does
(Hanika, Droske and Fascione 2015), on the traced surface itself: the
facets with their interpolated normals.

**Unknown and residual.** The direction d from x's ray origin o; the ray
meets the mirror at m(d) (the first face of piece k, past what lets light
through), whose shading normal n(d) reflects d to r = d − 2(d·n)n. The
residual is g = q − r, q the unit direction from m to a point light or the
direction of a distant one. Within one triangle everything is smooth in d:
m moves in the face's plane (δm = t(δd − d (n_g·δd)/(n_g·d))), the normal
is the corners' N_i at the barycentric weights of m, b_i = a_i·(m − P0)
with a_i the face's dual basis, and n = N/|N|. The 2 × 2 Jacobian A of g
(projected on the plane ⊥ q, d perturbed in the plane ⊥ d) is written out
in :func:`curve_local`; each Newton step re-casts the ray, so the step
walks across faces.

**Seed.** The piece's bounding sphere (centre c, radius R, from the host):
m₀ = c + R·(u_x + u_l)/|u_x + u_l|, u_x and u_l the unit vectors from c to
o and to the light (its direction for a distant light), then
:data:`SEED_STEPS` turns of the bisector m ← c + R·b/|b|, b the sum of the
unit vectors from m to o and to the light, which settle on the bounding
sphere's own reflection point without a ray (the point itself for a
Sphere, whose facets then need one or two Newton steps). A ray that misses
the piece is aimed at c instead.

**What the receiver gets.** A point light of intensity I(ω) reflected by
F(cos θ_m) gives

    E = F · I(ω) · cos θ_x / (|l − m|² · |det A|),

since the light's rays through a patch dω_x of directions at x cross the
plane ⊥ q at the light over |l − m|²·|det A|·dω_x (δp = −|l − m|·(I − qqᵀ)δg
at the solution): for a flat mirror |det A| = ((t + |l − m|)/|l − m|)², the
image source's F·I cos/D². A distant light of normal irradiance E⊥ gives
E = F·E⊥·cos θ_x/|det A| (A = ∂r/∂d: 1 for a flat mirror), and the sun one
direction s of its cone (pdf 1/Ω) with E ≈ F·L·cos θ_x·Ω/|det A|. The
segment x → m passes what lets light through at its share, m → light
likewise; F and the coverage c are the mirror face's (as on a flat mirror).

**One solution per piece.** A convex mirror seen from outside shows a
light at one point; a concave one or a saddle may show it at several, of
which Newton finds one (the others are named in the summary:
``simulator.scene.surfaces.curved_mirrors``). For the sun the paths that
meet its disc off a curved mirror are counted where this connection does
not count them: a path that reaches the sun off piece k from a vertex that
ran the connection is left out exactly when :func:`curve_covers` finds that
the solve from that vertex toward the path's own sun direction lands on the
path's mirror point (a deterministic function of the vertex and the
direction), so every path is counted by one strategy.
"""

import warp as wp

from .coverage import coverage_at
from .lights import RAY_INF, SceneRec, tri_vertex
from .rays import first_hit, offset_length
from .sampling import frame_x, frame_y
from .surfaces import MAX_PASSES, pass_factor

#: Newton iterations a solve may take (it converges in 3–5 from the seed on a sphere)
MAX_NEWTON = wp.constant(16)
#: |q − r| below which the reflection is taken as found (float32: the residual's floor is ~1e-7)
NEWTON_TOL = wp.constant(4.0e-6)
#: bisector iterations that move the seed to the bounding sphere's own reflection point (no rays cast)
SEED_STEPS = wp.constant(8)
#: the largest step (rad) one iteration takes
MAX_STEP = wp.constant(0.25)
#: a path's mirror point within this share of the piece's radius of the solve's is the same solution
SAME_POINT = wp.constant(1.0e-3)


@wp.struct
class CurveRay:
    face: int  # the first face of the piece along the ray, −1: none (missed, or a matte face first)
    t: float  # its distance from the origin
    vis_in: float  # the share passed by what lets light through before it


@wp.struct
class CurveLocal:
    ok: int
    m: wp.vec3  # the mirror point
    ns: wp.vec3  # the shading normal there, toward the origin
    q: wp.vec3  # unit direction from m toward the light
    dist: float  # |l − m| for a point light (1 for a distant one)
    res: float  # |q − r|
    a: wp.vec4  # the residual's Jacobian A (row-major 2 × 2)
    g2: wp.vec2  # the residual projected on the plane ⊥ q (not "rhs": Warp names its operators' argument so)


@wp.struct
class CurveSolve:
    ok: int
    face: int
    d: wp.vec3  # unit direction from the origin to the mirror point
    t: float
    m: wp.vec3
    ns: wp.vec3
    q: wp.vec3
    dist: float
    det: float  # |det A| at the solution
    vis_in: float


@wp.func
def curve_first(scene: SceneRec, k: int, o: wp.vec3, d: wp.vec3) -> CurveRay:
    """The first face of curved mirror ``k`` along (o, d), through what lets light through (its share in
    ``vis_in``); face −1 where the ray escapes, meets a matte face or another surface first."""
    out = CurveRay()
    out.face = -1
    out.vis_in = 1.0
    start = float(0.0)
    for j in range(MAX_PASSES):
        h = first_hit(scene, o + start * d, d, RAY_INF)
        if h.face < 0:
            return out
        if scene.face_curve[h.face] == k:
            out.face = h.face
            out.t = start + h.t
            return out
        if scene.surf_id[h.face] < 0:
            return out
        q = o + (start + h.t) * d
        out.vis_in = out.vis_in * pass_factor(scene, h.face, d, h.ng, q)
        if out.vis_in <= 0.0:
            return out
        start = start + h.t + offset_length(scene, q)
    return out


@wp.func
def curve_column(e: wp.vec3, d: wp.vec3, t: float, ng: wp.vec3, ndd: float, a1: wp.vec3, a2: wp.vec3, dn1: wp.vec3,
                 dn2: wp.vec3, nh: wp.vec3, ln: float, sgn: float, ns: wp.vec3, q: wp.vec3, dist: float,
                 point: int) -> wp.vec3:
    """δg for the perturbation ``e`` of d (module docstring): δm, then δN = ΔN₁(a₁·δm) + ΔN₂(a₂·δm),
    δn = ±(δN − n̂(n̂·δN))/|N|, δr = δd − 2(δd·n)n − 2(d·δn)n − 2(d·n)δn, δq = −(I − qqᵀ)δm/|l − m|."""
    dm = t * (e - d * (wp.dot(ng, e) / ndd))
    dnv = dn1 * wp.dot(a1, dm) + dn2 * wp.dot(a2, dm)
    dns = (sgn / ln) * (dnv - nh * wp.dot(nh, dnv))
    dr = e - (2.0 * wp.dot(e, ns)) * ns - (2.0 * wp.dot(d, dns)) * ns - (2.0 * wp.dot(d, ns)) * dns
    dq = wp.vec3(0.0, 0.0, 0.0)
    if point != 0:
        dq = -(dm - q * wp.dot(q, dm)) / dist
    return dq - dr


@wp.func
def curve_local(scene: SceneRec, face: int, o: wp.vec3, d: wp.vec3, tgt: wp.vec3, point: int) -> CurveLocal:
    """The mirror point, normal, residual and Jacobian of the ray (o, d) on ``face`` (module docstring);
    ``tgt`` the point light's position (``point`` 1) or the distant light's unit direction."""
    out = CurveLocal()
    out.ok = 0
    a = tri_vertex(scene, face, 0)
    e1 = tri_vertex(scene, face, 1) - a
    e2 = tri_vertex(scene, face, 2) - a
    cr = wp.cross(e1, e2)
    den = wp.length(cr)
    if den <= 0.0:
        return out
    ng = cr / den
    ndd = wp.dot(ng, d)
    if wp.abs(ndd) < 1.0e-9:
        return out
    t = wp.dot(ng, a - o) / ndd
    if t <= 0.0:
        return out
    m = o + t * d
    a1 = wp.cross(e2, ng) / den
    a2 = wp.cross(ng, e1) / den
    b1 = wp.dot(a1, m - a)
    b2 = wp.dot(a2, m - a)
    sid = scene.shade_id[face]
    n0 = scene.shade_n[3 * sid]
    dn1 = scene.shade_n[3 * sid + 1] - n0
    dn2 = scene.shade_n[3 * sid + 2] - n0
    nv = n0 + b1 * dn1 + b2 * dn2
    ln = wp.length(nv)
    if ln <= 0.0:
        return out
    nh = nv / ln
    sgn = wp.where(wp.dot(nh, o - m) < 0.0, -1.0, 1.0)
    ns = sgn * nh
    r = d - (2.0 * wp.dot(d, ns)) * ns
    q = tgt
    dist = float(1.0)
    if point != 0:
        w = tgt - m
        dist = wp.length(w)
        if dist <= 0.0:
            return out
        q = w / dist
    g = q - r
    eu = frame_x(d)
    ev = frame_y(d)
    gu = curve_column(eu, d, t, ng, ndd, a1, a2, dn1, dn2, nh, ln, sgn, ns, q, dist, point)
    gv = curve_column(ev, d, t, ng, ndd, a1, a2, dn1, dn2, nh, ln, sgn, ns, q, dist, point)
    f1 = frame_x(q)
    f2 = frame_y(q)
    out.a = wp.vec4(wp.dot(f1, gu), wp.dot(f1, gv), wp.dot(f2, gu), wp.dot(f2, gv))
    out.g2 = wp.vec2(wp.dot(f1, g), wp.dot(f2, g))
    out.m = m
    out.ns = ns
    out.q = q
    out.dist = dist
    out.res = wp.length(g)
    out.ok = 1
    return out


@wp.func
def curve_solve(scene: SceneRec, k: int, o: wp.vec3, tgt: wp.vec3, point: int) -> CurveSolve:
    """Where curved mirror ``k`` reflects the light at ``tgt`` (a point, ``point`` 1, or a unit direction)
    toward the ray origin o: Newton's method from the seed (module docstring); ``ok`` 0 where it does
    not converge, or the solution's mirror point lies within a ray offset of o (o's own surface)."""
    out = CurveSolve()
    out.ok = 0
    sph = scene.curve_sphere[k]
    c = wp.vec3(sph[0], sph[1], sph[2])
    ux = o - c
    lx = wp.length(ux)
    if lx <= 0.0:
        return out
    ul = tgt
    if point != 0:
        ul = wp.normalize(tgt - c)
    b = ux / lx + ul
    lb = wp.length(b)
    if lb < 1.0e-3:
        return out  # the light straight behind the mirror
    m0 = c + (sph[3] / lb) * b
    for it in range(SEED_STEPS):  # the bounding sphere's own reflection point: the bisector, iterated
        if point != 0:
            ul = wp.normalize(tgt - m0)
        b = wp.normalize(o - m0) + ul
        lb = wp.length(b)
        if lb < 1.0e-3:
            break
        m0 = c + (sph[3] / lb) * b
    d = wp.normalize(m0 - o)
    retried = int(0)
    for it in range(MAX_NEWTON):
        cr = curve_first(scene, k, o, d)
        if cr.face < 0:
            if retried == 0:  # the seed missed the piece: aim at its centre once
                retried = 1
                d = wp.normalize(c - o)
                continue
            return out
        loc = curve_local(scene, cr.face, o, d, tgt, point)
        if loc.ok == 0:
            return out
        if loc.res < NEWTON_TOL:
            if cr.t <= 2.0 * offset_length(scene, loc.m):
                return out
            if wp.abs(loc.a[0] * loc.a[3] - loc.a[1] * loc.a[2]) <= 1.0e-20:
                return out  # on a caustic (a concave mirror's focus): no finite reading there
            out.ok = 1
            out.face = cr.face
            out.d = d
            out.t = cr.t
            out.m = loc.m
            out.ns = loc.ns
            out.q = loc.q
            out.dist = loc.dist
            out.det = wp.abs(loc.a[0] * loc.a[3] - loc.a[1] * loc.a[2])
            out.vis_in = cr.vis_in
            return out
        det = loc.a[0] * loc.a[3] - loc.a[1] * loc.a[2]
        if wp.abs(det) < 1.0e-12:
            return out
        su = -(loc.a[3] * loc.g2[0] - loc.a[1] * loc.g2[1]) / det
        sv = -(loc.a[0] * loc.g2[1] - loc.a[2] * loc.g2[0]) / det
        step = wp.sqrt(su * su + sv * sv)
        if step > MAX_STEP:
            su = su * (MAX_STEP / step)
            sv = sv * (MAX_STEP / step)
        d = wp.normalize(d + su * frame_x(d) + sv * frame_y(d))
    return out


@wp.func
def curve_covers(scene: SceneRec, k: int, o: wp.vec3, m: wp.vec3, s: wp.vec3) -> bool:
    """Whether the connection from the ray origin o toward the distant direction s lands on the mirror
    point m of curved mirror ``k`` (module docstring: a path that reached the sun there is then left out)."""
    cs = curve_solve(scene, k, o, s, 0)
    if cs.ok == 0:
        return False
    return wp.length(cs.m - m) <= SAME_POINT * scene.curve_sphere[k][3]


@wp.func
def curve_cover(scene: SceneRec, face: int, m: wp.vec3) -> float:
    """The mirror face's coverage at m (a perforated mirror reflects only its share)."""
    return coverage_at(scene, scene.surf[scene.surf_id[face]], face, m)
