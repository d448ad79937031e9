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
