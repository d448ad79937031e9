"""The leaderboard's charts (`reporting.charts`, `_charts.html.j2`): one inline SVG per headline
metric, the methods side by side, each bar as long as its value and its whisker at the ends of its
95 % interval; nothing external, so the page works offline. The browser check is in
tests/test_integration_browser_ray.py."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest
from defusedxml import ElementTree

from logicenveval.reporting.charts import HEADLINE, headline_charts
from logicenveval.reporting.leaderboard import Collected, jinja, render_main
from logicenveval.reporting.tables import metric

ROOT = Path(__file__).resolve().parents[1]
SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def results() -> dict[str, Any]:
    from logicenveval.runner.results import load_results

    return load_results(ROOT / "reports" / "reference")


@pytest.fixture(scope="module")
def page(results: dict[str, Any]) -> str:
    return render_main(results, Collected([], [], {}, {}, set()), jinja())


def _svgs(html: str) -> dict[str, Any]:
    """metric key -> parsed <svg> of each chart figure on the page."""
    out = {}
    for key, svg in re.findall(r'<figure class="chart" id="chart-([\w-]+)">.*?(<svg.*?</svg>)', html, re.S):
        out[key] = ElementTree.fromstring(svg)
    return out


def test_one_chart_per_headline_metric_with_every_method(results: dict[str, Any], page: str) -> None:
    svgs = _svgs(page)
    assert list(svgs) == ["phypr-avg", "logcov", "scevr", "faudr-avg", "st-ticks"]
    methods = results["generators"]
    for svg in svgs.values():
        bars = svg.findall(f"{SVG}g")
        assert [g.get("data-method") for g in bars] == methods  # side by side, in the run's order


def test_bars_and_whiskers_are_where_the_figures_say(results: dict[str, Any], page: str) -> None:
    charts = {c.key: c for c in headline_charts(results)}
    svgs = _svgs(page)
    for title, path, percent, _ in HEADLINE:
        c = charts["-".join(path).replace("_", "-")]
        svg = svgs[c.key]
        for gen, g in zip(results["generators"], svg.findall(f"{SVG}g"), strict=True):
            values = results["results"][gen]
            value = metric(values, path)
            assert value is not None
            width = float(g.find(f"{SVG}rect").get("width"))
            scale = 1.0 if percent else float(c.ticks[-1].text)
            assert width == pytest.approx(c.plot_w * value / scale, abs=0.06), (title, gen)
            shown = f"{100 * value:.2f}" if percent else f"{value:.2f}"
            assert g.get("data-value") == shown and shown in g.find(f"{SVG}title").text
            whisker = g.find(f"{SVG}path")
            ci = values["ci95"]
            for key in path:
                ci = ci.get(key) if isinstance(ci, dict) else None
            if ci is None:  # ST (ticks): deterministic, no interval drawn
                assert whisker is None and "no interval" in g.find(f"{SVG}title").text
                continue
            ends = [float(x) for x in re.findall(r"M([\d.]+) ", whisker.get("d"))]
            lo, hi = (c.plot_x + c.plot_w * v / scale for v in ci)
            assert ends[0] == pytest.approx(lo, abs=0.06) and ends[-1] == pytest.approx(hi, abs=0.06)
            assert ends[0] <= c.plot_x + width + 0.06 <= ends[-1] + 0.12  # the bar ends inside its interval


def test_charts_need_nothing_from_outside_the_page(page: str) -> None:
    charts = page[page.index('<div class="charts"'):page.index("</svg>\n</figure>\n</div>") + 20]
    assert "<script" not in charts and "href" not in charts
    assert re.findall(r"https?://[^\"]+", charts) == ["http://www.w3.org/2000/svg"] * 5  # the namespace only
    assert not re.search(r"<(script|link)[^>]+(src|href)=\"https?:", page)


def test_a_row_that_was_not_measured_says_so(results: dict[str, Any]) -> None:
    data = json.loads(json.dumps(results))
    gen = data["generators"][-1]
    data["results"][gen]["measured"] = False
    bars = {c.key: c.bars[-1] for c in headline_charts(data)}
    assert all(b.width == 0 and b.text == "not measured" and b.lo is None for b in bars.values())


def test_a_single_task_run_has_bars_without_whiskers(results: dict[str, Any]) -> None:
    data = json.loads(json.dumps(results))
    for values in data["results"].values():
        values["ci95"] = {k: None for k in values["ci95"]}
    for c in headline_charts(data):
        assert all(b.lo is None and b.hi is None and b.width > 0 or b.text in ("0.00", "–") for b in c.bars)
        assert all("no interval" in b.tooltip for b in c.bars)


def test_a_merged_report_charts_every_run_and_method(tmp_path: Path) -> None:
    """`report RUN RUN`: one bar per (run, method) row, named by both, the method's name kept
    whole even where a long label is shortened."""
    from logicenveval.reporting.merged import write_merged

    packs = [ROOT / "reports" / "real" / name for name in
             ("SmolLM2-135M-Instruct.Q4_1", "qwen2.5-coder-1.5b-instruct-q4_k_m")]
    runs = write_merged(packs, tmp_path / "merged")
    svgs = _svgs((tmp_path / "merged" / "leaderboard.html").read_text())
    assert len(svgs) == len(HEADLINE)
    rows = sum(len(results["results"]) for _, results in runs)
    for svg in svgs.values():
        bars = svg.findall(f"{SVG}g")
        assert len(bars) == rows == 8
        for g in bars:
            method = g.get("data-method").rsplit(" · ", 1)[1]
            assert g.find(f"{SVG}text").text.endswith(method)
