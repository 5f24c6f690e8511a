"""Public assets with glass, translucent opacity and cut-outs, read under a zenith sun of 1000 lx.

The assets are not part of the project: point the script at checkouts of
``ft-lab/sample_usd`` and ``PixarAnimationStudios/OpenUSD``. For each asset a
wrapper stage (written into a temporary folder) sub-layers it, adds a
zero-angle DistantLight of 1000 lx at the zenith (and turns off the asset's
own dome, whose HDR is not at hand), and irradiance sensors or a patch read
what passes:

- ft-lab ``UsdPreviewSurface_opacity.usda``: four spheres (r 0.35 m,
  diffuseColor 0.5, ior 1) of opacity 1, 0.75, 0.5, 0.25 in the default
  ``transparent`` mode; a sensor 5 cm under each centre. The direct light
  through two translucent layers is E(1 − o)²: 0, 62.5, 250, 562.5 lx;
- ft-lab ``OmniPBR_opacity.usda``: the same spheres as OmniPBR cut-outs
  (presence), the same closed form;
- ft-lab ``OmniPBR_opacityThreshold.usda``: a 1 m² leaf whose OmniPBR
  opacity map is the texture's alpha (``opacity_mode`` 0, threshold 0.1); a
  1 m² patch under it collects E·(1 − the share of the leaf's texels at or
  above the threshold) (printed beside it, from the texture);
- OpenUSD ``testUsdImagingGLMaterialXBasic/mxGlass.usda``: spheres of
  MaterialX standard_surface glass and of UsdPreviewSurface glass (opacity
  0), both ior 1.52, read as solids entered once: 2n/(n² + 1) = 918.3 lx
  under each (refraction's bend, which would focus the sun, is not traced).

Run from the repository root:

    PYTHONPATH=. python benchmarks/public_glass_assets.py --ftlab ../sample_usd --openusd ../OpenUSD \\
        [--method light] [--samples 4096]
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

import numpy as np

from simulator.engine.driver import Engine
from simulator.scene.model import Sensor, SensorKind
from simulator.scene.usd import load_stage

E_SUN = 1000.0  # lx

SUN = """
def DistantLight "ProbesimSun"
{
    float inputs:intensity = 1000
    float inputs:angle = 0
    float3 xformOp:rotateXYZ = (%s, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
}
"""


def wrapper(folder: Path, name: str, asset: Path, meters: float, up: str, extra: str = "") -> Path:
    """A stage sub-layering ``asset`` with a zenith sun (a Y-up stage's −Y: rotate X by −90°)."""
    path = folder / f"{name}.usda"
    tilt = -90 if up == "Y" else 0
    path.write_text(f'#usda 1.0\n(\n    metersPerUnit = {meters}\n    upAxis = "{up}"\n'
                    f'    subLayers = [@{asset.resolve()}@]\n)\n{SUN % tilt}{extra}')
    return path


def up_sensor(name: str, x: float, y: float, z: float) -> Sensor:
    return Sensor(name=name, kind=SensorKind.IRRADIANCE, position=np.array([x, y, z]), normal=np.array([0.0, 0.0, 1.0]))


def leaf_share(png: Path, threshold: float) -> float:
    """The share of a texture's texels whose alpha is at or above ``threshold``."""
    from PIL import Image

    alpha = np.asarray(Image.open(png).convert("RGBA"), float)[..., 3] / 255.0
    return float(np.mean(alpha >= threshold))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ftlab", type=Path, required=True, help="a checkout of ft-lab/sample_usd")
    ap.add_argument("--openusd", type=Path, required=True, help="a checkout of PixarAnimationStudios/OpenUSD")
    ap.add_argument("--method", default="light")
    ap.add_argument("--samples", type=int, default=4096)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    mat = a.ftlab / "samples" / "Material"
    glass = a.openusd / "pxr/usdImaging/usdImagingGL/testenv/testUsdImagingGLMaterialXBasic/mxGlass.usda"
    spheres = [up_sensor(f"under opacity {o}", x, 0.0, -0.4) for o, x in ((1, -1.5), (0.75, -0.5), (0.5, 0.5),
                                                                           (0.25, 1.5))]
    sphere_truth = [E_SUN * (1 - o) ** 2 for o in (1, 0.75, 0.5, 0.25)]
    patch = Sensor(name="patch under the leaf (lm)", kind=SensorKind.PATCH, position=np.array([0.0, 0.0, -0.01]),
                   normal=np.array([0.0, 0.0, 1.0]), size=(1.0, 1.0), up=np.array([0.0, 1.0, 0.0]))
    n = 1.52
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        cases = [
            ("ft-lab UsdPreviewSurface_opacity", wrapper(folder, "a", mat / "UsdPreviewSurface/UsdPreviewSurface_opacity.usda",
                                                         0.01, "Y"), spheres, sphere_truth),
            ("ft-lab OmniPBR_opacity", wrapper(folder, "b", mat / "OmniPBR/OmniPBR_opacity.usda", 0.01, "Y"),
             spheres, sphere_truth),
            ("ft-lab OmniPBR_opacityThreshold", wrapper(folder, "c", mat / "OmniPBR/OmniPBR_opacityThreshold.usda",
                                                        0.01, "Y"), [patch],
             [E_SUN * (1 - leaf_share(mat / "textures/leaf_diffuse.png", 0.1))]),
            ("OpenUSD mxGlass", wrapper(folder, "d", glass, 1.0, "Z",
                                        'over "lights"\n{\n    over "DomeLight" (\n        active = false\n    )\n'
                                        '    {\n    }\n}\n'),
             [up_sensor("under standard_surface glass", -1.5, 0.0, -1.1),
              up_sensor("under UsdPreviewSurface glass", 1.5, 0.0, -1.1)], [E_SUN * 2 * n / (n * n + 1)] * 2),
        ]
        print(f"method {a.method}, {a.samples} samples, seed {a.seed}; a zero-angle sun of {E_SUN:g} lx at the zenith")
        for title, stage, sensors, truth in cases:
            res = Engine(load_stage(stage), sensors).run(a.method, samples=a.samples, seed=a.seed)
            print(title)
            for k, s in enumerate(sensors):
                print(f"  {s.name:34s} {res.mean[k, 1]:9.2f} ± {res.stderr[k, 1]:6.2f}   direct closed form {truth[k]:8.2f}")


if __name__ == "__main__":
    main()
