"""The UsdPreviewSurface BSDF: each lobe's value, sampler and pdf side by side, as ``@wp.func`` (no kernels).

Directions are in the local shading frame (normal +Z), both pointing away
from the surface: ``wo`` toward the viewer (or the previous vertex), ``wi``
toward the light. Values are grey (luminance) reflectances.

Lobes (UsdPreviewSurface specification; docs/REFERENCES.md §Microfacet BSDF):

- **specular**: Trowbridge–Reitz (GGX) microfacets, α = roughness²,
  D(h) = α²/(π (cos²θ_h (α² − 1) + 1)²), height-correlated Smith
  masking-shadowing G₂ = 1/(1 + Λ(wi) + Λ(wo)), Λ(w) = (√(1 + α² tan²θ) −
  1)/2, and Schlick's Fresnel F = F0 + (F90 − F0)(1 − wi·h)⁵:
  f_s = D G₂ F / (4 cosθ_i cosθ_o). Metallic workflow: F0 = (1 − m)·((1 −
  ior)/(1 + ior))² + m·ρ, F90 = (1 − m) + m·ρ (ρ the diffuseColor); specular
  workflow: F0 = specularColor, F90 = 1.
- **diffuse**: ρ_d/π with ρ_d = (1 − m)·ρ, coupled to the specular lobe by
  (1 − F(cosθ_i))(1 − F(cosθ_o)) (Fresnel at the normal's angle, so the
  product is symmetric): light the specular lobe reflects is not also
  diffused.
- **clearcoat** of weight c: a second GGX lobe (α_c = clearcoatRoughness²,
  F0 = 0.04, the ior 1.5 the specification fixes for it, F90 = 1) over the
  base, which it dims by (1 − c·F_c(cosθ_i))(1 − c·F_c(cosθ_o)).

Every term is symmetric in (wi, wo) (h, G₂ and the Fresnel products are),
so the BSDF is reciprocal. Sampling is one-sample over the lobes with the
probabilities :func:`lobe_weights` (their Fresnel-weighted shares at wo);
the specular lobes draw h ∝ D(h) cosθ_h, so pdf(wi) = D cosθ_h / (4 wo·h);
the diffuse lobe is cosine-weighted. A sampled wi below the horizon is no
sample (its pdf mass is the difference of the integral from 1).

Roughness at or below :data:`DELTA_ROUGHNESS` is a *delta* lobe: a mirror
with reflectance F(cosθ_o), which no sampled direction can meet and no
light sample can find; the kernels flag it like a delta light
(:func:`has_mirror`) and handle it exactly. That holds for either specular
lobe: a clearcoat at or below the limit (its fallback, 0.01, is) is a
mirror of reflectance c·F_c(cosθ_o) over the base, added to the base's own
mirror where that is one too (both reflect about the same normal,
:func:`mirror_reflectance`). In float32 a GGX lobe that narrow cannot be
evaluated (cos²θ_h's rounding, 6·10⁻⁸, is above α² = 10⁻⁸), so it could not
be kept as a lobe: it read as reflecting nothing.
"""

import warp as wp

PI_B = wp.constant(3.14159265358979)
INV_PI_B = wp.constant(0.318309886183791)
#: roughness at or below this is a mirror (α = 1e-4: a lobe 0.01° wide)
DELTA_ROUGHNESS = wp.constant(0.01)
#: the clearcoat's F0: ((1 − 1.5)/(1 + 1.5))²
COAT_F0 = wp.constant(0.04)


@wp.struct
class Bsdf:
    diffuse: float  # ρ_d = (1 − metallic)·ρ
    f0: float  # specular Fresnel at normal incidence
    f90: float  # specular Fresnel at grazing incidence
    alpha: float  # GGX α = roughness² (≤ DELTA_ROUGHNESS²: a mirror)
    coat: float  # clearcoat weight c
    coat_alpha: float  # clearcoat α


@wp.func
def preview_bsdf(rho: float, roughness: float, metallic: float, ior: float, specular: float, workflow: int,
                 coat: float, coat_roughness: float) -> Bsdf:
    """The lobes of UsdPreviewSurface inputs (greys): metallic workflow when ``workflow`` is 0, else the
    specular workflow with F0 = ``specular``."""
    b = Bsdf()
    if workflow != 0:
        b.f0 = specular
        b.f90 = 1.0
        b.diffuse = rho
    else:
        r = (1.0 - ior) / (1.0 + ior)
        b.f0 = (1.0 - metallic) * r * r + metallic * rho
        b.f90 = (1.0 - metallic) + metallic * rho
        b.diffuse = (1.0 - metallic) * rho
    b.alpha = roughness * roughness
    b.coat = coat
    b.coat_alpha = coat_roughness * coat_roughness
    return b


@wp.func
def schlick(f0: float, f90: float, c: float) -> float:
    """Schlick's Fresnel F0 + (F90 − F0)(1 − c)⁵ at cosine c."""
    m = wp.clamp(1.0 - c, 0.0, 1.0)
    m2 = m * m
    return f0 + (f90 - f0) * m2 * m2 * m


@wp.func
def ggx_d(cos_h: float, alpha: float) -> float:
    """Trowbridge–Reitz normal distribution D(h), sr⁻¹ (∫ D cosθ_h dω = 1)."""
    a2 = alpha * alpha
    t = cos_h * cos_h * (a2 - 1.0) + 1.0
    return a2 * INV_PI_B / (t * t)


@wp.func
def ggx_lambda(c: float, alpha: float) -> float:
    """Smith's Λ for GGX at direction cosine c > 0."""
    c2 = c * c
    tan2 = wp.max(0.0, 1.0 - c2) / c2
    return 0.5 * (wp.sqrt(1.0 + alpha * alpha * tan2) - 1.0)


@wp.func
def ggx_g2(ci: float, co: float, alpha: float) -> float:
    """Height-correlated Smith masking-shadowing 1/(1 + Λ(wi) + Λ(wo))."""
    return 1.0 / (1.0 + ggx_lambda(ci, alpha) + ggx_lambda(co, alpha))


@wp.func
def microfacet_f(wi: wp.vec3, wo: wp.vec3, alpha: float, f0: float, f90: float) -> float:
    """One GGX lobe's value D G₂ F / (4 cosθ_i cosθ_o), sr⁻¹; 0 below either horizon."""
    ci = wi[2]
    co = wo[2]
    if ci <= 0.0 or co <= 0.0:
        return 0.0
    h = wp.normalize(wi + wo)
    return ggx_d(h[2], alpha) * ggx_g2(ci, co, alpha) * schlick(f0, f90, wp.dot(wi, h)) / (4.0 * ci * co)


@wp.func
def microfacet_pdf(wi: wp.vec3, wo: wp.vec3, alpha: float) -> float:
    """Solid-angle pdf of :func:`microfacet_sample`: D(h) cosθ_h / (4 wo·h); 0 below the horizon."""
    if wi[2] <= 0.0 or wo[2] <= 0.0:
        return 0.0
    h = wp.normalize(wi + wo)
    return ggx_d(h[2], alpha) * h[2] / (4.0 * wp.max(wp.dot(wo, h), 1.0e-12))


@wp.func
def microfacet_sample(wo: wp.vec3, alpha: float, u: wp.vec2) -> wp.vec3:
    """wi reflected off a microfacet normal drawn ∝ D(h) cosθ_h: tan²θ_h = α² u/(1 − u), φ = 2π u₂
    (may lie below the horizon: no sample)."""
    t2 = alpha * alpha * u[0] / wp.max(1.0 - u[0], 1.0e-12)
    ch = 1.0 / wp.sqrt(1.0 + t2)
    sh = wp.sqrt(wp.max(0.0, 1.0 - ch * ch))
    phi = 2.0 * PI_B * u[1]
    h = wp.vec3(sh * wp.cos(phi), sh * wp.sin(phi), ch)
    return (2.0 * wp.dot(wo, h)) * h - wo


@wp.func
def is_delta_specular(b: Bsdf) -> bool:
    """The specular lobe is a mirror (roughness ≤ DELTA_ROUGHNESS)."""
    return b.alpha <= DELTA_ROUGHNESS * DELTA_ROUGHNESS


@wp.func
def is_delta_coat(b: Bsdf) -> bool:
    """The clearcoat lobe is there and a mirror (clearcoatRoughness ≤ DELTA_ROUGHNESS)."""
    return b.coat > 0.0 and b.coat_alpha <= DELTA_ROUGHNESS * DELTA_ROUGHNESS


@wp.func
def has_mirror(b: Bsdf) -> bool:
    """Either specular lobe is a mirror: the BSDF has a delta part (:func:`mirror_reflectance`)."""
    return is_delta_specular(b) or is_delta_coat(b)


@wp.func
def coat_factor(b: Bsdf, c: float) -> float:
    """What the clearcoat passes to the base at cosine c: 1 − c_w·F_c(c)."""
    return 1.0 - b.coat * schlick(COAT_F0, 1.0, c)


@wp.func
def diffuse_f(b: Bsdf, ci: float, co: float) -> float:
    """The diffuse lobe's value ρ_d/π (1 − F(ci))(1 − F(co)), sr⁻¹."""
    return b.diffuse * INV_PI_B * (1.0 - schlick(b.f0, b.f90, ci)) * (1.0 - schlick(b.f0, b.f90, co))


@wp.func
def bsdf_f(b: Bsdf, wi: wp.vec3, wo: wp.vec3) -> float:
    """The whole BSDF's value less its delta lobes (a mirror base or coat, :func:`mirror_reflectance`),
    sr⁻¹; 0 below either horizon."""
    ci = wi[2]
    co = wo[2]
    if ci <= 0.0 or co <= 0.0:
        return 0.0
    base = diffuse_f(b, ci, co)
    if not is_delta_specular(b):
        base += microfacet_f(wi, wo, b.alpha, b.f0, b.f90)
    f = base
    if b.coat > 0.0:
        f = coat_factor(b, ci) * coat_factor(b, co) * base
        if not is_delta_coat(b):
            f += b.coat * microfacet_f(wi, wo, b.coat_alpha, COAT_F0, 1.0)
    return f


@wp.func
def lobe_weights(b: Bsdf, co: float) -> wp.vec3:
    """Probabilities (coat, specular, diffuse) of the lobe that draws wi, from their Fresnel-weighted
    shares at wo; the share of a delta lobe is 0 (the kernels sample the mirror on their own)."""
    wc = b.coat * schlick(COAT_F0, 1.0, co)
    fs = schlick(b.f0, b.f90, co)
    ws = (1.0 - wc) * fs
    if is_delta_specular(b):
        ws = 0.0
    wd = (1.0 - wc) * (1.0 - fs) * b.diffuse
    if is_delta_coat(b):
        wc = 0.0
    tot = wc + ws + wd
    if tot <= 0.0:
        return wp.vec3(0.0, 0.0, 1.0)
    return wp.vec3(wc / tot, ws / tot, wd / tot)


@wp.func
def bsdf_pdf(b: Bsdf, wi: wp.vec3, wo: wp.vec3) -> float:
    """Solid-angle pdf of :func:`bsdf_sample` at wi (its non-delta part)."""
    if wi[2] <= 0.0 or wo[2] <= 0.0:
        return 0.0
    p = lobe_weights(b, wo[2])
    pdf = p[2] * wi[2] * INV_PI_B
    if p[0] > 0.0:
        pdf += p[0] * microfacet_pdf(wi, wo, b.coat_alpha)
    if p[1] > 0.0:
        pdf += p[1] * microfacet_pdf(wi, wo, b.alpha)
    return pdf


@wp.func
def bsdf_sample(b: Bsdf, wo: wp.vec3, u: wp.vec3) -> wp.vec3:
    """A direction drawn with :func:`bsdf_pdf`: the lobe by u₀ (:func:`lobe_weights`), then within it by
    (u₁, u₂); the result may lie below the horizon (no sample)."""
    p = lobe_weights(b, wo[2])
    v = wp.vec2(u[1], u[2])
    if u[0] < p[0]:
        return microfacet_sample(wo, b.coat_alpha, v)
    if u[0] < p[0] + p[1]:
        return microfacet_sample(wo, b.alpha, v)
    r = wp.sqrt(v[0])
    phi = 2.0 * PI_B * v[1]
    return wp.vec3(r * wp.cos(phi), r * wp.sin(phi), wp.sqrt(wp.max(0.0, 1.0 - v[0])))


@wp.func
def mirror_reflectance(b: Bsdf, co: float) -> float:
    """The delta lobes' reflectance at cosine co: a mirror base's F(co), dimmed by the clearcoat on the
    way in and out, plus a mirror coat's c·F_c(co); 0 without a delta lobe (the other lobes are sampled
    by :func:`bsdf_sample`)."""
    fs = float(0.0)
    if is_delta_specular(b):
        fs = schlick(b.f0, b.f90, co)
        if b.coat > 0.0:
            k = coat_factor(b, co)
            fs = fs * k * k
    if is_delta_coat(b):
        fs += b.coat * schlick(COAT_F0, 1.0, co)
    return fs
