"""Hero-wavelength transport on the device (spectral mode).

The tables are built on the host by :mod:`simulator.spectra.hero`; see
docs/DESIGN.md "Spectral transport".
"""

import warp as wp

from .lights import SceneRec
from .records import TraceParams


# ---------------------------------------------------------------- hero wavelengths
#
# Spectral mode (params.spectral = 1, simulator.spectra.hero): each sample
# carries 4 wavelengths (grid nodes params.hero) and, besides the scalar
# throughput β that Russian roulette reads, a tint per lane: the spectral
# throughput divided by β, kept at mean 1 (so β is the lanes' mean). A
# contribution value (W channel) × tint_k × the light's spectral row at node
# k is the spectral density the sample adds at λ_k; it is summed per lane in
# scene.response_lanes and projected on every response when the sample ends.

#: hero wavelengths per sample (simulator.spectra.transport.HERO_WAVELENGTHS)
N_HERO = wp.constant(4)
#: grid nodes spanned by the 4 lanes: 380–780 nm at 1 nm
GRID_SPAN_NM = wp.constant(400.0)


@wp.func
def hero_nodes(u: float) -> wp.vec4i:
    """Grid nodes of the 4 hero wavelengths of a uniform ``u`` ∈ [0, 1):
    x_k = 400·frac(u + k/4) nm above 380 nm, each rounded to its nearest
    node ⌊x_k + ½⌋ ∈ {0 … 400}. Node i is then drawn with probability w_i/400
    (w the trapezoid weights: ½ at either end), which
    ``scene.response_weights`` (400·q/w) divides out (simulator.spectra.hero)."""
    h = wp.vec4i(0, 0, 0, 0)
    for k in range(4):
        x = GRID_SPAN_NM * (u + float(k) * 0.25)
        if x >= GRID_SPAN_NM:
            x = x - GRID_SPAN_NM
        h[k] = wp.min(int(x + 0.5), 400)
    return h


@wp.func
def spectral_row(table: wp.array2d(dtype=float), row: int, h: wp.vec4i) -> wp.vec4:
    """``table[row]`` at the 4 hero nodes."""
    return wp.vec4(table[row, h[0]], table[row, h[1]], table[row, h[2]], table[row, h[3]])


@wp.func
def lane_response(scene: SceneRec, r: int, h: wp.vec4i, lanes: wp.vec4) -> float:
    """Response ``r`` of one sample from its 4 lanes: (1/4) Σ_k W_r(λ_k)·X_k."""
    return 0.25 * wp.dot(spectral_row(scene.response_weights, r, h), lanes)


@wp.func
def spectral_contribution(scene: SceneRec, params: TraceParams, li: int, value: wp.vec2, tint: wp.vec4) -> wp.vec2:
    """Tally light ``li``'s share of a spectral sample in its lanes and
    return its (radiometric, photopic) responses, which stand for the W and
    lm channels in spectral mode."""
    lanes = value[0] * wp.cw_mul(tint, spectral_row(scene.spectral_emission, li, params.hero))
    scene.response_lanes[params.thread] = scene.response_lanes[params.thread] + lanes
    return wp.vec2(lane_response(scene, 0, params.hero, lanes), lane_response(scene, 1, params.hero, lanes))


@wp.struct
class Reflection:
    rho: float  # what the path's throughput β is multiplied by
    tint: wp.vec4  # the lanes' spectral throughput / β after the reflection
