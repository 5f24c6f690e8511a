"""Ray queries alone, for profiling: the cost of a ray without the estimator around it.

``benchmarks/profile_office.py`` casts rays of the distribution a path
draws (cosine directions from the sensors and from the surfaces they reach,
shadow segments toward the lights) through these kernels into the same BVH
the estimator queries, and times them, so the share of an estimator's time
spent in ray queries can be told from the rest. Each thread casts one ray.
"""

import warp as wp

from .lights import SceneRec, sample_light
from .rays import first_hit

wp.set_module_options({"enable_backward": False})


@wp.kernel
def closest_hit_kernel(
    scene: SceneRec,
    origin: wp.array(dtype=wp.vec3),
    direction: wp.array(dtype=wp.vec3),
    t_max: wp.array(dtype=float),
    out_t: wp.array(dtype=float),
    out_face: wp.array(dtype=wp.int32),
    out_ng: wp.array(dtype=wp.vec3),
):
    """The estimator's ray query, :func:`~.rays.first_hit` (BVH traversal, then the
    hit's distance solved again in float64): distance (m), triangle (−1: none) and
    unit geometric normal of the first surface each ray meets before ``t_max`` (m)."""
    i = wp.tid()
    h = first_hit(scene, origin[i], direction[i], t_max[i])
    out_t[i] = h.t
    out_face[i] = h.face
    out_ng[i] = h.ng


@wp.kernel
def bvh_only_kernel(
    scene: SceneRec,
    origin: wp.array(dtype=wp.vec3),
    direction: wp.array(dtype=wp.vec3),
    t_max: wp.array(dtype=float),
    out_face: wp.array(dtype=wp.int32),
):
    """Warp's BVH query alone (``wp.mesh_query_ray``, float32), without the
    float64 re-solve of :func:`~.rays.first_hit`: what a leaner query could cost."""
    i = wp.tid()
    q = wp.mesh_query_ray(scene.mesh, origin[i], direction[i], t_max[i])
    f = int(-1)
    if q.result:
        f = q.face
    out_face[i] = f


@wp.kernel
def light_sample_kernel(
    scene: SceneRec,
    point: wp.array(dtype=wp.vec3),
    normal: wp.array(dtype=wp.vec3),
    li: int,
    seed: int,
    out_value: wp.array(dtype=wp.vec2),
):
    """One sample of light ``li`` (:func:`~.lights.sample_light`, no ray cast) for each receiver
    (point m, unit normal): the cost of next-event estimation's sampling, apart from its shadow ray."""
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    u = wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng))
    ls = sample_light(scene, li, point[i], normal[i], u)
    out_value[i] = ls.value
