"""One category vocabulary (logicenveval.domain.categories): any spelling, one catalog key."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task
from logicenveval.cli import main
from logicenveval.domain.catalog import load_catalog
from logicenveval.domain.categories import forms, normalise_env, singular, snake, vocabulary
from logicenveval.domain.roles import prepare_env
from logicenveval.envfiles import env_from_dict
from logicenveval.sim.world import World

CATALOG = load_catalog()
VOCAB = vocabulary(CATALOG)
REFERENCE = Path(__file__).resolve().parents[1] / "reports" / "reference" / "envs" / "logicenvgen"


@pytest.mark.parametrize(("written", "key"), [
    ("Couch", "sofa"), ("Toy Chest", "toy_box"), ("CoffeeTable", "coffee_table"),
    ("wet wipes", "wet_wipe"), ("toy_boxes", "toy_box"), ("ToyBoxes", "toy_box"),
    ("toybox", "toy_box"), ("dishes", "plate"), ("knives", "knife"), ("key", "keys"),
    ("glasses", "glasses"), ("shoes", "shoe"), ("Refrigerator", "fridge"),
    ("kitchen-counters", "kitchen_counter"), ("TVStand", "tv_stand"),
    ("HousePlant", "potted_plant"), ("GarbageCan", "trash_can"), ("LaundryHamper", "hamper"),
])
def test_spellings_synonyms_plurals_and_ai2thor_types_name_one_key(written: str, key: str) -> None:
    assert VOCAB.canonical(written) == key


def test_plural_suffixes_are_stripped_whole() -> None:
    assert singular("toy_boxes") == "toy_box" and singular("dishes") == "dish"
    assert singular("brushes") == "brush" and singular("batteries") == "battery"
    assert forms("brushes")[1] != "brushe"
    assert VOCAB.canonical("brushes") is None  # no brush in the catalog: unknown, not "brushe"


def test_a_name_that_fits_several_prefers_the_task_roles_and_says_so() -> None:
    res = VOCAB.resolve("clock")
    assert res.ambiguous and res.candidates == ("alarm_clock", "wall_clock")
    assert VOCAB.resolve("clock", prefer={"wall_clock"}).category == "wall_clock"
    assert VOCAB.resolve("CounterTop", prefer={"kitchen_island"}).category == "kitchen_counter"  # synonym
    assert VOCAB.resolve("Bed", prefer={"bunk_bed"}).category == "bed"  # the key beats the type


_NAMES = sorted(CATALOG.categories)


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(_NAMES), st.sampled_from(["upper", "camel", "spaced", "plural", "dashed"]))
def test_every_catalog_key_survives_every_spelling(name: str, how: str) -> None:
    words = name.split("_")
    if how == "plural" and name.endswith("s") and not name.endswith("ss"):
        return  # `keys`, `scissors`, `dirty_clothes`: a plural's plural is no spelling
    written = {"upper": name.upper(), "camel": "".join(w.title() for w in words),
               "spaced": " ".join(words), "dashed": "-".join(words),
               "plural": name + ("es" if name.endswith(("s", "x", "ch", "sh")) else "s")}[how]
    got = VOCAB.canonical(written)
    if how == "plural" and snake(written) != name and VOCAB.canonical(snake(written)) not in (None, name):
        return  # the plural is itself another category's name (it wins, by rule 1)
    assert got == name, (written, got)


def test_every_unique_synonym_names_its_category() -> None:
    owners: dict[str, set[str]] = {}
    for name, cat in CATALOG.categories.items():
        for syn in cat.synonyms:
            owners.setdefault(snake(syn), set()).add(name)
    for syn, names in owners.items():
        if len(names) == 1 and syn not in CATALOG.categories:
            assert VOCAB.canonical(syn) == next(iter(names)), syn


def _env(objects: list[dict[str, Any]]) -> Any:
    return env_from_dict({"task_id": "t", "env_id": "e", "rooms": [{"id": "living_room"}],
                          "objects": [{"room": "living_room", **o} for o in objects]})


def test_normalise_env_maps_once_keeps_the_written_name_and_lists_unknowns() -> None:
    env = _env([{"id": "s", "category": "Couch"}, {"id": "b", "category": "toy_boxes"},
                {"id": "k", "category": "toy_box"}, {"id": "d", "category": "Kayak"}])
    out, report = normalise_env(env, CATALOG)
    assert [o.category for o in out.objects] == ["sofa", "toy_box", "toy_box", "Kayak"]
    assert out.obj("s").model_dump()["source_category"] == "Couch"
    assert "source_category" not in out.obj("k").model_dump()
    assert report.mapped == {"Couch": "sofa", "toy_boxes": "toy_box"}
    assert report.unknown == {"Kayak": ["d"]}
    assert any("'Kayak' is not in the catalog" in n for n in report.notes())
    assert normalise_env(out, CATALOG)[0].objects == out.objects  # idempotent


def test_the_simulator_reads_the_mapped_category() -> None:
    world = World.from_env(_env([{"id": "s", "category": "Couch"}, {"id": "f", "category": "Refrigerator"}]),
                           CATALOG)
    assert world.caps("s").surface and world.category("s") == "sofa"
    assert world.caps("f").openable and world.category("f") == "fridge"


#: the reference environments rewritten as a user might write them
SPELLING = {"sofa": "Couch", "toy_box": ["Toy Chest", "toy_boxes"], "coffee_table": "CoffeeTable",
            "wet_wipe": "wet wipes", "book": "Books", "floor_stain": "FloorStain", "mop": "Wet Mop",
            "toy": "Toys", "sofa_pillow": "sofa pillows", "dining_table": "DiningTable",
            "trash_can": "GarbageCan", "bookshelf": "Bookshelves", "rug": "Rugs",
            "light_switch": "LightSwitch"}
TASKS = ("clean_living_room", "living_room_toy_boxes")


def _write_folder(root: Path, respell: bool) -> Path:
    for task in TASKS:
        (root / task).mkdir(parents=True)
        for path in sorted((REFERENCE / task).glob("logicenvgen-*.json")):
            data = json.loads(path.read_text())
            data.pop("roles")  # a foreign tool knows no roles: the harness binds them
            boxes = 0
            for o in data["objects"] if respell else ():
                word = SPELLING.get(o["category"])
                if isinstance(word, list):
                    word, boxes = word[boxes % 2], boxes + 1
                o["category"] = word or o["category"]
            (root / task / path.name).write_text(json.dumps(data))
    return root


def _scores(run_root: Path) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    (run_dir,) = list(run_root.iterdir())
    results = json.loads((run_dir / "results.json").read_text())["results"]["envs"]
    results.pop("st_ms")
    results["ci95"].pop("st_ms", None)
    samples = [json.loads(line) for line in (run_dir / "samples.jsonl").read_text().splitlines()]
    for s in samples:
        s.pop("sim_ms")
        s.pop("categories")
    return results, samples


def test_a_folder_written_with_synonyms_scores_as_with_catalog_keys(tmp_path: Path) -> None:
    for respell in (False, True):
        folder = _write_folder(tmp_path / ("words" if respell else "keys") / "envs", respell)
        assert main(["evaluate", str(folder), "--executor", "inprocess",
                     "--output", str(tmp_path / f"out-{respell}")]) == 0
    keys, key_samples = _scores(tmp_path / "out-False")
    words, word_samples = _scores(tmp_path / "out-True")
    assert words == keys and word_samples == key_samples
    assert words["scevr"] == 1.0 and words["faudr"]["avg"] > 0.5 and words["logcov"] > 0.8
    (run_dir,) = list((tmp_path / "out-True").iterdir())
    first = json.loads((run_dir / "samples.jsonl").read_text().splitlines()[0])
    assert first["categories"]["Couch"] == "sofa" and first["unknown_categories"] == {}


def test_simulate_env_binds_roles_as_evaluate_does(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    folder = _write_folder(tmp_path / "envs", respell=True)
    env_file = next((folder / "clean_living_room").glob("*.json"))
    assert main(["simulate", "--task", "clean_living_room", "--policy", "correct", "--env",
                 str(env_file), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["status"] == "passed"
    task = load_task("clean_living_room")
    prepared = prepare_env(env_from_dict(json.loads(env_file.read_text())), task.roles, CATALOG)
    assert prepared.binding.well_formed and None not in prepared.binding.roles.values()


@pytest.mark.parametrize(("written", "lemma"), [
    ("vases", "vase"), ("Knives", "knife"), ("bookshelves", "bookshelf"), ("potatoes", "potato"),
    ("DirtyClothes", "dirty_clothes"), ("scissors", "scissors"), ("toy_boxes", "toy_box"), ("tvs", "tv"),
])
def test_singulars_come_from_the_lemmatiser(written: str, lemma: str) -> None:
    """Suffix rules read "vases" as "vas", "potatoes" as "potatoe" and "clothes" as "clothe"."""
    assert singular(written) == lemma
    if lemma in CATALOG.categories:
        assert VOCAB.canonical(written) == lemma
