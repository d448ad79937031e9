"""The committed real-model replay packs (`reports/real/<model>/`) reproduce their metrics from
their reply cache alone: no model, no server, no network."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
PACKS = sorted(p for p in (REPO / "reports" / "real").glob("*")
               if (p / "llm_cache.sqlite").is_file() and (p / "results.json").is_file())
sys.path.insert(0, str(REPO / "benchmarks"))


@pytest.mark.skipif(not PACKS, reason="no replay pack committed under reports/real/")
@pytest.mark.parametrize("pack", PACKS, ids=[p.name for p in PACKS])
def test_replaying_a_pack_reproduces_its_metrics(pack: Path, tmp_path: Path) -> None:
    from llm_validity import replay, same_metrics  # type: ignore[import-not-found]

    recorded = json.loads((pack / "results.json").read_text(encoding="utf-8"))
    replayed = replay(pack, tmp_path)
    assert same_metrics(recorded, replayed)
    assert replayed["llm"] == recorded["llm"]  # the same questions, attempts and valid replies
    def stages(results: dict) -> dict:  # messages name the run folder, which differs
        return {g: sorted((f["task"], f.get("stage", "")) for f in fs) for g, fs in results["failures"].items()}

    assert stages(replayed) == stages(recorded)


SEED_RUNS = sorted((REPO / "reports" / "real" / "stability").glob("*/seed*/results.json"))


@pytest.mark.skipif(not SEED_RUNS, reason="no stability seed runs committed under reports/real/stability/")
@pytest.mark.parametrize("results", SEED_RUNS, ids=[f"{p.parent.parent.name}/{p.parent.name}" for p in SEED_RUNS])
def test_replaying_a_stability_seed_run_reproduces_it(results: Path, tmp_path: Path) -> None:
    """The App. C table in docs/llm.md is computed from these runs: each one replays from the
    shared stability cache to the same metrics and reply counts, seed included."""
    from llm_validity import replay, same_metrics

    recorded = json.loads(results.read_text(encoding="utf-8"))
    replayed = replay(results.parent, tmp_path, cache=REPO / "reports" / "real" / "stability" / "llm_cache.sqlite")
    assert replayed["seed"] == recorded["seed"]
    assert same_metrics(recorded, replayed)
    assert replayed["llm"] == recorded["llm"]


def test_a_pack_replays_with_the_protocol_it_was_recorded_with() -> None:
    """Packs recorded before issue 39 name no protocol and replay with protocol 1 (their request
    texts); a pack recorded with `--model-args ...,protocol=N` replays with protocol N."""
    from llm_validity import pack_protocol

    assert pack_protocol({"model_args": "threads=1,parallel=2"}) == 1
    assert pack_protocol({"model_args": "threads=2,ctx=20480,protocol=2"}) == 2
    assert pack_protocol({"model_args": "threads=1,parallel=3,ctx=20480,protocol=3"}) == 3
    recorded = {pack.name: pack_protocol(json.loads((pack / "config.json").read_text(encoding="utf-8")))
                for pack in PACKS}
    assert recorded.get("SmolLM2-135M-Instruct.Q4_1", 1) == 1  # recorded before issue 39
    assert recorded.get("qwen2.5-coder-1.5b-instruct-q4_k_m", 4) == 4  # recorded with protocol=4


@pytest.mark.skipif(not SEED_RUNS, reason="no stability seed runs committed under reports/real/stability/")
def test_rescoring_a_pack_keeps_its_replies_and_names_its_model(tmp_path: Path) -> None:
    """`llm_validity.py --rescore`: derived files rewritten from the pack's own replies, its
    config (the model named by its file, no folder of the recording machine) and reply cache
    kept, results.json still naming the model that answered."""
    import shutil

    from llm_validity import DERIVED, portable_model, replay, rescore, same_metrics

    pack = tmp_path / SEED_RUNS[0].parent.name
    shutil.copytree(SEED_RUNS[0].parent, pack)
    cache = tmp_path / "llm_cache.sqlite"
    shutil.copy(REPO / "reports" / "real" / "stability" / "llm_cache.sqlite", cache)
    config, replies = (pack / "config.json").read_bytes(), cache.read_bytes()
    (pack / "results.json").write_text("{}")  # stale: rescoring must rewrite it
    rescore(pack, cache)
    results = json.loads((pack / "results.json").read_text(encoding="utf-8"))
    recorded = json.loads(config)
    assert results["model"] == portable_model(recorded["model"]) == results["config"]["model"]
    assert "/" not in results["model"]
    kept = json.loads((pack / "config.json").read_text(encoding="utf-8"))
    assert kept == {**recorded, "model": results["model"]} and cache.read_bytes() == replies
    assert all((pack / name).exists() for name in DERIVED)
    assert same_metrics(results, replay(pack, tmp_path / "again", cache=cache))


PAPER_SETUP = REPO / "reports" / "real" / "qwen2.5-coder-1.5b-description"


@pytest.mark.skipif(not (PAPER_SETUP / "results.json").is_file(), reason="the paper-setup Qwen pack is not committed")
def test_the_paper_setup_pack_builds_the_situations_its_plans_claim(tmp_path: Path) -> None:
    """Issue 46: with Qwen2.5-Coder-1.5B under protocol 7, LogicEnvGen's environments realise the
    situation their plan claims (`realised_share` >= 0.90), each environment of a task another
    one; the same replies replayed under protocol 6 (kept in the cache) give the 0.5625 of the
    recording before, whose bathroom plan put one bottle in two places."""
    from llm_validity import replay

    recorded = json.loads((PAPER_SETUP / "results.json").read_text(encoding="utf-8"))
    assert recorded["protocol"] == 7 and recorded["results"]["logicenvgen"]["realised_share"] >= 0.90
    for task in recorded["tasks"]:
        plan = PAPER_SETUP / "envs" / "logicenvgen" / task / "plan.json"
        if plan.is_file():
            claimed = json.loads(plan.read_text(encoding="utf-8"))["trajectories"]
            assert len(set(claimed)) == len(claimed) > 1, task
    before = replay(PAPER_SETUP, tmp_path, protocol=6)
    assert before["protocol"] == 6 and before["results"]["logicenvgen"]["realised_share"] == 0.5625
