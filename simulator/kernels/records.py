"""Device records of one trace: a sensor and the strategy switches.

:class:`SensorRec` is one sensor as the estimator kernel reads it (filled
by ``estimators.sensor_record``); :class:`TraceParams` holds the run's
strategy switches and per-thread state, built only by
``simulator.engine.driver.Engine.trace_params``.
"""

import warp as wp


@wp.struct
class SensorRec:
    kind: int
    position: wp.vec3
    normal: wp.vec3  # faces the light it measures; look direction for radiance
    right: wp.vec3  # patch width axis
    up: wp.vec3  # patch height axis
    width: float
    height: float
    one_minus_cos: float  # radiance cone: 1 − cos(half-angle); 0 = one direction
    cull: int  # 1: the first vertex is the sensor, so the plan's light mask applies there
    optics: int  # 0: an ideal head (cosine); k ≥ 1: its angular response is SceneRec.optics[k − 1] (kernels.optics)


@wp.struct
class TraceParams:
    nee: int  # sample every light at each vertex
    bsdf: int  # follow cosine-weighted directions and count emitters they hit
    mis: int  # weight the two by the power heuristic
    bounces: int  # surface interactions to follow: 0 = direct only, −1 = unbounded
    skip_direct: int  # 1: leave out light that reaches the sensor without a reflection (indirect only)
    emissive_light: int  # index of the EMISSIVE light record, −1 if none
    seed: int
    count_rays: int  # 1: count traced rays per thread in scene.ray_counts (benchmarks); 2: shadow rays only
    thread: int  # set by the kernel for each thread
    mask_row: int  # set by the kernel: the sensor whose light mask applies at vertex 0, −1 for none
    spectral: int  # 1: hero-wavelength transport (scene.spectral_* tables, response tallies)
    hero: wp.vec4i  # set by the kernel per sample: the 4 hero wavelengths' grid nodes (0…400)
    tint: wp.vec4  # spectral throughput / β per hero lane where a path starts (mean 1; ones at a sensor)
    # -- light-group tallies (see light_contribution and fold_group_sample); unused while group_tally is 0.
    # Groups of the light records: SceneRec.light_group. One array holds a thread's state, G·(G + 3)
    # slots from thread·G·(G + 3): this sample's light per group (G), K_g the thread's first sample
    # per group (G), Σ(x_g − K_g) (G), Σ(x_g − K_g)(x_h − K_h) at g·G + h, h ≤ g (G × G).
    group_tally: int  # 1: tally each sample's light per group as well as its total
    n_groups: int  # G
    # Batch tallies (group_batch 1, for many groups: a dome split into sky patches): 2G + 1 + GROUP_TOUCHED
    # slots a thread, this sample's light per group (G), Σx_g (G), the touched count and list; the host's
    # batch means give the covariance (see group_width, fold_group_batch).
    group_batch: int  # 1: batch tallies
    group_state: wp.array(dtype=wp.vec2d)  # (threads × group_width)
    guide_c: float  # guided paths: probability of sampling the surface guide at a vertex (0: plain paths)
    guide_first: int  # the guide is used at vertices of depth ≥ guide_first ...
    guide_depth: int  # ... and < guide_depth (−1: no upper bound)
    tally: int  # 1: add each surface vertex's next-event contributions to scene.guide.tally (the pilot)
    tally_chunk: int  # the pilot's kernel threads per block of scene.guide.tally (thread // tally_chunk: its block)
    pick_light: int  # one picked light with area (light_pick.py): 0 never, 1 at every vertex, 2 past the first
    tally_pick: int  # 1: tally the light pick's pilot sums in scene.pick_tally (a pilot run)
    rr_threshold: float  # Russian roulette weight window (engine.methods.rr_threshold_rule)
    split_indirect: int  # K ≥ 2: an irradiance sample is one direct estimate + the mean of K indirect paths (kernels.estimators.split_irradiance)
    optics: int  # set by the kernel: the sensor's SensorRec.optics, read at its own vertex (depth 0) only
    optics_x: wp.vec3  # set by the kernel: the sensor's azimuth reference (SensorRec.right), for a head with azimuth columns
