"""Cross-check of probesim's glare views against Radiance and evalglare on the bundled office.

    python benchmarks/glare_radiance.py [--res 800] [--ab 5] [--ad 2048] [--aa 0.1] [--procs 2]
        [--views window,overcast,luminaires,sun] [--keep DIR]

Needs ``pyradiance`` (``pip install ".[radiance]"``: its wheel ships the
Radiance binaries, evalglare among them); an optional extra, not a test
dependency.

What it does, for each view (an eye, a view direction, up +Z):

1. probesim: a run of one ``kind = "glare"`` sensor (default settings:
   evalglare's default source finding, DGP traced to a standard error of
   0.005) on the office as authored, or on a copy (a USD layer over it)
   with the sun switched off and the sky a CIE overcast sky (a lat-long
   texture of L_z·(1 + 2 sin γ)/3, 4000 cd/m² at the zenith, the ground
   0.2·(7/9)·L_z·… as gensky's) or with sky and sun off (luminaires only).
2. Radiance: the same stage exported (every triangle a polygon of grey
   ``plastic`` of its albedo, each RectLight a ``light`` polygon of its
   luminance facing down, the dome a ``glow`` over the whole sphere, the sun
   a ``light`` source of its own angle), an angular fisheye of the view
   (``vwrays -vta -vh 180 -vv 180`` into ``rtrace``, ``--res`` pixels square)
   and ``rtrace -I`` at the eye for E_v (and for the sun's own illuminance
   at the eye, ``-ab 0`` with the sun alone).
3. evalglare (``-d``, its defaults) on Radiance's picture and on probesim's
   own ``.hdr`` fisheye.
4. Prints, per view: E_v (probesim ± its standard error; Radiance's
   ``rtrace -I``; evalglare on each picture), DGP and UGR (probesim ± its
   standard error; evalglare on Radiance's picture; evalglare on probesim's
   picture), and with the sun in sight the sun's own illuminance at the eye.

Conventions that differ, stated: probesim reads the sun as its disk exactly
(its L²ω from the disk, never from pixels), Radiance's picture samples it at
pixel centres (evalglare then sees a disk of a few pixels, its area within
about a pixel's); probesim's RectLight does not hide the ceiling 5 cm behind
it (its luminance is the lamp's plus what lies behind), Radiance's ``light``
polygon does; Radiance's ambient cache smooths interreflection.
"""

from __future__ import annotations

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

#: the views: (name, eye, direction, lighting) on stages/office.usda
VIEWS = {
    "window": ((4.5, 2.0, 1.2), (-1.0, 0.0, 0.0), "as authored: uniform sky, sun (out of sight), lamps"),
    "overcast": ((4.5, 2.0, 1.2), (-1.0, 0.0, 0.0), "CIE overcast sky, no sun, lamps off"),
    "luminaires": ((3.0, 2.0, 1.2), (1.0, 0.0, 0.0), "lamps only (no sky, no sun)"),
    "luminaires_256": ((3.0, 2.0, 1.2), (1.0, 0.0, 0.0), "lamps only; probesim's map 256 x 256"),
    "sun": ((1.6, 2.6, 1.2), (-1.0, 0.5, 0.0), "as authored: the sun in sight"),
}
#: probesim's half map per view where it is not the default, and the view whose Radiance picture a view shares
RESOLUTION = {"luminaires_256": 256}
SAME_PICTURE = {"luminaires_256": "luminaires"}
#: the CIE overcast sky's zenith luminance, cd/m², and the ground's (gensky -c's ground: 0.2 reflectance
#: of the sky's horizontal illuminance, (7/9)·π·L_z, over π)
ZENITH_CD_M2 = 4000.0
GROUND_CD_M2 = 0.2 * 7.0 / 9.0 * ZENITH_CD_M2


def _radiance():
    try:
        import pyradiance
    except ImportError:
        sys.exit("glare_radiance: needs pyradiance (pip install pyradiance), which ships the Radiance binaries and evalglare")
    binpath = Path(pyradiance.__file__).parent / "bin"
    libpath = Path(pyradiance.__file__).parent / "lib"
    return {**os.environ, "PATH": f"{binpath}{os.pathsep}{os.environ.get('PATH', '')}", "RAYPATH": f".{os.pathsep}{libpath}"}


def overcast_texture(path: Path, width: int = 1024, height: int = 512) -> None:
    """A lat-long EXR of the CIE overcast sky relative to its zenith, for a DomeLight turned so that its
    pole is world +Z: (1 + 2 sin γ)/3 above the horizon, the ground's share below."""
    from simulator.io.exr import write_channels

    lat = (0.5 - (np.arange(height) + 0.5) / height) * math.pi
    rel = np.where(lat > 0, (1.0 + 2.0 * np.sin(lat)) / 3.0, GROUND_CD_M2 / ZENITH_CD_M2)
    img = np.repeat(rel[:, None], width, axis=1).astype(np.float32)
    write_channels(path, {"R": img, "G": img, "B": img})


def wrapper_stage(path: Path, lighting: str) -> None:
    """A layer over the office: the overcast sky (sun off, lamps off), or lamps only."""
    office = (ROOT / "stages" / "office.usda").resolve()
    body = ""
    if lighting.startswith("CIE"):
        body = ('    over "Sky" {\n        asset inputs:texture:file = @overcast.exr@\n'
                f'        float inputs:intensity = {ZENITH_CD_M2}\n'
                '        float3 xformOp:rotateXYZ = (90, 0, 0)\n        uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]\n    }\n'
                '    over "Sun" (active = false) {}\n    over "Lights" (active = false) {}\n')  # fmt: skip
    elif lighting.startswith("lamps"):
        body = '    over "Sky" (active = false) {}\n    over "WindowPortal" (active = false) {}\n    over "Sun" (active = false) {}\n'
    path.write_text(f'#usda 1.0\n(\n    subLayers = [@{office}@]\n    defaultPrim = "Office"\n    metersPerUnit = 1\n'
                    f'    upAxis = "Z"\n)\n\nover "Office"\n{{\n{body}}}\n')  # fmt: skip


def export_rad(scene, lighting: str, path: Path, sun_only: bool = False) -> None:
    """The scene for Radiance (module docstring, step 2); ``sun_only``: the sun and black surfaces."""
    from simulator.scene.model import LightKind

    g = scene.geometry
    pts = np.asarray(g.points, np.float64)
    out, mats = [], {}
    for t, tri in enumerate(np.asarray(g.triangles)):
        rho = 0.0 if sun_only else round(float(g.albedo[t]), 6)
        if rho not in mats:
            mats[rho] = f"grey{len(mats)}"
            out.append(f"void plastic {mats[rho]}\n0\n0\n5 {rho} {rho} {rho} 0 0\n")
        out.append(f"{mats[rho]} polygon t{t}\n0\n0\n9 " + " ".join(f"{x:.9g}" for x in pts[tri].ravel()) + "\n")
    for k, l in enumerate(scene.lights):
        rad = float(l.emission[1]) / 179.0
        if l.kind == LightKind.RECT and not sun_only:
            hx, hy = 0.5 * l.width * l.frame[:, 0], 0.5 * l.height * l.frame[:, 1]
            c = np.asarray(l.position, np.float64)
            quad = [c - hx - hy, c - hx + hy, c + hx + hy, c + hx - hy]  # normal −Z: it faces where it emits
            out.append(f"void light lamp{k}\n0\n0\n3 {rad:.9g} {rad:.9g} {rad:.9g}\n")
            out.append(f"lamp{k} polygon lamp{k}p\n0\n0\n12 " + " ".join(f"{x:.9g}" for p in quad for x in p) + "\n")
        elif l.kind == LightKind.DOME and not sun_only:
            if lighting.startswith("CIE"):
                out.append("void brightfunc skyfunc\n2 skybr sky.cal\n0\n0\n")
                out.append(f"skyfunc glow skyglow\n0\n0\n4 {ZENITH_CD_M2 / 179:.9g} {ZENITH_CD_M2 / 179:.9g} {ZENITH_CD_M2 / 179:.9g} 0\n")
            else:
                out.append(f"void glow skyglow\n0\n0\n4 {rad:.9g} {rad:.9g} {rad:.9g} 0\n")
            out.append("skyglow source skydome\n0\n0\n4 0 0 1 360\n")
        elif l.kind == LightKind.DISTANT and l.half_angle > 0:
            d = l.frame[:, 2]
            out.append(f"void light solar{k}\n0\n0\n3 {rad:.9g} {rad:.9g} {rad:.9g}\n")
            out.append(f"solar{k} source sun{k}\n0\n0\n4 {d[0]:.9g} {d[1]:.9g} {d[2]:.9g} {math.degrees(2 * l.half_angle):.9g}\n")
    path.write_text("".join(out))
    (path.parent / "sky.cal").write_text(f"skybr = if(Dz, (1 + 2*Dz)/3, {GROUND_CD_M2 / ZENITH_CD_M2:.9g});\n")


def view_args(eye, direction) -> list[str]:
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    return ["-vta", "-vp", *map(str, eye), "-vd", *(f"{x:.9g}" for x in d), "-vu", "0", "0", "1", "-vh", "180", "-vv", "180"]


def evalglare(picture: Path, env, view: list[str] | None = None) -> dict:
    """evalglare -d's figures of a picture: E_v, DGP, UGR, the sources' (L, ω, E) rows."""
    cmd = ["evalglare", "-d", *(view or []), str(picture)]
    text = subprocess.run(cmd, env=env, check=True, capture_output=True, text=True).stdout
    out = {"sources": []}
    for line in text.splitlines():
        if line.startswith("dgp,av_lum,E_v"):
            names, values = line.split(":", 1)
            v = dict(zip(names.split(","), map(float, values.split())))
            out.update(ev=v["E_v"], dgp=v["dgp"], ugr=v["ugr"], lb=v["lum_backg"], edir=v["E_v_dir"])
        elif re.match(r"^\d+ \d", line) and len(line.split()) >= 17:
            f = list(map(float, line.split()))
            out["sources"].append({"L": f[4], "omega": f[5], "P": f[6], "E": f[16]})
    return out


def probesim_view(tmp: Path, name: str, eye, direction, lighting: str):
    """A probesim run of the view; returns its glare record and the .hdr fisheye."""
    import json

    import simulator

    stage = tmp / f"{name}.usda"
    wrapper_stage(stage, lighting)
    d = ", ".join(f"{x:g}" for x in direction)
    cfg = tmp / f"{name}.toml"
    res = f"resolution = [{RESOLUTION[name]}, {RESOLUTION[name]}]\n" if name in RESOLUTION else ""
    cfg.write_text(f'stage = "{stage.name}"\n[simulation]\nseed = 3\n[[sensor]]\nname = "{name}"\nkind = "glare"\n'
                   f'position = [{", ".join(map(str, eye))}]\ndirection = [{d}]\n{res}')  # fmt: skip
    t0 = time.process_time()
    out = simulator.run(simulator.load_config(cfg), log=lambda m: None)
    cpu = time.process_time() - t0
    rec = json.loads((tmp / f"{name}.glare.json").read_text())[name]
    return rec, tmp / rec["files"]["hdr"], out.scene, cpu


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--res", type=int, default=400, help="Radiance's fisheye side, pixels")
    ap.add_argument("--ab", type=int, default=4, help="ambient bounces of the picture")
    ap.add_argument("--ad", type=int, default=1024)
    ap.add_argument("--aa", type=float, default=0.1)
    ap.add_argument("--ev-ab", type=int, default=7, help="ambient bounces of rtrace -I's E_v at the eye")
    ap.add_argument("--ev-ad", type=int, default=2048)
    ap.add_argument("--procs", type=int, default=2)
    ap.add_argument("--views", default=",".join(VIEWS))
    ap.add_argument("--keep", help="a folder to keep the pictures in")
    ap.add_argument("--reuse", action="store_true", help="with --keep: Radiance's pictures and E_v already there are read, not made again")
    a = ap.parse_args(argv)
    env = _radiance()
    amb = ["-ab", str(a.ab), "-ad", str(a.ad), "-as", str(a.ad // 4), "-aa", str(a.aa), "-ar", "256", "-lw", "2e-4"]
    amb_ev = ["-ab", str(a.ev_ab), "-ad", str(a.ev_ad), "-as", str(a.ev_ad // 4), "-aa", "0.05", "-ar", "512", "-lw", "1e-5"]
    rows = []
    with tempfile.TemporaryDirectory() as tmpd:
        tmp = Path(a.keep) if a.keep else Path(tmpd)
        tmp.mkdir(parents=True, exist_ok=True)
        overcast_texture(tmp / "overcast.exr")
        for name in a.views.split(","):
            eye, direction, lighting = VIEWS[name]
            rec, hdr, scene, cpu = probesim_view(tmp, name, eye, direction, lighting)
            if name in SAME_PICTURE:  # Radiance's side is another view's
                twin = next(r for r in rows if r[0] == SAME_PICTURE[name])
                rows.append((name, lighting, rec, twin[3], twin[4], twin[5], evalglare(hdr, env), twin[7], cpu, 0.0))
                print(f"{name}: probesim {cpu:.1f} s CPU ({rec['passes']} passes), Radiance's as {SAME_PICTURE[name]}'s", flush=True)
                continue
            export_rad(scene, lighting, tmp / f"{name}.rad")
            with open(tmp / f"{name}.oct", "wb") as fh:
                subprocess.run(["oconv", f"{name}.rad"], cwd=tmp, env=env, check=True, stdout=fh)
            vw = view_args(eye, direction)
            dv = np.asarray(direction, float) / np.linalg.norm(direction)
            point = f"{eye[0]} {eye[1]} {eye[2]} {dv[0]} {dv[1]} {dv[2]}\n"
            t1 = time.perf_counter()
            cache = tmp / f"{name}_radiance.json"
            if a.reuse and cache.is_file() and (tmp / f"{name}_radiance.hdr").is_file():
                import json

                kept = json.loads(cache.read_text())
                eg_rad = evalglare(tmp / f"{name}_radiance.hdr", env, vw)
                eg_rad_i = evalglare(tmp / f"{name}_radiance.hdr", env, vw + ["-i", f"{kept['ev_rt']:.3f}"])
                eg_ps = evalglare(hdr, env)
                rows.append((name, lighting, rec, kept["ev_rt"], eg_rad, eg_rad_i, eg_ps, kept["sun_rt"], cpu, 0.0))
                print(f"{name}: probesim {cpu:.1f} s CPU ({rec['passes']} passes), Radiance's picture and E_v reused", flush=True)
                continue
            irr = subprocess.run(["rtrace", "-h", "-I", "-n", str(a.procs), *amb_ev, f"{name}.oct"], cwd=tmp, env=env, check=True,
                                 input=point, capture_output=True, text=True).stdout.split()  # fmt: skip
            ev_rt = 179.0 * (0.265 * float(irr[0]) + 0.670 * float(irr[1]) + 0.065 * float(irr[2]))
            size = subprocess.run(["vwrays", "-d", "-x", str(a.res), "-y", str(a.res), *vw], env=env, check=True, capture_output=True,
                                  text=True).stdout.split()  # fmt: skip
            rays = subprocess.run(["vwrays", "-ff", "-x", str(a.res), "-y", str(a.res), *vw], env=env, check=True, capture_output=True).stdout
            pic = subprocess.run(["rtrace", "-ffc", "-n", str(a.procs), *size, *amb, f"{name}.oct"], cwd=tmp, env=env, check=True,
                                 input=rays, capture_output=True).stdout  # fmt: skip
            (tmp / f"{name}_radiance.hdr").write_bytes(pic)
            wall = time.perf_counter() - t1
            eg_rad = evalglare(tmp / f"{name}_radiance.hdr", env, vw)
            eg_rad_i = evalglare(tmp / f"{name}_radiance.hdr", env, vw + ["-i", f"{ev_rt:.3f}"])
            eg_ps = evalglare(hdr, env)
            sun_rt = None
            if rec["suns"] and any(s["sun"] for s in rec["sources"]):
                export_rad(scene, lighting, tmp / f"{name}_sun.rad", sun_only=True)
                with open(tmp / f"{name}_sun.oct", "wb") as fh:
                    subprocess.run(["oconv", f"{name}_sun.rad"], cwd=tmp, env=env, check=True, stdout=fh)
                irr = subprocess.run(["rtrace", "-h", "-I", "-ab", "0", "-dj", "0", "-ds", "0", f"{name}_sun.oct"], cwd=tmp, env=env,
                                     check=True, input=point, capture_output=True, text=True).stdout.split()  # fmt: skip
                sun_rt = 179.0 * (0.265 * float(irr[0]) + 0.670 * float(irr[1]) + 0.065 * float(irr[2]))
            rows.append((name, lighting, rec, ev_rt, eg_rad, eg_rad_i, eg_ps, sun_rt, cpu, wall))
            import json

            cache.write_text(json.dumps({"ev_rt": ev_rt, "sun_rt": sun_rt}))
            print(f"{name}: probesim {cpu:.1f} s CPU ({rec['passes']} passes), Radiance {wall:.0f} s wall", flush=True)
    print()
    print("| view | lighting | E_v probesim (lx) | E_v Radiance rtrace -I | E_v evalglare: Radiance / probesim picture | "
          "DGP probesim | DGP evalglare: Radiance with -i E_v / Radiance / probesim picture | UGR probesim | "
          "UGR evalglare: Radiance / probesim picture |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, lighting, rec, ev_rt, eg_rad, eg_rad_i, eg_ps, sun_rt, cpu, wall in rows:
        ugr = f"{rec['ugr']:.2f} ± {rec['ugr_stderr']:.2f}" if rec["ugr"] is not None else "—"
        print(f"| {name} | {lighting} | {rec['ev_lx']:.1f} ± {rec['ev_stderr_lx']:.1f} | {ev_rt:.1f} ({ev_rt / rec['ev_lx'] - 1:+.2%}) | "
              f"{eg_rad['ev']:.1f} / {eg_ps['ev']:.1f} | {rec['dgp']:.4f} ± {rec['dgp_stderr']:.4f} | "
              f"{eg_rad_i['dgp']:.4f} / {eg_rad['dgp']:.4f} / {eg_ps['dgp']:.4f} | {ugr} | {eg_rad['ugr']:.2f} / {eg_ps['ugr']:.2f} |")  # fmt: skip
    for name, lighting, rec, ev_rt, eg_rad, eg_rad_i, eg_ps, sun_rt, cpu, wall in rows:
        if sun_rt is not None:
            e_ps = sum(s["ev_lx"] for s in rec["sources"] if s["sun"])
            print(f"{name}: the sun's own E_v at the eye: probesim {e_ps:.1f} lx, Radiance (rtrace -I, sun alone, black room) "
                  f"{sun_rt:.1f} lx ({e_ps / sun_rt - 1:+.3%})")  # fmt: skip
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
