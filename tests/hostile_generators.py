"""Generators that misbehave on purpose (issue 27), importable by worker processes as
`hostile_generators:<Class>` (the tests folder is on the Python path of pytest and of the CLI
subprocesses the tests start with it as the working folder)."""

from __future__ import annotations

import json
import os
import signal
import time
from pathlib import Path
from typing import Any

from logicenveval.generators.base import GenerationContext, GenerationResult
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import TaskBrief

FIXTURE = Path(__file__).parent / "fixtures" / "envs" / "one_room.json"
#: env ids a plug-in might return: every kind of path trick, and one plain id
HOSTILE_IDS = ["/tmp/logicenveval-hostile-abs", "../../escaped", "sub/../a", "a", "", "nul\x00id",
               "x" * 300, ".hidden", "A"]


def fixture_env(brief: TaskBrief, env_id: str = "env-1") -> EnvSpec:
    data = json.loads(FIXTURE.read_text())
    data.update(env_id=env_id, task_id=brief.id)
    return EnvSpec.model_validate(data)


class _Base:
    name = "hostile"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        raise NotImplementedError


class Ids(_Base):
    name = "ids"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        env = fixture_env(brief)
        return GenerationResult(envs=[env.model_copy(update={"env_id": i}) for i in HOSTILE_IDS])


class ReturnsNone(_Base):
    name = "returns-none"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        return None


class ReturnsDict(_Base):
    name = "returns-dict"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        return {"envs": [fixture_env(brief)]}


class NotEnvSpecItems(_Base):
    name = "not-envspecs"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        return GenerationResult.model_construct(envs=[{"env_id": "x"}, 3], artifacts={}, failures=[])


class CircularArtifacts(_Base):
    name = "circular"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        loop: dict[str, Any] = {}
        loop["self"] = loop
        return GenerationResult.model_construct(envs=[fixture_env(brief)], artifacts=loop, failures=[])


class RaisesSystemExit(_Base):
    name = "sys-exit"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        raise SystemExit(3)


class RaisesKeyboardInterrupt(_Base):
    name = "raises-interrupt"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        raise KeyboardInterrupt


class WrongTask(_Base):
    name = "wrong-task"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        mine = fixture_env(brief, "mine")
        other = fixture_env(brief, "other").model_copy(update={"task_id": "kitchen_fridge_restock"})
        return GenerationResult(envs=[mine, other])


class Empty(_Base):
    name = "empty"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        return GenerationResult()


class Many(_Base):
    """10,001 environments for one task (the issue: 10k envs took 1.2 GB)."""

    name = "many"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        env = fixture_env(brief)
        return GenerationResult(envs=[env.model_copy(update={"env_id": f"e{i}"}) for i in range(10_001)])


class Huge(_Base):
    """One environment of 50,000 objects (the issue: 4.5 GB), next to a normal one."""

    name = "huge"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        env = fixture_env(brief, "huge")
        obj = env.objects[0]
        objects = [obj.model_copy(update={"id": f"o{i}"}) for i in range(50_000)]
        return GenerationResult(envs=[fixture_env(brief, "normal"),
                                      env.model_copy(update={"objects": objects, "roles": {}})])


class Forever(_Base):
    """Never returns (a pure-Python loop)."""

    name = "forever"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        while True:
            pass


class Stubborn(_Base):
    """Never returns and ignores the time bound's alarm (as native code that blocks it would)."""

    name = "stubborn"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        signal.signal(signal.SIGALRM, signal.SIG_IGN)
        while True:
            time.sleep(3600)


class Sleeper(_Base):
    """Writes its pid to `<work_dir>/started-<pid>` and sleeps (for the Ctrl-C test)."""

    name = "sleeper"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        assert ctx.work_dir is not None
        ctx.work_dir.mkdir(parents=True, exist_ok=True)
        (ctx.work_dir / f"started-{os.getpid()}").write_text("")
        time.sleep(3600)


class KillsItself(_Base):
    """Dies like an out-of-memory kill on one task, works on the others."""

    name = "kills-itself"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        if brief.id == "kitchen_fridge_restock":
            os.kill(os.getpid(), signal.SIGKILL)
        return GenerationResult(envs=[fixture_env(brief)])


class CatalogVandal(_Base):
    """Changes the shared asset catalog in place: nothing is pickable, a surface or a container."""

    name = "vandal"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        cats = ctx.catalog.categories
        for key, cat in list(cats.items()):
            cats[key] = cat.model_copy(update={"pickable": False, "surface": False,
                                               "container": False, "synonyms": []})
        return GenerationResult(envs=[fixture_env(brief)])


class WithArgs(_Base):
    """A plug-in with factory arguments (`--generator-args`)."""

    def __init__(self, n_envs: int = 1, label: str = "none") -> None:
        self.name = "with-args"
        self.n_envs = n_envs
        self.label = label

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        return GenerationResult(envs=[fixture_env(brief, f"e{i}") for i in range(self.n_envs)],
                                artifacts={"label": self.label})


class ExitsInInit(_Base):
    """A factory that calls sys.exit."""

    def __init__(self) -> None:
        raise SystemExit(4)
