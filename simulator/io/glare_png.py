"""A glare view's fisheye as a false-colour PNG, its glare sources outlined and numbered (Pillow).

Luminance on a log scale (viridis, the decade ticks on a colour bar), four
decades down from the brightest pixel; outside the 180° circle black. Each
source's pixels get a white outline and its number (as in ``.glare.json``)
at its luminance-weighted centre; the title gives DGP, DGPs, UGR and E_v
with their standard errors.
"""

from __future__ import annotations

import math

import numpy as np

from simulator.io.map_png import FONT_PX, colour_map, png_bytes

__all__ = ["fisheye_png"]

#: the fisheye's side in the picture, px
SIDE_PX = 512
#: decades of luminance the colours span
DECADES = 4.0


def fisheye_png(img: dict, name: str, est) -> bytes:
    """PNG bytes of a fisheye (:func:`simulator.io.glare_maps.fisheye`'s arrays) and its estimate's figures."""
    from PIL import Image, ImageDraw, ImageFont

    lum, inside, source = img["L"], img["inside"], img["source"]
    n = lum.shape[0]
    idx = np.minimum((np.arange(SIDE_PX) * n) // SIDE_PX, n - 1)
    lum_s, inside_s, src_s = lum[idx][:, idx], inside[idx][:, idx], source[idx][:, idx]
    top = float(img.get("L_map_max", lum_s[inside_s].max() if inside_s.any() else 1.0))  # a sun saturates
    top = top if top > 0 else 1.0
    hi = math.log10(top)
    lo = hi - DECADES
    with np.errstate(divide="ignore"):
        u = (np.log10(np.maximum(lum_s, 10.0**lo)) - lo) / DECADES
    rgb = colour_map(u)
    rgb[~inside_s] = 0
    # outlines: a source pixel with a 4-neighbour of another label
    edge = np.zeros_like(src_s, bool)
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        edge |= src_s != np.roll(np.roll(src_s, dy, axis=0), dx, axis=1)
    rgb[edge & (src_s > 0)] = 255
    font = ImageFont.load_default(size=FONT_PX)
    margin_top, margin_right = 70, 110
    canvas = Image.new("RGB", (SIDE_PX + margin_right + 20, SIDE_PX + margin_top + 16), "white")
    canvas.paste(Image.fromarray(rgb, "RGB"), (10, margin_top))
    draw = ImageDraw.Draw(canvas)
    black = (0, 0, 0)
    for k in range(1, int(src_s.max()) + 1 if src_s.size else 1):
        ys, xs = np.nonzero(src_s == k)
        if len(ys):
            w = lum_s[ys, xs]
            cx, cy = float((xs * w).sum() / w.sum()), float((ys * w).sum() / w.sum())
            draw.text((10 + cx, margin_top + cy), str(k), fill=(255, 60, 60), font=font, anchor="mm")
    ugr = f"UGR {est.ugr:.1f} ± {est.ugr_stderr:.2f}" if math.isfinite(est.ugr) else "UGR undefined"
    lines = [f"{name}: DGP {est.dgp:.3f} ± {est.dgp_stderr:.3f}, DGPs {est.dgps:.3f}, {ugr}",
             f"E_v {est.ev_lx:.4g} ± {est.ev_stderr_lx:.2g} lx, {len(est.sources)} glare source(s) above "
             f"{est.threshold_cd_m2:.4g} cd/m2 (outlined)", "180° angular fisheye, luminance (cd/m2, log scale; suns saturate)"]  # fmt: skip
    for k, line in enumerate(lines):
        draw.text((10, 6 + k * (FONT_PX + 6)), line, fill=black, font=font)
    bx0, bw = SIDE_PX + 30, 18
    ramp = np.linspace(1.0, 0.0, SIDE_PX)[:, None].repeat(bw, axis=1)
    canvas.paste(Image.fromarray(colour_map(ramp), "RGB"), (bx0, margin_top))
    draw.rectangle((bx0 - 1, margin_top - 1, bx0 + bw, margin_top + SIDE_PX), outline=black)
    for dec in range(math.ceil(lo), math.floor(hi) + 1):
        y = margin_top + SIDE_PX - 1 - (dec - lo) / DECADES * (SIDE_PX - 1)
        draw.line((bx0 + bw, y, bx0 + bw + 4, y), fill=black)
        draw.text((bx0 + bw + 7, y), f"{10.0 ** dec:g}", fill=black, font=font, anchor="lm")
    return png_bytes(np.asarray(canvas))
