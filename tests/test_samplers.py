"""Samplers against their densities: chi-square goodness of fit, normalisation,
sample/pdf agreement, and the Lambertian reflection the kernels implement.

Each sampling routine of ``simulator/kernels/sampling.py`` and each light
sampler of ``simulator/kernels/lights.py`` is called from a small test
kernel. Samples are binned in a parametrisation where each bin's expected
count is computable exactly: either the map is measure-preserving (uniform
bins), or the expected count is N·∫_bin pdf dω with the *code's* pdf
function integrated over the bin by Gauss–Legendre quadrature (so a pdf that
does not describe its sampler fails, and so does a pdf that does not
integrate to 1: expected counts are never rescaled to N). Bins with an
expected count under 5 are merged with their neighbours. A test fails when
the chi-square p-value is under ``ALPHA`` = 1e-3 (fixed seeds, so each test
is deterministic; for a correct sampler a fresh seed would fail one time in
a thousand).

Light samplers may return "no sample" (pdf 0): e.g. a cylinder's side facing
away from the receiver. Those outcomes form one more bin whose expected
count is N·(1 − ∫ pdf dω).
"""

from __future__ import annotations

import math
import zlib

import numpy as np
import pytest
import warp as wp
from scipy import stats

from simulator.reference import closed_forms as cf
from simulator.engine.device import warp as _warp
from simulator.engine.driver import Engine
from simulator.kernels.lights import SceneRec, pdf_light, sample_light
from simulator.kernels.sampling import (
    frame_x,
    frame_y,
    pdf_cosine_hemisphere,
    pdf_uniform_cone,
    sample_concentric_disk,
    sample_cosine_hemisphere,
    sample_triangle_bary,
    sample_uniform_cone,
    sphrect_sample,
    sphrect_setup,
)
from simulator.scene.model import Geometry, Light, LightKind, Scene, Sensor, SensorKind

wp.set_module_options({"enable_backward": False})

ALPHA = 1e-3
N = 1 << 18
MIN_EXPECTED = 5.0


# --------------------------------------------------------------------------- test kernels


@wp.kernel
def k_concentric_disk(seed: int, out: wp.array(dtype=wp.vec2)):
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    out[i] = sample_concentric_disk(wp.vec2(wp.randf(rng), wp.randf(rng)))


@wp.kernel
def k_cosine_hemisphere(seed: int, out: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float)):
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    d = sample_cosine_hemisphere(wp.vec2(wp.randf(rng), wp.randf(rng)))
    out[i] = d
    pdf[i] = pdf_cosine_hemisphere(d[2])


@wp.kernel
def k_pdf_cosine(cos_theta: wp.array(dtype=float), out: wp.array(dtype=float)):
    i = wp.tid()
    out[i] = pdf_cosine_hemisphere(cos_theta[i])


@wp.kernel
def k_uniform_cone(seed: int, omc: float, out: wp.array(dtype=wp.vec3), pdf: wp.array(dtype=float)):
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    out[i] = sample_uniform_cone(wp.vec2(wp.randf(rng), wp.randf(rng)), omc)
    pdf[i] = pdf_uniform_cone(omc)


@wp.kernel
def k_triangle(seed: int, out: wp.array(dtype=wp.vec2)):
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    out[i] = sample_triangle_bary(wp.vec2(wp.randf(rng), wp.randf(rng)))


@wp.kernel
def k_sphrect(
    seed: int, o: wp.vec3, corner: wp.vec3, ex: wp.vec3, ey: wp.vec3, w: float, h: float,
    out: wp.array(dtype=wp.vec3), solid_angle: wp.array(dtype=float),
):  # fmt: skip
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    r = sphrect_setup(o, corner, ex, ey, w, h)
    out[i] = sphrect_sample(r, wp.vec2(wp.randf(rng), wp.randf(rng)))
    solid_angle[i] = r.solid_angle


@wp.kernel
def k_frames(n: wp.array(dtype=wp.vec3), x: wp.array(dtype=wp.vec3), y: wp.array(dtype=wp.vec3)):
    i = wp.tid()
    x[i] = frame_x(n[i])
    y[i] = frame_y(n[i])


@wp.kernel
def k_sample_light(
    scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3, seed: int,
    wi: wp.array(dtype=wp.vec3), dist: wp.array(dtype=float), pdf: wp.array(dtype=float),
    value: wp.array(dtype=wp.vec2), tri: wp.array(dtype=int), pdf_again: wp.array(dtype=float),
):  # fmt: skip
    i = wp.tid()
    rng = wp.rand_init(seed, i)
    s = sample_light(scene, li, p, n, wp.vec3(wp.randf(rng), wp.randf(rng), wp.randf(rng)))
    wi[i] = s.wi
    dist[i] = s.dist
    pdf[i] = s.pdf
    value[i] = s.value
    tri[i] = s.tri
    pdf_again[i] = pdf_light(scene, li, p, n, s.wi, s.dist, s.tri)


@wp.kernel
def k_pdf_light(
    scene: SceneRec, li: int, p: wp.vec3, n: wp.vec3,
    wi: wp.array(dtype=wp.vec3), t: wp.array(dtype=float), tri: wp.array(dtype=int), out: wp.array(dtype=float),
):  # fmt: skip
    i = wp.tid()
    out[i] = pdf_light(scene, li, p, n, wi[i], t[i], tri[i])


def launch(kernel, n: int, inputs: list, out_dtypes: list) -> list[np.ndarray]:
    _warp()
    outs = [wp.empty(n, dtype=dt, device="cpu") for dt in out_dtypes]
    wp.launch(kernel, dim=n, inputs=inputs, outputs=outs, device="cpu")
    return [o.numpy() for o in outs]


# --------------------------------------------------------------------------- statistics


def chi_square(observed: np.ndarray, expected: np.ndarray) -> tuple[float, int, float]:
    """Pearson's statistic over bins merged (in order) until each expects ≥ 5.

    ``observed`` and ``expected`` are flat arrays over the same bins; their
    totals should both be N (a null bin included where it applies).
    Returns (statistic, degrees of freedom, p-value).
    """
    o_m, e_m = [], []
    o_acc = e_acc = 0.0
    for o, e in zip(observed.astype(float), expected.astype(float)):
        o_acc += o
        e_acc += e
        if e_acc >= MIN_EXPECTED:
            o_m.append(o_acc)
            e_m.append(e_acc)
            o_acc = e_acc = 0.0
    if e_acc > 0 or o_acc > 0:  # leftovers join the last bin
        if e_m:
            o_m[-1] += o_acc
            e_m[-1] += e_acc
        else:
            o_m.append(o_acc)
            e_m.append(e_acc)
    o_m, e_m = np.array(o_m), np.array(e_m)
    if np.any((e_m <= 0) & (o_m > 0)):
        return math.inf, len(e_m) - 1, 0.0
    stat = float(np.sum((o_m - e_m) ** 2 / e_m))
    dof = len(e_m) - 1
    return stat, dof, float(stats.chi2.sf(stat, dof))


def assert_fits(observed, expected, what: str):
    stat, dof, p = chi_square(np.ravel(observed), np.ravel(expected))
    assert p > ALPHA, f"{what}: chi-square {stat:.1f} with {dof} dof, p = {p:.3g} < {ALPHA}"


def gauss_legendre(n: int, a: float, b: float):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (a + b), 0.5 * (b - a) * w


def hemisphere_bins(pdf_of, nmu: int, nphi: int, order: int, z_sign: float = 1.0) -> np.ndarray:
    """Each (μ, φ) bin's ∫ pdf dω over the hemisphere z_sign·z > 0 (μ = z_sign·z in [0, 1] in ``nmu``
    bins, φ in [0, 2π) in ``nphi``), by Gauss–Legendre with ``order`` nodes per bin and axis;
    ``pdf_of`` maps unit directions (M, 3) to their solid-angle densities (M,). Shape (nmu, nphi)."""
    mu_edges = np.linspace(0.0, 1.0, nmu + 1)
    phi_edges = np.linspace(0.0, 2 * np.pi, nphi + 1)
    mus, wmus = zip(*(gauss_legendre(order, a, b) for a, b in zip(mu_edges[:-1], mu_edges[1:])))
    phis, wphis = zip(*(gauss_legendre(order, a, b) for a, b in zip(phi_edges[:-1], phi_edges[1:])))
    mu_n, wmu_n = np.concatenate(mus), np.concatenate(wmus)
    phi_n, wphi_n = np.concatenate(phis), np.concatenate(wphis)
    M, P = np.meshgrid(mu_n, phi_n, indexing="ij")
    r = np.sqrt(1 - M * M)
    dirs = np.stack([r * np.cos(P), r * np.sin(P), z_sign * M], -1).reshape(-1, 3)
    cell = np.asarray(pdf_of(dirs)).reshape(len(mu_n), len(phi_n)) * wmu_n[:, None] * wphi_n[None, :]
    return cell.reshape(nmu, order, nphi, order).sum(axis=(1, 3))


def hist2d(u: np.ndarray, v: np.ndarray, nu: int, nv: int) -> np.ndarray:
    iu = np.clip((u * nu).astype(int), 0, nu - 1)
    iv = np.clip((v * nv).astype(int), 0, nv - 1)
    return np.bincount(iu * nv + iv, minlength=nu * nv).reshape(nu, nv)


def basis(axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Any orthonormal pair (a, b) with (a, b, axis) right-handed (numpy, for binning)."""
    axis = axis / np.linalg.norm(axis)
    helper = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    a = np.cross(helper, axis)
    a /= np.linalg.norm(a)
    return a, np.cross(axis, a)


# --------------------------------------------------------------------------- sampling.py


def test_chi_square_helper_rejects_a_wrong_density():
    """The helper itself: counts drawn from a known multinomial pass; the same
    counts judged against a visibly different density fail."""
    rng = np.random.default_rng(1)
    prob = np.linspace(1.0, 3.0, 50)
    prob /= prob.sum()
    counts = rng.multinomial(N, prob)
    assert chi_square(counts, N * prob)[2] > ALPHA
    flat = np.full(50, N / 50)
    assert chi_square(counts, flat)[2] < 1e-12


def test_concentric_disk_is_uniform_in_area():
    """sample_concentric_disk: uniform on the unit disk (area pdf 1/π), so in
    (r², φ) — an area-preserving parametrisation — every bin expects N/256."""
    (d,) = launch(k_concentric_disk, N, [11], [wp.vec2])
    d = d.astype(np.float64)
    r2 = np.sum(d * d, axis=1)
    assert r2.max() <= 1.0 + 1e-6
    phi = (np.arctan2(d[:, 1], d[:, 0]) / (2 * np.pi)) % 1.0
    assert_fits(hist2d(r2, phi, 16, 16), np.full((16, 16), N / 256), "concentric disk")


def test_cosine_hemisphere_matches_its_pdf():
    """sample_cosine_hemisphere against pdf_cosine_hemisphere = cosθ/π: bins in
    (cosθ, φ) (dω = d(cosθ) dφ) expect N·Δφ·∫ pdf d(cosθ), the pdf integrated
    by 8-point Gauss–Legendre per bin. The returned pdf also integrates to 1."""
    d, pdf = launch(k_cosine_hemisphere, N, [12], [wp.vec3, float])
    d = d.astype(np.float64)
    assert np.all(d[:, 2] >= 0) and np.allclose(np.linalg.norm(d, axis=1), 1.0, atol=1e-6)
    nmu, nphi = 16, 16
    mu_edges = np.linspace(0.0, 1.0, nmu + 1)
    nodes, weights = zip(*(gauss_legendre(8, a, b) for a, b in zip(mu_edges[:-1], mu_edges[1:])))
    nodes, weights = np.concatenate(nodes), np.concatenate(weights)
    (pdf_nodes,) = launch(k_pdf_cosine, len(nodes), [wp.array(nodes.astype(np.float32), dtype=float)], [float])
    per_mu = (pdf_nodes * weights).reshape(nmu, 8).sum(axis=1) * (2 * np.pi / nphi)  # probability per bin
    phi = (np.arctan2(d[:, 1], d[:, 0]) / (2 * np.pi)) % 1.0
    assert_fits(hist2d(d[:, 2], phi, nmu, nphi), N * np.repeat(per_mu[:, None], nphi, axis=1), "cosine hemisphere")
    assert per_mu.sum() * nphi == pytest.approx(1.0, abs=1e-6)
    # the pdf the sampler reports for each sample is cosθ/π
    np.testing.assert_allclose(pdf, d[:, 2] / np.pi, rtol=2e-6, atol=1e-7)


@pytest.mark.parametrize("omc", [1.0, 0.25, 1e-6], ids=["hemisphere", "wide", "tiny"])
def test_uniform_cone_matches_its_pdf(omc):
    """sample_uniform_cone with 1 − cosθmax = omc: uniform in solid angle, so
    bins uniform in (1 − cosθ)/omc and φ expect N·pdf·omc·Δa·Δφ with the
    code's pdf_uniform_cone (= N/256 when pdf = 1/(2π·omc)). The tiny cone
    (θmax ≈ 1.4 mrad, cosθmax = 1 in float32) is binned through sin²θ = x² + y²
    so no precision is lost: 1 − cosθ = sin²θ/(1 + cosθ)."""
    d, pdf = launch(k_uniform_cone, N, [13, float(omc)], [wp.vec3, float])
    d = d.astype(np.float64)
    sin2 = d[:, 0] ** 2 + d[:, 1] ** 2
    a = sin2 / (1.0 + d[:, 2]) / omc
    assert a.max() <= 1.0 + 1e-4
    phi = (np.arctan2(d[:, 1], d[:, 0]) / (2 * np.pi)) % 1.0
    prob = float(pdf[0]) * omc * (1 / 16) * (2 * np.pi / 16)  # ∫ pdf dω over one bin, dω = omc·da·dφ
    assert prob * 256 == pytest.approx(1.0, rel=1e-6)  # the pdf integrates to 1 over the cone
    assert_fits(hist2d(a, phi, 16, 16), np.full((16, 16), N * prob), f"uniform cone omc={omc}")


def test_triangle_barycentrics_are_uniform_in_area():
    """sample_triangle_bary: uniform in area (pdf 1/A). The triangle is cut
    into 16² congruent sub-triangles (midpoint subdivision), each expecting N/256."""
    (b,) = launch(k_triangle, N, [14], [wp.vec2])
    b = b.astype(np.float64)
    assert np.all(b >= -1e-7) and np.all(b.sum(axis=1) <= 1 + 1e-6)
    m = 16
    i = np.clip(np.floor(b[:, 0] * m).astype(int), 0, m - 1)
    j = np.clip(np.floor(b[:, 1] * m).astype(int), 0, m - 1)
    upper = (b[:, 0] * m - i) + (b[:, 1] * m - j) >= 1.0
    upper &= i + j <= m - 2  # rounding on the long edge: count it in the lower cell
    j = np.minimum(j, m - 1 - i)
    idx = (i * m + j) * 2 + upper
    valid = np.zeros(2 * m * m, bool)
    ii, jj = np.meshgrid(np.arange(m), np.arange(m), indexing="ij")
    valid[((ii * m + jj) * 2)[ii + jj <= m - 1]] = True
    valid[((ii * m + jj) * 2 + 1)[ii + jj <= m - 2]] = True
    counts = np.bincount(idx, minlength=2 * m * m)
    assert counts[~valid].sum() == 0 and valid.sum() == m * m
    assert_fits(counts[valid], np.full(m * m, N / (m * m)), "triangle")


RECT_VIEWS = {
    # (viewpoint, rectangle corner, width, height): rectangle in z = 0 spanned by +x, +y
    "centred_1m": ((0.5, 1.0, 1.0), (0, 0, 0), 1.0, 2.0),
    "near_field": ((0.3, 0.4, 0.05), (0, 0, 0), 1.0, 2.0),
    "grazing": ((1.6, 1.0, 0.03), (0, 0, 0), 1.0, 2.0),
    "far": ((0.5, 1.0, 12.0), (0, 0, 0), 1.0, 2.0),
    "behind": ((0.7, 0.2, -0.4), (0, 0, 0), 1.0, 2.0),
}


@pytest.mark.parametrize("view", list(RECT_VIEWS))
def test_spherical_rectangle_is_uniform_in_solid_angle(view):
    """sphrect_setup/sphrect_sample: points on the rectangle whose directions
    are uniform in solid angle, pdf 1/Ω. Ω agrees with Van Oosterom &
    Strackee's closed form (closed_forms.polygon_solid_angle); each of 12×12
    sub-rectangles expects N·Ω_bin/Ω_kernel, Ω_bin from the same closed form.
    Views: centred at 1 m, near field (5 cm), grazing (3 cm above the plane,
    beyond an edge), far (12 m, Ω ≈ 0.014 sr) and from behind (the sampler is
    two-sided)."""
    o, corner, w, h = RECT_VIEWS[view]
    o, corner = np.array(o, float), np.array(corner, float)
    ex, ey = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    q, omega = launch(k_sphrect, N, [15, wp.vec3(*o), wp.vec3(*corner), wp.vec3(*ex), wp.vec3(*ey), w, h], [wp.vec3, float])
    q = q.astype(np.float64)
    verts = np.array([corner, corner + w * ex, corner + w * ex + h * ey, corner + h * ey])
    omega_exact = float(cf.polygon_solid_angle(verts, o))
    assert float(omega[0]) == pytest.approx(omega_exact, rel=2e-4)
    assert np.all(np.abs(q[:, 2]) < 1e-5)  # on the rectangle's plane
    x, y = (q - corner) @ ex / w, (q - corner) @ ey / h
    assert x.min() >= -1e-5 and x.max() <= 1 + 1e-5 and y.min() >= -1e-5 and y.max() <= 1 + 1e-5
    n = 12
    edges_x, edges_y = np.linspace(0, w, n + 1), np.linspace(0, h, n + 1)
    omega_bins = np.array([
        [cf.polygon_solid_angle(np.array([[edges_x[i], edges_y[j], 0], [edges_x[i + 1], edges_y[j], 0],
                                          [edges_x[i + 1], edges_y[j + 1], 0], [edges_x[i], edges_y[j + 1], 0]]) + corner, o)
         for j in range(n)] for i in range(n)
    ])  # fmt: skip
    assert omega_bins.sum() == pytest.approx(omega_exact, rel=1e-9)
    assert_fits(hist2d(x, y, n, n), N * omega_bins / float(omega[0]), f"spherical rectangle ({view})")


def test_frames_are_orthonormal_and_right_handed():
    """frame_x/frame_y (Duff et al. 2017) give (x, y, n) orthonormal and
    right-handed for any unit n, including ±Z and near −Z."""
    rng = np.random.default_rng(2)
    n = rng.normal(size=(1000, 3))
    n = np.vstack([n, [[0, 0, 1], [0, 0, -1], [1e-4, 0, -1], [1, 0, 0]]])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    x, y = launch(k_frames, len(n), [wp.array(n.astype(np.float32), dtype=wp.vec3)], [wp.vec3, wp.vec3])
    x, y = x.astype(np.float64), y.astype(np.float64)
    np.testing.assert_allclose(np.linalg.norm(x, axis=1), 1.0, atol=1e-5)
    np.testing.assert_allclose(np.linalg.norm(y, axis=1), 1.0, atol=1e-5)
    np.testing.assert_allclose(np.sum(x * y, axis=1), 0.0, atol=1e-5)
    np.testing.assert_allclose(np.sum(x * n, axis=1), 0.0, atol=1e-5)
    np.testing.assert_allclose(np.cross(x, y), n, atol=1e-5)


# --------------------------------------------------------------------------- lights.py


def _frame(z) -> np.ndarray:
    z = np.asarray(z, float)
    z = z / np.linalg.norm(z)
    a, b = basis(z)
    return np.column_stack([a, b, z])


def _engine(lights: list[Light], geometry: Geometry | None = None) -> Engine:
    scene = Scene(geometry=geometry or Geometry(), lights=lights, sensors=[], path="<test>")
    dummy = Sensor("s", SensorKind.IRRADIANCE, np.zeros(3), np.array([0.0, 0.0, 1.0]))
    return Engine(scene, [dummy], device="cpu", threads=1)


class SurfaceParam:
    """A light's surface (or a cone of directions) as a map (u, v) ∈ [0, 1]²
    → point / direction, with the Jacobian that turns du dv into dω at p."""

    def __init__(self, to_dirs, to_uv, jac_solid_angle):
        self.to_dirs = to_dirs  # (u, v) -> (wi, t, tri) seen from p
        self.to_uv = to_uv  # (wi, t, tri) of samples -> (u, v, bin offset)
        self.jac = jac_solid_angle  # (u, v) -> |dω / (du dv)|


def _expected_counts(eng: Engine, li: int, p, n, param: SurfaceParam, nu: int, nv: int, order: int = 8, n_parts: int = 1):
    """N·∫_bin pdf_light dω for an nu×nv grid in (u, v), per part (emissive
    triangles), by order×order Gauss–Legendre per bin."""
    xu, wu = np.polynomial.legendre.leggauss(order)
    cells_u = (np.arange(nu)[:, None] + 0.5 * (xu[None, :] + 1)) / nu  # (nu, order)
    cells_v = (np.arange(nv)[:, None] + 0.5 * (xu[None, :] + 1)) / nv
    U = np.broadcast_to(cells_u[:, None, :, None], (nu, nv, order, order)).ravel()
    V = np.broadcast_to(cells_v[None, :, None, :], (nu, nv, order, order)).ravel()
    W = np.broadcast_to((wu[:, None] * wu[None, :])[None, None], (nu, nv, order, order)).ravel() * 0.25 / (nu * nv)
    out = []
    for part in range(n_parts):
        wi, t, tri = param.to_dirs(U, V, part)
        with wp.ScopedDevice("cpu"):
            (pdf,) = launch(
                k_pdf_light, len(U),
                [eng.scene_rec, li, wp.vec3(*p), wp.vec3(*n), wp.array(wi.astype(np.float32), dtype=wp.vec3),
                 wp.array(t.astype(np.float32), dtype=float), wp.array(tri.astype(np.int32), dtype=int)],
                [float],
            )  # fmt: skip
        dens = pdf.astype(np.float64) * param.jac(U, V, part) * W
        out.append(N * dens.reshape(nu, nv, order * order).sum(axis=2))
    return np.stack(out)


def _check_light(eng: Engine, li: int, p, n, param: SurfaceParam, nu: int, nv: int, what: str, n_parts: int = 1,
                 emission=None, integral=1.0, pdf_rtol=None):  # fmt: skip
    """Sample the light, check the sample's pdf equals pdf_light for the same
    direction and its value is L·cos⁺/pdf, and chi-square the directions
    against the quadrature of pdf_light (plus a null bin for 'no sample').
    ``integral``: what ∫ pdf dω over the light should be (1, or less when some
    samples are legitimately empty). ``pdf_rtol(wi, dist)``: per-sample
    relative tolerance of that agreement where pdf_light must reconstruct
    geometry from float32 data (default 2e-5)."""
    p, n = np.asarray(p, float), np.asarray(n, float)
    seed = zlib.crc32(what.encode()) & 0x7FFFFFFF  # a different stream per test
    with wp.ScopedDevice("cpu"):
        wi, dist, pdf, value, tri, pdf_again = launch(
            k_sample_light, N, [eng.scene_rec, li, wp.vec3(*p), wp.vec3(*n), seed], [wp.vec3, float, float, wp.vec2, int, float]
        )
    ok = pdf > 0
    # the pdf a sample reports is the pdf the MIS weights ask for
    rtol = 2e-5 if pdf_rtol is None else pdf_rtol(wi[ok].astype(np.float64), dist[ok].astype(np.float64))
    rel = np.abs(pdf_again[ok].astype(np.float64) / pdf[ok] - 1.0)
    assert np.all(rel <= rtol), f"{what}: sample pdf and pdf_light differ by up to {rel.max():.2e} (relative)"
    if emission is not None:  # value = L·cos⁺θ/pdf (channel 0)
        cos_r = np.maximum(wi[ok].astype(np.float64) @ n, 0.0)
        np.testing.assert_allclose(value[ok, 0], emission * cos_r / pdf[ok], rtol=1e-4, atol=1e-12)
    expected = _expected_counts(eng, li, p, n, param, nu, nv, n_parts=n_parts)
    u, v, part = param.to_uv(wi[ok].astype(np.float64), dist[ok].astype(np.float64), tri[ok])
    counts = np.stack([hist2d(u[part == k], v[part == k], nu, nv) for k in range(n_parts)])
    observed = np.append(counts.ravel(), np.count_nonzero(~ok))
    assert_fits(observed, np.append(expected.ravel(), max(N - expected.sum(), 0.0)), what)
    assert expected.sum() / N == pytest.approx(integral, rel=2e-4, abs=2e-5), f"{what}: ∫ pdf dω = {expected.sum() / N}"
    return ok


def _cone_param(p, axis, omc):
    """Directions in the cone about ``axis`` with 1 − cosθmax = omc: 1 − cosθ =
    u·omc, φ = 2πv, so dω = 2π·omc du dv."""
    a, b = basis(np.asarray(axis, float))
    axis = np.asarray(axis, float) / np.linalg.norm(axis)

    def to_dirs(u, v, part):
        one_minus = u * omc
        cos_t = 1.0 - one_minus
        sin_t = np.sqrt(np.maximum(one_minus * (2.0 - one_minus), 0.0))
        phi = 2 * np.pi * v
        wi = cos_t[:, None] * axis + sin_t[:, None] * (np.cos(phi)[:, None] * a + np.sin(phi)[:, None] * b)
        return wi, np.ones_like(u), np.full(len(u), -1)

    def to_uv(wi, t, tri):
        c = wi @ axis
        s2 = np.sum(np.cross(wi, axis) ** 2, axis=1)
        return s2 / (1.0 + c) / omc, (np.arctan2(wi @ b, wi @ a) / (2 * np.pi)) % 1.0, np.zeros(len(wi), int)

    return SurfaceParam(to_dirs, to_uv, lambda u, v, part: np.full_like(u, 2 * np.pi * omc))


def _surface_param(p, point_fn, normal_fn, area_jac, inverse_fn, tri_of_part=None):
    """A light surface point q(u, v) (on part ``part``: an emissive triangle)
    with its normal and area Jacobian; dω = |cosθ_l|/d² dA."""
    p = np.asarray(p, float)

    def to_dirs(u, v, part):
        q = point_fn(u, v, part)
        d = q - p
        t = np.linalg.norm(d, axis=1)
        return d / t[:, None], t, np.full(len(u), -1 if tri_of_part is None else tri_of_part(part))

    def jac(u, v, part):
        q = point_fn(u, v, part)
        d = q - p
        t2 = np.sum(d * d, axis=1)
        cos_l = np.abs(np.sum(d * normal_fn(u, v, part), axis=1)) / np.sqrt(t2)
        return area_jac(u, v, part) * cos_l / t2

    def to_uv(wi, t, tri):
        return inverse_fn(p + t[:, None] * wi, tri)

    return SurfaceParam(to_dirs, to_uv, jac)


def test_sphere_light_sampler_matches_pdf_light():
    """SphereLight: uniform in the cone the sphere subtends, pdf 1/(2π(1 −
    cosθmax)); bins in the cone's (1 − cosθ, φ), expected from pdf_light.
    Also a small sphere far away (θmax ≈ 0.6 mrad)."""
    for centre, radius, p in [((0.3, -0.2, 2.0), 0.5, (0, 0, 0)), ((0, 0, 30.0), 0.02, (1.0, 0, 0))]:
        centre, p = np.array(centre), np.array(p, float)
        light = Light("s", LightKind.SPHERE, centre, np.eye(3), (10.0, 2000.0), radius=radius)
        eng = _engine([light])
        d = np.linalg.norm(centre - p)
        sin2 = (radius / d) ** 2
        omc = sin2 / (1.0 + math.sqrt(1.0 - sin2))
        n = np.array([0.2, 0.1, 1.0]) / np.linalg.norm([0.2, 0.1, 1.0])
        _check_light(eng, 0, p, n, _cone_param(p, centre - p, omc), 12, 12, f"sphere r={radius}", emission=10.0)


def test_distant_light_cone_sampler_matches_pdf_light():
    """DistantLight with an angle: uniform in its cone about +Z of its frame."""
    half = math.radians(3.0)
    frame = _frame([0.3, 0.0, 1.0])
    light = Light("d", LightKind.DISTANT, np.zeros(3), frame, (5.0, 1000.0), half_angle=half)
    eng = _engine([light])
    omc = 2.0 * math.sin(0.5 * half) ** 2
    p, n = np.zeros(3), np.array([0.0, 0.0, 1.0])
    _check_light(eng, 0, p, n, _cone_param(p, frame[:, 2], omc), 12, 12, "distant cone", emission=5.0)


def test_uniform_dome_sampler_matches_pdf_light():
    """Untextured DomeLight: cosine lobe about the receiver normal, pdf cosθ/π.
    Bins uniform in (sin²θ, φ), where dω = π du dv / cosθ."""
    light = Light("dome", LightKind.DOME, np.zeros(3), np.eye(3), (1.0, 100.0))
    eng = _engine([light])
    n = np.array([0.3, -0.4, 0.8]) / np.linalg.norm([0.3, -0.4, 0.8])
    a, b = basis(n)

    def to_dirs(u, v, part):
        sin_t, cos_t = np.sqrt(u), np.sqrt(1.0 - u)
        phi = 2 * np.pi * v
        return cos_t[:, None] * n + sin_t[:, None] * (np.cos(phi)[:, None] * a + np.sin(phi)[:, None] * b), np.full_like(u, 1e30), np.full(len(u), -1)

    def to_uv(wi, t, tri):
        s2 = np.sum(np.cross(wi, n) ** 2, axis=1)
        return s2, (np.arctan2(wi @ b, wi @ a) / (2 * np.pi)) % 1.0, np.zeros(len(wi), int)

    param = SurfaceParam(to_dirs, to_uv, lambda u, v, part: np.pi / np.sqrt(1.0 - u))

    def pdf_rtol(wi, dist):
        # the sample's pdf uses the local cosθ, pdf_light recomputes dot(wi, n) from
        # the float32 world direction: an absolute error of a few ε32 in cosθ,
        # relative ε32/cosθ in the pdf cosθ/π. 16× headroom.
        return 2e-5 + 16 * 6e-8 / np.maximum(wi @ n, 1e-12)

    _check_light(eng, 0, np.zeros(3), n, param, 12, 12, "uniform dome", emission=1.0, pdf_rtol=pdf_rtol)


RECT_LIGHT_VIEWS = {
    "centred": (0.0, 0.0, 0.0),
    "near_field": (0.2, 0.3, 1.9),
    "grazing": (1.2, 0.2, 1.97),
}


@pytest.mark.parametrize("view", list(RECT_LIGHT_VIEWS))
def test_rect_light_sampler_matches_pdf_light(view):
    """RectLight 1 m × 2 m at z = 2 facing down: spherical-rectangle sampling
    (pdf 1/Ω). Bins on the rectangle, expected N·∫_bin pdf_light·cosθ_l/d² dA."""
    frame = np.eye(3)
    light = Light("r", LightKind.RECT, np.array([0.0, 0.0, 2.0]), frame, (3.0, 600.0), width=1.0, height=2.0)
    _check_rect(light, np.array(RECT_LIGHT_VIEWS[view]), f"rect ({view})")


def test_tiny_rect_light_uses_area_sampling():
    """A 2 cm × 1 cm RectLight at 2 m subtends Ω ≈ 5e-5 sr < 1e-4: the sampler
    switches to uniform area sampling, pdf d²/(A·cosθ_l); same checks."""
    light = Light("r", LightKind.RECT, np.array([0.1, 0.0, 2.0]), np.eye(3), (3.0, 600.0), width=0.02, height=0.01)
    _check_rect(light, np.array([0.5, 0.3, 0.0]), "tiny rect")


def _check_rect(light: Light, p: np.ndarray, what: str):
    eng = _engine([light])
    ex, ey = light.frame[:, 0], light.frame[:, 1]
    corner = light.position - 0.5 * light.width * ex - 0.5 * light.height * ey

    def point(u, v, part):
        return corner + (u * light.width)[:, None] * ex + (v * light.height)[:, None] * ey

    def inverse(q, tri):
        r = q - corner
        return r @ ex / light.width, r @ ey / light.height, np.zeros(len(q), int)

    param = _surface_param(p, point, lambda u, v, part: light.frame[:, 2], lambda u, v, part: light.width * light.height, inverse)
    n = np.array([0.0, 0.0, 1.0])
    _check_light(eng, 0, p, n, param, 10, 10, what, emission=light.emission[0])


def test_disk_light_sampler_matches_pdf_light():
    """DiskLight radius 0.5 m: uniform in area, pdf d²/(A·cosθ_l). Bins in
    (r²/R², φ), area-preserving (dA = πR² du dv)."""
    light = Light("k", LightKind.DISK, np.array([0.0, 0.0, 2.0]), _frame([0.2, 0.0, 1.0]), (2.0, 400.0), radius=0.5)
    eng = _engine([light])
    ex, ey, ez = light.frame.T

    def point(u, v, part):
        r = light.radius * np.sqrt(u)
        phi = 2 * np.pi * v
        return light.position + (r * np.cos(phi))[:, None] * ex + (r * np.sin(phi))[:, None] * ey

    def inverse(q, tri):
        r = q - light.position
        x, y = r @ ex, r @ ey
        return (x * x + y * y) / light.radius**2, (np.arctan2(y, x) / (2 * np.pi)) % 1.0, np.zeros(len(q), int)

    for p in [np.array([0.4, 0.1, 0.0]), np.array([1.2, 0.0, 1.6])]:
        param = _surface_param(p, point, lambda u, v, part: ez, lambda u, v, part: np.pi * light.radius**2, inverse)
        _check_light(eng, 0, p, np.array([0.0, 0.0, 1.0]), param, 10, 12, f"disk from {p}", emission=2.0)


def test_cylinder_light_sampler_matches_pdf_light():
    """CylinderLight (radius 0.1 m, length 1 m along X): uniform in area on the
    side; points facing away from the receiver return no sample. Bins in
    (x along the axis, φ around it), with the φ bins split at the terminator
    (the side faces p where cos(φ − φ0) > r/|p⊥|, independent of x), so no
    bin straddles the pdf's jump to 0: half the bins cover the facing arc,
    half the back, where pdf_light is 0. The null bin expects
    N·(1 − ∫ pdf dω), the chance of drawing a point facing away."""
    light = Light("c", LightKind.CYLINDER, np.array([0.0, 0.0, 1.5]), np.eye(3), (1.0, 100.0), radius=0.1, length=1.0)
    eng = _engine([light])
    ex, ey, ez = np.eye(3)
    p = np.array([0.3, -0.5, 0.2])
    perp = (p - light.position) - ((p - light.position) @ ex) * ex
    phi0 = math.atan2(perp @ ez, perp @ ey)
    half = math.acos(light.radius / np.linalg.norm(perp))  # half-width of the facing arc

    def phi_of(v):
        return np.where(v < 0.5, phi0 - half + 4 * half * v, phi0 + half + (2 * np.pi - 2 * half) * (2 * v - 1))

    def dphi_dv(v):
        return np.where(v < 0.5, 4 * half, 2 * (2 * np.pi - 2 * half))

    def point(u, v, part):
        phi = phi_of(v)
        return light.position + ((u - 0.5) * light.length)[:, None] * ex + light.radius * (np.cos(phi)[:, None] * ey + np.sin(phi)[:, None] * ez)

    def normal(u, v, part):
        phi = phi_of(v)
        return np.cos(phi)[:, None] * ey + np.sin(phi)[:, None] * ez

    def inverse(q, tri):
        r = q - light.position
        dphi = (np.arctan2(r @ ez, r @ ey) - (phi0 - half)) % (2 * np.pi)
        v = np.where(dphi < 2 * half, dphi / (4 * half), 0.5 + (dphi - 2 * half) / (2 * (2 * np.pi - 2 * half)))
        return r @ ex / light.length + 0.5, v, np.zeros(len(q), int)

    param = _surface_param(p, point, normal, lambda u, v, part: light.radius * light.length * dphi_dv(v), inverse)
    # ∫ pdf dω = the chance that a uniform point of the side faces p: 2·half/(2π)
    facing = half / math.pi

    def pdf_rtol(wi, dist):
        # pdf_light finds the surface normal at the float32 point p + t·wi, which
        # is off by ~ε32·(|p| + t); the normal turns by that over the radius, so
        # cosθ_l (and the pdf ∝ 1/cosθ_l) carries a relative error of about
        # ε32·(|p| + t)/(r·cosθ_l): large only at grazing points. 16× headroom.
        q = p + dist[:, None] * wi
        r = q - light.position
        r[:, 0] = 0.0
        cos_l = np.abs(np.sum(wi * r, axis=1)) / np.linalg.norm(r, axis=1)
        return 2e-5 + 16 * 6e-8 * (np.linalg.norm(p) + dist) / (light.radius * cos_l)

    _check_light(eng, 0, p, np.array([0.0, 0.0, 1.0]), param, 8, 24, "cylinder", emission=1.0, integral=facing, pdf_rtol=pdf_rtol)


@pytest.mark.parametrize("piece_m, split_m", [(10.0, 10.0), (0.5, 10.0), (0.5, 0.4)])
def test_emissive_triangles_sampler_matches_pdf_light(monkeypatch, piece_m, split_m):
    """Emissive geometry: a triangle picked ∝ its power (radiance × area ×
    sides), then a uniform point on it; pdf P(tri)·d²/(A·|cosθ_l|). Three
    triangles of different size and radiance, one of them two-sided. Each
    triangle is binned in the square-to-triangle map (b1, b2) = (u1·√u0,
    1 − √u0), which is area-preserving (dA = A du0 du1).
    With pieces of at most 0.5 m each triangle is a piece of its own, picked
    with P(k | c) from the pieces' table of the receiver's cell
    (simulator.engine.piece_table): the pdf is then P(k | c)·d²/(A·|cosθ_l|).
    Cut at 0.4 m, each triangle is m × m elements (patches of it, m = 2 or
    3) grouped into more pieces, an element picked ∝ its power within its
    piece and a point uniform on it: the pdf P(k | c)·P(e | k)·m²·d²/(A·|cosθ_l|)
    then steps from element to element, and the binning, which knows nothing
    of the elements, still meets the code's pdf (the triangles keep their
    indices: the cut is the sampler's, not the geometry's)."""
    from simulator.scene import emitters

    monkeypatch.setattr(emitters, "SPLIT_M", split_m)
    monkeypatch.setattr(emitters, "PIECE_M", piece_m)
    pts = np.array([
        [0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 0.8, 2.0],      # faces down (wound clockwise from above)
        [-1.0, 0.5, 1.5], [-1.0, -0.5, 1.5], [-0.4, 0.0, 2.5],  # tilted
        [0.5, -1.0, 1.0], [0.9, -1.0, 1.0], [0.5, -1.0, 1.6],   # vertical, two-sided
    ])  # fmt: skip
    tris = np.array([[0, 2, 1], [3, 4, 5], [6, 7, 8]], np.int32)
    emission = np.array([[1.0, 100.0], [2.5, 250.0], [0.7, 70.0]])
    geo = Geometry(points=pts, triangles=tris, albedo=np.zeros(3), emission=emission, two_sided=np.array([False, False, True]),
                   prim=np.zeros(3, np.int32), prim_names=["/E"])  # fmt: skip
    eng = _engine([], geometry=geo)
    li = eng.emissive_light
    assert li >= 0
    p = np.array([0.2, 0.1, 0.0])
    tri_pts = pts[tris]
    area = 0.5 * np.linalg.norm(np.cross(tri_pts[:, 1] - tri_pts[:, 0], tri_pts[:, 2] - tri_pts[:, 0]), axis=1)
    ng = np.cross(tri_pts[:, 1] - tri_pts[:, 0], tri_pts[:, 2] - tri_pts[:, 0])
    ng /= np.linalg.norm(ng, axis=1, keepdims=True)

    def point(u, v, part):
        su = np.sqrt(u)
        b1, b2 = v * su, 1.0 - su
        a, b, c = tri_pts[part]
        return a + b1[:, None] * (b - a) + b2[:, None] * (c - a)

    def inverse(q, tri):
        u = np.zeros(len(q))
        v = np.zeros(len(q))
        for k in range(3):
            m = tri == k
            a, b, c = tri_pts[k]
            # solve q − a = b1 (b − a) + b2 (c − a) by least squares (the point is on the plane)
            sol = np.linalg.lstsq(np.column_stack([b - a, c - a]), (q[m] - a).T, rcond=None)[0]
            b1, b2 = sol
            su = np.clip(1.0 - b2, 1e-12, 1.0)
            u[m], v[m] = su * su, b1 / su
        return u, v, tri

    param = _surface_param(p, point, lambda u, v, part: ng[part], lambda u, v, part: area[part], inverse, tri_of_part=lambda part: part)
    assert eng._dev.pieces.n == (1 if piece_m > 1 else 3 if split_m > 1 else eng._dev.pieces.n)
    assert eng._dev.rec.tris.shape[0] == 9  # the stage's three triangles, cut or not
    if split_m < 1:
        assert eng._dev.n_elements > 3 and eng._dev.pieces.n > 3
    if piece_m < 1:  # the receiver's cell has a table: the pick is the cell's
        assert eng.piece_table is not None and eng.piece_table.cell_of(p, [0.0, 0.0, 1.0])[0] >= 0
    _check_light(eng, li, p, np.array([0.0, 0.0, 1.0]), param, 8, 8,
                 f"emissive triangles, pieces of {piece_m} m, cut at {split_m} m", n_parts=3)


# --------------------------------------------------------------------------- Lambertian reflection


def test_cosine_sampling_weight_is_pi():
    """The kernels estimate irradiance from a cosine-weighted direction as
    E ≈ π·L(ω) (``w_dir = weight·π``): that weight is L·cosθ/pdf with the
    sampler's own pdf, so cosθ/pdf_cosine_hemisphere(cosθ) must be π for every
    sample it draws (to float32 precision)."""
    d, pdf = launch(k_cosine_hemisphere, 1 << 16, [31], [wp.vec3, float])
    ok = d[:, 2] > 1e-6
    np.testing.assert_allclose(d[ok, 2].astype(np.float64) / pdf[ok], np.pi, rtol=2e-6)


def _floor_scene(rho: float, toward_light: np.ndarray, view_dirs: np.ndarray, e_normal: float = 1000.0):
    """A grey floor at z = 0 (albedo ρ, the only surface), a delta sun along
    ``toward_light`` with normal illuminance ``e_normal``, and one radiance
    meter (no cone) per view direction ωo, 0.5 m from the origin along ωo,
    looking back at it. The floor is a 3×3 grid of quads whose centre tile
    spans only ±1 m, like stages/dome.usda: the meters see the floor there,
    where float32 intersection is exact enough that a shadow ray leaving the
    floor does not hit the floor again (on a 2 km triangle the rounding of
    the hit distance, ~1e-4 m, exceeds the 1e-5 m ray offset)."""
    xs = np.array([-50.0, -1.0, 1.0, 50.0])
    pts = np.array([[x, y, 0.0] for y in xs for x in xs])
    quads = [(4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4) for j in range(3) for i in range(3)]
    tris = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], np.int32)
    k = len(tris)
    geo = Geometry(points=pts, triangles=tris, albedo=np.full(k, rho), emission=np.zeros((k, 2)),
                   two_sided=np.zeros(k, bool), prim=np.zeros(k, np.int32), prim_names=["/F"])  # fmt: skip
    sun = Light("sun", LightKind.DISTANT, np.zeros(3), _frame(toward_light), (e_normal, e_normal))
    view_dirs = view_dirs / np.linalg.norm(view_dirs, axis=1, keepdims=True)
    sensors = [Sensor(f"m{i}", SensorKind.RADIANCE, 0.5 * d, -d) for i, d in enumerate(view_dirs)]
    return Scene(geometry=geo, lights=[sun], sensors=[], path="<floor>"), sensors


def _measured_brdf(rho, wi, wos):
    """f(ωi, ωo) = L_o / (E⊥·cosθi), as the kernels compute it (method light: the
    delta sun makes every reading exact, zero variance)."""
    wi = wi / np.linalg.norm(wi)
    scene, sensors = _floor_scene(rho, wi, wos)
    res = Engine(scene, sensors, threads=1).run("light", samples=64, seed=1)
    assert np.all(res.stderr[:, 0] == 0)
    return res.mean[:, 0] / (1000.0 * wi[2])


def test_lambert_reflection_is_reciprocal():
    """Helmholtz reciprocity of the reflection the kernels implement: the
    BRDF measured with the sun along ωi and the meter along ωo equals the one
    with the two swapped, f(ωi, ωo) = f(ωo, ωi), for random pairs — and both
    are ρ/π (Lambert) to float32 precision."""
    rng = np.random.default_rng(5)
    rho = 0.6
    a = rng.normal(size=(12, 3))
    b = rng.normal(size=(12, 3))
    a[:, 2], b[:, 2] = np.abs(a[:, 2]) + 0.1, np.abs(b[:, 2]) + 0.1
    a /= np.linalg.norm(a, axis=1, keepdims=True)
    b /= np.linalg.norm(b, axis=1, keepdims=True)
    f_ab = np.array([_measured_brdf(rho, a[k], b[k : k + 1])[0] for k in range(len(a))])
    f_ba = np.array([_measured_brdf(rho, b[k], a[k : k + 1])[0] for k in range(len(a))])
    np.testing.assert_allclose(f_ab, f_ba, rtol=4e-6)
    np.testing.assert_allclose(f_ab, rho / np.pi, rtol=4e-6)


@pytest.mark.parametrize("theta_i_deg", [0.0, 40.0, 75.0])
def test_lambert_reflection_conserves_energy(theta_i_deg):
    """Directional-hemispherical reflectance of the kernels' reflection,
    ∫ f(ωi, ωo) cosθo dωo over the hemisphere, is ρ ≤ 1 for every incidence:
    the measured f is integrated by Gauss–Legendre in cosθo (16 nodes) and
    the midpoint rule in φ (8 directions)."""
    rho = 0.8
    ti = math.radians(theta_i_deg)
    wi = np.array([math.sin(ti), 0.0, math.cos(ti)])
    mu, w_mu = gauss_legendre(16, 0.0, 1.0)
    phi = 2 * np.pi * (np.arange(8) + 0.5) / 8
    MU, PHI = np.meshgrid(mu, phi, indexing="ij")
    s = np.sqrt(1 - MU**2)
    wos = np.stack([s * np.cos(PHI), s * np.sin(PHI), MU], axis=-1).reshape(-1, 3)
    f = _measured_brdf(rho, wi, wos).reshape(MU.shape)
    albedo = float(np.sum(f * MU * w_mu[:, None]) * (2 * np.pi / 8))
    assert albedo == pytest.approx(rho, rel=1e-5)
    assert albedo <= 1.0


@pytest.mark.parametrize("rho", [0.3, 0.8])
def test_path_throughput_in_a_furnace_is_unbiased(rho):
    """Energy balance of the path estimator, Russian roulette included. In a
    closed box whose walls emit L_e and reflect ρ, the radiance is
    L_e·Σ_k ρ^k = L_e/(1 − ρ) (each bounce multiplies the throughput by ρ; the
    kernel's roulette must leave its expectation unchanged), so any receiver
    reads E = π·L_e/(1 − ρ) (closed_forms.furnace_irradiance). A biased
    roulette (e.g. survival ρ without dividing by it) would read π·L_e·(1 + …)
    short of that by far more than 4 standard errors."""
    # unit cube, 12 triangles wound so their normals point inward
    c = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = np.array([t for a, b, cc, d in quads for t in ((a, b, cc), (a, cc, d))], np.int32)
    p = c[tris]
    centre_dir = np.array([0.5, 0.5, 0.5]) - p.mean(axis=1)
    assert np.all(np.sum(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]) * centre_dir, axis=1) > 0)
    le = 1.0
    geo = Geometry(points=c, triangles=tris, albedo=np.full(12, rho), emission=np.tile([le, 2 * le], (12, 1)),
                   two_sided=np.zeros(12, bool), prim=np.zeros(12, np.int32), prim_names=["/Box"])  # fmt: skip
    scene = Scene(geometry=geo, lights=[], sensors=[], path="<furnace>")
    sensors = [Sensor("up", SensorKind.IRRADIANCE, np.array([0.5, 0.5, 0.5]), np.array([0.0, 0.0, 1.0])),
               Sensor("tilted", SensorKind.IRRADIANCE, np.array([0.2, 0.7, 0.4]), np.array([0.6, 0.0, 0.8]))]  # fmt: skip
    res = Engine(scene, sensors).run("path", samples=1 << 15, seed=3)
    truth = float(cf.furnace_irradiance(le, rho))
    for i in range(len(sensors)):
        est, se = res.mean[i, 0], res.stderr[i, 0]
        assert abs(est - truth) <= 4 * se + 2e-6 * truth, f"{sensors[i].name}: {est} vs {truth} ± {se}"
        assert se < 0.01 * truth
