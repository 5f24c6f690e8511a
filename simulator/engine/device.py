"""Warp on one device: import it once, name the device, upload a scene.

Only this package and :mod:`simulator.kernels` import ``warp``, and only
when a run starts (:func:`warp`).
"""

from __future__ import annotations

import contextlib
import os
import re
import sys
from dataclasses import replace as dc_replace

import numpy as np

from simulator.errors import UserError
from simulator.scene import emitters
from simulator.scene.emitters import element_index, emitter_cuts, emitter_pieces, split_emitters
from simulator.scene.model import Scene, Sensor
from simulator.scene.patches import patch_layout, source_rows

__all__ = ["CHECKED_WARP", "warp", "skip_reload_scan", "warp_version", "cuda_available", "resolve_device", "models_surfaces",
           "DeviceScene"]

_wp = None

#: Triangles per BVH leaf of the scene's ``wp.Mesh`` (Warp's default is 1).
#: Measured on the CPU (SAH build; CPU time of path runs, median of 3, a
#: shared 2-core machine): the office (188 triangles) 803 → 759 ns per ray
#: at 2 (934 → 864 in a second run; 4 and 8 slower than 1), the integrating
#: sphere (261,120 triangles) 3,362 → 2,981 ns per ray at 2 (4: slower than
#: 1); its build took 0.2–0.4 s at 1 and at 2, within the noise. Leaf size
#: does not change what a query returns. Shadow rays keep the closest-hit
#: query: ``mesh_query_ray_anyhit`` was 18% faster on random office segments
#: (41% blocked) but returns no face, so first_hit's exact plane test (shadow
#: acne on large triangles, lights flush with a surface) cannot be applied
#: to its hit, and a miss costs both queries the same traversal, so "any-hit
#: first, the exact query on a hit" can only add work.
BVH_LEAF_SIZE = 2


@contextlib.contextmanager
def _stderr_silenced():
    """Silence native writes to fd 2 (Warp's loader notes that no CUDA driver
    exists are noise on a CPU machine; real failures still raise)."""
    sys.stderr.flush()
    saved = os.dup(2)
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


#: LLVM's inlining thresholds for every CPU module: (call site, cold call site). Warp's CPU flags raise
#: them to 9000 and 3000 (LLVM's own: 225 and 45); these lower them to 5000 and 1700 and keep the rest of
#: Warp's flags. Measured on the shared 2-core machine under load (``python benchmarks/compile_flags.py``,
#: docs/DESIGN.md §Kernel modules): the all-matte trace module's object code 275 → 221 kB and clang's CPU
#: time on it 8-16% less, the surface model's 884 → 592 kB and 4-31% less; a run's CPU time on the
#: quickstart, office and glazed office within ±2% of Warp's thresholds (their noise there), the furnace's
#: 16% less. At 3000 the quickstart and glazed office ran 2-4% slower in nearly every alternated pair, at
#: 1000 and below the office 1.4-1.7× slower. Readings are the same bytes at any threshold (no fast-math:
#: each float operation is kept as written, and FMAs are formed per expression by the front end).
INLINE_THRESHOLDS = (5000, 1700)


def cpu_compiler_flags(default: str | None) -> str | None:
    """Warp's CPU compiler flags ``default`` with its inlining thresholds set to :data:`INLINE_THRESHOLDS`
    (a flag string without them, or None, is returned as it is)."""
    if not default:
        return default
    site, cold = INLINE_THRESHOLDS
    flags = re.sub(r"(-mllvm[= ]-inline-threshold=)\d+", rf"\g<1>{site}", default)
    return re.sub(r"(-mllvm[= ]-inline-cold-callsite-threshold=)\d+", rf"\g<1>{cold}", flags)


#: the Warp versions whose internals probesim reaches past the public API were checked against (a module's
#: hash and the bookkeeping its functions' definitions do: :func:`skip_reload_scan`,
#: :mod:`simulator.engine.kernel_hashes`); another Warp is used only through what it documents
CHECKED_WARP = ("1.19.",)

_reload_scan = True  # whether Warp notes the module dependencies of probesim's kernel functions (see skip_reload_scan)
_KERNELS = "simulator.kernels"


def skip_reload_scan() -> None:
    """Spare a process that never imports a kernel module twice (a fresh ``probesim run`` or ``plan``) the
    scan Warp makes of every ``@wp.func`` and kernel as it is defined, for probesim's kernel modules.

    The scan walks the function's syntax tree once more to note which other Warp modules it calls
    into. Warp reads those notes only when a Python module is imported again under a new loader, to
    unload the modules that depend on it (a developer's reload); it does not enter a module's hash,
    its code or its loading. On the all-matte trace variant's functions it is about 0.04 s of a
    run's start (docs/DESIGN.md §Start-up of a small run). Other modules, and probesim's in any
    process that did not ask (a notebook, the API), are scanned as always; so is every module under a
    Warp this was not checked against (:data:`CHECKED_WARP`)."""
    global _reload_scan
    _reload_scan = False
    if _wp is not None:
        _skip_scan(_wp)


def _skip_scan(wp) -> None:
    try:
        from warp._src.context import Module
    except ImportError:
        return
    scan = getattr(Module, "_find_references", None)
    if scan is None or getattr(scan, "skips", None) == _KERNELS or not wp.config.version.startswith(CHECKED_WARP):
        return

    def _find_references(self, adj):
        if self.name == _KERNELS or self.name.startswith(_KERNELS + "."):
            return None
        return scan(self, adj)

    _find_references.skips = _KERNELS
    Module._find_references = _find_references


def warp():
    """The ``warp`` module, imported and initialised once, quietly."""
    global _wp
    if _wp is None:
        import warp as wp

        if not _reload_scan:
            _skip_scan(wp)

        wp.config.quiet = True
        wp.config.log_level = 30  # warnings and errors only: no banner, no per-module load lines
        # Warp builds a precompiled header per process and compiling thread (a temporary folder, never
        # reused), which pays only when one thread compiles several modules; here each compiles one
        # (kernel_modules.load): building it cost 2.7 s of CPU more than parsing the headers (a tiny module)
        wp.config.use_precompiled_headers = False
        # every module with the same flags: LLVM's options are process-wide, so modules compiled at once on
        # two threads (kernel_modules.load) must not ask for different ones
        wp.config.cpu_compiler_flags = cpu_compiler_flags(wp.config.cpu_compiler_flags)
        with _stderr_silenced():
            wp.init()
        _wp = wp
    return _wp


def warp_version() -> str:
    """The Warp version in use (for run records), read from the installed
    package's metadata so that a run that never traces does not import Warp."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("warp-lang")
    except PackageNotFoundError:
        return warp().config.version


def cuda_available() -> bool:
    """Whether Warp finds a CUDA device on this machine."""
    return warp().get_cuda_device_count() > 0


def resolve_device(requested: str) -> str:
    """Warp device name for ``cpu``, ``cuda`` or ``auto`` (CUDA when present)."""
    if requested == "cpu":
        return "cpu"  # without importing Warp: a run read wholly in closed form never needs it
    wp = warp()
    has_cuda = wp.get_cuda_device_count() > 0
    if requested == "auto":
        return "cuda:0" if has_cuda else "cpu"
    if requested == "cuda":
        if not has_cuda:
            raise UserError("--device cuda: no CUDA device is available on this machine (use cpu or auto)")
        return "cuda:0"
    if requested == "cpu":
        return "cpu"
    raise UserError(f"--device: unknown device {requested!r} (expected cpu, cuda or auto)")


def models_surfaces(geometry) -> bool:
    """Whether a stage's geometry needs the surface model (panes, cut-outs, glossy faces): its
    ``SceneRec.surfaces``, which picks the trace variant (``kernels.estimators.trace_for``)."""
    return bool(geometry.has_surfaces and geometry.n_triangles > 0)


class DeviceScene:
    """A scene's geometry, lights and sensors as device records.

    Parameters
    ----------
    scene : Scene
    sensors : list of Sensor
        Sensors read by the estimator kernel (one :class:`SensorRec` each).
    device : str
        A Warp device name (see :func:`resolve_device`).
    pieces : bool
        Emissive triangles in pieces, the large ones cut (:mod:`simulator.scene.emitters`); False:
        the scene's triangles as they are and one piece (each triangle picked ∝ its power), the
        fallback where a pilot finds that the pieces do not pay (``Engine._choose_pieces``).

    Attributes
    ----------
    rec : SceneRec
        What every kernel takes; the arrays it points to are kept alive here.
    sensors : wp.array of SensorRec
    emissive_light : int
        Index of the record standing for all emissive triangles, −1 if none.
    layout : PatchLayout
        The surfaces cut into patches for the guide (:mod:`simulator.scene.patches`).
    """

    def __init__(self, scene: Scene, sensors: list[Sensor], device: str, pieces: bool = True):
        wp = warp()
        from simulator.kernels import estimators as K
        from simulator.kernels import lights as L

        self.device = device
        self._n_sensors = len(sensors)
        self.in_pieces = pieces
        self.layout = patch_layout(scene.geometry.points, scene.geometry.triangles)
        g = scene.geometry
        self._prim = g.prim if len(g.prim) == g.n_triangles else np.zeros(g.n_triangles, np.int32)
        self.guide_rows = 1
        self._light_mask = None
        self._keep: list = []  # device arrays referenced only by pointer from the records
        with wp.ScopedDevice(device):
            self.rec = self._upload_scene(wp, K, L, scene, len(sensors))
            rows = self._upload_optics(wp, sensors)
            recs = [K.sensor_record(s, rows.get(id(s.optics), 0)) for s in sensors]
            self.sensors = wp.array(recs, dtype=K.SensorRec) if recs else wp.zeros(1, dtype=K.SensorRec)

    def _upload_scene(self, wp, K, L, scene: Scene, n_sensors: int):
        g = scene.geometry
        rec = K.SceneRec()
        # Ray origins are pushed off surfaces by 1e-5 × max(1 m, |p|∞) (see
        # kernels.estimators.offset_length): 170× float32 resolution, 10 µm at
        # room scale.
        rec.eps = 1.0e-5
        rec.ray_counts = wp.zeros(1, dtype=wp.int32)
        rec.light_mask = wp.ones(max(1, n_sensors * (len(scene.lights) + 1)), dtype=wp.int32)
        self._upload_hero(wp, rec, None)
        rec.light_group = wp.full(len(scene.lights) + 1, -1, dtype=wp.int32)  # no groups until a run tallies them
        rec.patch_base = wp.full(len(scene.lights) + 1, -1, dtype=wp.int32)  # no dome split into sky patches
        n_rec = len(scene.lights) + 1  # the lights, and room for the emissive record
        rec.pick_factor = wp.ones((1 + n_sensors) * n_rec, dtype=float)
        rec.pick_tally = wp.zeros(1, dtype=wp.vec2)
        rec.n_patch_pick = 0
        rec.patch_pick_factor = wp.ones(1, dtype=float)
        rec.patch_pick_tally = wp.zeros(1, dtype=wp.vec3)
        n_tri = g.n_triangles
        pts = g.points.astype(np.float32) if n_tri else np.zeros((3, 3), np.float32)
        tris = g.triangles.astype(np.int32) if n_tri else np.array([[0, 1, 2]], np.int32)
        points = wp.array(pts, dtype=wp.vec3)
        tri_ids = wp.array(tris.reshape(-1), dtype=wp.int32)
        mesh = wp.Mesh(points=points, indices=tri_ids, bvh_leaf_size=BVH_LEAF_SIZE) if n_tri else None
        rec.mesh = mesh.id if n_tri else wp.uint64(0)
        rec.has_mesh = 1 if n_tri else 0
        rec.points = points
        rec.tris = tri_ids

        def arr(a, dtype):
            return wp.array(a, dtype=dtype) if len(a) else wp.zeros(1, dtype=dtype)

        albedo = g.albedo.astype(np.float32) if n_tri else np.zeros(1, np.float32)
        emission = g.emission.astype(np.float32) if n_tri else np.zeros((1, 2), np.float32)
        two_sided = g.two_sided.astype(np.int32) if n_tri else np.zeros(1, np.int32)
        rec.albedo = arr(albedo, float)
        rec.emission = arr(emission, wp.vec2)
        rec.two_sided = arr(two_sided, wp.int32)
        self._upload_surfaces(wp, K, rec, g, scene.lights)

        # Emissive triangles in pieces (simulator.scene.emitters): a piece is picked (by its cell's table,
        # engine.piece_table, or its estimate × learned factor), then an element of it ∝ its emitted power
        # (radiance × area × sides), the best choice when all are visible. An element is a sub-triangle of
        # an emitting triangle cut m × m (a patch of it, simulator.scene.patches: the device keeps the
        # stage's triangles, so the cut adds nothing to the hierarchy rays traverse), or the triangle (m = 1).
        lights = [L.light_record(l, self._keep) for l in scene.lights]
        self.emissive_light = -1
        cap = emitters.MAX_PIECES if self.in_pieces else 1
        m = emitter_cuts(g, emitters.SPLIT_M) if n_tri and self.in_pieces else np.ones(n_tri, np.int64)
        split, orig = split_emitters(g, emitters.SPLIT_M) if (m > 1).any() else (g, np.arange(n_tri))
        pieces = emitter_pieces(split, emitters.PIECE_M, cap) if n_tri else None
        self.pieces = pieces
        emitting = np.flatnonzero(np.any(g.emission > 0, axis=1)) if n_tri else np.zeros(0, np.int64)
        base = np.full(n_tri, -1, np.int64)
        base[emitting] = np.cumsum(m[emitting] ** 2) - m[emitting] ** 2
        n_elem = int((m[emitting] ** 2).sum())
        prob = np.zeros(n_elem, np.float64)
        piece_of = np.full(n_elem, -1, np.int64)
        elem = np.zeros(0, np.int64)
        cdf = np.zeros(0)
        if pieces is not None:
            elem = base[orig[pieces.tris]] + element_index(orig)[pieces.tris]  # each split triangle's element
            prob[elem] = pieces.prob
            cdf = np.zeros(len(elem))
            for k in range(pieces.n):
                sl = slice(int(pieces.first[k]), int(pieces.first[k] + pieces.count[k]))
                c = np.cumsum(pieces.prob[sl])
                cdf[sl] = c / c[-1]
                piece_of[elem[sl]] = k
            lights.append(L.emissive_record())
            self.emissive_light = len(lights) - 1
        self.n_elements = n_elem
        k = 0 if pieces is None else pieces.n
        rec.n_pieces = k
        rec.n_emit_tris = n_tri
        rec.n_elems = n_elem
        rec.piece_tally = wp.zeros(1, dtype=wp.vec4)
        # the tables' sections in the order of SceneRec.emit_ints / emit_floats (the table's come last)
        geom = (np.concatenate([pieces.centre, pieces.normal, pieces.area[:, None], pieces.radiance[:, None],
                                pieces.reach[:, None], pieces.two_sided[:, None].astype(np.float64)], axis=1).reshape(-1)
                if k else np.zeros(0))  # fmt: skip
        self._emit_ints = [base, np.maximum(m, 1), np.repeat(emitting, m[emitting] ** 2), piece_of, elem,
                           pieces.first if k else np.zeros(0), pieces.count if k else np.zeros(0)]  # fmt: skip
        self._emit_floats = [prob, cdf, np.ones(k), pieces.power_share if k else np.zeros(0), geom]
        self._table_fields(wp, rec, None)
        rec.lights = wp.array(lights, dtype=K.LightRec) if lights else wp.zeros(1, dtype=K.LightRec)
        rec.n_lights = len(lights)
        self._light_src, self._lights_authored = list(scene.lights), rec.lights  # for set_light_scale
        rec.guide = self._guide_record(wp, K, n_tri)
        self._keep += [mesh, points, tri_ids, rec.albedo, rec.emission, rec.two_sided, rec.lights]
        return rec

    def _upload_optics(self, wp, sensors: list[Sensor]) -> dict[int, int]:
        """The sensor models' angular responses (``Sensor.optics``, on the optics twins of modelled
        sensors) as ``rec.optics``, one row per distinct response; returns ``id(response)`` → its row + 1
        (``SensorRec.optics``). A run without one uploads a placeholder the kernels never read."""
        from simulator.kernels.optics import OpticsRec, no_optics, optics_record

        rows: dict[int, int] = {}
        recs = []
        for s in sensors:
            if s.optics is not None and id(s.optics) not in rows:
                recs.append(optics_record(s.optics, self._keep))
                rows[id(s.optics)] = len(recs)
        self.rec.optics = wp.array(recs or [no_optics(self._keep)], dtype=OpticsRec)
        self._keep.append(self.rec.optics)
        return rows

    def _upload_surfaces(self, wp, K, rec, g, lights: list) -> None:
        """The surfaces beyond Lambert (``Geometry.surfaces``, :mod:`simulator.kernels.surfaces`) on
        ``rec``; an all-matte stage gets ``surfaces = 0`` and one-element placeholders the kernels never
        read, so its trace is today's matte trace."""
        from simulator.kernels.surface_rec import SurfRec

        modelled = models_surfaces(g)
        rec.surfaces = 1 if modelled else 0
        rows = []
        for s in (g.surfaces if modelled else []):
            r = SurfRec()
            r.coverage = float(s.coverage)
            r.pane = (2 if s.layered else 1) if s.pane else 0  # kernels.surface_rec codes
            r.ior = float(s.ior)
            r.tau = float(s.tau)
            r.glossy = 1 if s.glossy else 0
            r.roughness, r.metallic = float(s.roughness), float(s.metallic)
            r.specular, r.workflow = float(s.specular_grey), 1 if s.use_specular_workflow else 0
            r.coat, r.coat_roughness = float(s.clearcoat), float(s.clearcoat_roughness)
            r.textured = 1 if s.opacity_texture >= 0 and g.texture_id is not None else 0
            r.threshold = float(s.opacity_threshold) if r.textured else 0.0
            rows.append(r)
        if modelled:
            sid = np.ascontiguousarray(g.surface_id, np.int32)
            side = np.zeros(g.n_triangles, np.int32) if g.solid_side is None else g.solid_side.astype(np.int32)
        else:
            sid, side = np.full(1, -1, np.int32), np.zeros(1, np.int32)
        if not rows:
            rows = [SurfRec()]
        rec.surf_id = wp.array(sid, dtype=wp.int32)
        rec.surf_side = wp.array(side, dtype=wp.int32)
        rec.surf = wp.array(rows, dtype=SurfRec)
        from simulator.scene.surfaces import mirror_planes, shaded_faces

        shaded = shaded_faces(g) if modelled else None
        planes, face_plane, _ = (mirror_planes(g.points, g.triangles, g.surface_id, g.surfaces, shaded) if modelled
                                 else (np.zeros((0, 4)), np.full(1, -1, np.int32), 0))
        rec.n_mirror_planes = len(planes)
        rec.mirror_planes = wp.array(planes.astype(np.float32) if len(planes) else np.zeros((1, 4), np.float32),
                                     dtype=wp.vec4)
        rec.face_mirror = wp.array(face_plane.astype(np.int32), dtype=wp.int32)
        if len(planes):  # a plane that holds a mirror face (not panes alone): area lights are sampled in it
            mirror_row = np.array([bool(getattr(s, "delta", False)) for s in g.surfaces] + [False], bool)
            on = np.flatnonzero((face_plane >= 0) & mirror_row[g.surface_id])
            plane_mirror = np.zeros(len(planes), np.int32)
            plane_mirror[np.unique(face_plane[on])] = 1
        else:
            plane_mirror = np.zeros(1, np.int32)
        rec.plane_mirror = wp.array(plane_mirror, dtype=wp.int32)
        self._upload_glints(wp, rec, g if modelled else None, lights)
        self._keep += [rec.surf_id, rec.surf_side, rec.surf, rec.mirror_planes, rec.face_mirror, rec.plane_mirror]
        self._upload_textures(wp, rec, g if modelled else None)
        self._upload_shading(wp, rec, g if modelled else None, shaded)

    def _upload_shading(self, wp, rec, g, shaded) -> None:
        """The shading normals of glossy and mirror faces and the curved mirrors they make
        (:func:`simulator.scene.surfaces.curved_mirrors`, :mod:`simulator.kernels.glossy`,
        :mod:`simulator.kernels.curved`) on ``rec``; one-element placeholders, never read, where no face
        has them."""
        from simulator.scene.surfaces import curved_mirrors

        if g is None or shaded is None:
            rec.n_shaded, rec.n_curves = 0, 0
            ids, normals = np.full(1, -1, np.int32), np.zeros((3, 3), np.float32)
            face_curve, spheres = np.full(1, -1, np.int32), np.zeros((1, 4), np.float32)
        else:
            faces = np.flatnonzero(shaded)
            ids = np.full(g.n_triangles, -1, np.int32)
            ids[faces] = np.arange(len(faces), dtype=np.int32)
            corner = g.shading_normals[faces].astype(np.float64)
            p = g.points[g.triangles[faces]]
            front = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
            # on the front face's side (normals authored against the winding are read as the winding says)
            corner *= np.where(np.einsum("ij,ij->i", corner.sum(axis=1), front) < 0, -1.0, 1.0)[:, None, None]
            corner /= np.maximum(np.linalg.norm(corner, axis=2, keepdims=True), 1e-300)
            normals = np.ascontiguousarray(corner.reshape(-1, 3), np.float32)
            curves = curved_mirrors(g, shaded)
            rec.n_shaded, rec.n_curves = len(faces), curves.n
            face_curve = curves.face_curve.astype(np.int32)
            spheres = curves.spheres.astype(np.float32) if curves.n else np.zeros((1, 4), np.float32)
        rec.shade_id = wp.array(ids, dtype=wp.int32)
        rec.shade_n = wp.array(normals, dtype=wp.vec3)
        rec.face_curve = wp.array(face_curve, dtype=wp.int32)
        rec.curve_sphere = wp.array(spheres, dtype=wp.vec4)
        self._keep += [rec.shade_id, rec.shade_n, rec.face_curve, rec.curve_sphere]

    def _upload_glints(self, wp, rec, g, lights: list) -> None:
        """The glint pairs (:func:`simulator.scene.surfaces.glint_pairs`, :mod:`simulator.kernels.glints`)
        on ``rec``; lights keep the scene's order on the device."""
        from simulator.kernels.surface_rec import GlintRec
        from simulator.scene.surfaces import glint_pairs

        recs = []
        for plane, alpha, li in (glint_pairs(g, lights) if g is not None else []):
            r = GlintRec()
            r.plane = wp.vec4(*[float(v) for v in plane])
            r.alpha = float(alpha)
            r.light = li
            ez = np.asarray(lights[li].frame, float)[:, 2]  # the light record's +ez
            r.s = wp.vec3(*[float(v) for v in ez / np.linalg.norm(ez)])
            recs.append(r)
        rec.n_glints = len(recs)
        rec.glints = wp.array(recs if recs else [GlintRec()], dtype=GlintRec)
        self._keep.append(rec.glints)

    def _upload_textures(self, wp, rec, g) -> None:
        """The opacity textures read per texel (:mod:`simulator.kernels.coverage`) on ``rec``: one
        placeholder each where none (no row is then textured, so the kernels never read them)."""
        from simulator.kernels.surface_rec import TexRec
        from simulator.scene.surfaces import WRAP_MODES

        wraps = {w: k for k, w in enumerate(WRAP_MODES)}
        if g is None or g.texture_id is None:
            ids, uv, recs, texels = np.full(1, -1, np.int32), np.zeros((3, 2), np.float32), [TexRec()], np.zeros(1)
        else:
            ids = np.ascontiguousarray(g.texture_id, np.int32)
            uv = np.ascontiguousarray(g.texture_uv.reshape(-1, 2), np.float32)
            recs, chunks, offset = [], [], 0
            for t in g.coverage_textures:
                r = TexRec()
                r.offset, (r.h, r.w) = offset, t.opacity.shape
                r.wrap_s, r.wrap_t, r.border = wraps[t.wrap[0]], wraps[t.wrap[1]], float(t.border)
                recs.append(r)
                chunks.append(t.opacity.reshape(-1))
                offset += t.opacity.size
            texels = np.concatenate(chunks)
        rec.tex_id = wp.array(ids, dtype=wp.int32)
        rec.tex_uv = wp.array(uv, dtype=wp.vec2)
        rec.tex = wp.array(recs, dtype=TexRec)
        rec.texels = wp.array(np.ascontiguousarray(texels, np.float32), dtype=float)
        self._keep += [rec.tex_id, rec.tex_uv, rec.tex, rec.texels]

    def set_piece_table(self, table) -> None:
        """The pieces' table per cell (:class:`simulator.engine.piece_table.PieceTable`; None: no table,
        every receiver weighs the pieces one by one)."""
        wp = warp()
        with wp.ScopedDevice(self.device):
            self._table_fields(wp, self.rec, table)

    def _table_fields(self, wp, rec, table) -> None:
        """Upload the emitters' two arrays (SceneRec.emit_ints, emit_floats) with the pieces' table
        ``table`` (None: none) after their other sections."""
        self.piece_table = table
        ints, floats = list(self._emit_ints), list(self._emit_floats)
        if table is None:
            rec.n_cells = 0
            rec.cell_dims = wp.vec3i(0, 0, 0)
        else:
            rec.n_cells = table.n_cells
            rec.cell_dims = wp.vec3i(*table.dims)
            ints.append(table.grid)
            floats += [np.asarray(table.lo, np.float64), [1.0 / table.h], table.cdf.reshape(-1), table.total]
        i = np.concatenate([np.asarray(x, np.int64).reshape(-1) for x in ints] + [np.zeros(1, np.int64)])
        f = np.concatenate([np.asarray(x, np.float32).reshape(-1) for x in floats] + [np.zeros(1, np.float32)])
        rec.emit_ints = wp.array(i.astype(np.int32), dtype=wp.int32)  # (a last 0: never an empty array)
        rec.emit_floats = wp.array(f, dtype=float)
        self._emit_arrays = (rec.emit_ints, rec.emit_floats)  # the record holds only their pointers

    def set_piece_factors(self, factors: np.ndarray) -> None:
        """The emitter pieces' learned factors, (K,) (see kernels/lights/emissive.py)."""
        wp = warp()
        self._emit_floats[2] = np.asarray(factors, np.float64)
        self.piece_factors = self._emit_floats[2]
        with wp.ScopedDevice(self.device):
            self._table_fields(wp, self.rec, self.piece_table)

    def _upload_hero(self, wp, rec, tables) -> None:
        """The hero-wavelength tables (:class:`simulator.spectra.hero.HeroTables`) on ``rec``; placeholders
        (1 × 1) when None, for grey transport, which never reads them."""
        if tables is None:
            one = np.zeros((1, 1), np.float32)
            refl, face, emis, weights, colour = one, np.zeros(1, np.int32), one, one, one
            face_em = np.full(1, -1, np.int32)
        else:
            refl, emis, weights, colour = (np.ascontiguousarray(a, np.float32) for a in
                                           (tables.reflectance, tables.emission, tables.weights, tables.colour))
            face = np.ascontiguousarray(tables.face_reflectance, np.int32)
            if not len(face):
                face = np.zeros(1, np.int32)
            face_em = np.ascontiguousarray(getattr(tables, "face_emission", np.zeros(0)), np.int32)
            if len(face_em) != len(face):  # none coloured (or no triangles): every face its record's row
                face_em = np.full(len(face), -1, np.int32)
        rec.spectral_reflectance = wp.array2d(refl, dtype=float)
        rec.spectral_face = wp.array(face, dtype=wp.int32)
        rec.spectral_emission = wp.array2d(emis, dtype=float)
        rec.spectral_face_emission = wp.array(face_em, dtype=wp.int32)
        rec.response_weights = wp.array2d(weights, dtype=float)
        rec.response_lanes = wp.zeros(1, dtype=wp.vec4)
        rec.colour_weights = wp.array2d(colour, dtype=float)
        rows = np.zeros((0, 3), np.int32) if tables is None else np.asarray(tables.surface_spectral, np.int32).reshape(-1, 3)
        rec.spectral_panes = int(np.any(rows[:, 2] >= 0)) if len(rows) else 0
        if not len(rows):
            rows = np.array([[0, -1, -1]], np.int32)
        rec.spectral_surface = wp.array(np.ascontiguousarray(rows), dtype=wp.vec3i)
        self.n_responses = 0 if tables is None else int(weights.shape[0])

    def set_hero_tables(self, tables) -> None:
        """Upload the tables of spectral transport (``None``: back to grey placeholders)."""
        wp = warp()
        if tables is not None and tables.emission.shape[0] < int(self.rec.n_lights):
            raise ValueError(f"{tables.emission.shape[0]} emission rows for {int(self.rec.n_lights)} light records")
        with wp.ScopedDevice(self.device):
            self._upload_hero(wp, self.rec, tables)
    def _guide_record(self, wp, K, n_tri: int):
        """The guide's layout on the device, with nothing to sample yet (n = 0)."""
        lay = self.layout
        g = K.GuideRec()
        ok = lay.n_patches > 0
        g.tri_m = wp.array(lay.m if ok else np.ones(max(n_tri, 1), np.int32), dtype=wp.int32)
        g.tri_offset = wp.array(lay.offset if ok else np.zeros(max(n_tri, 1), np.int32), dtype=wp.int32)
        g.patch_tri = wp.array(lay.patch_tri if ok else np.zeros(1, np.int32), dtype=wp.int32)
        from simulator.engine.guide import ROWS_PER_PRIM

        tri_row, self.guide_rows = source_rows(self._prim, lay.n_patches, ROWS_PER_PRIM) if ok else (np.zeros(max(n_tri, 1), np.int32), 1)
        g.tri_row = wp.array(tri_row, dtype=wp.int32)
        g.n_rows = self.guide_rows
        g.density = wp.zeros(max(lay.n_patches * self.guide_rows, 1), dtype=float)
        g.ids = wp.zeros(1, dtype=wp.int32)
        g.cdf = wp.ones(1, dtype=float)
        g.row_start = wp.zeros(self.guide_rows + 1, dtype=wp.int32)
        g.n = 0
        g.n_patches = lay.n_patches
        g.tally = wp.zeros(1, dtype=wp.vec2)
        return g

    def tally_rows(self, blocks: int) -> None:
        """Zeroed pilot tallies: ``blocks`` blocks of guide rows × patches, one
        per chunk of the pilot's kernel threads (``TraceParams.tally_chunk``)."""
        wp = warp()
        with wp.ScopedDevice(self.device):
            g = self.rec.guide
            g.tally = wp.zeros(max(1, blocks * self.guide_rows * self.layout.n_patches), dtype=wp.vec2)
            self.rec.guide = g  # reassigned: the record holds the struct by value

    def read_tally(self, blocks: int) -> np.ndarray:
        """The pilot's tallies, (guide rows, N, 2) float64: the blocks added
        one after another in block order (a fixed order, so fixed bytes)."""
        t = self.rec.guide.tally.numpy().astype(np.float64)
        r, n = self.guide_rows, self.layout.n_patches
        if not n:
            return np.zeros((r, 0, 2))
        t = t[: blocks * r * n].reshape(blocks, r, n, 2)
        out = np.zeros((r, n, 2))
        for b in range(blocks):
            out += t[b]
        return out

    def set_guide(self, ids: np.ndarray, cdf: np.ndarray, row_start: np.ndarray, density: np.ndarray) -> None:
        """Upload the patch sampler's tables (:func:`~simulator.scene.patches.patch_distribution_rows`)."""
        wp = warp()
        with wp.ScopedDevice(self.device):
            g = self.rec.guide
            if len(ids):
                g.ids = wp.array(ids.astype(np.int32), dtype=wp.int32)
                g.cdf = wp.array(cdf.astype(np.float32), dtype=float)
                g.row_start = wp.array(row_start.astype(np.int32), dtype=wp.int32)
                g.density = wp.array(density.astype(np.float32), dtype=float)
            g.n = int(len(ids))
            g.tally = wp.zeros(1, dtype=wp.vec2)
            self.rec.guide = g  # reassigned: the record holds the struct by value
    def set_pick_factors(self, factors: np.ndarray) -> None:
        """The light pick's learned factors, (1 + S, L) over the light
        records: row 0 for path vertices past the first, row 1 + s for sensor
        s's first vertex (see kernels.light_pick)."""
        wp = warp()
        f = np.ascontiguousarray(factors, np.float32).reshape(-1)
        with wp.ScopedDevice(self.device):
            self.rec.pick_factor = wp.array(f, dtype=float)
        self._pick_factor = self.rec.pick_factor  # the record holds only its pointer

    def start_patch_pick_tally(self) -> None:
        """Zeroed per-patch sums of the pick pilot, (patches × light records) vec3."""
        wp = warp()
        with wp.ScopedDevice(self.device):
            self.rec.patch_pick_tally = wp.zeros(max(1, self.layout.n_patches * int(self.rec.n_lights)), dtype=wp.vec3)
        self._patch_pick_tally = self.rec.patch_pick_tally

    def read_patch_pick_tally(self) -> np.ndarray:
        """The pick pilot's per-patch sums, (patches, light records, 3) float64 (w·ê, w·value, visits)."""
        t = self.rec.patch_pick_tally.numpy().astype(np.float64)
        return t[: self.layout.n_patches * int(self.rec.n_lights)].reshape(self.layout.n_patches, int(self.rec.n_lights), 3)

    def set_patch_pick_factors(self, factors: np.ndarray) -> None:
        """The light pick's factors per patch, (patches, light records), for vertices past the first."""
        wp = warp()
        with wp.ScopedDevice(self.device):
            self.rec.patch_pick_factor = wp.array(np.ascontiguousarray(factors, np.float32).reshape(-1), dtype=float)
            self.rec.patch_pick_tally = wp.zeros(1, dtype=wp.vec3)
            self.rec.n_patch_pick = 1
        self._patch_pick_factor = self.rec.patch_pick_factor  # the record holds only its pointer

    def set_light_scale(self, scale: np.ndarray | None) -> None:
        """Each light record's emission × ``scale[l]`` (L,) for the launches that follow (a pilot that
        lights some lights only), or, with None, the authored records back. The emissive record, last
        where there is one, keeps its own emission (its triangles' rows are not scaled)."""
        wp = warp()
        if scale is None:
            self.rec.lights = self._lights_authored
            return
        from simulator.kernels import estimators as K
        from simulator.kernels import lights as L

        recs = [L.light_record(dc_replace(l, emission=(l.emission[0] * float(k), l.emission[1] * float(k))), self._keep)
                for l, k in zip(self._light_src, scale)]  # fmt: skip
        if self.emissive_light >= 0:
            recs.append(L.emissive_record())
        with wp.ScopedDevice(self.device):
            self.rec.lights = wp.array(recs, dtype=K.LightRec) if recs else self._lights_authored

    def use_patch_pick(self, on: bool) -> None:
        """Let the per-patch factors steer the pick (where they have been set), or the rows alone."""
        learnt = getattr(self, "_patch_pick_factor", None) is not None
        self.rec.n_patch_pick = 1 if on and learnt else 0

    def set_light_mask(self, mask: np.ndarray) -> None:
        """Lights to skip per sensor at its first vertex: ``mask`` (S, L) over
        the scene's lights, 0 = wholly behind the sensor (see plan.lights_behind)."""
        wp = warp()
        n_l = int(self.rec.n_lights)
        full = np.ones((self._n_sensors, n_l), np.int32)
        full[:, : mask.shape[1]] = mask
        if self._light_mask is not None and np.array_equal(self._light_mask, full):
            return  # already on the device: a plan run again (adaptive runs, charts) uploads nothing
        self._light_mask = full
        with wp.ScopedDevice(self.device):
            self.rec.light_mask = wp.array(full.reshape(-1) if full.size else np.ones(1, np.int32), dtype=wp.int32)
