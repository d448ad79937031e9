"""The typed outcome of one BT run in one environment (DESIGN.md §5)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

Status = Literal["passed", "precondition_violation", "tree_failure", "goal_unmet", "tick_limit",
                 "unknown_node", "bad_port", "ill_formed"]
STATUSES: tuple[str, ...] = ("passed", "precondition_violation", "tree_failure", "goal_unmet",
                             "tick_limit", "unknown_node", "bad_port", "ill_formed")


class Verdict(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")

    status: Status
    fault_node: str | None = None  # the node's name attribute, else its ID (e.g. "PutIn")
    fault_path: str | None = None  # e.g. "Main/Sequence[0]/Fallback[1]/PutIn[3]"
    message: str = ""
    ticks: int = 0
    trace: list[dict[str, Any]] = Field(default_factory=list)
    goal_holds: bool | None = None  # None when no goal could be computed (ill-formed env)
    goal: str | None = None
    final_state: dict[str, Any] = Field(default_factory=dict)

    @property
    def passed(self) -> bool:
        return self.status == "passed"
