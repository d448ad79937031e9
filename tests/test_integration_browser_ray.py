"""Slow end-to-end checks that need optional tools: a local Ray instance and headless Chromium."""

from __future__ import annotations

import json
import re
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


#: tasks on which cot's environments interpenetrate, leave their room and block doors, and
#: LogicEnvGen's are ill-formed (multi_room_trash_run: two trash bags told apart by nothing)
BROWSER_TASKS = "clean_living_room,hallway_entry_tidy,bathroom_towel_refresh,multi_room_trash_run"


def _reason_words(label: str) -> list[str]:
    """The words of a reason's label a reader would type: codes and words, not `…` or `#`."""
    return [w for w in re.findall(r"[A-Za-z][\w-]+", label) if len(w) > 2]


@pytest.mark.slow
def test_report_in_headless_chromium(tmp_path: Path) -> None:
    """The report as a reader uses it: the table fits 1,400 px, the filter finds every reason
    word the page shows (and keeps the reasons list), an environment's anchor opens its task
    page with its linked render (full size on click) and EnvSpec JSON, a trace is a tick table
    with port values, and the task page's filter finds codes and node names."""
    browser_path = _chromium()
    sync_api = pytest.importorskip("playwright.sync_api",
                                   reason="Playwright is not installed (pip install -e '.[browser]')")
    out = tmp_path / "out"
    assert main(["run", "--model", "offline", "--tasks", BROWSER_TASKS, "--generators", "logicenvgen,cot",
                 "--executor", "inprocess", "--output", str(out), "--quiet"]) == 0
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    moved = tmp_path / "moved"  # the run folder, elsewhere: every link is relative
    shutil.copytree(run_dir, moved)
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
            assert rows.count() == 8
            page.fill("#filter", "hallway_entry_tidy cot")
            visible = [r for r in rows.all() if r.is_visible()]
            assert len(visible) == 1 and "hallway_entry_tidy" in visible[0].inner_text()
            assert page.locator("#row-gen-cot").is_visible()  # the method's own row stays
            assert not page.locator("#row-gen-logicenvgen").is_visible()
            # every word of every reason shown finds index rows, and its reason stays listed
            page.fill("#filter", "")
            reasons = page.locator("ul.why li")
            labels = [li.inner_text().split(" — ")[0].split("×", 1)[1] for li in reasons.all()]
            words = sorted({w for label in labels for w in _reason_words(label)})
            assert {"interpenetration", "outside_room", "ill-formed", "blocks_door"} <= set(words)
            for word in words:
                page.fill("#filter", word)
                shown = page.locator("table.idx tbody tr:visible").count()
                assert shown > 0, f"the filter finds no row for {word!r}, shown on the page"
                assert not page.locator("#filter-count").inner_text().startswith("0 of")
                assert page.locator("ul.why li:visible").count() > 0, f"{word!r} hides the reasons"
                assert page.locator("#leaderboard tbody tr:visible").count() > 0
            page.fill("#filter", "interpenetration")
            assert not page.locator("#t-logicenvgen--clean_living_room").is_visible()
            assert page.locator("#t-cot--bathroom_towel_refresh").is_visible()
            page.screenshot(path=str(tmp_path / "leaderboard.png"), full_page=True)
            page.fill("#filter", "")
            link = page.locator("#t-logicenvgen--clean_living_room a.env").first
            env_id = link.inner_text()
            link.click()
            page.wait_for_load_state()
            assert page.url.endswith(f"details/logicenvgen/clean_living_room.html#env-{env_id}")
            card = page.locator(f"#env-{env_id}")
            assert card.is_visible() and card.locator("img").evaluate("i => i.naturalWidth") > 0
            # the render opens full size; the EnvSpec JSON is linked
            assert card.locator("a:has(img)").get_attribute("href", timeout=1000).endswith(f"{env_id}.svg")
            env_href = card.locator("a", has_text="EnvSpec JSON").get_attribute("href")
            assert env_href is not None and (page_dir := moved / "details" / "logicenvgen").is_dir()
            assert json.loads((page_dir / env_href).read_text())["env_id"] == env_id
            card.locator("details.bt").first.locator("summary").click()
            ticks = card.locator("table.ticks").first
            assert ticks.is_visible() and ticks.locator("tbody tr").count() > 1
            node = next(t for t in ticks.locator("tbody tr td:nth-child(2)").all_inner_texts() if "=" in t)
            assert re.fullmatch(r"\w+ \w+=\S+.*", node), node  # `Walk target=...`: ports shown
            where = ticks.locator("tbody tr td:nth-child(4)").first
            where.hover()  # the full tree path appears as the cell's title
            full = where.get_attribute("title")
            assert full and full.count("/") >= 1 and full.endswith(where.inner_text().removeprefix("…/"))
            page.screenshot(path=str(tmp_path / "task.png"))
            page.fill("#filter", node.split()[-1])
            assert card.is_visible()
            # a detail page's filter finds a code (not printed on the card) and an object id
            page.goto((moved / "details" / "cot" / "bathroom_towel_refresh.html").as_uri())
            cards = page.locator("article.env")
            page.fill("#filter", "interpenetration")
            hit = page.locator("article.env:visible")
            assert 0 < hit.count() <= cards.count()
            obj = re.search(r"(\w+) and \w+ interpenetrate", hit.first.inner_text())
            assert obj is not None
            page.fill("#filter", obj.group(1))
            assert page.locator("article.env:visible").count() > 0
        finally:
            context.close()
    for shot in ("leaderboard.png", "task.png"):
        assert (tmp_path / shot).stat().st_size > 10_000
        shutil.copy(tmp_path / shot, run_dir / shot)
