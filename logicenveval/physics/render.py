"""Top-down renders of an EnvSpec (x to the right, z downwards), SVG text and PNG via Pillow.

Both renders draw the same scene description, so the output is deterministic: rooms (grey),
walls, doors (brown gaps), windows (blue), object footprints labelled by role or id, and every
room/object/door named by a failure outlined in red. Labels are placed so that they do not
overlap (`_labels`): a label that would cover another moves up or down by a line, with a thin
leader to its object, and none runs off the picture.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from xml.sax.saxutils import escape

from PIL import Image, ImageDraw, ImageFont

from logicenveval.model.envspec import EnvSpec
from logicenveval.physics.geometry import build_bodies, finite
from logicenveval.physics.report import PhysicsReport

_RED = "#d62728"
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
        pts = [(float(x), float(z)) for x, z in list(body.footprint.exterior.coords)[:-1]]
        if pts:
            shapes.append(_Shape("object", pts, labels.get(body.id, body.id), body.id in bad))
    shapes += [_Shape("door", [(p[0], p[1]) for p in d.segment], d.id, d.id in bad)
               for d in env.doors if d.segment is not None]
    shapes += [_Shape("window", [(p[0], p[1]) for p in w.segment], w.id, w.id in bad)
               for w in env.windows if w.segment is not None]
    return [s for s in shapes if finite(*(c for p in s.points for c in p))
            and all(abs(c) <= _FAR for p in s.points for c in p)]


class _View:
    """Maps metres to pixels with a margin, keeping the aspect ratio."""

    def __init__(self, shapes: list[_Shape], scale: float = 80.0, margin: float = 30.0) -> None:
        xs = [p[0] for s in shapes for p in s.points] or [0.0, 1.0]
        zs = [p[1] for s in shapes for p in s.points] or [0.0, 1.0]
        self.x0, self.z0 = min(xs), min(zs)
        self.scale, self.margin = scale, margin
        self.width = int(round((max(xs) - self.x0) * scale + 2 * margin))
        self.height = int(round((max(zs) - self.z0) * scale + 2 * margin))

    def px(self, p: tuple[float, float]) -> tuple[float, float]:
        return (round((p[0] - self.x0) * self.scale + self.margin, 2),
                round((p[1] - self.z0) * self.scale + self.margin, 2))


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
            y = min(max(base + shift * (size + 2), size), max(v.height - size, size))
            cost = sum(_overlap(_box(x, y, s.label, size), b) for b in placed)
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


_STYLE = {"room": ("#f2f2f2", "#333333", 3), "object": ("#9ecae1", "#3182bd", 1),
          "door": (None, "#8c564b", 6), "window": (None, "#17becf", 5)}


def render_svg(env: EnvSpec, report: PhysicsReport | None = None) -> str:
    shapes = _scene(env, report)
    v = _View(shapes)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{v.width}" height="{v.height}" '
           f'viewBox="0 0 {v.width} {v.height}" font-family="sans-serif">',
           f'<rect width="{v.width}" height="{v.height}" fill="white"/>']
    for s in shapes:
        fill, stroke, width = _STYLE[s.kind]
        stroke = _RED if s.failed else stroke
        fill = _RED_FILL if s.failed and s.kind == "object" else fill
        pts = " ".join(f"{x},{y}" for x, y in (v.px(p) for p in s.points))
        if s.kind in ("room", "object"):
            out.append(f'<polygon points="{pts}" fill="{fill}" stroke="{stroke}" stroke-width="{width}"/>')
        else:
            out.append(f'<polyline points="{pts}" fill="none" stroke="{stroke}" stroke-width="{width}"/>')
    for label in _labels(shapes, v):
        if label.leader is not None:
            lx, ly = label.leader
            out.append(f'<line x1="{lx}" y1="{ly}" x2="{label.x}" y2="{label.y}" stroke="#9a9a9a" '
                       'stroke-width="0.6"/>')
        out.append(f'<text x="{label.x}" y="{label.y}" font-size="{label.size}" text-anchor="middle" '
                   f'dominant-baseline="middle" fill="{label.color}" stroke="white" stroke-width="2.5" '
                   f'paint-order="stroke">{escape(label.text)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


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
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    img.save(str(path), format="PNG", optimize=False)
