"""The agent's start point: all grid clearances at once, the same point as point by point."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.scene.construct import start_point
from logicenveval.scene.geometry import Rect


def _point_by_point(rect: Rect, fps: list[Rect]) -> tuple[float, float]:
    """The earlier loop of `_Builder.agent`."""
    best, score = (rect.x0 + rect.w / 2, rect.z0 + rect.d / 2), -1.0
    for i in range(1, int(rect.w / 0.25)):
        for j in range(1, int(rect.d / 0.25)):
            x, z = rect.x0 + i * 0.25, rect.z0 + j * 0.25
            clear = min([x - rect.x0, rect.x1 - x, z - rect.z0, rect.z1 - z]
                        + [max(f.x0 - x, x - f.x1, f.z0 - z, z - f.z1) for f in fps])
            if clear > score + 1e-9:
                best, score = (x, z), clear
    return best


_COORD = st.floats(-3, 9, allow_nan=False).map(lambda v: round(v, 2))


@st.composite
def _rect(draw: st.DrawFn, lo: float = 0.0) -> Rect:
    x0, z0 = draw(_COORD), draw(_COORD)
    return Rect(x0, z0, x0 + draw(st.floats(lo, 8)), z0 + draw(st.floats(lo, 8)))


@settings(deadline=None, max_examples=300)
@given(_rect(), st.lists(_rect(0.05), max_size=6))
def test_start_point_is_the_point_by_point_choice(rect: Rect, fps: list[Rect]) -> None:
    point = start_point(rect, fps)
    assert point == _point_by_point(rect, fps)
    assert all(type(v) is float for v in point)


def test_ties_keep_the_first_point_in_x_major_order() -> None:
    # a square room without objects: the centre is the farthest point, whatever the order
    assert start_point(Rect(0.0, 0.0, 2.0, 2.0), []) == (1.0, 1.0)
    # a strip with a row of equally clear points: the first of them
    assert start_point(Rect(0.0, 0.0, 1.0, 0.5), []) == (0.25, 0.25)
    assert start_point(Rect(0.0, 0.0, 0.2, 0.2), []) == (0.1, 0.1)  # too small for the grid: its centre
