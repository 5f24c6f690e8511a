"""Writes the synthetic photometric files of tests/data/photometry.

Each is written by the IES LM-63 grammar or the EULUMDAT layout from an
analytic distribution, so the tests know the exact candelas. Run from this
folder: ``python make_files.py``.
"""


import numpy as np


def fmt(vals, per_line=10):
    vals = list(vals)
    return "\n".join(" ".join(f"{v:.6g}" for v in vals[i : i + per_line]) for i in range(0, len(vals), per_line))


def ies(name, version_line, theta, phi, cd, lumens=-1.0, multiplier=1.0, ballast=1.0, bl=1.0, tilt="NONE", keywords=None):
    kw = keywords or {"TEST": "synthetic", "MANUFAC": "probesim tests"}
    head = ([version_line] if version_line else []) + [f"[{k}] {v}" for k, v in kw.items()]
    body = [
        f"TILT={tilt}" if not tilt.startswith("INCLUDE") else "TILT=INCLUDE",
    ]
    if tilt.startswith("INCLUDE"):
        body += tilt.split("\n")[1:]
    body += [
        f"1 {lumens:g} {multiplier:g} {len(theta)} {len(phi)} 1 2 0.1 0.1 0",
        f"{ballast:g} {bl:g} 10",
        fmt(theta),
        fmt(phi),
    ]
    for row in cd:
        body.append(fmt(row))
    with open(name, "w", newline="\r\n" if "crlf" in name else "\n") as f:
        f.write("\n".join(head + body) + "\n")


theta_full = np.arange(0, 181, 5.0)
theta_down = np.arange(0, 91, 5.0)

# 1. LM-63-2002, rotationally symmetric Lambertian downlight I = 1000 cos θ (θ ≤ 90°), absolute
ies("lambert_2002.ies", "IESNA:LM-63-2002", theta_down, [0.0], [1000 * np.cos(np.radians(theta_down))],
    keywords={"TEST": "CIE 171 5.2 source", "MANUFAC": "probesim tests", "LUMCAT": "LAMBERT-1000"})

# 2. LM-63-1995, isotropic 100 cd over the whole sphere, relative (1 lamp, 1256.64 lm), multiplier 0.5 on 200
ies("isotropic_1995.ies", "IESNA:LM-63-1995", theta_full, [0.0], [np.full(len(theta_full), 200.0)], lumens=1256.637, multiplier=0.5)

# 3. LM-63-2019, quadrant symmetry (0–90°): I = 500 cos θ (1 + 0.5 cos 2φ) (θ ≤ 90°)
phi_q = np.arange(0, 91, 15.0)
f_q = lambda t, p: 500 * np.cos(np.radians(t)) * (1 + 0.5 * np.cos(np.radians(2 * p)))
ies("quadrant_2019.ies", "IES:LM-63-2019", theta_down, phi_q, [f_q(theta_down, p) for p in phi_q])

# 4. LM-63-2002, bilateral (0–180°): I = 400 cos θ (1 + 0.5 cos φ) (θ ≤ 90°)
phi_b = np.arange(0, 181, 22.5)
f_b = lambda t, p: 400 * np.cos(np.radians(t)) * (1 + 0.5 * np.cos(np.radians(p)))
ies("bilateral_2002.ies", "IESNA:LM-63-2002", theta_down, phi_b, [f_b(theta_down, p) for p in phi_b])

# 5. LM-63-2002, full (0–360°), asymmetric: I = 300 (1 + 0.5 sin φ) cos θ over θ ≤ 90°, plus an
#    uplight 100 |cos θ| over θ > 90°; ballast factor 0.9; CRLF line ends
phi_f = np.arange(0, 361, 30.0)
f_f = lambda t, p: np.where(t <= 90, 300 * (1 + 0.5 * np.sin(np.radians(p))) * np.cos(np.radians(t)), 100 * np.abs(np.cos(np.radians(t))))
ies("asymmetric_2002_crlf.ies", "IESNA:LM-63-2002", theta_full, phi_f, [f_f(theta_full, p) / 0.9 for p in phi_f], ballast=0.9)

# 6. LM-63-1986 (no version line), bilateral about the 90–270° plane: I = 200 cos θ (1 + 0.5 sin φ)... mirrored: sin(180−φ)=sin φ
phi_b90 = np.arange(90, 271, 30.0)
f_b90 = lambda t, p: 200 * np.cos(np.radians(t)) * (1 + 0.5 * np.sin(np.radians(p)))
ies("bilateral90_1986.ies", None, theta_down, phi_b90, [f_b90(theta_down, p) for p in phi_b90])

# 7. TILT=INCLUDE with trivial factors, and one with real factors (refused)
ies("tilt_trivial.ies", "IESNA:LM-63-2002", theta_down, [0.0], [1000 * np.cos(np.radians(theta_down))], tilt="INCLUDE\n1\n3\n0 45 90\n1 1 1")
ies("tilt_real.ies", "IESNA:LM-63-2002", theta_down, [0.0], [1000 * np.cos(np.radians(theta_down))], tilt="INCLUDE\n1\n3\n0 45 90\n1 0.95 0.9")


def ldt(name, isym, mc, dc, gammas, planes, flux=1000.0, n_lamps=1, cfli=1.0):
    lines = ["probesim tests", "1" if isym == 1 else "3", str(isym), str(mc), f"{dc:g}", str(len(gammas)), f"{gammas[1] - gammas[0]:g}",
             "synthetic", name, "0", name, "2026-01-01",
             "100", "100", "50", "90", "90", "0", "0", "0", "0",
             "100", "100", f"{cfli:g}", "0", "1",
             str(n_lamps), "LED", f"{flux:g}", "3000", "90", "10"]
    lines += ["0.5"] * 10
    lines += [f"{c:g}" for c in np.arange(mc) * dc]
    lines += [f"{g:g}" for g in gammas]
    for row in planes:
        lines += [f"{v:.6g}" for v in row]
    with open(name, "w") as f:
        f.write("\n".join(lines) + "\n")


g = np.arange(0, 181, 5.0)
# the same analytic distribution in cd/klm for lamp flux 2000 lm: I_cd = 2 × value
f_ldt = lambda t, c: np.where(t <= 90, 300 * (1 + 0.5 * np.sin(np.radians(c))) * np.cos(np.radians(t)), 0.0)
f_sym = lambda t, c: np.where(t <= 90, 300 * (1 + 0.25 * np.cos(np.radians(2 * c)) + 0.25 * np.cos(np.radians(c))) * np.cos(np.radians(t)), 0.0)
mc, dc = 24, 15.0
C = np.arange(mc) * dc
ldt("full_isym0.ldt", 0, mc, dc, g, [f_ldt(g, c) / 2 for c in C], flux=2000)
ldt("rot_isym1.ldt", 1, 1, 0, g, [f_ldt(g, 0) * 0 + 500 * np.clip(np.cos(np.radians(g)), 0, None)], flux=1000)
ldt("c0c180_isym2.ldt", 2, mc, dc, g, [f_sym(g, c) / 2 for c in C[: mc // 2 + 1]], flux=2000)
# Isym 3: symmetric about C90–C270: I(c) = I(180 − c); planes C270 … C360/0 … C90
f_s3 = lambda t, c: np.where(t <= 90, 300 * (1 + 0.5 * np.sin(np.radians(c))) * np.cos(np.radians(t)), 0.0)
ldt("c90c270_isym3.ldt", 3, mc, dc, g, [f_s3(g, c) / 2 for c in np.mod(270 + np.arange(mc // 2 + 1) * dc, 360)], flux=2000)
f_s4 = lambda t, c: np.where(t <= 90, 300 * (1 + 0.5 * np.cos(np.radians(2 * c))) * np.cos(np.radians(t)), 0.0)
ldt("quadrant_isym4.ldt", 4, mc, dc, g, [f_s4(g, c) / 2 for c in C[: mc // 4 + 1]], flux=2000)
ldt("absolute_isym1.ldt", 1, 1, 0, g, [400 * np.clip(np.cos(np.radians(g)), 0, None)], flux=1000, n_lamps=-1)
