"""The leaderboard's charts as a reader sees them, in headless Chromium with the network cut off:
one chart per headline metric, every method's bar drawn as long as its figure, the interval
whiskers drawn, nothing loaded from outside the page (slow: needs Chromium and Playwright)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from logicenveval.cli import main
from logicenveval.runner.results import load_results

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM_FLAGS = ["--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync"]


def _chromium() -> str:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    pytest.skip("no Chromium on this machine (Debian: apt-get install chromium)")


@pytest.mark.slow
def test_charts_in_headless_chromium_offline(tmp_path: Path) -> None:
    browser_path = _chromium()
    sync_api = pytest.importorskip("playwright.sync_api",
                                   reason="Playwright is not installed (pip install -e '.[browser]')")
    run_dir = tmp_path / "reference"
    shutil.copytree(ROOT / "reports" / "reference", run_dir)
    assert main(["report", str(run_dir)]) == 0  # the page as this code writes it
    results = load_results(run_dir)
    outside: list[str] = []
    with sync_api.sync_playwright() as pw:
        context = pw.chromium.launch_persistent_context(
            str(tmp_path / "profile"), executable_path=browser_path, headless=True,
            args=CHROMIUM_FLAGS, viewport={"width": 1400, "height": 1000}, offline=True)
        try:
            page = context.new_page()

            def cut_off(route: object) -> None:  # anything but the page's own files is refused
                outside.append(route.request.url)  # type: ignore[attr-defined]
                route.abort()  # type: ignore[attr-defined]

            page.route(lambda url: not url.startswith("file://"), cut_off)
            page.goto((run_dir / "leaderboard.html").as_uri())
            figures = page.locator("figure.chart")
            assert figures.count() == 5
            width = page.evaluate("[document.documentElement.scrollWidth, window.innerWidth]")
            assert width[0] <= width[1], f"the charts overflow 1,400 px: {width}"
            for k in range(figures.count()):
                box = figures.nth(k).locator("svg").bounding_box()
                assert box is not None and box["width"] > 300 and box["height"] > 100
                assert figures.nth(k).is_visible()
            logcov = page.locator("#chart-logcov")
            drawn = {g.get_attribute("data-method"): g.locator("rect").bounding_box()["width"]
                     for g in logcov.locator("g.bar").all()}
            assert list(drawn) == results["generators"]
            figures_of = {g: results["results"][g]["logcov"] for g in drawn}
            # the longest bar is the best method's, and bars keep the figures' proportions
            assert max(drawn, key=drawn.__getitem__) == max(figures_of, key=figures_of.__getitem__)
            best = max(figures_of.values())
            for g, w in drawn.items():
                assert w == pytest.approx(max(drawn.values()) * figures_of[g] / best, abs=1.0)
            whiskers = logcov.locator("path.ci")
            assert whiskers.count() == len(drawn)
            assert all((b := w.bounding_box()) is not None and b["width"] > 1 for w in whiskers.all())
            assert page.locator("#chart-st-ticks path.ci").count() == 0  # ticks: no interval
            page.locator("#charts").screenshot(path=str(tmp_path / "charts.png"))
        finally:
            context.close()
    assert outside == [], f"the page asked for files outside it: {outside}"
    assert (tmp_path / "charts.png").stat().st_size > 10_000
