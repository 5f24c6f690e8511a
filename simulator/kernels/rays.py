"""Ray queries robust to float32 stage coordinates.

Rays leave surfaces pushed off by :func:`offset_length`; :func:`first_hit`
finds the first surface a ray crosses, each hit's distance solved again in
float64 (:func:`plane_distance`) so that a surface a ray cannot cross is
skipped, not hit; :func:`unoccluded` is the visibility test shadow rays
use. UsdLux lights are not geometry: :func:`near_light` tells when a ray
origin pushed off a surface could land behind one.
"""

import warp as wp

from .lights import RAY_INF, SceneRec, light_within, tri_vertex
from .records import TraceParams


@wp.func
def offset_length(scene: SceneRec, p: wp.vec3) -> float:
    """How far a ray origin is pushed off a surface at p: ``scene.eps``
    relative to the coordinate's magnitude, so the push stays well above
    float32 resolution (6e-8 relative) far from the origin, and well below
    modelled gaps (0.1 mm under a lamp) near it."""
    return scene.eps * wp.max(1.0, wp.max(wp.abs(p[0]), wp.max(wp.abs(p[1]), wp.abs(p[2]))))


@wp.func
def count_ray(scene: SceneRec, params: TraceParams):
    """Tally one closest-hit ray (a path's next vertex) for ``probesim bench`` and the pilots (a branch
    when counting is off), in the thread's first slot of ``scene.ray_counts`` (two per thread: path
    rays, shadow rays): counted in mode 1 (every ray), not in mode 2 (shadow rays only)."""
    if params.count_rays == 1:
        k = 2 * params.thread
        scene.ray_counts[k] = scene.ray_counts[k] + 1


@wp.func
def count_shadow_ray(scene: SceneRec, params: TraceParams):
    """Tally one shadow ray (a next-event visibility test or an image connection) in the thread's
    second slot: counted in modes 1 and 2."""
    if params.count_rays != 0:
        k = 2 * params.thread + 1
        scene.ray_counts[k] = scene.ray_counts[k] + 1


#: hits on planes a ray cannot cross that one query may skip (see first_hit)
MAX_SKIPS = wp.constant(4)


@wp.struct
class RayHit:
    t: float  # distance along the ray; RAY_INF when nothing is hit
    face: int  # triangle hit, −1 when none
    ng: wp.vec3  # its unit geometric normal


@wp.func
def plane_distance(scene: SceneRec, face: int, o: wp.vec3, d: wp.vec3) -> float:
    """Distance t > 0 at which the ray (o, d) meets the plane of triangle
    ``face``, or −1 when it cannot meet it ahead: o lies on the plane, or d
    is parallel to it or heads away. Solved in float64 on the float32
    vertices (exact up to ~1e-16 relative), whatever the triangle's size; a
    degenerate triangle has no plane and is never met."""
    a = wp.vec3d(tri_vertex(scene, face, 0))
    ng = wp.cross(wp.vec3d(tri_vertex(scene, face, 1)) - a, wp.vec3d(tri_vertex(scene, face, 2)) - a)
    side = wp.dot(wp.vec3d(o) - a, ng)
    dn = wp.dot(wp.vec3d(d), ng)
    if side * dn >= wp.float64(0.0):
        return -1.0
    return float(-side / dn)


@wp.func
def first_hit(scene: SceneRec, o: wp.vec3, d: wp.vec3, t_max: float) -> RayHit:
    """The first surface the ray (o, d) meets before ``t_max``.

    Warp's ray-triangle test works in float32 on vertices relative to the
    ray origin, so its error grows with the triangle's coordinates, not with
    the origin's: from a point 1e-5 m above a tilted 10 km ground plane
    (vertices 5 km out, float32 spacing 5e-4 m) it reports the plane as hit
    by rays that leave it (shadow acne: a receiver lying on the ground read
    0), and puts hits up to ~1e-4 m off the plane (a path vertex may then lie
    behind its own surface, which shadows it). So each hit's distance is
    recomputed by :func:`plane_distance`; a reported hit on a plane the ray
    cannot meet is skipped by restarting the query just past it, so
    occluders beyond are still found."""
    h = RayHit()
    h.t = RAY_INF
    h.face = -1
    h.ng = wp.vec3(0.0, 0.0, 1.0)
    if scene.has_mesh == 0:
        return h
    start = float(0.0)
    k = int(0)
    while k < MAX_SKIPS and start < t_max:
        q = wp.mesh_query_ray(scene.mesh, o + start * d, d, t_max - start)
        if not q.result:
            return h
        t = plane_distance(scene, q.face, o, d)
        if t > t_max:
            return h  # the exact crossing lies past the segment's end: nothing in the way
        if t > 0.0:
            h.t = t
            h.face = q.face
            h.ng = wp.normalize(q.normal)
            return h
        start = start + q.t + offset_length(scene, o + (start + q.t) * d)
        k += 1
    return h


@wp.func
def near_light(scene: SceneRec, p: wp.vec3, reach: float) -> bool:
    """True if the surface of a UsdLux area light lies within ``reach`` of p
    (or p is inside a sphere light). A ray origin pushed off p by ``reach``
    could then land inside or behind that light, which rays from there
    cannot see: a sensor 1 µm from a sphere light read 0 with ``bsdf``, and
    ``mis`` lost the bsdf share of its weight."""
    for li in range(scene.n_lights):
        l = scene.lights[li]
        if light_within(l, p - l.position, reach):
            return True
    return False


# inlined wherever it is called: out of line, each shadow ray would copy the whole scene record into it (its
# argument is passed by value), which made a sample 10-15% slower when the compiler's own inlining decision
# tipped that way (it did for one more field of SceneRec, or one more caller)
@wp.func(inline=True)
def unoccluded(scene: SceneRec, o: wp.vec3, wi: wp.vec3, dist: float, tri: int) -> bool:
    """True if nothing blocks the segment from o along wi for ``dist``. A
    sampled emissive triangle is reached when the first hit is that triangle;
    UsdLux lights are not geometry, so the segment ends on them (see
    :func:`light_end_offset`) and a surface 10⁻⁴ m in front of a lamp still
    blocks it."""
    if scene.has_mesh == 0:
        return True
    if tri >= 0:
        h = first_hit(scene, o, wi, dist * 1.001)
        return h.face < 0 or h.face == tri
    return first_hit(scene, o, wi, dist).face < 0
