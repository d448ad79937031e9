"""Prompt templates are loaded once per process, not checked on disk per request."""

from __future__ import annotations

import os

import pytest

from logicenveval.llm import ask


def test_templates_are_not_stat_ed_again_once_loaded(monkeypatch: pytest.MonkeyPatch) -> None:
    first = ask._jinja().get_template("decompose_task.j2")
    text = ask._reply_format()

    def no_stat(path: object) -> float:
        raise AssertionError(f"template {path} checked on disk again")

    monkeypatch.setattr(os.path, "getmtime", no_stat)
    assert ask._jinja().get_template("decompose_task.j2") is first
    assert ask._reply_format() == text and text


def test_factor_answers_are_not_primed_with_a_book_kind_from_protocol_2_on() -> None:
    """Protocol 1 named 'novel' (a kind of book) as an example answer; Qwen2.5-Coder-1.5B then
    added a response `novel` to yes/no factors, identical to `no`, and lost its re-asks on it.
    Protocol 2 gives yes/no or one answer per kind; protocol 1 keeps its text (its packs replay)."""
    from logicenveval.benchmark import load_tasks
    from logicenveval.generators.brief import description_brief

    (task,) = load_tasks(ids=["clean_living_room"])
    payload = {"task": description_brief(task).model_dump(mode="json"),
               "subtask": {"id": "tidy_toy", "description": "put the toy away", "roles": ["toy"]},
               "feedback": []}
    answers = {p: ask.render_messages("identify_factors", payload, {}, protocol=p)[1]["content"]
               for p in (1, 2)}
    assert "(yes, no, novel, ...)" in answers[1]
    assert "novel" not in answers[2] and "yes and no, or one answer per kind" in answers[2]
