"""Every table of figures in README.md and docs/ is what tools/docs_figures.py makes from the data."""

from __future__ import annotations

import importlib.util
import shutil
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def figures() -> ModuleType:
    spec = importlib.util.spec_from_file_location("docs_figures", ROOT / "tools" / "docs_figures.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_committed_tables_are_what_the_data_gives(figures: ModuleType) -> None:
    assert figures.differences() == []


def test_every_marked_block_and_figure_is_known(figures: ModuleType) -> None:
    used = {m.group(2) for p in figures.DOCS for m in figures.BLOCK.finditer(p.read_text())}
    inline = {m.group(2) for p in figures.DOCS for m in figures.FIG.finditer(p.read_text())}
    assert {"reference", "ablation", "task-stats", "paper-vs-ours"} <= used
    assert used <= set(figures.BLOCKS) | {"paper-vs-ours"}
    assert all(name in figures.INLINE or figures.data_figure(name) is not None for name in inline)


def test_a_figure_edited_by_hand_is_caught(figures: ModuleType, tmp_path: Path) -> None:
    readme = tmp_path / "README.md"
    shutil.copy(ROOT / "README.md", readme)
    text = readme.read_text()
    start = text.index("<!-- figures:reference -->")
    row = text.index("| logicenvgen (MTSA) |", start)
    cell = text.index(" | ", row + len("| logicenvgen (MTSA)")) + 3
    end = text.index(" |", cell)
    readme.write_text(text[:cell] + "12.34" + text[end:])
    diff = figures.differences([readme])
    assert diff and "12.34" in diff[0]


def test_an_inline_figure_edited_by_hand_is_caught(figures: ModuleType, tmp_path: Path) -> None:
    doc = tmp_path / "benchmark.md"
    shutil.copy(ROOT / "docs" / "benchmark.md", doc)
    text = doc.read_text()
    assert "<!--fig:bt_nodes-->" in text
    doc.write_text(text.replace("<!--fig:bt_nodes-->", "<!--fig:bt_nodes-->9"))
    assert figures.differences([doc])


def test_the_why_column_is_kept_and_the_figures_are_not(figures: ModuleType) -> None:
    text = (ROOT / "docs" / "fidelity.md").read_text()
    block = figures.BLOCK.search(text[text.index("<!-- figures:paper-vs-ours -->"):])
    assert block is not None
    body = block.group(3)
    assert "TODO" not in body
    edited = body.replace("| same: the solver", "| hand-kept prose: the solver")
    assert figures.block_paper_vs_ours(edited) == edited
    row = next(line for line in body.splitlines() if line.startswith("| LogicEnvGen LogCov |"))
    tampered = body.replace(row, row.replace(row.split(" | ")[2], "1.00"))
    assert figures.block_paper_vs_ours(tampered) == body


def test_an_empty_block_is_filled_and_the_text_after_it_kept(figures: ModuleType) -> None:
    """Two markers on consecutive lines are an empty block: filling it must not swallow the prose
    up to the next block's end (it once did, and an empty last block was never filled)."""
    text = ("intro\n<!-- figures:real -->\n<!-- /figures -->\nprose kept\n"
            "<!-- figures:real -->\nold table\n<!-- /figures -->\nend\n")
    body = figures.block_real()
    assert figures.render(text) == (f"intro\n<!-- figures:real -->\n{body}\n<!-- /figures -->\n"
                                    f"prose kept\n<!-- figures:real -->\n{body}\n<!-- /figures -->\nend\n")
