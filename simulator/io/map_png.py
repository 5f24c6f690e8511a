"""A false-colour map of a grid's readings as PNG bytes, drawn with Pillow.

One picture: the cells as a nearest-neighbour image in the grid's aspect
ratio, axes in metres with round ticks, a colour bar in the reading's unit
and a title of a few lines. Pillow (imported in ~25 ms, drawing in ~50 ms)
instead of matplotlib (~1.5 s to import and draw once), so that writing a
map costs a quick run little.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["nice_ticks", "colour_map", "map_png", "png_bytes"]

#: the viridis colour map at 0, 1/8, …, 1 (sRGB, 0–255), interpolated linearly between
VIRIDIS_9 = np.array([
    (0x44, 0x01, 0x54), (0x47, 0x2D, 0x7B), (0x3B, 0x52, 0x8B), (0x2C, 0x72, 0x8E), (0x21, 0x91, 0x8C),
    (0x28, 0xAE, 0x80), (0x5E, 0xC9, 0x62), (0xAD, 0xDC, 0x30), (0xFD, 0xE7, 0x25),
], dtype=np.float64)  # fmt: skip
#: a cell with no reading
NO_READING_RGB = (200, 200, 200)
#: picture size (px) and margins: title, left (y ticks and label), bottom (x ticks and label), right (colour bar)
SIZE_PX = (640, 480)
MARGINS_PX = {"top": 66, "left": 74, "bottom": 52, "right": 130}
FONT_PX = 13


def nice_ticks(lo: float, hi: float, most: int = 7) -> list[float]:
    """Round tick values within [lo, hi]: steps of 1, 2, 2.5 or 5 × 10^k,
    the finest giving at most ``most`` ticks (``[lo]`` when lo = hi)."""
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= lo:
        return [lo] if math.isfinite(lo) else []
    span = hi - lo
    k = math.floor(math.log10(span / most))
    for base in (1.0, 2.0, 2.5, 5.0, 10.0, 20.0):
        step = base * 10.0**k
        first = math.ceil(lo / step - 1e-9)
        last = math.floor(hi / step + 1e-9)
        if last - first + 1 <= most:
            return [round(i * step, 12) for i in range(first, last + 1)]
    return [lo, hi]


def colour_map(u: np.ndarray) -> np.ndarray:
    """sRGB bytes (…, 3) of the viridis map at u ∈ [0, 1] (clipped); NaN gives
    :data:`NO_READING_RGB`."""
    u = np.asarray(u, np.float64)
    bad = ~np.isfinite(u)
    x = np.clip(np.where(bad, 0.0, u), 0.0, 1.0) * (len(VIRIDIS_9) - 1)
    i = np.minimum(x.astype(np.int64), len(VIRIDIS_9) - 2)
    f = (x - i)[..., None]
    rgb = VIRIDIS_9[i] * (1.0 - f) + VIRIDIS_9[i + 1] * f
    rgb[bad] = NO_READING_RGB
    return np.rint(rgb).astype(np.uint8)


def _fmt(v: float) -> str:
    return f"{v:.4g}"


def map_png(values: np.ndarray, extent_m: tuple[float, float], title_lines: list[str], bar_label: str,
            x_label: str, y_label: str) -> bytes:
    """PNG bytes of a false-colour map.

    Parameters
    ----------
    values : ndarray, shape (ny, nx)
        One value per cell; row 0 is drawn on top; NaN cells grey.
    extent_m : (float, float)
        Width and height the image spans (m), centred on 0 on both axes.
    title_lines : list of str
        Lines of the title, centred above the map.
    bar_label, x_label, y_label : str
        Colour bar label (with its unit) and axis labels.

    Returns
    -------
    bytes
        An 8-bit sRGB PNG of :data:`SIZE_PX`.
    """
    from PIL import Image, ImageDraw, ImageFont

    values = np.asarray(values, np.float64)
    ny, nx = values.shape
    w_m, h_m = (float(extent_m[0]), float(extent_m[1]))
    W, H = SIZE_PX
    m = MARGINS_PX
    font = ImageFont.load_default(size=FONT_PX)
    img = Image.new("RGB", SIZE_PX, "white")
    draw = ImageDraw.Draw(img)
    black = (0, 0, 0)
    # the map: cells as pixels, the grid's aspect ratio kept
    avail_w, avail_h = W - m["left"] - m["right"], H - m["top"] - m["bottom"]
    scale = min(avail_w / w_m, avail_h / h_m) if w_m > 0 and h_m > 0 else 1.0
    pw, ph = max(1, int(round(w_m * scale))), max(1, int(round(h_m * scale)))
    x0 = m["left"] + (avail_w - pw) // 2
    y0 = m["top"] + (avail_h - ph) // 2
    finite = values[np.isfinite(values)]
    lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    span = hi - lo
    u = (values - lo) / span if span > 0 else np.where(np.isfinite(values), 0.5, np.nan)
    cols = np.minimum((np.arange(pw) * nx) // pw, nx - 1)
    rows = np.minimum((np.arange(ph) * ny) // ph, ny - 1)
    img.paste(Image.fromarray(colour_map(u)[rows][:, cols], "RGB"), (x0, y0))
    draw.rectangle((x0 - 1, y0 - 1, x0 + pw, y0 + ph), outline=black)
    # axes: metres from the centre
    for t in nice_ticks(-w_m / 2, w_m / 2):
        x = x0 + (t + w_m / 2) * scale
        draw.line((x, y0 + ph, x, y0 + ph + 4), fill=black)
        draw.text((x, y0 + ph + 6), f"{t:g}", fill=black, font=font, anchor="mt")
    for t in nice_ticks(-h_m / 2, h_m / 2):
        y = y0 + ph - (t + h_m / 2) * scale
        draw.line((x0 - 5, y, x0 - 1, y), fill=black)
        draw.text((x0 - 7, y), f"{t:g}", fill=black, font=font, anchor="rm")
    draw.text((x0 + pw / 2, y0 + ph + 24), x_label, fill=black, font=font, anchor="mt")
    _vertical_text(img, y_label, font, (x0 - 52, y0 + ph / 2))
    # colour bar: lo at the bottom, hi at the top
    bx0, bw = x0 + pw + 24, 18
    ramp = np.linspace(1.0, 0.0, ph)[:, None].repeat(bw, axis=1)
    img.paste(Image.fromarray(colour_map(ramp), "RGB"), (bx0, y0))
    draw.rectangle((bx0 - 1, y0 - 1, bx0 + bw, y0 + ph), outline=black)
    widest = 0.0
    for t in nice_ticks(lo, hi) if span > 0 else [lo]:
        y = y0 + ph - 1 - ((t - lo) / span if span > 0 else 0.5) * (ph - 1)
        draw.line((bx0 + bw, y, bx0 + bw + 4, y), fill=black)
        draw.text((bx0 + bw + 7, y), _fmt(t), fill=black, font=font, anchor="lm")
        widest = max(widest, draw.textlength(_fmt(t), font=font))
    _vertical_text(img, bar_label, font, (bx0 + bw + 7 + widest + 14, y0 + ph / 2))
    # title
    for k, line in enumerate(title_lines):
        draw.text((W / 2, 8 + k * (FONT_PX + 4)), line, fill=black, font=font, anchor="mt")
    return png_bytes(np.asarray(img))


def png_bytes(rgb: np.ndarray, level: int = 3) -> bytes:
    """An 8-bit RGB PNG of ``rgb`` (H, W, 3) uint8, written by Pillow at zlib ``level``.

    Level 3 rather than Pillow's default 6: a map is mostly flat colour, and
    a 640 × 480 map is encoded in ~2.7 ms instead of ~4.2 ms (the warm runs of
    a parametric study write one per run), for a file about 3× the size.
    """
    import io

    from PIL import Image

    out = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(rgb, np.uint8), "RGB").save(out, "PNG", compress_level=level)
    return out.getvalue()


def _vertical_text(img, text: str, font, centre: tuple[float, float]) -> None:
    """Draw ``text`` turned 90° anticlockwise, centred on ``centre`` (px)."""
    from PIL import Image, ImageDraw

    left, top, right, bottom = font.getbbox(text)
    tile = Image.new("RGB", (right - left + 2, bottom - top + 2), "white")
    ImageDraw.Draw(tile).text((1 - left, 1 - top), text, fill=(0, 0, 0), font=font)
    tile = tile.rotate(90, expand=True)
    img.paste(tile, (int(round(centre[0] - tile.width / 2)), int(round(centre[1] - tile.height / 2))))
