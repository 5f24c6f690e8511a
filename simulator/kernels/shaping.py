"""UsdLuxShapingAPI on the device: cone, focus and IES candela tables.

:func:`shaping_factor` scales a light's emission toward a direction; every
estimator multiplies its sample's value by it and keeps the pdfs of the
unshaped light, so shaping never biases a reading.
"""

import warp as wp

from .lights import LightRec
from .sampling import PI


@wp.func
def ies_candela(l: LightRec, theta_deg: float, phi_deg: float) -> float:
    """Bilinear interpolation of the light's regular (θ, φ) candela table
    (rows θ = 0…180°, columns φ = 0…360°; see
    GoniometricDistribution.regular_table, which puts every measured angle
    on a node, so this equals the distribution's own interpolation)."""
    ft = wp.clamp(theta_deg, 0.0, 180.0) / 180.0 * float(l.map_h - 1)
    fp = wp.clamp(phi_deg, 0.0, 360.0) / 360.0 * float(l.map_w - 1)
    i = wp.clamp(int(wp.floor(ft)), 0, l.map_h - 2)
    j = wp.clamp(int(wp.floor(fp)), 0, l.map_w - 2)
    a = wp.clamp(ft - float(i), 0.0, 1.0)
    b = wp.clamp(fp - float(j), 0.0, 1.0)
    w = l.map_w
    v0 = (1.0 - b) * l.map[i * w + j] + b * l.map[i * w + j + 1]
    v1 = (1.0 - b) * l.map[(i + 1) * w + j] + b * l.map[(i + 1) * w + j + 1]
    return (1.0 - a) * v0 + a * v1


@wp.func
def shaping_factor(l: LightRec, w_out: wp.vec3) -> float:
    """UsdLuxShapingAPI factor of light ``l``'s emission toward the unit
    direction ``w_out`` (from the light to the receiver); 1 for an unshaped
    light. θ is the angle from the light's −Z axis, φ its azimuth from +X
    toward +Y (the IES frame); see :class:`simulator.scene.model.LightShaping`
    for the formula (cone with smoothstep softness, focus with tint, IES
    candela table). Multiplying a sample's value by it keeps every estimator
    unbiased: the pdfs are those of the unshaped light."""
    if l.shaped == 0:
        return 1.0
    cos_t = wp.clamp(-wp.dot(w_out, l.ez), -1.0, 1.0)
    theta = wp.acos(cos_t)
    f = float(1.0)
    if l.ies_scale <= 0.0:  # UsdLux: the cone "does not affect IES profiles"
        cut = l.shaping[0]
        if theta > cut:
            return 0.0
        start = cut * (1.0 - l.shaping[1])
        if l.shaping[1] > 0.0 and cut > start:
            t = wp.clamp((theta - start) / (cut - start), 0.0, 1.0)
            f = 1.0 - t * t * (3.0 - 2.0 * t)
    if l.shaping[2] > 0.0:
        tint = l.shaping[3]
        f = f * (tint + (1.0 - tint) * wp.pow(wp.abs(cos_t), l.shaping[2]))
    if l.ies_scale > 0.0:
        phi = wp.atan2(wp.dot(w_out, l.ey), wp.dot(w_out, l.ex))
        if phi < 0.0:
            phi = phi + 2.0 * PI
        f = f * l.ies_scale * ies_candela(l, wp.degrees(theta), wp.degrees(phi))
    return f
