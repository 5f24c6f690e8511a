"""House rules of the source tree that no behaviour test would see."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "simulator"


def _module_names() -> dict[str, Path]:
    out = {}
    for p in PACKAGE.rglob("*.py"):
        parts = p.relative_to(ROOT).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = p
    return out


def _imports(name: str, path: Path, modules: dict[str, Path]) -> set[str]:
    """The package's modules that ``name`` imports anywhere in its text (a function's
    deferred import counts: it only hides a cycle until the function runs)."""
    pkg = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = pkg.split(".")[: len(pkg.split(".")) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            for a in node.names:
                full = f"{mod}.{a.name}"
                out.add(full if full in modules else mod)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return {m for m in out if m in modules and m != name}


def test_no_import_cycles():
    """The module import graph of ``simulator`` (top-level and deferred imports)
    has no cycle: a strongly connected component of one module each (Tarjan)."""
    modules = _module_names()
    graph = {n: _imports(n, p, modules) for n, p in modules.items()}
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    cycles = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                cycles.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    assert not cycles, cycles
    assert "simulator.scene.photometry.files" in graph["simulator.scene.photometry"]


def _development_table() -> list[tuple[str, str]]:
    """docs/development.md's table of the package's rooms: (room, job) per row."""
    part = (ROOT / "docs" / "development.md").read_text(encoding="utf-8")
    rows = []
    for line in part.splitlines()[1:]:
        if line.startswith("## "):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| `") and len(cells) == 2:
            rows.append((cells[0], cells[1]))
    return rows


def test_the_development_table_names_what_is_there():
    """Every room of docs/development.md's table exists, and every file or folder
    its job names (``x.py``, ``x/``) is inside that room; every subpackage of
    ``simulator`` has a row."""
    import re

    rows = _development_table()
    rooms = []
    for room, job in rows:
        for r in re.findall(r"`([^`]+)`", room):
            assert (ROOT / r).exists(), r
            rooms.append(r.rstrip("/"))
        base = ROOT / re.findall(r"`([^`]+)`", room)[0]
        if not base.is_dir():
            continue
        for name in re.findall(r"`([\w./]+(?:\.py|/))`", job):
            if (ROOT / name).exists() and (name.startswith(("simulator/", "docs/")) or "/" not in name.rstrip("/")):
                continue  # a path from the top of the tree (setup.py, simulator/...)
            found = (base / name).exists() or any(p.as_posix().endswith("/" + name.rstrip("/")) for p in base.rglob("*"))
            assert found, f"{room}: {name}"
    for pkg in sorted(p.parent for p in PACKAGE.glob("*/__init__.py")):
        assert pkg.relative_to(ROOT).as_posix() in rooms, pkg


def test_the_docs_claim_no_peer_figure_on_the_same_room():
    """docs/comparisons.md's "Furnished, interreflecting rooms" gives the Mitsuba
    figures for the bundled office from the side-by-side script anyone can rerun
    (its command is there), and says that the 5.7 s once quoted was measured on
    another office, not claiming it for the bundled room."""
    text = (ROOT / "docs" / "comparisons.md").read_text(encoding="utf-8")
    item = text[text.index("## Furnished, interreflecting rooms") :]
    item = item[: item.index("\n## ", 4)]
    assert "benchmarks/peer_mitsuba.py configs/office_bench.toml" in item
    if "5.7 s" in item:
        assert "another office" in item and "not this one" in item
