"""The UsdPreviewSurface BSDF in float64 numpy, and its directional albedo by quadrature.

Written from the formulas (docs/REFERENCES.md §Microfacet BSDF), not from
the device code (:mod:`simulator.kernels.bsdf`), so the two check each
other: same closed form, two implementations. Angles are in the local frame
(normal +Z); ``mu`` is a cosine to the normal.
"""

from __future__ import annotations

import numpy as np

__all__ = ["preview_lobes", "bsdf_value", "directional_albedo"]


def preview_lobes(rho: float, roughness: float, metallic: float = 0.0, ior: float = 1.5, specular: float | None = None,
                  coat: float = 0.0, coat_roughness: float = 0.01) -> dict:
    """The lobe parameters of UsdPreviewSurface inputs (greys): metallic workflow, or the specular
    workflow when ``specular`` (its F0) is given."""
    if specular is not None:
        f0, f90, kd = specular, 1.0, rho
    else:
        r0 = ((1.0 - ior) / (1.0 + ior)) ** 2
        f0 = r0 + metallic * (rho - r0)
        f90 = 1.0 + metallic * (rho - 1.0)
        kd = rho * (1.0 - metallic)
    return {"kd": kd, "f0": f0, "f90": f90, "a": roughness ** 2, "coat": coat, "ac": coat_roughness ** 2}


def _fresnel(f0, f90, c):
    return f0 + (f90 - f0) * np.clip(1.0 - c, 0.0, 1.0) ** 5


def _ggx(wi, wo, a, f0, f90):
    """D·G2·F/(4 μi μo) with D = a²/(π((a²−1)μh² + 1)²), G2 = 1/(1 + Λi + Λo)."""
    mi, mo = wi[..., 2], wo[..., 2]
    h = wi + wo
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    mh = h[..., 2]
    d = a * a / (np.pi * ((a * a - 1.0) * mh * mh + 1.0) ** 2)

    def lam(m):
        return 0.5 * (np.sqrt(1.0 + a * a * (1.0 - m * m) / (m * m)) - 1.0)

    g = 1.0 / (1.0 + lam(mi) + lam(mo))
    return d * g * _fresnel(f0, f90, np.sum(wi * h, axis=-1)) / (4.0 * mi * mo)


def bsdf_value(lobes: dict, wi: np.ndarray, wo: np.ndarray) -> np.ndarray:
    """The BSDF (sr⁻¹) for directions (..., 3) in the upper hemisphere (0 elsewhere)."""
    wi = np.asarray(wi, float)
    wo = np.broadcast_to(np.asarray(wo, float), wi.shape)
    mi, mo = wi[..., 2], wo[..., 2]
    ok = (mi > 0) & (mo > 0)
    mi_s, mo_s = np.where(ok, mi, 1.0), np.where(ok, mo, 1.0)
    wi_s = np.where(ok[..., None], wi, [0.0, 0.0, 1.0])
    wo_s = np.where(ok[..., None], wo, [0.0, 0.0, 1.0])
    f0, f90 = lobes["f0"], lobes["f90"]
    base = lobes["kd"] / np.pi * (1 - _fresnel(f0, f90, mi_s)) * (1 - _fresnel(f0, f90, mo_s))
    if lobes["a"] > 1e-4:
        base = base + _ggx(wi_s, wo_s, lobes["a"], f0, f90)
    c = lobes["coat"]
    if c > 0:
        base = ((1 - c * _fresnel(0.04, 1.0, mi_s)) * (1 - c * _fresnel(0.04, 1.0, mo_s)) * base
                + c * _ggx(wi_s, wo_s, lobes["ac"], 0.04, 1.0))
    return np.where(ok, base, 0.0)


def directional_albedo(lobes: dict, mu_o: float, n_mu: int = 512, n_phi: int = 256) -> float:
    """∫ f(wi, wo) cosθ_i dω_i over the hemisphere for wo at cosine ``mu_o`` (φ_o = 0).

    Gauss–Legendre in μ_i on [0, 1] split at the mirror direction's cosine
    (where a glossy lobe peaks), and in φ_i on [0, π] (the integrand is even
    in φ), clustered toward φ = π (the mirror direction, wo being at φ = 0) by a second split.
    """
    so = np.sqrt(max(0.0, 1.0 - mu_o * mu_o))
    wo = np.array([so, 0.0, mu_o])

    def gl(n, a, b):
        x, w = np.polynomial.legendre.leggauss(n)
        return 0.5 * (b - a) * x + 0.5 * (a + b), 0.5 * (b - a) * w

    parts_mu = [gl(n_mu // 2, 0.0, mu_o), gl(n_mu // 2, mu_o, 1.0)]
    mu = np.concatenate([p[0] for p in parts_mu])
    wmu = np.concatenate([p[1] for p in parts_mu])
    parts_phi = [gl(n_phi // 2, 0.0, np.pi - 0.3), gl(n_phi // 2, np.pi - 0.3, np.pi)]
    phi = np.concatenate([p[0] for p in parts_phi])
    wphi = np.concatenate([p[1] for p in parts_phi])
    M, P = np.meshgrid(mu, phi, indexing="ij")
    s = np.sqrt(np.maximum(0.0, 1.0 - M * M))
    wi = np.stack([s * np.cos(P), s * np.sin(P), M], axis=-1)
    f = bsdf_value(lobes, wi, wo)
    return float(2.0 * np.sum(f * M * wmu[:, None] * wphi[None, :]))
