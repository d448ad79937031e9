"""Word forms by a maintained lemmatiser (lemminflect), for every layer that compares names.

The judge resolves an object's name to a catalog kind (`domain.categories`) and the embedded
model reads a description (`offline.lexicon`); both need a plural's singular, and they must agree,
so the one rule lives here, below both. lemminflect's dictionary knows the irregular plurals
(shelves, knives, children, cacti) and the plural-only nouns (clothes, scissors, jeans) that
suffix rules get wrong ("vases" -> "vas", "clothes" -> "clothe", "potatoes" -> "potatoe").
"""

from __future__ import annotations

import re
from functools import lru_cache

from lemminflect import getAllLemmas, getInflection, getLemma

#: the plural of a two-letter initialism: two consonants and an "s" ("cds", "tvs")
_INITIALISM_PLURAL = re.compile(r"[b-df-hj-np-tv-z]{2}s")


@lru_cache(maxsize=16384)
def noun_lemma(word: str) -> str:
    """The noun lemma of `word`: lemminflect's dictionary (irregular plurals: shelves, knives,
    children; of two, the one that is not a verb's: leaves -> leaf), then its rules for a word it
    does not know that ends in -s ("tins"). Words of three letters or fewer ("was", "has", "its")
    stay as written, but for the plural of a two-letter initialism ("cds", "tvs", "pcs": no vowel
    before the "s"), which is its letters."""
    if len(word) <= 3:
        return word[:2] if _INITIALISM_PLURAL.fullmatch(word) else word
    known = getAllLemmas(word, upos="NOUN").get("NOUN")
    if known:
        # "leaves": the noun "leaf", not the verb "leave" (read as an action elsewhere)
        verbs = set(getAllLemmas(word, upos="VERB").get("VERB", ()))
        return str(next((lemma for lemma in known if lemma not in verbs and lemma != word), known[0]))
    if word.endswith("s") and not word.endswith("ss"):
        return str(getLemma(word, upos="NOUN")[0])
    return word


@lru_cache(maxsize=16384)
def noun_lemmas(word: str) -> tuple[str, ...]:
    """Every noun lemma lemminflect gives `word` ("glasses": glass, glasses), `noun_lemma` first."""
    first = noun_lemma(word)
    rest = [str(x) for x in getAllLemmas(word, upos="NOUN").get("NOUN", ()) if x != first]
    return (first, *rest)


@lru_cache(maxsize=16384)
def noun_plurals(word: str) -> tuple[str, ...]:
    """The plural forms of the noun `word` (lemminflect: "key" -> "keys", "box" -> "boxes")."""
    return tuple(str(x) for x in getInflection(word, "NNS") or ())
