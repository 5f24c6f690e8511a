"""Per-light-group tallies of a sample (light groups and sky patches of ``probesim study``).

The estimator's hook ``light_contribution`` adds each emitted-light share of
a sample to its group's slot (:func:`tally_group`); when the sample ends
its slots are folded into the thread's sums: every pair of groups
(:func:`fold_group_sample`, the full covariance) or, for many groups (a
dome split into Tregenza's sky patches, :func:`tregenza_patch`), the sums
the host's batch means need (:func:`fold_group_batch`). Host side:
``simulator.engine.stats`` (``GroupStats``, ``GroupBatchStats``) and
docs/DESIGN.md "Light groups in one pass".
"""

import warp as wp

from simulator.study.inputs.sky_patches import BAND_COUNTS, BAND_DEG, BAND_START, GROUND

from .records import TraceParams
from .sampling import PI


# Tregenza's bands, from the one table the host uses (simulator.study.inputs.sky_patches)
_BAND_VEC = wp.types.vector(length=len(BAND_COUNTS), dtype=wp.int32)
BAND_COUNT = wp.constant(_BAND_VEC(*BAND_COUNTS))
BAND_FIRST = wp.constant(_BAND_VEC(*BAND_START))
N_BANDS = wp.constant(len(BAND_COUNTS))
GROUND_SLOT = wp.constant(GROUND)
BAND_WIDTH_DEG = wp.constant(BAND_DEG)


@wp.func
def tregenza_patch(d: wp.vec3) -> int:
    """Tregenza sky patch of direction ``d`` (world frame, +Z up, +Y north, +X east): 0…144 above the
    horizon, 145 at or below it; the twin of :func:`simulator.study.inputs.sky_patches.patch_index`
    (12° altitude bands, the last the polar cap; patch 0 of a band centred on north)."""
    if d[2] <= 0.0:
        return GROUND_SLOT
    alt = wp.asin(wp.clamp(d[2] / wp.length(d), -1.0, 1.0)) * (180.0 / PI)
    band = wp.min(int(alt / BAND_WIDTH_DEG), N_BANDS - 1)
    n = BAND_COUNT[band]
    az = wp.atan2(d[0], d[1])
    if az < 0.0:
        az = az + 2.0 * PI
    j = int(wp.floor(az / (2.0 * PI / float(n)) + 0.5))
    return BAND_FIRST[band] + j % n


#: batch tallies: distinct groups a sample's touched list holds; past it the fold scans all G slots
GROUP_TOUCHED = wp.constant(32)


@wp.func
def group_width(params: TraceParams) -> int:
    """Slots of a thread's group state: G·(G + 3), or for batch tallies 2G + 1 + ``GROUP_TOUCHED``
    (this sample's light, the sums, the touched count, the touched list)."""
    if params.group_batch != 0:
        return 2 * params.n_groups + 1 + GROUP_TOUCHED
    return params.n_groups * (params.n_groups + 3)


@wp.func
def tally_group(params: TraceParams, g: int, v: wp.vec2):
    """Add ``v`` to this sample's slot of group ``g`` (none for g < 0). Batch tallies also note a
    slot the sample touches for the first time in the thread's touched list (its index in the
    first component of a list slot), so the fold visits only those."""
    if g < 0:
        return
    base = params.thread * group_width(params)
    k = base + g
    x = params.group_state[k]
    if params.group_batch != 0 and x[0] == wp.float64(0.0) and x[1] == wp.float64(0.0):
        c0 = base + 2 * params.n_groups  # the touched count, in the first component
        n = int(params.group_state[c0][0])
        if n < GROUP_TOUCHED:
            params.group_state[c0 + 1 + n] = wp.vec2d(wp.float64(g), wp.float64(0.0))
        params.group_state[c0] = wp.vec2d(wp.float64(wp.min(n + 1, GROUP_TOUCHED + 1)), wp.float64(0.0))
    params.group_state[k] = x + wp.vec2d(v)


@wp.func
def clear_group_sample(params: TraceParams, t: int):
    """Zero thread ``t``'s per-group slots of this sample (batch tallies: the fold leaves them zero)."""
    if params.group_batch != 0:
        return
    base = t * group_width(params)
    for g in range(params.n_groups):
        params.group_state[base + g] = wp.vec2d(wp.float64(0.0), wp.float64(0.0))


@wp.func
def fold_group_batch(params: TraceParams, t: int, keep: int):
    """Batch tallies: add thread ``t``'s sample, per group, to its sums Σx_g (no shift, no cross
    products) and zero the sample's slots, visiting only the touched ones (all G when the list
    overflowed); the host estimates the covariance from the threads' block means
    (:class:`simulator.engine.stats.GroupBatchStats`). A non-finite sample (``keep`` 0) adds nothing."""
    n_g = params.n_groups
    x0 = t * group_width(params)
    s0 = x0 + n_g
    c0 = x0 + 2 * n_g
    st = params.group_state
    zero = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
    n = int(st[c0][0])
    if n <= GROUP_TOUCHED:
        for j in range(n):
            g = int(st[c0 + 1 + j][0])
            if keep != 0:
                st[s0 + g] = st[s0 + g] + st[x0 + g]
            st[x0 + g] = zero
    else:
        for g in range(n_g):
            if keep != 0:
                st[s0 + g] = st[s0 + g] + st[x0 + g]
            st[x0 + g] = zero
    st[c0] = zero


@wp.func
def fold_group_sample(params: TraceParams, t: int, first: int, keep: int):
    """Add thread ``t``'s sample, per group, to its shifted sums.

    Notes
    -----
    With x_g the sample's light from group g and K_g the thread's first
    sample of it, the thread keeps S_g = Σ(x_g − K_g) and the lower triangle
    of P_gh = Σ(x_g − K_g)(x_h − K_h) (per channel, float64), from which the
    host forms each block's mean and co-moment (:mod:`simulator.engine.stats`).
    A non-finite sample (``keep`` 0) counts as 0 in every group, as it does
    in the total."""
    n_g = params.n_groups
    if params.group_batch != 0:
        fold_group_batch(params, t, keep)
        return
    x0 = t * n_g * (n_g + 3)  # this sample's light per group
    k0 = x0 + n_g  # shifts
    s0 = k0 + n_g  # sums
    p0 = s0 + n_g  # cross sums
    st = params.group_state
    for g in range(n_g):
        if keep == 0:
            st[x0 + g] = wp.vec2d(wp.float64(0.0), wp.float64(0.0))
        if first != 0:
            st[k0 + g] = st[x0 + g]
        st[x0 + g] = st[x0 + g] - st[k0 + g]  # from here on the slot holds x_g − K_g
    for g in range(n_g):
        dg = st[x0 + g]
        st[s0 + g] = st[s0 + g] + dg
        for h in range(g + 1):
            k = p0 + g * n_g + h
            st[k] = st[k] + wp.cw_mul(dg, st[x0 + h])
