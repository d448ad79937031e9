"""The embedded `offline` model: a deterministic, rule-based ChatModel that answers every request
kind from its payload alone, as a careful reader of the text would (no network, no ground truth).

One room for the whole model: `lexicon` and `sentences` (word forms, word tables, sentence
splitting), `analysis` (the reader: factors and facts of a description), `placement` (the
placements a description states), `naming` (the objects it names), `realise` (a situation's facts
as objects), `plan` (the planner's answers: subtasks, factors, trees), `scene_answers` and
`baseline_answers` (the scene and comparison methods' request kinds), `handlers` (the registry of
answers per request kind) and `model` (`OfflineModel`, which registers every answer when made).
`llm.registry` makes it by a lazily imported name, so `llm` never imports this package.
"""
