"""Slow end-to-end checks that need optional tools: a local Ray instance and headless Chromium."""

from __future__ import annotations

import json
import shutil
import subprocess
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


@pytest.mark.slow
def test_leaderboard_html_renders_in_headless_chromium(tmp_path: Path) -> None:
    browser = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if browser is None:
        pytest.skip("no Chromium on this machine (apt-get install chromium)")
    out = tmp_path / "out"
    assert main(["run", "--model", "offline", "--tasks", "clean_living_room", "--generators", "logicenvgen",
                 "--executor", "inprocess", "--output", str(out), "--quiet"]) == 0
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    page = (run_dir / "leaderboard.html").resolve().as_uri()
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={tmp_path / 'profile'}", "--allow-file-access-from-files"]
    dom = subprocess.run([browser, *flags, "--dump-dom", page], capture_output=True, text=True, timeout=120)
    assert '<table class="lb"' in dom.stdout and "logicenvgen" in dom.stdout
    assert 'src="renders/logicenvgen/clean_living_room/' in dom.stdout
    shot = tmp_path / "leaderboard.png"
    subprocess.run([browser, *flags, "--window-size=1400,1000", f"--screenshot={shot}", page],
                   capture_output=True, timeout=120, check=False)
    assert shot.exists() and shot.stat().st_size > 10_000
    shutil.copy(shot, run_dir / "leaderboard.png")
