"""Write the furnished office lit by emissive daylight: ``stages/office_furnished.usda`` and its config.

``python benchmarks/furnished_office.py`` writes the stage and ``configs/office_furnished.toml``
(both bundled; run it again after changing the layout below). The room is a benchmark of the
kind where light sampling is hard and shadows are everywhere: an 8 m × 6 m × 3 m office whose
daylight is a large emitter (8 m × 4 m, 4,000 cd/m², the sky's luminance) 0.3 m outside a 4 m ×
1.6 m window, most of it hidden by the wall; eight emissive diffusers under the ceiling; six desks
and six chairs on legs (so the work plane sees between and under them), a low cabinet and a shelf.
1,518 work-plane sensors at 0.8 m on a 0.16 m grid, none inside furniture.
"""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

W, D, H = 8.0, 6.0, 3.0  # room, metres (x, y, z)
WINDOW = (1.0, 5.0, 0.9, 2.5)  # west wall opening: y0, y1, z0, z1
SKY = (-0.3, -1.0, 7.0, 0.0, 4.0)  # the emitter outside: x, y0, y1, z0, z1
LUMINANCE = 4000.0  # cd/m², window emitter and diffusers
ALBEDO = {"Floor": 0.2, "Wall": 0.5, "Ceiling": 0.8, "Desk": 0.45, "Leg": 0.3, "Chair": 0.15, "Cabinet": 0.35,
          "Shelf": 0.5}  # fmt: skip


def _quad_mesh(name: str, pts, look: str, note: str) -> str:
    p = ", ".join(f"({x:g}, {y:g}, {z:g})" for x, y, z in pts)
    return f'''
        def Mesh "{name}" (
            prepend apiSchemas = ["MaterialBindingAPI"]
        )
        {{
            # {note}
            int[] faceVertexCounts = [{", ".join("4" for _ in range(len(pts) // 4))}]
            int[] faceVertexIndices = [{", ".join(str(i) for i in range(len(pts)))}]
            point3f[] points = [{p}]
            uniform bool doubleSided = 0
            rel material:binding = </Office/Looks/{look}>
        }}
'''


def _cube(name: str, centre, size, look: str, indent: str = "        ") -> str:
    c = ", ".join(f"{v:g}" for v in centre)
    s = ", ".join(f"{v:g}" for v in size)
    return f'''
{indent}def Cube "{name}" (
{indent}    prepend apiSchemas = ["MaterialBindingAPI"]
{indent})
{indent}{{
{indent}    double size = 1
{indent}    double3 xformOp:translate = ({c})
{indent}    float3 xformOp:scale = ({s})
{indent}    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
{indent}    rel material:binding = </Office/Looks/{look}>
{indent}}}
'''


def _room() -> str:
    y0, y1, z0, z1 = WINDOW
    out = _quad_mesh("Floor", [(0, 0, 0), (W, 0, 0), (W, D, 0), (0, D, 0)], "Floor", "z = 0, faces +Z")
    out += _quad_mesh("Ceiling", [(0, 0, H), (0, D, H), (W, D, H), (W, 0, H)], "Ceiling", "z = 3, faces -Z")
    west = [(0, 0, 0), (0, 0, H), (0, y0, H), (0, y0, 0),  # south of the opening
            (0, y1, 0), (0, y1, H), (0, D, H), (0, D, 0),  # north of it
            (0, y0, 0), (0, y0, z0), (0, y1, z0), (0, y1, 0),  # below the sill
            (0, y0, z1), (0, y0, H), (0, y1, H), (0, y1, z1)]  # above the head  # fmt: skip
    out += _quad_mesh("WallWest", west, "Wall", "x = 0, faces +X, around the window opening")
    out += _quad_mesh("WallEast", [(W, 0, 0), (W, D, 0), (W, D, H), (W, 0, H)], "Wall", "x = 8, faces -X")
    out += _quad_mesh("WallSouth", [(0, 0, 0), (W, 0, 0), (W, 0, H), (0, 0, H)][::-1], "Wall", "y = 0, faces +Y")
    out += _quad_mesh("WallNorth", [(0, D, 0), (W, D, 0), (W, D, H), (0, D, H)], "Wall", "y = 6, faces -Y")
    return out


def _furniture() -> str:
    out = []
    k = 0
    for y, facing in ((1.6, -1), (4.2, 1)):
        for x in (2.0, 4.0, 6.0):
            k += 1
            parts = [_cube("Top", (x, y, 0.735), (1.6, 0.8, 0.03), "Desk", "            ")]
            for i, (dx, dy) in enumerate(((-0.75, -0.35), (0.75, -0.35), (0.75, 0.35), (-0.75, 0.35))):
                parts.append(_cube(f"Leg_{i + 1}", (x + dx, y + dy, 0.36), (0.05, 0.05, 0.72), "Leg", "            "))
            out.append(f'\n        def Xform "Desk_{k}"\n        {{{"".join(parts)}        }}\n')
            cy = y + facing * 0.65  # the chair on the aisle side
            parts = [_cube("Seat", (x, cy, 0.455), (0.45, 0.45, 0.05), "Chair", "            ")]
            for i, (dx, dy) in enumerate(((-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2))):
                parts.append(_cube(f"Leg_{i + 1}", (x + dx, cy + dy, 0.215), (0.03, 0.03, 0.43), "Leg", "            "))
            parts.append(_cube("Back", (x, cy + facing * 0.21, 0.63), (0.45, 0.03, 0.3), "Chair", "            "))
            out.append(f'\n        def Xform "Chair_{k}"\n        {{{"".join(parts)}        }}\n')
    out.append(_cube("Cabinet", (7.72, 3.0, 0.35), (0.45, 3.0, 0.7), "Cabinet"))
    out.append(_cube("Shelf", (2.0, 5.78, 0.9), (2.0, 0.35, 1.8), "Shelf"))
    return "".join(out)


def _emitters() -> str:
    x, y0, y1, z0, z1 = SKY
    out = _quad_mesh("Window", [(x, y0, z0), (x, y1, z0), (x, y1, z1), (x, y0, z1)], "Sky",
                     "8 m x 4 m, 0.3 m outside the west wall, wound so that its front (emitting) face is +X")
    pts = []
    for lx in (2.5, 5.5):
        for ly in (0.9, 2.3, 3.7, 5.1):
            a, b = lx - 0.6, lx + 0.6
            c, d = ly - 0.15, ly + 0.15
            pts += [(a, c, 2.95), (a, d, 2.95), (b, d, 2.95), (b, c, 2.95)]
    out += _quad_mesh("Diffusers", pts, "Diffuser", "eight 1.2 m x 0.3 m quads at z = 2.95, front faces down")
    return out


def _look(name: str, grey: float | None = None, emit: float | None = None) -> str:
    body = f"color3f inputs:diffuseColor = ({grey:g}, {grey:g}, {grey:g})" if emit is None else (
        f"color3f inputs:diffuseColor = (0, 0, 0)\n                color3f inputs:emissiveColor = ({emit:g}, {emit:g}, {emit:g})")
    return f'''
        def Material "{name}"
        {{
            token outputs:surface.connect = </Office/Looks/{name}/Surface.outputs:surface>
            def Shader "Surface"
            {{
                uniform token info:id = "UsdPreviewSurface"
                {body}
                token outputs:surface
            }}
        }}
'''


def stage_text() -> str:
    looks = "".join(_look(k, v) for k, v in ALBEDO.items()) + _look("Sky", emit=LUMINANCE) + _look("Diffuser", emit=LUMINANCE)
    return f'''#usda 1.0
# office_furnished.usda: a furnished office lit by emissive daylight (written by benchmarks/furnished_office.py).
(
    doc = """An 8 m (X) x 6 m (Y) x 3 m (Z) office, floor at z = 0, corner at the origin. Its daylight is a
    large emitter: an 8 m x 4 m quad 0.3 m outside the west wall (x = -0.3 m, y -1..7 m, z 0..4 m),
    {LUMINANCE:g} cd/m^2 (a sky's luminance), facing into the room, seen only through a 4 m x 1.6 m
    opening (y 1..5 m, sill 0.9 m, head 2.5 m); eight emissive diffusers (1.2 m x 0.3 m, {LUMINANCE:g} cd/m^2,
    5 cm below the ceiling, facing down) in rows at x = 2.5 and 5.5 m. Six desks (top 1.6 m x 0.8 m at
    0.72..0.75 m on four 5 cm legs) and six chairs (seat at 0.43..0.48 m on four legs, a back up to
    0.78 m), a cabinet (0.7 m high) on the east wall and a shelf (1.8 m) on the north wall.
    Grey Lambertian surfaces: floor 0.2, walls 0.5, ceiling 0.8, desks 0.45, legs 0.3, chairs 0.15,
    cabinet 0.35, shelf 0.5; the emitters reflect nothing. Every wall, floor and ceiling faces into
    the room."""
    metersPerUnit = 1
    upAxis = "Z"
    defaultPrim = "Office"
)

def Xform "Office"
{{
    def Scope "Room"
    {{{_room()}    }}

    def Xform "Furniture"
    {{{_furniture()}    }}

    def Scope "Emitters"
    {{{_emitters()}    }}

    def Scope "Looks"
    {{{looks}    }}
}}
'''


CONFIG = """# Benchmark: a furnished office lit by emissive daylight (stages/office_furnished.usda: a window
# onto a large emitter, eight emissive diffusers, desks and chairs on legs), the room of
# benchmarks/peer_mitsuba.py's second comparison. 1,518 work-plane sensors at 0.8 m on a 0.16 m grid.
#
#   probesim run configs/office_furnished.toml
#   python benchmarks/peer_mitsuba.py configs/office_furnished.toml --replicas 4
stage = "../stages/office_furnished.usda"
light_units = "photometric"

[simulation]
method = "auto"
samples = 256
seed = 1

[[grid]]
name = "workplane"
position = [4.0, 2.84, 0.8]
normal = [0, 0, 1]
size = [7.36, 5.28]
up = [0, 1, 0]
spacing = 0.16

[output]
csv = "../out/office_furnished.csv"
"""


def main() -> None:
    (ROOT / "stages" / "office_furnished.usda").write_text(stage_text())
    (ROOT / "configs" / "office_furnished.toml").write_text(CONFIG)
    print("wrote stages/office_furnished.usda and configs/office_furnished.toml")


if __name__ == "__main__":
    main()
