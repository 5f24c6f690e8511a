"""Glossy, metal and glass faces: probesim against Mitsuba 3 on small stages whose models match.

Each scene is a USD stage written here (into a temporary folder) and one
sensor; probesim traces the stage, Mitsuba 3 renders the same scene as
``benchmarks/peer_mitsuba.py`` converts it, with each non-matte face given
the Mitsuba BSDF of the same model:

- a perfect mirror (metallic 1, roughness 0, white) is ``conductor`` with
  ``material='none'`` (reflectance 1);
- a rough metal (metallic 1, roughness r, diffuseColor ρ) is
  ``roughconductor``, ``distribution='ggx'``, α = r², ``material='none'``,
  ``specular_reflectance`` ρ: probesim's Schlick term with metallic 1 has
  F0 = F90 = ρ, a constant, so the Fresnel terms are the same. Mitsuba's
  Smith term is separable, G1(wi)·G1(wo), probesim's height-correlated,
  1/(1 + Λ(wi) + Λ(wo)); for a view along the normal Λ(wo) = 0 and the two
  are the same function, so the rough-metal scenes look along the normal;
- a clear pane (opacity 0, ior 1.5, an open sheet) is ``thindielectric``
  (int_ior 1.5): both sum the slab's inner reflections, Mitsuba on the
  unpolarised Fresnel reflectance r, R = 2r/(1 + r), probesim per
  polarisation, R = ½Σ 2r_s,p/(1 + r_s,p). At normal incidence r_s = r_p and
  they coincide; at 60° the table states the closed-form gap and judges the
  difference after it.

A glossy dielectric (plastic) floor is not compared: Mitsuba's
``plastic``/``roughplastic`` couple the diffuse base to the coat's internal
reflections and ``principled`` uses its own diffuse and sheen model, so the
table would compare models.

Mitsuba's standard error: ``--passes`` independent renders (seeds), the
spread of their means. Verdict: ``ok`` when |difference − model gap| is
within 1% of the value and within 4 combined standard errors.

Needs the optional extra ``peer`` and Dr.Jit's LLVM (see peer_mitsuba.py):

    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
        PYTHONPATH=. python benchmarks/mitsuba_surfaces.py
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from peer_mitsuba import run_mitsuba  # noqa: E402  (the stage → Mitsuba conversion)

L_DOME = 100.0  # cd/m², the uniform sky
L_PANEL = 1000.0  # cd/m², the RectLight
IOR = 1.5


def _usda(body: str) -> str:
    return f'#usda 1.0\n(\n    metersPerUnit = 1\n    upAxis = "Z"\n)\n\n{body}\n'


def _material(name: str, rho: float, extra: str = "") -> str:
    return (f'def Material "{name}"\n{{\n    token outputs:surface.connect = </{name}/S.outputs:surface>\n'
            f'    def Shader "S"\n    {{\n        uniform token info:id = "UsdPreviewSurface"\n'
            f"        color3f inputs:diffuseColor = ({rho}, {rho}, {rho})\n        {extra}\n"
            "        token outputs:surface\n    }\n}\n")  # fmt: skip


def _quad(name: str, z: float, bind: str, half: float = 1e4) -> str:
    h = half
    return (f'def Mesh "{name}"\n{{\n    int[] faceVertexCounts = [4]\n    int[] faceVertexIndices = [0, 1, 2, 3]\n'
            f"    point3f[] points = [(-{h}, -{h}, {z}), ({h}, -{h}, {z}), ({h}, {h}, {z}), (-{h}, {h}, {z})]\n"
            f"    rel material:binding = </{bind}>\n}}\n")  # fmt: skip


DOME = f'def DomeLight "Sky"\n{{\n    float inputs:intensity = {L_DOME}\n}}\n'
# a 4 m × 4 m panel at z = 1.5 facing down (a RectLight emits toward its −Z)
PANEL = (f'def RectLight "Panel"\n{{\n    float inputs:intensity = {L_PANEL}\n    float inputs:width = 4\n'
         '    float inputs:height = 4\n    double3 xformOp:translate = (0, 0, 1.5)\n'
         '    uniform token[] xformOpOrder = ["xformOp:translate"]\n}\n')  # fmt: skip


def _metal(rough: float, rho: float) -> str:
    return _material("Metal", rho, f"float inputs:roughness = {rough}\n        float inputs:metallic = 1")


PANE = _material("Glass", 0.5, f"float inputs:opacity = 0\n        float inputs:ior = {IOR}")


def fresnel_sp(c: float, n: float) -> tuple[float, float]:
    """(r_s, r_p) from air into index n at incidence cosine c (Fresnel's equations)."""
    ct = math.sqrt(1.0 - (1.0 - c * c) / (n * n))
    return ((c - n * ct) / (c + n * ct)) ** 2, ((n * c - ct) / (n * c + ct)) ** 2


def slab_t(c: float, n: float) -> tuple[float, float]:
    """Clear thin slab's transmittance (per polarisation then averaged, on the unpolarised r)."""
    rs, rp = fresnel_sp(c, n)
    r = 0.5 * (rs + rp)
    return 0.5 * ((1 - rs) / (1 + rs) + (1 - rp) / (1 + rp)), (1 - r) / (1 + r)


@dataclass
class Case:
    """One comparison: a stage body, one sensor, budgets, and the expected model gap (Mitsuba/probesim − 1)."""

    name: str
    body: str
    kind: str  # "irradiance" or "radiance"
    position: tuple
    direction: tuple
    samples: int  # probesim samples per sensor
    spp: int  # Mitsuba samples per pass
    gap: float = 0.0
    note: str = ""
    exact: float | None = None  # a closed form of the probesim model, where there is one


def panel_image_irradiance() -> float:
    """lx on the down-facing sensor 0.5 m over the mirror from the panel's image: a 4 m square
    2 m below it, centred (four corner rectangles of the point-to-parallel-rectangle form factor
    F = (1/2π)[A/√(1+A²)·atan(B/√(1+A²)) + B/√(1+B²)·atan(A/√(1+B²))], A = B = 2/2)."""
    a = b = 1.0
    f = (a / math.sqrt(1 + a * a) * math.atan(b / math.sqrt(1 + a * a))
         + b / math.sqrt(1 + b * b) * math.atan(a / math.sqrt(1 + b * b))) / (2 * math.pi)
    return 4 * f * math.pi * L_PANEL


def ggx_albedo(alpha: float, mu_o: float, separable: bool, n: int = 256) -> float:
    """Directional albedo of a white GGX reflector (F = 1) seen at cosine ``mu_o``:
    ∫ D(h)·G(wi, wo)/(4μ_o) dω_i, G separable (1/((1+Λ_i)(1+Λ_o)), Mitsuba's) or height-correlated
    (1/(1+Λ_i+Λ_o), probesim's); Λ(μ) = (√(1 + α²tan²θ) − 1)/2. Gauss–Legendre in μ_i split at
    μ_o and in φ_i on [0, π] split at π/2 (the integrand is even in φ)."""
    x, w = np.polynomial.legendre.leggauss(n)

    def nodes(lo, hi, split):
        a, b = lo + (split - lo) * 0.5 * (x + 1), split + (hi - split) * 0.5 * (x + 1)
        return np.concatenate([a, b]), np.concatenate([0.5 * (split - lo) * w, 0.5 * (hi - split) * w])

    mu, wm = nodes(0.0, 1.0, mu_o)
    ph, wp = nodes(0.0, math.pi, 0.5 * math.pi)
    m, p = np.meshgrid(mu, ph, indexing="ij")
    wi = np.stack([np.sqrt(1 - m * m) * np.cos(p), np.sqrt(1 - m * m) * np.sin(p), m], -1)
    h = wi + np.array([math.sqrt(1 - mu_o * mu_o), 0.0, mu_o])
    c2 = h[..., 2] ** 2 / np.sum(h * h, axis=-1)
    d = alpha * alpha / (math.pi * (c2 * (alpha * alpha - 1) + 1) ** 2)

    def lam(u):
        return 0.5 * (np.sqrt(1 + alpha * alpha * (1 - u * u) / (u * u)) - 1)

    g = 1 / ((1 + lam(m)) * (1 + lam(mu_o))) if separable else 1 / (1 + lam(m) + lam(mu_o))
    return float(np.sum(np.outer(wm, 2 * wp) * d * g / (4 * mu_o)))


def cases(scale: float = 1.0) -> list[Case]:
    """The scenes; ``scale`` multiplies every budget (the test uses a small one)."""
    from simulator.reference.microfacet import directional_albedo, preview_lobes

    s = lambda n: max(16, int(n * scale))  # noqa: E731
    t0, t0_m = slab_t(1.0, IOR)
    c60 = math.cos(math.radians(60.0))
    t60, t60_m = slab_t(c60, IOR)
    down = (0.0, 0.0, -1.0)
    return [
        Case("mirror under a panel", _metal(0.0, 1.0) + _quad("Floor", 0.0, "Metal") + PANEL, "irradiance",
             (0.0, 0.0, 0.5), down, s(1_600_000), s(160_000), 0.0, "conductor, material none", panel_image_irradiance()),
        Case("rough metal r=0.5 under sky", _metal(0.5, 0.9) + _quad("Floor", 0.0, "Metal") + DOME, "radiance",
             (0.0, 0.0, 1.0), down, s(800_000), s(80_000), 0.0, "roughconductor ggx α=0.25, view along the normal",
             L_DOME * directional_albedo(preview_lobes(0.9, 0.5, 1.0), 1.0)),
        Case("rough metal r=0.5 under sky, 60°", _metal(0.5, 0.9) + _quad("Floor", 0.0, "Metal") + DOME, "radiance",
             (0.0, 0.0, 1.0), (0.0, math.sin(math.radians(60.0)), -c60), s(800_000), s(80_000),
             ggx_albedo(0.25, c60, True) / ggx_albedo(0.25, c60, False) - 1.0,
             "roughconductor ggx α=0.25; separable Smith G", L_DOME * directional_albedo(preview_lobes(0.9, 0.5, 1.0), c60)),
        Case("rough metal r=0.3 under panel", _metal(0.3, 0.8) + _quad("Floor", 0.0, "Metal") + PANEL, "radiance",
             (0.0, 0.0, 1.0), down, s(800_000), s(80_000), 0.0, "roughconductor ggx α=0.09, view along the normal"),
        Case("clear pane, normal", PANE + _material("Black", 0.0) + _quad("Pane", 1.0, "Glass")
             + _quad("Floor", 0.0, "Black") + DOME, "radiance", (0.0, 0.0, 0.5), (0.0, 0.0, 1.0),
             s(400_000), s(40_000), t0_m / t0 - 1.0, f"thindielectric; T = {t0:.5f} both", L_DOME * t0),
        Case("clear pane, 60°", PANE + _material("Black", 0.0) + _quad("Pane", 1.0, "Glass")
             + _quad("Floor", 0.0, "Black") + DOME, "radiance", (0.0, 0.0, 0.5),
             (0.0, math.sin(math.radians(60.0)), c60), s(400_000), s(40_000), t60_m / t60 - 1.0,
             f"thindielectric; T {t60:.5f} per polarisation, {t60_m:.5f} unpolarised", L_DOME * t60),
    ]


def mitsuba_bsdf(row, rho: float):
    """The Mitsuba BSDF of a probesim surface row of the same model (None: keep the Lambertian conversion)."""
    if row is None:
        return None
    if row.pane:
        return {"type": "thindielectric", "int_ior": float(row.ior), "ext_ior": 1.0}
    if row.glossy and row.metallic == 1.0:
        refl = {"type": "spectrum", "value": rho}
        if row.roughness == 0.0:
            inner = {"type": "conductor", "material": "none", "specular_reflectance": refl}
        else:
            inner = {"type": "roughconductor", "distribution": "ggx", "alpha": float(row.roughness) ** 2,
                     "material": "none", "specular_reflectance": refl}  # fmt: skip
        return {"type": "twosided", "bsdf": inner}
    raise SystemExit(f"{row.name}: no Mitsuba BSDF of the same model")


def load_case(case: Case, tmp: Path):
    """(scene, [sensor]) of a case, its stage written under ``tmp``."""
    from simulator.scene.model import Sensor, SensorKind
    from simulator.scene.usd import load_stage

    path = tmp / (case.name.replace(" ", "_").replace("=", "").replace("°", "deg") + ".usda")
    path.write_text(_usda(case.body))
    kind = SensorKind.RADIANCE if case.kind == "radiance" else SensorKind.IRRADIANCE
    sensor = Sensor(name="s", kind=kind, position=np.array(case.position, float), normal=np.array(case.direction, float))
    return load_stage(path), [sensor]


def probesim_value(scene, sensors, samples: int, seed: int = 7) -> tuple[float, float]:
    """probesim's (reading, standard error) of the one sensor, photometric (lx or cd/m²), plain paths."""
    from simulator.engine.driver import Engine

    res = Engine(scene, sensors).run("path", samples=samples, seed=seed)
    return float(res.mean[0, 1]), float(res.stderr[0, 1])


def mitsuba_value(scene, sensors, spp: int, passes: int, seed: int = 11) -> tuple[float, float]:
    """Mitsuba's (reading, standard error): the mean of ``passes`` renders at distinct seeds and the
    standard error of that mean from their spread."""
    v = np.array([run_mitsuba(scene, sensors, spp, 0.002, seed + k, mitsuba_bsdf)[0][0] for k in range(passes)])
    return float(v.mean()), float(v.std(ddof=1) / math.sqrt(passes))


def compare(case: Case, tmp: Path, passes: int) -> dict:
    """Both readings of a case, their relative difference, the residual beyond the model gap in
    combined standard errors, the verdict, and each renderer's CPU seconds."""
    scene, sensors = load_case(case, tmp)
    t0 = time.process_time()
    p, pse = probesim_value(scene, sensors, case.samples)
    t1 = time.process_time()
    m, mse = mitsuba_value(scene, sensors, case.spp, passes)
    t2 = time.process_time()
    rel = m / p - 1.0
    resid = m - p * (1.0 + case.gap)  # the difference beyond the stated model gap
    sig = math.hypot(pse * (1.0 + case.gap), mse)
    nsig = abs(resid) / sig if sig > 0 else math.inf
    ok = abs(resid) <= 0.01 * abs(p) and nsig <= 4.0
    return {"case": case, "p": p, "pse": pse, "m": m, "mse": mse, "rel": rel, "nsig": nsig, "ok": ok,
            "cpu_p": t1 - t0, "cpu_m": t2 - t1}  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scale", type=float, default=1.0, help="multiply every sample budget")
    ap.add_argument("--passes", type=int, default=16, help="independent Mitsuba renders per scene")
    a = ap.parse_args()
    import mitsuba as mi

    mi.set_variant("llvm_ad_mono")
    print(f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f} at start")
    print("| scene | sensor | probesim | Mitsuba 3 | Mitsuba/probesim − 1 | model gap | (diff − gap)/σ | verdict "
          "| closed form (probesim model) | Mitsuba model |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    cpu = [0.0, 0.0]
    with tempfile.TemporaryDirectory() as tmp:
        for case in cases(a.scale):
            r = compare(case, Path(tmp), a.passes)
            cpu[0], cpu[1] = cpu[0] + r["cpu_p"], cpu[1] + r["cpu_m"]
            unit = "cd/m²" if case.kind == "radiance" else "lx"
            print(f"| {case.name} | {case.kind} | {r['p']:.4g} ± {r['pse']:.2g} {unit} | {r['m']:.4g} ± {r['mse']:.2g} | "
                  f"{r['rel']:+.3%} | {case.gap:+.3%} | {r['nsig']:.1f} | {'ok' if r['ok'] else 'DIFFERS'} | "
                  f"{'—' if case.exact is None else f'{case.exact:.4g}'} | {case.note} |",
                  flush=True)  # fmt: skip
    print(f"CPU seconds: probesim {cpu[0]:.1f}, Mitsuba {cpu[1]:.1f} (kernel compilation included); "
          f"load {os.getloadavg()[0]:.2f} at end")


if __name__ == "__main__":
    main()
