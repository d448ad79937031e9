"""The catalog as the offline reader reads it: each kind's names, then WordNet's as a last resort.

A kind is named in a description by its catalog name or a hand-written synonym
(`benchmark_data/catalog.json`); a word the catalog lacks ("sandals", "the quilt", "a penknife")
would name nothing. `wordnet_names.json`, beside this module, holds more names for the kinds,
derived from WordNet 3.1 (hyponyms of each kind's hand-checked senses,
`benchmark_data/wordnet_senses.json`, by `tools/wordnet_names.py`; WordNet's licence is
`WORDNET_LICENSE`). They are appended after the catalog's own synonyms, and a name whose words
are already a catalog name or synonym is left out, so the catalog's names always win and the
WordNet names only name what nothing else does; nor do they lend their head nouns to the
reader's bare-head rules (`offline.wordnet.is_wordnet_name`). A few names an English dictionary
gives a kind that neither has (`DICTIONARY_NAMES`, each with its dictionary's sense) come after
the catalog's synonyms too. Only the reader reads this catalog: the judge, the generators' prompts
and catalog.json itself keep the catalog's own names (a synonym added there would also change the
catalog's fingerprint, which keys every shipped mutant list).
"""

from __future__ import annotations

from logicenveval.domain.catalog import Catalog, per_catalog
from logicenveval.offline.lexicon import words_of
from logicenveval.offline.wordnet import wordnet_names

#: names an English dictionary gives a catalog kind that neither the catalog nor WordNet 3.1's
#: hyponyms of the kind's senses hold, with the sense (the twenty-ninth session: met as unbound
#: roles of development texts of four sets; each name kept only with the dictionary's sense)
DICTIONARY_NAMES = {
    "shelving": "shelving_unit",  # Oxford: "shelving: shelves collectively"
    "standard lamp": "floor_lamp",  # Oxford (British): "standard lamp: a tall lamp set on the floor"
}


@per_catalog
def reading_catalog(catalog: Catalog) -> Catalog:
    """The catalog with each kind's dictionary and WordNet names appended to its synonyms (for
    kinds it has), skipping a name whose words a catalog name or synonym already has."""
    taken = {words_of(n) for name, cat in catalog.categories.items() for n in (name, *cat.synonyms)}
    extra: dict[str, list[str]] = {}
    for word, kind in [*DICTIONARY_NAMES.items(), *wordnet_names().items()]:
        if kind in catalog.categories and words_of(word) not in taken:
            taken.add(words_of(word))
            extra.setdefault(kind, []).append(word)
    categories = {name: cat.model_copy(update={"synonyms": [*cat.synonyms, *extra[name]]}) if name in extra else cat
                  for name, cat in catalog.categories.items()}
    return catalog.model_copy(update={"categories": categories})
