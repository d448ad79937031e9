"""Top-down renders of an EnvSpec, seen from above (+y): +x to the right, +z up, as in
docs/envspec.md's axes (AI2-THOR's left-handed frame). SVG text and PNG via Pillow.

Both renders draw the same scene description, so the output is deterministic: rooms (grey),
walls, doors (brown gaps), windows (blue), object footprints labelled by role or id, and every
room/object/door named by a failure outlined in red. Labels are placed so that they do not
overlap (`_labels`): a label that would cover another moves up or down by a line, with a thin
leader to its object, and none runs off the picture. Under the plan, a legend band says what
the colours mean, and holds a 1 m scale bar and the +x/+z axes, so a picture read alone is
read right.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path
from xml.sax.saxutils import escape

import shapely
from PIL import Image, ImageDraw, ImageFont

from logicenveval.model.envspec import EnvSpec
from logicenveval.physics.geometry import build_bodies
from logicenveval.physics.report import PhysicsReport

_RED = "#d62728"
_INK = "#333333"
_RED_FILL = "#f7b6b6"


@dataclass(frozen=True)
class _Shape:
    kind: str                       # room | door | window | object
    points: list[tuple[float, float]]
    label: str
    failed: bool


#: metres; shapes farther out are left out of the picture (the checker reports them), so that
#: absurd coordinates cannot overflow the pixel arithmetic
_FAR = 1e4


def _scene(env: EnvSpec, report: PhysicsReport | None) -> list[_Shape]:
    bad: set[str] = set()
    if report is not None:
        for f in report.failures():
            bad.update(f.objects)
            bad.update(f.rooms)
    labels = {oid: role for role, oid in sorted(env.roles.items()) if oid is not None}
    shapes = [_Shape("room", [(p[0], p[1]) for p in r.polygon], r.id, r.id in bad)
              for r in env.rooms if r.polygon is not None and len(r.polygon) >= 3]
    for body in sorted(build_bodies(env).values(), key=lambda b: (b.top, b.id)):
        pts = [(x, z) for x, z in shapely.get_coordinates(body.footprint.exterior)[:-1].tolist()]
        if pts:
            shapes.append(_Shape("object", pts, labels.get(body.id, body.id), body.id in bad))
    shapes += [_Shape("door", [(p[0], p[1]) for p in d.segment], d.id, d.id in bad)
               for d in env.doors if d.segment is not None]
    shapes += [_Shape("window", [(p[0], p[1]) for p in w.segment], w.id, w.id in bad)
               for w in env.windows if w.segment is not None]
    return [s for s in shapes if _drawable(s.points)]


def _drawable(points: list[tuple[float, float]]) -> bool:
    """Every coordinate finite and within `_FAR` (a NaN compares false, so it is left out too)."""
    return all(abs(x) <= _FAR and abs(z) <= _FAR for x, z in points)


#: the legend's entries: (kind, text); "failed" is the red of a shape named by a failure
_LEGEND = (("room", "room"), ("object", "object"), ("door", "door"), ("window", "window"),
           ("failed", "named by a failure"))
_LEGEND_ROW = 22
#: pixels a legend entry takes: swatch, gap, text (~6 px a character at 11 px)
_SWATCH, _CHAR = 16, 6.2
_AXES_W, _SCALE_W = 84, 24


def _entry_width(text: str) -> float:
    return _SWATCH + 6 + _CHAR * len(text) + 14


def _legend_rows(width: float, margin: float, scale: float) -> list[list[tuple[str, str, float]]]:
    """The legend's entries (kind, text, x) wrapped into rows that fit `width`; the axes and the
    scale bar come first."""
    items = [("axes", "", _AXES_W), ("scale", "1 m", scale + _SCALE_W)]
    items += [(k, t, _entry_width(t)) for k, t in _LEGEND]
    rows: list[list[tuple[str, str, float]]] = [[]]
    x = margin
    for kind, text, w in items:
        if rows[-1] and x + w > width - margin / 2:
            rows.append([])
            x = margin
        rows[-1].append((kind, text, x))
        x += w
    return rows


class _View:
    """Maps metres to pixels with a margin, keeping the aspect ratio: +x right, +z up."""

    def __init__(self, shapes: list[_Shape], scale: float = 80.0, margin: float = 30.0) -> None:
        xs = [p[0] for s in shapes for p in s.points] or [0.0, 1.0]
        zs = [p[1] for s in shapes for p in s.points] or [0.0, 1.0]
        self.x0, self.z1 = min(xs), max(zs)
        self.scale, self.margin = scale, margin
        self.width = int(round((max(xs) - self.x0) * scale + 2 * margin))
        self.plan_height = int(round((self.z1 - min(zs)) * scale + 2 * margin))
        self.legend = _legend_rows(self.width, margin, scale)
        self.height = self.plan_height + _LEGEND_ROW * len(self.legend) + 8

    def px(self, p: tuple[float, float]) -> tuple[float, float]:
        return (round((p[0] - self.x0) * self.scale + self.margin, 2),
                round((self.z1 - p[1]) * self.scale + self.margin, 2))


@dataclass(frozen=True)
class _Label:
    x: float
    y: float  # the label's vertical middle
    size: int
    color: str
    text: str
    #: the object's centre when the label moved off it (a leader line is drawn), else None
    leader: tuple[float, float] | None


#: candidate vertical shifts of a label, in lines, tried in order
_SHIFTS = (0, 1, -1, 2, -2, 3, -3, 4, -4)


def _box(x: float, y: float, text: str, size: int) -> tuple[float, float, float, float]:
    half_w = 0.3 * size * len(text) + 1  # sans-serif averages ~0.6 em per character
    half_h = 0.6 * size
    return (x - half_w, y - half_h, x + half_w, y + half_h)


def _overlap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> float:
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return w * h if w > 0 and h > 0 else 0.0


def _covered(a: tuple[float, float, float, float], placed: list[tuple[float, float, float, float]]) -> float:
    """`sum(_overlap(a, b) for b in placed)`, inlined: label placement tries up to nine places
    per label against every label placed, the bulk of a render's time. Only the boxes that
    overlap add, in the same order, so the sum is the very same float."""
    ax0, ay0, ax1, ay1 = a
    total = 0.0
    for bx0, by0, bx1, by1 in placed:
        w = min(ax1, bx1) - max(ax0, bx0)
        if w > 0:
            h = min(ay1, by1) - max(ay0, by0)
            if h > 0:
                total += w * h
    return total


def _labels(shapes: list[_Shape], v: _View) -> list[_Label]:
    """Room and object labels, greedily placed (rooms, then objects smallest first) without overlaps."""
    def area(s: _Shape) -> float:
        xs, zs = [p[0] for p in s.points], [p[1] for p in s.points]
        return (max(xs) - min(xs)) * (max(zs) - min(zs))

    items = [s for s in shapes if s.kind == "room"] + sorted(
        (s for s in shapes if s.kind == "object"), key=lambda s: (area(s), s.label))
    placed: list[tuple[float, float, float, float]] = []
    out = []
    for s in items:
        cx = sum(p[0] for p in s.points) / len(s.points)
        cz = sum(p[1] for p in s.points) / len(s.points)
        x0, y0 = v.px((cx, cz))
        size = 14 if s.kind == "room" else 10
        base = y0 - 2 * size if s.kind == "room" else y0
        half_w = 0.3 * size * len(s.label) + 1
        x = min(max(x0, half_w + 2), max(v.width - half_w - 2, half_w + 2))
        best: tuple[float, float] | None = None
        best_cost = float("inf")
        for shift in _SHIFTS:
            y = min(max(base + shift * (size + 2), size), max(v.plan_height - size, size))
            cost = _covered(_box(x, y, s.label, size), placed)
            if cost < best_cost:
                best, best_cost = (x, y), cost
            if cost == 0:
                break
        assert best is not None
        placed.append(_box(best[0], best[1], s.label, size))
        color = _RED if s.failed else ("#777777" if s.kind == "room" else "#08306b")
        moved = s.kind == "object" and abs(best[1] - y0) > size
        out.append(_Label(round(best[0], 2), round(best[1], 2), size, color, s.label,
                          (x0, y0) if moved else None))
    return out


_STYLE = {"room": ("#f2f2f2", _INK, 3), "object": ("#9ecae1", "#3182bd", 1),
          "door": (None, "#8c564b", 6), "window": (None, "#17becf", 5)}


@dataclass(frozen=True)
class _Mark:
    """One drawing primitive of the legend band, drawn alike by the SVG and the PNG writer."""

    kind: str  # rect | line | text
    points: tuple[tuple[float, float], ...]
    fill: str | None = None
    stroke: str | None = None
    width: int = 1
    text: str = ""
    anchor: str = "start"  # start | middle


def _legend_marks(width: int, plan_height: int, scale: float,
                  legend: list[list[tuple[str, str, float]]]) -> list[_Mark]:
    """Axes (+x right, +z up), a 1 m scale bar and the colour legend, under the plan (a
    `_View`'s width, plan height, scale and legend rows)."""
    out = [_Mark("line", ((0, plan_height), (width, plan_height)), stroke="#dddddd")]
    for i, row in enumerate(legend):
        y = plan_height + 8 + _LEGEND_ROW * i + _LEGEND_ROW / 2
        for kind, text, x in row:
            if kind == "axes":  # an L: +x to the right, +z up
                ox, oy = x + 4, y + 7
                out += [_Mark("line", ((ox, oy), (ox + 22, oy)), stroke=_INK),
                        _Mark("line", ((ox + 17, oy - 3), (ox + 22, oy), (ox + 17, oy + 3)), stroke=_INK),
                        _Mark("text", ((ox + 25, oy),), fill=_INK, text="+x"),
                        _Mark("line", ((ox, oy), (ox, oy - 16)), stroke=_INK),
                        _Mark("line", ((ox - 3, oy - 11), (ox, oy - 16), (ox + 3, oy - 11)), stroke=_INK),
                        _Mark("text", ((ox + 5, oy - 13),), fill=_INK, text="+z")]
            elif kind == "scale":
                out += [_Mark("line", ((x, y + 4), (x + scale, y + 4)), stroke=_INK, width=2),
                        _Mark("line", ((x, y), (x, y + 8)), stroke=_INK),
                        _Mark("line", ((x + scale, y), (x + scale, y + 8)), stroke=_INK),
                        _Mark("text", ((x + scale / 2, y - 4),), fill=_INK, text=text, anchor="middle")]
            else:
                box = ((x, y - 6), (x + _SWATCH, y + 6))
                if kind == "failed":
                    out.append(_Mark("rect", box, fill=_RED_FILL, stroke=_RED, width=2))
                elif kind in ("door", "window"):
                    out.append(_Mark("line", ((x, y), (x + _SWATCH, y)), stroke=_STYLE[kind][1],
                                     width=_STYLE[kind][2]))
                else:
                    fill, stroke, _ = _STYLE[kind]
                    out.append(_Mark("rect", box, fill=fill, stroke=stroke, width=1))
                out.append(_Mark("text", ((x + _SWATCH + 6, y),), fill=_INK, text=text))
    return out


def _svg_mark(m: _Mark) -> str:
    """One legend mark, inside a group that sets its defaults (no fill, dark stroke and text)."""
    if m.kind == "rect":
        (x0, y0), (x1, y1) = m.points
        return (f'<rect x="{x0:g}" y="{y0:g}" width="{x1 - x0:g}" height="{y1 - y0:g}" fill="{m.fill}" '
                f'stroke="{m.stroke}" stroke-width="{m.width}"/>')
    if m.kind == "line":
        pts = " ".join(f"{x:g},{y:g}" for x, y in m.points)
        stroke = "" if m.stroke == _INK else f' stroke="{m.stroke}"'
        width = "" if m.width == 1 else f' stroke-width="{m.width}"'
        return f'<polyline points="{pts}"{stroke}{width}/>'
    (x, y), = m.points
    anchor = "" if m.anchor == "start" else f' text-anchor="{m.anchor}"'
    return f'<text x="{x:g}" y="{y:g}"{anchor} fill="{m.fill}" stroke="none">{escape(m.text)}</text>'


def render_svg(env: EnvSpec, report: PhysicsReport | None = None) -> str:
    shapes = _scene(env, report)
    v = _View(shapes)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{v.width}" height="{v.height}" '
           f'viewBox="0 0 {v.width} {v.height}" font-family="sans-serif">',
           f'<rect width="{v.width}" height="{v.height}" fill="white"/>']
    x0, z1, scale, margin = v.x0, v.z1, v.scale, v.margin  # `v.px`, inlined: ~9 points a shape
    for s in shapes:
        fill, stroke, width = _STYLE[s.kind]
        stroke = _RED if s.failed else stroke
        fill = _RED_FILL if s.failed and s.kind == "object" else fill
        pts = " ".join(f"{round((x - x0) * scale + margin, 2)},{round((z1 - z) * scale + margin, 2)}"
                       for x, z in s.points)
        if s.kind in ("room", "object"):
            out.append(f'<polygon points="{pts}" fill="{fill}" stroke="{stroke}" stroke-width="{width}"/>')
        else:
            out.append(f'<polyline points="{pts}" fill="none" stroke="{stroke}" stroke-width="{width}"/>')
    labels = _labels(shapes, v)
    out += [f'<line x1="{lb.leader[0]}" y1="{lb.leader[1]}" x2="{lb.x}" y2="{lb.y}" stroke="#9a9a9a" '
            'stroke-width="0.6"/>' for lb in labels if lb.leader is not None]
    # labels share their look through a group (a render holds dozens of them)
    out.append('<g text-anchor="middle" dominant-baseline="middle" stroke="white" stroke-width="2.5" '
               'paint-order="stroke" font-size="10">')
    for lb in labels:
        size = "" if lb.size == 10 else f' font-size="{lb.size}"'
        out.append(f'<text x="{lb.x}" y="{lb.y}"{size} fill="{lb.color}">{escape(lb.text)}</text>')
    out.append("</g>")
    out.append(f'<g fill="none" stroke="{_INK}" font-size="11" dominant-baseline="middle">')
    out.append(_legend_svg(v.width, v.plan_height, v.scale, v.margin))
    out += ["</g>", "</svg>"]
    return "\n".join(out) + "\n"


@functools.lru_cache(maxsize=256)
def _legend_svg(width: int, plan_height: int, scale: float, margin: float) -> str:
    """The legend band's SVG lines: a function of the picture's size alone, and environments of
    one task share their size (a run draws ~650 renders)."""
    marks = _legend_marks(width, plan_height, scale, _legend_rows(width, margin, scale))
    return "\n".join(_svg_mark(m) for m in marks)


def render_png(env: EnvSpec, path: str | Path, report: PhysicsReport | None = None) -> None:
    """Write the same drawing as `render_svg` as a PNG (Pillow, default bitmap font)."""
    shapes = _scene(env, report)
    v = _View(shapes)
    img = Image.new("RGB", (max(v.width, 1), max(v.height, 1)), "white")
    draw = ImageDraw.Draw(img)
    font = ImageFont.load_default()
    for s in shapes:
        fill, stroke, width = _STYLE[s.kind]
        stroke = _RED if s.failed else stroke
        fill = _RED_FILL if s.failed and s.kind == "object" else fill
        pts = [v.px(p) for p in s.points]
        if s.kind in ("room", "object"):
            draw.polygon(pts, fill=fill, outline=stroke, width=width)
        else:
            draw.line(pts, fill=stroke, width=width)
    for label in _labels(shapes, v):
        if label.leader is not None:
            draw.line([label.leader, (label.x, label.y)], fill="#9a9a9a", width=1)
        draw.text((label.x, label.y), label.text, fill=label.color, font=font, anchor="mm")
    for m in _legend_marks(v.width, v.plan_height, v.scale, v.legend):
        if m.kind == "rect":
            draw.rectangle(m.points, fill=m.fill, outline=m.stroke, width=m.width)
        elif m.kind == "line":
            draw.line(m.points, fill=m.stroke, width=m.width)
        else:
            draw.text(m.points[0], m.text, fill=m.fill, font=font, anchor="mm" if m.anchor == "middle" else "lm")
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    img.save(str(path), format="PNG", optimize=False)
