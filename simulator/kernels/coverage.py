"""Coverage read per texel: an opacity texture looked up at a ray's hit, as ``@wp.func``.

A face whose surface row is ``textured`` (``SurfRec.textured``) has, per
triangle, a texture (``scene.tex_id``) and the texture coordinates of its
three corners (``scene.tex_uv``). At a hit point p the barycentric
coordinates (b0, b1, b2) of p in the triangle give st = Σ bᵢ stᵢ (st is
linear over a triangle), and the opacity there is the texture's bilinear
interpolation at st, UsdUVTexture's default ``linear`` filter (no mip-maps:
a ray is a point, its footprint is the texel it lands in):

    x = s·w − ½,  y = (1 − t)·h − ½,  i = ⌊x⌋, j = ⌊y⌋, fx = x − i, fy = y − j,
    o = (1 − fx)(1 − fy)·τ(i, j) + fx(1 − fy)·τ(i + 1, j) + (1 − fx)fy·τ(i, j + 1) + fx·fy·τ(i + 1, j + 1),

texel centres at (i + ½)/w, row 0 at the top of the image (t = 1, USD's
st origin is the image's lower left), τ(i, j) a texel after the wrap of
each axis (black: the border value outside, clamp, repeat, mirror).

The coverage is c = o (``presence``) or, with an ``opacityThreshold`` > 0,
c = 1 where o ≥ the threshold and 0 below (the threshold applies to the
filtered value, as a fragment's opacity). A shadow ray multiplies by the
expected visibility (1 − c) + c·T at that point and a path ray passes with
probability 1 − c drawn from its own random stream
(:mod:`.surfaces`): both unbiased for the texture as authored.
"""

import warp as wp

from .lights import SceneRec, tri_params
from .surface_rec import SurfRec, TexRec

#: TexRec wrap codes (simulator.scene.surfaces.WRAP_MODES)
WRAP_BLACK = wp.constant(0)
WRAP_CLAMP = wp.constant(1)
WRAP_REPEAT = wp.constant(2)
WRAP_MIRROR = wp.constant(3)


@wp.func
def wrap_index(i: int, n: int, mode: int) -> int:
    """Texel index i of an axis of n texels after the wrap ``mode``; −1 outside the image for black."""
    if i >= 0 and i < n:
        return i
    if mode == WRAP_CLAMP:
        return wp.clamp(i, 0, n - 1)
    if mode == WRAP_REPEAT:
        return ((i % n) + n) % n
    if mode == WRAP_MIRROR:
        m = ((i % (2 * n)) + 2 * n) % (2 * n)  # period 2n: 0 … n−1 forward, then n−1 … 0
        if m >= n:
            m = 2 * n - 1 - m
        return m
    return -1


@wp.func
def texel(scene: SceneRec, t: TexRec, i: int, j: int) -> float:
    """Texel (column i, row j from the top) of texture t after its wraps."""
    a = wrap_index(i, t.w, t.wrap_s)
    b = wrap_index(j, t.h, t.wrap_t)
    if a < 0 or b < 0:
        return t.border
    return scene.texels[t.offset + b * t.w + a]


@wp.func
def bilinear_opacity(scene: SceneRec, t: TexRec, st: wp.vec2) -> float:
    """The texture's bilinear value at st (module docstring)."""
    x = st[0] * float(t.w) - 0.5
    y = (1.0 - st[1]) * float(t.h) - 0.5
    fi = wp.floor(x)
    fj = wp.floor(y)
    fx = x - fi
    fy = y - fj
    i = int(fi)
    j = int(fj)
    top = (1.0 - fx) * texel(scene, t, i, j) + fx * texel(scene, t, i + 1, j)
    bottom = (1.0 - fx) * texel(scene, t, i, j + 1) + fx * texel(scene, t, i + 1, j + 1)
    return (1.0 - fy) * top + fy * bottom


@wp.func
def hit_st(scene: SceneRec, face: int, p: wp.vec3) -> wp.vec2:
    """Texture coordinates at point p on triangle ``face``: its corners' st at p's barycentric weights
    (:func:`~.lights.tri_params`, clamped to the triangle)."""
    st = tri_params(scene, face, p)
    b1 = wp.clamp(st[0], 0.0, 1.0)
    b2 = wp.clamp(st[1], 0.0, 1.0 - b1)
    k = 3 * face
    return (1.0 - b1 - b2) * scene.tex_uv[k] + b1 * scene.tex_uv[k + 1] + b2 * scene.tex_uv[k + 2]


@wp.func
def coverage_at(scene: SceneRec, s: SurfRec, face: int, p: wp.vec3) -> float:
    """The coverage of surface row s at point p of ``face``: the row's own unless it is textured and the
    face has a texture, then the texture's opacity there (or 0/1 against the row's threshold)."""
    if s.textured == 0:
        return s.coverage
    k = scene.tex_id[face]
    if k < 0:
        return s.coverage
    o = wp.clamp(bilinear_opacity(scene, scene.tex[k], hit_st(scene, face, p)), 0.0, 1.0)
    if s.threshold > 0.0:
        if o >= s.threshold:
            return 1.0
        return 0.0
    return o
