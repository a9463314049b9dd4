"""What a controller draws for a step: lines, circles, polygons, arrows and text in world
coordinates (metres), shown by `dream view` and `dream render`, never read by the world.

Mirrors agents/include/dream/agents/framework/drawing.h, bounds included (drawing_t's in
lcmtypes/dream/drawing_t.lcm): past them a shape is left out, a polygon cut to its first
MAX_POLYGON_POINTS corners, a text cut to MAX_TEXT_BYTES between characters; a shape with a
coordinate that is not finite or past 100 m, or a size past 10 m, is left out; a text's
characters that are not printable become '?'. Each is counted with its reason (`clipped`,
`clip_reasons`); the agent host logs each reason once per robot. Arguments of the wrong
type (a point that is no pair of numbers, an unknown colour) raise: that is the controller's bug.
"""

import math

LINE, CIRCLE, POLYGON, ARROW, TEXT = 1, 2, 3, 4, 5
MAX_SHAPES = 64
MAX_POLYGON_POINTS = 64
MAX_POINTS = 1024
MAX_TEXT_BYTES = 96
MAX_ALL_TEXT_BYTES = 2048
MAX_ABS_COORDINATE_M = 100.0
MAX_SIZE_M = 10.0

# matplotlib's single-letter colours and a few names, as 0xRRGGBB.
COLOURS = {"k": 0x000000, "black": 0x000000, "w": 0xFFFFFF, "white": 0xFFFFFF, "r": 0xFF0000, "red": 0xD62728,
           "g": 0x008000, "green": 0x2CA02C, "b": 0x0000FF, "blue": 0x1F77B4, "c": 0x00BFBF, "cyan": 0x17BECF,
           "m": 0xBF00BF, "magenta": 0xBF00BF, "y": 0xBFBF00, "yellow": 0xBCBD22, "orange": 0xFF7F0E,
           "purple": 0x9467BD, "gray": 0x7F7F7F, "grey": 0x7F7F7F, "brown": 0x8C564B, "pink": 0xE377C2}


def rgba_of(colour, alpha=None):
    """`colour` as 0xRRGGBBAA: a name of COLOURS, "#rrggbb", "#rrggbbaa", or (r, g, b[, a]) in 0..1;
    `alpha` (0..1), when given, replaces its opacity. Raises ValueError naming what is wrong."""
    if isinstance(colour, str):
        text = colour.strip().lower()
        if text in COLOURS:
            rgba = (COLOURS[text] << 8) | 0xFF
        elif text.startswith("#") and len(text) in (7, 9) and all(c in "0123456789abcdef" for c in text[1:]):
            rgba = int(text[1:], 16) if len(text) == 9 else (int(text[1:], 16) << 8) | 0xFF
        else:
            raise ValueError(f"colour {colour!r}: expected a name ({', '.join(sorted(COLOURS))}), "
                             "'#rrggbb' or '#rrggbbaa'")
    else:
        try:
            parts = [float(part) for part in colour]
        except (TypeError, ValueError):
            raise ValueError(f"colour {colour!r}: expected a name, '#rrggbb' or (r, g, b[, a]) in 0..1") from None
        if len(parts) not in (3, 4) or not all(0.0 <= part <= 1.0 for part in parts):
            raise ValueError(f"colour {colour!r}: (r, g, b[, a]) needs 3 or 4 numbers in 0..1")
        parts += [1.0] * (4 - len(parts))
        rgba = 0
        for part in parts:
            rgba = (rgba << 8) | int(round(part * 255))
    if alpha is not None:
        alpha = float(alpha)
        if not 0.0 <= alpha <= 1.0:
            raise ValueError(f"alpha {alpha}: expected 0..1")
        rgba = (rgba & ~0xFF) | int(round(alpha * 255))
    return rgba


def _point(value, what):
    """`value`'s first two numbers (a pose [x, y, theta] gives its position)."""
    try:
        return (float(value[0]), float(value[1]))
    except (TypeError, ValueError, IndexError, KeyError):
        raise ValueError(f"{what} {value!r}: expected a point [x, y] of numbers (metres)") from None


def _number(value, what):
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{what} {value!r}: expected a number") from None


def _printable(text):
    """`text` with each non-printable character made '?', and how many were."""
    out = []
    bad = 0
    for char in text:
        code = ord(char)
        if code < 0x20 or code == 0x7F or 0xD800 <= code <= 0xDFFF:
            out.append("?")
            bad += 1
        else:
            out.append(char)
    return "".join(out), bad


class Shape:
    """One drawn shape: kind (LINE..TEXT), points [(x, y)], size (circle radius, text height),
    rgba, width (metres), fill, text."""

    __slots__ = ("kind", "points", "size", "rgba", "width", "fill", "text")

    def __init__(self, kind, points, size, rgba, width, fill, text=""):
        self.kind, self.points, self.size = kind, points, size
        self.rgba, self.width, self.fill, self.text = rgba, width, fill, text

    def key(self):
        return (self.kind, tuple(self.points), self.size, self.rgba, self.width, self.fill, self.text)


class Drawing:
    """One robot's drawing for one step, bounded (see the module's doc)."""

    def __init__(self):
        self.shapes = []
        self.clipped = 0
        self.clip_reasons = {}
        self._points = 0
        self._text_bytes = 0

    def key(self):
        """What tells two drawings apart (the host sends a drawing only when it changed)."""
        return (tuple(shape.key() for shape in self.shapes), self.clipped)

    def _clip(self, reason, amount=1):
        self.clipped += amount
        self.clip_reasons[reason] = self.clip_reasons.get(reason, 0) + amount

    def _bounded_text(self, text):
        text, bad = _printable(str(text))
        if bad:
            self._clip("a text character that is not printable (made '?')", bad)
        data = text.encode("utf-8")
        room = min(MAX_TEXT_BYTES, MAX_ALL_TEXT_BYTES - self._text_bytes)
        if len(data) <= room:
            return text
        kept = data[:room].decode("utf-8", "ignore")  # cut between characters
        self._clip(f"text bytes past {MAX_TEXT_BYTES} in one text or {MAX_ALL_TEXT_BYTES} in one step (cut)",
                   len(data) - len(kept.encode("utf-8")))
        return kept

    def add(self, shape):
        if len(self.shapes) >= MAX_SHAPES:
            self._clip(f"more than {MAX_SHAPES} shapes in one step (left out)")
            return
        if not all(math.isfinite(c) and abs(c) <= MAX_ABS_COORDINATE_M for point in shape.points for c in point):
            self._clip("a point that is not finite or past 100 m (shape left out)")
            return
        if not all(math.isfinite(v) and 0.0 <= v <= MAX_SIZE_M for v in (shape.size, shape.width)):
            self._clip("a size or width that is not finite, negative or past 10 m (shape left out)")
            return
        if self._points + len(shape.points) > MAX_POINTS:
            self._clip(f"more than {MAX_POINTS} points in one step (shape left out)")
            return
        if shape.kind == TEXT:
            shape.text = self._bounded_text(shape.text)
            self._text_bytes += len(shape.text.encode("utf-8"))
        if shape.kind not in (CIRCLE, POLYGON):
            shape.fill = False
        self._points += len(shape.points)
        self.shapes.append(shape)

    def line(self, start, end, color="k", width=0.01, alpha=None):
        self.add(Shape(LINE, [_point(start, "start"), _point(end, "end")], 0.0, rgba_of(color, alpha),
                       _number(width, "width"), False))

    def arrow(self, start, end, color="k", width=0.01, alpha=None):
        self.add(Shape(ARROW, [_point(start, "start"), _point(end, "end")], 0.0, rgba_of(color, alpha),
                       _number(width, "width"), False))

    def circle(self, center, radius, color="k", width=0.01, fill=False, alpha=None):
        self.add(Shape(CIRCLE, [_point(center, "center")], _number(radius, "radius"), rgba_of(color, alpha),
                       _number(width, "width"), bool(fill)))

    def polygon(self, points, color="k", width=0.01, fill=False, alpha=None):
        try:
            corners = [_point(point, "polygon point") for point in points]
        except TypeError:
            raise ValueError(f"polygon points {points!r}: expected a list of [x, y]") from None
        if len(corners) < 3:
            self._clip("a polygon of fewer than 3 corners (left out)")
            return
        if len(corners) > MAX_POLYGON_POINTS:
            self._clip(f"polygon corners past {MAX_POLYGON_POINTS} (cut)", len(corners) - MAX_POLYGON_POINTS)
            corners = corners[:MAX_POLYGON_POINTS]
        self.add(Shape(POLYGON, corners, 0.0, rgba_of(color, alpha), _number(width, "width"), bool(fill)))

    def text(self, at, text, color="k", height=0.06, alpha=None):
        self.add(Shape(TEXT, [_point(at, "at")], _number(height, "height"), rgba_of(color, alpha), 0.0, False,
                       str(text)))

    def message(self, drawing_t):
        """This drawing as a drawing_t (lcm-gen's Python type), header fields left for the caller."""
        message = drawing_t()
        message.clipped = min(self.clipped, 2**31 - 1)
        message.num_shapes = len(self.shapes)
        message.kind = [shape.kind for shape in self.shapes]
        message.rgba = [shape.rgba - (1 << 32) if shape.rgba >= (1 << 31) else shape.rgba for shape in self.shapes]
        message.width = [shape.width for shape in self.shapes]
        message.size = [shape.size for shape in self.shapes]
        message.fill = [1 if shape.fill else 0 for shape in self.shapes]
        message.point_count = [len(shape.points) for shape in self.shapes]
        texts = [shape.text.encode("utf-8") for shape in self.shapes]
        message.text_length = [len(text) for text in texts]
        message.x = [x for shape in self.shapes for x, _ in shape.points]
        message.y = [y for shape in self.shapes for _, y in shape.points]
        message.num_points = len(message.x)
        message.text = b"".join(texts)
        message.num_text_bytes = len(message.text)
        return message


# What take_drawing() hands over when the robot drew nothing (most steps of most controllers): one
# shared empty drawing, never added to, so a step without drawing costs no allocation.
NOTHING_DRAWN = Drawing()
EMPTY_KEY = NOTHING_DRAWN.key()
