"""Slow end-to-end checks that need optional tools: a local Ray instance and headless Chromium."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from logicenveval.cli import main

TASKS = "clean_living_room,hallway_entry_tidy"


def _results(out: Path) -> dict[str, object]:
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    data = json.loads((run_dir / "results.json").read_text())
    data.pop("timing")
    for values in data["results"].values():
        values.pop("st_ms")
    for per in data["per_task"].values():
        for values in per.values():
            values.pop("st_ms")
    return data


@pytest.mark.slow
def test_ray_executor_gathers_the_same_results(tmp_path: Path) -> None:
    pytest.importorskip("ray")
    common = ["run", "--model", "offline", "--tasks", TASKS, "--generators", "logicenvgen,holodeck", "--quiet"]
    assert main([*common, "--executor", "ray", "--workers", "2", "--output", str(tmp_path / "ray")]) == 0
    assert main([*common, "--executor", "inprocess", "--output", str(tmp_path / "local")]) == 0
    assert _results(tmp_path / "ray") == _results(tmp_path / "local")


CHROMIUM_FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def _chromium() -> str:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    pytest.skip("no Chromium on this machine (Debian: apt-get install chromium)")


@pytest.mark.slow
def test_report_in_headless_chromium(tmp_path: Path) -> None:
    """The report as a reader uses it: the table fits 1,400 px, the filter hides rows, an
    environment's anchor opens its task page with the embedded render, a trace is a tick table."""
    browser_path = _chromium()
    sync_api = pytest.importorskip("playwright.sync_api",
                                   reason="Playwright is not installed (pip install -e '.[browser]')")
    out = tmp_path / "out"
    assert main(["run", "--model", "offline", "--tasks", TASKS, "--generators", "logicenvgen,cot",
                 "--executor", "inprocess", "--output", str(out), "--quiet"]) == 0
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    moved = tmp_path / "moved"  # the report folder alone, elsewhere: nothing links back
    shutil.copytree(run_dir / "details", moved / "details")
    shutil.copy(run_dir / "leaderboard.html", moved / "leaderboard.html")
    with sync_api.sync_playwright() as pw:
        context = pw.chromium.launch_persistent_context(
            str(tmp_path / "profile"), executable_path=browser_path, headless=True,
            args=CHROMIUM_FLAGS, viewport={"width": 1400, "height": 1000})
        try:
            page = context.new_page()
            page.goto((moved / "leaderboard.html").as_uri())
            width = page.evaluate("[document.documentElement.scrollWidth, window.innerWidth]")
            assert width[0] <= width[1], f"the page overflows 1,400 px: {width}"
            extra = page.locator("#leaderboard th", has_text="Extra checks").bounding_box()
            assert extra is not None and extra["x"] + extra["width"] <= 1400
            assert page.evaluate("getComputedStyle(document.querySelector('#leaderboard thead')).position") == "sticky"
            rows = page.locator("table.idx tbody tr")
            assert rows.count() == 4
            page.fill("#filter", "hallway cot")
            visible = [r for r in rows.all() if r.is_visible()]
            assert len(visible) == 1 and "hallway_entry_tidy" in visible[0].inner_text()
            assert page.locator("#row-gen-cot").is_visible()  # the method's own row stays
            assert not page.locator("#row-gen-logicenvgen").is_visible()
            page.screenshot(path=str(tmp_path / "leaderboard.png"), full_page=True)
            page.fill("#filter", "")
            link = page.locator("#t-logicenvgen--clean_living_room a.env").first
            env_id = link.inner_text()
            link.click()
            page.wait_for_load_state()
            assert page.url.endswith(f"details/logicenvgen/clean_living_room.html#env-{env_id}")
            card = page.locator(f"#env-{env_id}")
            assert card.is_visible() and card.locator("img").evaluate("i => i.naturalWidth") > 0
            card.locator("details.bt").first.locator("summary").click()
            ticks = card.locator("table.ticks").first
            assert ticks.is_visible() and ticks.locator("tbody tr").count() > 1
            page.screenshot(path=str(tmp_path / "task.png"))
        finally:
            context.close()
    for shot in ("leaderboard.png", "task.png"):
        assert (tmp_path / shot).stat().st_size > 10_000
        shutil.copy(tmp_path / shot, run_dir / shot)
