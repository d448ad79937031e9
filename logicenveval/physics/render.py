"""Top-down renders of an EnvSpec (x to the right, z downwards), SVG text and PNG via Pillow.

Both renders draw the same scene description, so the output is deterministic: rooms (grey),
walls, doors (brown gaps), windows (blue), object footprints labelled by role or id, and every
room/object/door named by a failure outlined in red.
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
    for s in shapes:
        if s.kind in ("room", "object"):
            cx = sum(p[0] for p in s.points) / len(s.points)
            cz = sum(p[1] for p in s.points) / len(s.points)
            x, y = v.px((cx, cz))
            size = 14 if s.kind == "room" else 10
            color = _RED if s.failed else ("#777777" if s.kind == "room" else "#08306b")
            dy = -size * 2 if s.kind == "room" else 0
            out.append(f'<text x="{x}" y="{y + dy}" font-size="{size}" text-anchor="middle" '
                       f'fill="{color}">{escape(s.label)}</text>')
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
    for s in shapes:
        if s.kind in ("room", "object"):
            cx = sum(p[0] for p in s.points) / len(s.points)
            cz = sum(p[1] for p in s.points) / len(s.points)
            x, y = v.px((cx, cz))
            color = _RED if s.failed else ("#777777" if s.kind == "room" else "#08306b")
            dy = -28 if s.kind == "room" else 0
            draw.text((x, y + dy), s.label, fill=color, font=font, anchor="mm")
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    img.save(str(path), format="PNG", optimize=False)
