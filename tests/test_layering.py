"""No module imports from a higher layer (docs/ARCHITECTURE.md, "Dependency order")."""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "logicenveval"


def layers() -> dict[str, int]:
    """Top-level module -> layer index, from the fenced block under "## Dependency order"."""
    text = (ROOT / "docs" / "ARCHITECTURE.md").read_text(encoding="utf-8")
    block = text.split("## Dependency order", 1)[1].split("```", 2)[1]
    out: dict[str, int] = {}
    for level, line in enumerate(x for x in block.splitlines() if x.strip()):
        for name in re.split(r"\s{2,}", line.strip())[0].split(","):
            out[name.strip()] = level
    return out


def imports_of(source: str, module: str, is_package: bool = False) -> list[tuple[int, str]]:
    """(line, imported top-level module of logicenveval) of every import in `source`, including
    imports inside functions and relative ones; `module` is the dotted name of the file."""
    package = module if is_package else module.rsplit(".", 1)[0]
    out = []
    for node in ast.walk(ast.parse(source)):
        targets: list[str] = []
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                targets = [".".join(base + ([node.module] if node.module else []))]
            else:
                targets = [node.module or ""]
            if targets == ["logicenveval"]:  # `from logicenveval import x`: x is the module
                targets = [f"logicenveval.{a.name}" for a in node.names]
        out += [(node.lineno, t.split(".")[1]) for t in targets
                if t.startswith("logicenveval.") and len(t.split(".")) > 1]
    return out


def violations(known: dict[str, int], files: dict[str, str]) -> tuple[list[str], list[tuple[str, str]]]:
    """(upward imports, pairs of same-layer packages importing each other) of dotted-name -> source."""
    upward = []
    edges: set[tuple[str, str]] = set()
    for module, source in sorted(files.items()):
        parts = module.split(".")
        here = parts[1] if len(parts) > 1 and parts[1] != "__init__" else "__init__"
        for line, target in imports_of(source, module.removesuffix(".__init__"), module.endswith("__init__")):
            if target == here or target not in known:
                continue
            edges.add((here, target))
            if known[target] > known.get(here, -1):
                upward.append(f"{module}:{line}: {here} imports {target}")
    cycles = sorted((a, b) for a, b in edges
                    if a < b and a in known and known[a] == known.get(b) and (b, a) in edges)
    return upward, cycles


def package_files() -> dict[str, str]:
    return {".".join(p.relative_to(ROOT).with_suffix("").parts): p.read_text(encoding="utf-8")
            for p in sorted(PACKAGE.rglob("*.py"))}


def test_every_module_has_a_layer() -> None:
    assert all(name.isidentifier() for name in layers()), "two spaces between names and description"
    modules = {p.relative_to(PACKAGE).parts[0].removesuffix(".py") for p in PACKAGE.rglob("*.py")}
    assert sorted(modules - set(layers())) == [], "add these modules to docs/ARCHITECTURE.md's order"


def test_no_import_runs_upwards() -> None:
    upward, cycles = violations(layers(), package_files())
    assert upward == []
    assert cycles == [], "packages of one layer import each other"


def test_the_checker_finds_lazy_relative_and_circular_imports() -> None:
    """How the runner once reached reporting (a lazy import), and generators reached baselines."""
    files = {
        "logicenveval.runner.fake": "def f():\n    from logicenveval.reporting.leaderboard import w\n",
        "logicenveval.runner.other": "from ..reporting import tables\n",
        "logicenveval.generators.fake": "import logicenveval.baselines.cot\n",
        "logicenveval.baselines.fake": "from logicenveval import generators\n",
    }
    upward, cycles = violations(layers(), files)
    assert upward == ["logicenveval.runner.fake:2: runner imports reporting",
                      "logicenveval.runner.other:1: runner imports reporting"]
    assert cycles == [("baselines", "generators")]
