"""Shared fixtures."""

from __future__ import annotations

from collections.abc import Iterator

import pytest


@pytest.fixture
def no_procthor(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """Behave as without the `[procthor]` extra: no installed ProcTHOR databases are found."""
    from logicenveval.scene import procthor

    monkeypatch.setattr(procthor, "installed_procthor_db", lambda: None)
    yield
