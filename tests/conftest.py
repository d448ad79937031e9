"""Shared fixtures."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from hypothesis import settings

# Tests never assert wall-clock times: hypothesis's default per-example deadline (200 ms) is one,
# and on a loaded 2-core machine a property test over the scene resolver failed on it once
# (`test_scene_objects.py::test_resolve_never_crashes`, passing alone). Examples still run in full.
settings.register_profile("no_deadline", deadline=None)
settings.load_profile("no_deadline")


@pytest.fixture
def no_procthor(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """Behave as without the `[procthor]` extra: no installed ProcTHOR databases are found."""
    from logicenveval.scene import procthor

    monkeypatch.setattr(procthor, "installed_procthor_db", lambda: None)
    yield
