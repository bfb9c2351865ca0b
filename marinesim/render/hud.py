"""The viewer's heads-up display: a text block, strip charts of the motions, the exercise's criteria and
messages, a radar picture of the traffic, and a help panel.

Everything is laid out in pixels with the origin at the top-left of the target; the shaders
(``shaders/hud_text.*``, ``shaders/hud_line.*``) turn pixels into clip space with a ``viewport``
uniform. Text is a glyph atlas of printable ASCII (DejaVu Sans Mono, bundled with matplotlib)
drawn as instanced quads; panels are translucent triangles and charts are 1-pixel lines, both
from one dynamic vertex buffer. GL objects are made once in ``Hud.__init__``; each frame only
orphans and rewrites the two vertex buffers.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import moderngl
import numpy as np
from matplotlib.font_manager import FontProperties, findfont
from PIL import Image, ImageDraw, ImageFont

from marinesim.constants import NAUTICAL_MILE
from marinesim.errors import require_positive
from marinesim.gl import GraphicsError, Program
from marinesim.offshore.traffic import cpa

FIRST_CHAR, LAST_CHAR = 32, 126
"""The atlas holds printable ASCII; anything else is drawn as '?'."""
ATLAS_COLUMNS = 16
MARGIN = 8
"""Gap between the HUD's panels and the edges of the target, px at :data:`FONT_PX` and below (scaled with a larger
font, as :attr:`Hud.margin`)."""
PAD = 6
"""Gap between a panel's edge and its text, px at :data:`FONT_PX` and below (:attr:`Hud.pad`)."""
CHART_SIZE = (360, 70)
"""A strip chart's panel at :data:`FONT_PX`, px (scaled with the font; taller if the font needs it)."""
FONT_PX = 14
"""The HUD's font size on a 1280 x 720 target; :func:`font_px_for` scales it with the target."""
FONT_PX_RANGE = (9, 32)
"""The smallest font still read at a glance, and the largest, px: 4K takes it, whose capitals (about 22 px, 0.156 mm
a pixel on a 27-inch screen) subtend 20 arcmin at 60 cm, the character height ISO 9241-3 prefers (16 at least)."""
CHART_GAP = 6
CHART_SHARE = 0.45
"""The strip charts take at most this share of the target's height (the lowest-priority ones are left out): the
orbit camera puts the vessel in the middle of the picture, and the charts must not reach it."""
AXIS_FLOOR = 0.1
"""The smallest half-range of a chart's y axis, in the chart's unit (m, deg): a flat signal stays flat."""

FOOTPRINT_MIN_WIDTH = 960
"""The narrowest target (px) the footprint plot is drawn on: the DP line and the offset chart tell the rest."""
TEXT_COLOR = (0.95, 0.95, 0.95, 1.0)
DIM_TEXT_COLOR = (0.65, 0.68, 0.72, 1.0)
PANEL_COLOR = (0.0, 0.0, 0.0, 0.55)
HELP_PANEL_COLOR = (0.0, 0.0, 0.0, 0.82)
ZERO_LINE_COLOR = (0.55, 0.55, 0.55, 0.9)
TRACE_COLOR = (0.35, 1.0, 0.45, 1.0)
MESSAGE_COLOR = (1.0, 0.86, 0.45, 1.0)
LEVEL_COLORS = {"settling": DIM_TEXT_COLOR, "ok": (0.45, 0.92, 0.5, 1.0), "caution": (1.0, 0.75, 0.2, 1.0),
                "exceeded": (1.0, 0.35, 0.32, 1.0)}
"""A criterion's text colour by level: grey while settling, green, amber, red."""
ALARM_COLOR = (0.78, 0.06, 0.06, 0.92)
"""An alarm banner's background (the text is white)."""
SLIDER_TRACK_COLOR = (0.55, 0.58, 0.62, 0.9)
SLIDER_DONE_COLOR = (0.85, 0.88, 0.92, 1.0)
SLIDER_HEIGHT = 10

RADAR_SHARE = (0.36, 0.25)
"""The radar's square panel: at most these shares of the target's height and width (it keeps to the bottom-right
corner, right of the middle, where the orbit camera puts the vessel)."""
RADAR_MIN_LINES = 8
"""The smallest radar panel drawn, in text lines: less and the scope is too small to read."""
RADAR_VECTOR_S = 360.0
"""The vectors' time, s: 6 minutes, a radar's usual setting (a tenth of an hour: a vector is speed / 10 nm long)."""
RING_INTERVALS_NM = (0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0)
"""The range rings' intervals, nm: the smallest giving at most :data:`RADAR_MOST_RINGS` rings is used, as radars
do (0.25 nm rings on the 0.75 and 1.5 nm scales, 0.5 on 3 nm, 1 on 6 nm, 2 on 12 nm, ...)."""
RADAR_MOST_RINGS = 6
DANGER_CPA_M = 0.5 * NAUTICAL_MILE
DANGER_TCPA_S = 12 * 60.0
"""A contact closing to less than :data:`DANGER_CPA_M` within :data:`DANGER_TCPA_S` is a dangerous target (red):
an officer's usual CPA/TCPA alarm settings in open water."""
RADAR_PANEL_COLOR = (0.0, 0.05, 0.03, 0.85)
RING_COLOR = (0.16, 0.5, 0.26, 1.0)
RING_LABEL_COLOR = (0.4, 0.78, 0.48, 1.0)
OWN_SHIP_COLOR = (0.6, 1.0, 0.65, 1.0)
TRACK_COLOR = (0.3, 0.72, 0.82, 1.0)
CONTACT_COLOR = (1.0, 0.72, 0.18, 1.0)
DANGER_COLOR = (1.0, 0.22, 0.2, 1.0)
"""The radar's colours: a dark green-black scope, green rings and own ship (a radar's phosphor), her past track in
cyan, contacts in amber, a dangerous target in red."""

Color = tuple[float, float, float, float]


@dataclass(frozen=True)
class Banner:
    """A line of ``text`` on a solid ``background``, centred under the messages (an alarm, a status light)."""

    text: str
    background: Color
    color: Color = TEXT_COLOR


@dataclass(frozen=True)
class Slider:
    """A replay's time slider along the bottom: the position (0..1), marks (position, colour) and a label."""

    position: float
    marks: Sequence[tuple[float, Color]] = ()
    label: str = ""


@dataclass(frozen=True)
class Footprint:
    """A vessel keeping station: her recent positions ``east``, ``north`` (m from the set point, oldest first) and
    the footprint's ``radius`` (m), drawn to scale, north up (the DP operator's position plot)."""

    east: np.ndarray
    north: np.ndarray
    radius: float


@dataclass(frozen=True)
class Contact:
    """Another vessel on the radar: her ``name``, ``position`` relative to own ship (E, m, shape (2,)), her
    ``velocity`` over ground (E, m/s, (2,)) and her ``heading_deg`` (compass)."""

    name: str
    position: np.ndarray
    velocity: np.ndarray
    heading_deg: float


@dataclass(frozen=True)
class Radar:
    """A north-up, relative-motion radar picture with true vectors: own ship's ``heading_deg`` (compass) and
    ``velocity`` over ground (E, m/s, (2,)), her ``track`` as recent positions relative to her now (E, m, (n, 2),
    oldest first), the outer ring's range ``range_m`` (m) and the ``contacts``."""

    heading_deg: float
    velocity: np.ndarray
    track: np.ndarray
    range_m: float
    contacts: tuple[Contact, ...] = ()

    def __post_init__(self) -> None:
        require_positive("range_m", self.range_m)

    def approaches(self) -> tuple[np.ndarray, np.ndarray]:
        """Each contact's CPA (m) and TCPA (s), both ships holding their velocities (:func:`traffic.cpa`)."""
        if not self.contacts:
            return np.empty(0), np.empty(0)
        return cpa(np.zeros(2), self.velocity, [c.position for c in self.contacts], [c.velocity for c in self.contacts])

    def nearest(self) -> tuple[Contact, float, float] | None:
        """The closing contact (tcpa > 0) with the smallest CPA, her CPA (m) and TCPA (s); None if none closes."""
        dcpa, tcpa = self.approaches()
        closing = np.flatnonzero(tcpa > 0.0)
        if not closing.size:
            return None
        best = closing[np.argmin(dcpa[closing])]
        return self.contacts[best], float(dcpa[best]), float(tcpa[best])

    def cpa_line(self) -> tuple[str, Color]:
        """The radar's CPA line for the :meth:`nearest` contact and its colour: red for a dangerous target, amber
        otherwise, grey when no contact closes."""
        nearest = self.nearest()
        if nearest is None:
            return "CPA --  no target closing", DIM_TEXT_COLOR
        contact, near, when = nearest
        text = f"CPA {near / NAUTICAL_MILE:.2f} nm in {when / 60.0:.1f} min  {contact.name}"
        return text, DANGER_COLOR if dangerous(near, when) else CONTACT_COLOR


def dangerous(dcpa: np.ndarray | float, tcpa: np.ndarray | float) -> np.ndarray | bool:
    """Whether a contact with this CPA (m) and TCPA (s) is a dangerous target (:data:`DANGER_CPA_M`); arrays
    element-wise."""
    return (dcpa < DANGER_CPA_M) & (tcpa > 0.0) & (tcpa < DANGER_TCPA_S)


def ring_interval_m(range_m: float, most: int = RADAR_MOST_RINGS) -> float:
    """The range rings' interval (m) on a scope whose outer ring is ``range_m`` (m): the smallest of
    :data:`RING_INTERVALS_NM` giving at most ``most`` rings (the largest beyond them)."""
    for interval in RING_INTERVALS_NM:
        if range_m / (interval * NAUTICAL_MILE) <= most * (1.0 + 1e-9):
            return interval * NAUTICAL_MILE
    return RING_INTERVALS_NM[-1] * NAUTICAL_MILE


@dataclass(frozen=True)
class StripChart:
    """One channel's recent history: ``times`` (s, increasing) and ``values`` in ``unit``; the chart
    shows ``[times[-1] - span_s, times[-1]]``."""

    title: str
    unit: str
    times: np.ndarray
    values: np.ndarray
    span_s: float = 60.0


class StripHistory:
    """Ring buffer of the last span_s seconds of several named channels (heave, roll, pitch)."""

    def __init__(self, names: list[str], span_s: float = 60.0, capacity: int = 8192) -> None:
        if not names or capacity < 2 or not span_s > 0:
            raise ValueError("StripHistory needs channel names, a capacity of at least 2 and a positive span")
        self.names = list(names)
        self.span_s = float(span_s)
        self._times = np.zeros(capacity)
        self._values = np.zeros((capacity, len(names)))
        self._written = 0  # samples appended since the last clear; the next goes to _written % capacity

    def append(self, t: float, values: Sequence[float]) -> None:
        """Add the sample at time ``t`` (s), one value per channel; a time earlier than the last one
        means the simulation was reset and clears the history first."""
        if len(values) != len(self.names):
            raise ValueError(f"expected {len(self.names)} values ({', '.join(self.names)}), got {len(values)}")
        capacity = len(self._times)
        if self._written and t < self._times[(self._written - 1) % capacity]:
            self.clear()
        slot = self._written % capacity
        self._times[slot] = t
        self._values[slot] = values
        self._written += 1

    def chart(self, name: str, unit: str, span_s: float | None = None) -> StripChart:
        """The channel ``name`` over the last ``span_s`` seconds (default the history's), oldest first (copies)."""
        span_s = self.span_s if span_s is None else span_s
        column = self.names.index(name) if name in self.names else None
        if column is None:
            raise KeyError(f"no channel {name!r} (have {', '.join(self.names)})")
        capacity = len(self._times)
        count = min(self._written, capacity)
        order = np.arange(self._written - count, self._written) % capacity
        times, values = self._times[order], self._values[order, column]
        if count:
            recent = times >= times[-1] - span_s
            times, values = times[recent], values[recent]
        return StripChart(name, unit, times.copy(), values.copy(), span_s)

    def clear(self) -> None:
        self._written = 0


def nice_ceil(x: float) -> float:
    """The smallest 1, 2 or 5 times a power of ten that is at least ``x`` (> 0)."""
    exponent = math.floor(math.log10(x))
    for step in (1.0, 2.0, 5.0, 10.0):
        limit = step * 10.0**exponent
        if limit >= x * (1.0 - 1e-9):
            return limit
    raise AssertionError("unreachable")


def axis_limit(values: np.ndarray, floor: float = AXIS_FLOOR) -> float:
    """Half-range of a chart's symmetric y axis: the largest finite |value| rounded up to a 1-2-5
    step, never below ``floor``."""
    finite = np.abs(np.asarray(values, dtype=float))
    finite = finite[np.isfinite(finite)]
    return nice_ceil(max(float(finite.max()) if finite.size else 0.0, floor))


@dataclass
class _Layer:
    """Geometry of one layer, in pixels: panel triangles, line segments, glyph instances."""

    triangles: list[np.ndarray] = field(default_factory=list)  # rows (x, y, r, g, b, a)
    lines: list[np.ndarray] = field(default_factory=list)
    glyphs: list[np.ndarray] = field(default_factory=list)  # rows (x, y, glyph, r, g, b, a)

    def rect(self, x: float, y: float, w: float, h: float, color: Color) -> None:
        corners = np.array([(x, y), (x + w, y), (x, y + h), (x + w, y), (x + w, y + h), (x, y + h)])
        self.triangles.append(np.hstack([corners, np.tile(color, (6, 1))]))

    def polyline(self, xs: np.ndarray, ys: np.ndarray, color: Color) -> None:
        """Segments between consecutive points (px; a pixel's centre is at +0.5); non-finite points break it."""
        points = np.column_stack([xs, ys])
        keep = np.isfinite(points).all(axis=1)
        keep = keep[:-1] & keep[1:]
        ends = np.stack([points[:-1][keep], points[1:][keep]], axis=1).reshape(-1, 2)
        self.lines.append(np.hstack([ends, np.tile(color, (len(ends), 1))]))


def font_px_for(size: tuple[int, int]) -> int:
    """The HUD's font size for a target of ``size`` (w, h) px: :data:`FONT_PX` at 1280 x 720, in proportion to
    the smaller of the two ratios, within :data:`FONT_PX_RANGE` (so a small window keeps most of its view)."""
    low, high = FONT_PX_RANGE
    return int(min(max(round(FONT_PX * min(size[0] / 1280, size[1] / 720)), low), high))


class Hud:
    """Draws the HUD with ``ctx`` onto whatever framebuffer is bound; ``font_px`` is the font size.

    ``advance`` (the monospace character width), ``line_height``, ``margin`` and ``pad`` (:data:`MARGIN` and
    :data:`PAD` scaled with a font larger than :data:`FONT_PX`) are in pixels."""

    def __init__(self, ctx: moderngl.Context, font_px: int = FONT_PX) -> None:
        self.ctx = ctx
        font = ImageFont.truetype(findfont(FontProperties(family="DejaVu Sans Mono")), font_px)
        ascent, descent = font.getmetrics()
        self.advance = math.ceil(font.getlength("M"))
        self.line_height = ascent + descent
        count = LAST_CHAR - FIRST_CHAR + 1
        rows = -(-count // ATLAS_COLUMNS)
        image = Image.new("L", (ATLAS_COLUMNS * self.advance, rows * self.line_height), 0)
        draw = ImageDraw.Draw(image)
        for index in range(count):
            column, row = index % ATLAS_COLUMNS, index // ATLAS_COLUMNS
            draw.text((column * self.advance, row * self.line_height), chr(FIRST_CHAR + index), font=font, fill=255)
        self.atlas = ctx.texture(image.size, 1, image.tobytes(), alignment=1)
        self.atlas.filter = (moderngl.NEAREST, moderngl.NEAREST)
        self.atlas.repeat_x = self.atlas.repeat_y = False
        self.font_px = font_px
        scale = font_px / FONT_PX
        self.margin, self.pad = round(MARGIN * max(scale, 1.0)), round(PAD * max(scale, 1.0))
        self.chart_size = (round(CHART_SIZE[0] * scale), max(round(CHART_SIZE[1] * scale), 3 * self.line_height + 12))

        self.text_program = Program.from_files(ctx, "hud_text")
        self.text_program["cell"] = (self.advance, self.line_height)
        self.text_program["columns"] = ATLAS_COLUMNS
        self.text_program["atlas"] = 0
        self.line_program = Program.from_files(ctx, "hud_line")
        self.glyph_buffer = ctx.buffer(reserve=1 << 16, dynamic=True)
        self.shape_buffer = ctx.buffer(reserve=1 << 16, dynamic=True)
        self.text_vao = ctx.vertex_array(self.text_program.gl,
                                         [(self.glyph_buffer, "2f 1f 4f/i", "in_pos", "in_glyph", "in_color")])
        self.shape_vao = ctx.vertex_array(self.line_program.gl, [(self.shape_buffer, "2f 4f", "in_pos", "in_color")])
        self._lookup = np.full(256, ord("?") - FIRST_CHAR, dtype=np.float32)
        self._lookup[FIRST_CHAR:LAST_CHAR + 1] = np.arange(count)

    def draw(self, size: tuple[int, int], lines: Sequence[str], charts: Sequence[StripChart] = (),
             help_lines: Sequence[str] | None = None, panel: Sequence[tuple[str, str]] = (),
             messages: Sequence[str] = (), banners: Sequence[Banner] = (), slider: Slider | None = None,
             footprint: Footprint | None = None, radar: Radar | None = None) -> None:
        """Draw onto the currently bound framebuffer of `size` (w, h) pixels, alpha-blended, depth test off:
        `lines` as a text block at the top-left on a translucent dark panel; `charts` stacked at the bottom-left
        (each: a panel about 360x70 px with its title, unit, current value, the min/max of the y axis as labels,
        a zero line, and the trace as a line strip, y range symmetric about zero and rounded up to a 1-2-5 step,
        never below a small floor so a flat signal is not magnified noise); `help_lines`, when given, centred on a
        darker panel; ``panel`` (text, level) rows at the top-right (under the text block, on the left, if the
        two would overlap), each coloured by its level (:data:`LEVEL_COLORS`); ``messages`` in amber at
        the top-centre, below the top panels if they leave no room between them; ``banners`` along the
        bottom, right of the charts, the first lowest (the middle of the picture, where the orbit camera puts
        the vessel, stays free); ``slider`` along the bottom, right of the charts (:meth:`slider_rect`);
        ``footprint`` a square position plot at the right, under the criteria panel (:meth:`_footprint`), on a
        target at least :data:`FOOTPRINT_MIN_WIDTH` wide (on a smaller one it would cover the vessel); ``radar`` a
        square radar picture at the bottom-right (:meth:`radar_rect`, :meth:`_radar`), above the slider, below
        what the right side holds above it, the banners then centred between the charts and it.
        Charts that would take more than :data:`CHART_SHARE` of the height are left out (the last first), all of
        them while a banner has no room beside them, and a line longer than the target is wide is cut with ``~``.

        The bound framebuffer, its viewport and the enable flags (blend, depth test, face culling) are
        restored afterwards; the blend function is left at ``moderngl.DEFAULT_BLENDING`` and texture
        unit 0 holds the glyph atlas."""
        width, height = size
        fits = self.columns(width)

        def clip(text: str) -> str:
            return text if len(text) <= fits else text[:fits - 1] + "~"

        lines = [clip(line) for line in lines]
        panel = [(clip(text), level) for text, level in panel]
        banners = [replace(banner, text=clip(banner.text)) for banner in banners]
        charts = list(charts)[:self.charts_that_fit(size)]
        base = _Layer()
        if lines:
            self._text_block(base, self.margin, self.margin, lines, self.pad, PANEL_COLOR)
        left = self._text_size(lines, self.pad) if lines else (0, 0)
        right, right_y, right_bottom = (0, 0), self.margin, 0
        if panel:
            rows = [(text, LEVEL_COLORS[level]) for text, level in panel]
            right = self._text_size([text for text, _ in rows], self.pad)
            right_x = width - self.margin - right[0]
            if right_x < 2 * self.margin + left[0]:  # no room beside the text block: under it, on the left (the
                right_x, right_y = self.margin, 2 * self.margin + left[1]  # middle, the vessel's, stays free)
            else:
                right_bottom = right_y + right[1]
            self._text_block(base, right_x, right_y, rows, self.pad, PANEL_COLOR)
        if footprint is not None and width >= FOOTPRINT_MIN_WIDTH:
            side = 2 * self.chart_size[1]
            below = right_y + right[1] + self.margin if panel and right_y == self.margin else self.margin
            self._footprint(base, footprint, width - self.margin - side, below, side)
            right = (max(right[0], side), below + side - self.margin)
            right_bottom = below + side
        scope = self.radar_rect(size, right_bottom, slider is not None) if radar is not None else None
        band_right = width - self.margin if scope is None else scope[0] - self.margin  # the banners' band ends here
        widest = max((self._text_size([b.text], 2 * self.pad)[0] for b in banners), default=0)
        if widest > band_right - 2 * self.margin - self.chart_size[0]:
            charts = []  # a banner needs the bottom band and there is no room beside the charts: it comes first
        for index, chart in enumerate(charts):
            self._chart(base, chart, *self.chart_plot_rect(size, index, len(charts)))
        if scope is not None:
            self._radar(base, radar, *scope)
        if messages:
            messages = [clip(m) for m in messages]
            box_w, box_h = self._text_size(messages, self.pad)
            x, y = (width - box_w) // 2, self.margin
            if right_y > self.margin or x < 2 * self.margin + left[0] or x + box_w > width - 2 * self.margin - right[0]:
                y = self.margin + max(left[1], right_y - self.margin + right[1]) + self.margin  # below the top panels
            self._text_block(base, max(x, self.margin), y, [(m, MESSAGE_COLOR) for m in messages], self.pad,
                             PANEL_COLOR)
        above = height - self.margin  # the bottom band right of the charts, filled upwards
        if slider is not None:
            above -= self._slider_band()
        beside = self.margin + (self.chart_size[0] + self.margin if charts else 0)
        for banner in banners:
            box_w, box_h = self._text_size([banner.text], 2 * self.pad)
            x = beside + max((band_right - beside - box_w) // 2, 0)
            if x + box_w > band_right:  # no room beside the charts: centred, over them
                x = max((band_right + self.margin - box_w) // 2, self.margin)
            above -= box_h
            self._text_block(base, x, above, [(banner.text, banner.color)], 2 * self.pad, banner.background)
            above -= self.margin // 2
        if slider is not None:
            self._slider(base, slider, *self.slider_rect(size, bool(charts)))
        layers = [base]
        if help_lines:
            box_w, box_h = self._text_size(help_lines, 2 * self.pad)
            top = _Layer()
            self._text_block(top, (width - box_w) // 2, (height - box_h) // 2, help_lines, 2 * self.pad,
                             HELP_PANEL_COLOR)
            layers.append(top)

        ctx = self.ctx
        if ctx.fbo is None:
            raise GraphicsError("the HUD draws onto the bound framebuffer: bind one first (fbo.use())")
        with ctx.scope(ctx.fbo, enable_only=moderngl.BLEND):
            viewport = ctx.viewport
            ctx.viewport = (0, 0, width, height)
            ctx.blend_func = moderngl.DEFAULT_BLENDING
            self.text_program["viewport"] = (width, height)
            self.line_program["viewport"] = (width, height)
            self.atlas.use(0)
            for layer in layers:
                self._render(layer)
            ctx.viewport = viewport

    def columns(self, width: int) -> int:
        """How many characters a text block's line holds on a target ``width`` px wide."""
        return max(int((width - 2 * self.margin - 2 * self.pad) // self.advance), 1)

    def pack(self, segments: Sequence[str], width: int, gap: str = "   ") -> list[str]:
        """``segments`` joined by ``gap`` into as few lines as a target ``width`` px wide holds, in order; a
        segment is never split (one longer than a line is cut when drawn)."""
        fits, lines = self.columns(width), []
        for segment in segments:
            if lines and len(lines[-1]) + len(gap) + len(segment) <= fits:
                lines[-1] += gap + segment
            else:
                lines.append(segment)
        return lines

    def charts_that_fit(self, size: tuple[int, int]) -> int:
        """How many strip charts fit in :data:`CHART_SHARE` of the height of a target of ``size`` (w, h) px."""
        return max(int((CHART_SHARE * size[1] - self.margin + CHART_GAP) // (self.chart_size[1] + CHART_GAP)), 0)

    def chart_plot_rect(self, size: tuple[int, int], index: int, count: int) -> tuple[int, int, int, int, int]:
        """Where chart ``index`` of ``count`` is drawn, px from the top-left: ``(panel_x, panel_y,
        plot_x, plot_y, half)``; the plot spans columns ``plot_x .. panel_x + panel_w - self.pad`` and rows
        ``plot_y .. plot_y + 2 * half``, with zero on row ``plot_y + half`` and the axis limits on its
        first and last rows."""
        panel_h = self.chart_size[1]
        panel_x = self.margin
        panel_y = size[1] - self.margin - (count - index) * (panel_h + CHART_GAP) + CHART_GAP
        plot_x = panel_x + self.pad + 6 * self.advance + 4  # room for labels such as "+0.05" and "-200"
        plot_y = panel_y + self.line_height + 4
        half = (panel_y + panel_h - 4 - plot_y) // 2
        return panel_x, panel_y, plot_x, plot_y, half

    def radar_rect(self, size: tuple[int, int], top: int = 0, slider: bool = False) -> tuple[int, int, int] | None:
        """Where the radar's square panel goes, px from the top-left: ``(x, y, side)`` at the bottom-right corner,
        above the slider's band if ``slider``, and below ``top`` (the bottom of what the right side holds); its side
        :data:`RADAR_SHARE` of the target, less where that leaves no room; None when under :data:`RADAR_MIN_LINES`
        lines would remain."""
        width, height = size
        bottom = height - self.margin - (self._slider_band() if slider else 0)
        side = min(round(RADAR_SHARE[0] * height), round(RADAR_SHARE[1] * width),
                   bottom - max(top + self.margin, self.margin))
        if side < RADAR_MIN_LINES * self.line_height:
            return None
        return width - self.margin - side, bottom - side, side

    def radar_scope(self, x: int, y: int, side: int) -> tuple[float, float, float]:
        """The scope in the radar's panel at (``x``, ``y``), ``side`` px: its centre and its outer ring's radius, px
        (between the title line and the CPA line)."""
        top, bottom = y + self.line_height + 4, y + side - self.pad - self.line_height - 4
        radius = min(side / 2.0 - self.pad, (bottom - top) / 2.0)
        return x + side / 2.0, (top + bottom) / 2.0, radius

    def _slider_band(self) -> int:
        """The height the slider takes at the bottom, with its label and a margin above, px."""
        return SLIDER_HEIGHT + 2 * self.pad + self.line_height + self.margin

    def slider_rect(self, size: tuple[int, int], charts: bool) -> tuple[int, int, int, int]:
        """Where the time slider's track is, px from the top-left: ``(x, y, w, h)``, right of the charts."""
        x = self.margin + (self.chart_size[0] + self.margin if charts else 0) + self.pad
        w = max(size[0] - self.margin - self.pad - x, 1)
        return x, size[1] - self.margin - self.pad - SLIDER_HEIGHT, w, SLIDER_HEIGHT

    def _slider(self, layer: _Layer, slider: Slider, x: int, y: int, w: int, h: int) -> None:
        pad = self.pad
        layer.rect(x - pad, y - pad - self.line_height, w + 2 * pad, h + 2 * pad + self.line_height, PANEL_COLOR)
        self._text(layer, x, y - self.line_height - 2, slider.label, TEXT_COLOR)
        layer.rect(x, y + h // 2 - 1, w, 3, SLIDER_TRACK_COLOR)
        done = min(max(slider.position, 0.0), 1.0) * w
        layer.rect(x, y + h // 2 - 1, done, 3, SLIDER_DONE_COLOR)
        for position, color in slider.marks:
            layer.rect(x + min(max(position, 0.0), 1.0) * w - 1, y, 2, h, color)
        layer.rect(x + done - 3, y - 2, 6, h + 4, SLIDER_DONE_COLOR)

    def release(self) -> None:
        """Free the GL objects (idempotent)."""
        for thing in (self.text_vao, self.shape_vao, self.glyph_buffer, self.shape_buffer, self.text_program,
                      self.line_program, self.atlas):
            thing.release()

    def _text_size(self, lines: Sequence[str], pad: int) -> tuple[int, int]:
        """A text block's panel size, px."""
        return (max(len(line) for line in lines) * self.advance + 2 * pad, len(lines) * self.line_height + 2 * pad)

    def _text_block(self, layer: _Layer, x: int, y: int, lines: Sequence[str | tuple[str, Color]], pad: int,
                    panel: Color) -> None:
        """Lines (text, or (text, colour)) on a panel with its top-left corner at (x, y), px."""
        rows = [line if isinstance(line, tuple) else (line, TEXT_COLOR) for line in lines]
        layer.rect(x, y, *self._text_size([text for text, _ in rows], pad), panel)
        for row, (line, color) in enumerate(rows):
            self._text(layer, x + pad, y + pad + row * self.line_height, line, color)

    def _text(self, layer: _Layer, x: float, y: float, text: str, color: Color) -> None:
        """One line of text with its first cell's top-left corner at (x, y), px."""
        codes = np.array([min(ord(c), 255) for c in text], dtype=np.intp)
        glyphs = self._lookup[codes]
        ink = np.flatnonzero(codes != ord(" "))
        rows = np.empty((len(ink), 7), dtype=np.float32)
        rows[:, 0] = x + ink * self.advance
        rows[:, 1] = y
        rows[:, 2] = glyphs[ink]
        rows[:, 3:] = color
        layer.glyphs.append(rows)

    def _chart(self, layer: _Layer, chart: StripChart, panel_x: int, panel_y: int, plot_x: int, plot_y: int,
               half: int) -> None:
        panel_w, panel_h = self.chart_size
        right = panel_x + panel_w - self.pad
        layer.rect(panel_x, panel_y, panel_w, panel_h, PANEL_COLOR)
        times, values = np.asarray(chart.times, dtype=float), np.asarray(chart.values, dtype=float)
        if times.size:
            shown = times >= times[-1] - chart.span_s
            times, values = times[shown], values[shown]
        value = f"{values[-1]:+.2f}" if values.size else "--"
        self._text(layer, panel_x + self.pad, panel_y + 2, f"{chart.title} {value} {chart.unit}", TEXT_COLOR)
        span = f"last {chart.span_s:g} s"
        self._text(layer, right - len(span) * self.advance, panel_y + 2, span, DIM_TEXT_COLOR)
        limit = axis_limit(values)
        for label, row in ((f"+{limit:.10g}", plot_y), (f"-{limit:.10g}", plot_y + 2 * half + 1 - self.line_height)):
            self._text(layer, plot_x - 4 - len(label) * self.advance, row, label, DIM_TEXT_COLOR)
        zero = plot_y + half + 0.5  # the centre of the zero row
        layer.polyline(np.array([plot_x, right]), np.array([zero, zero]), ZERO_LINE_COLOR)
        if times.size > 1:
            xs = right - (times[-1] - times) / chart.span_s * (right - plot_x)
            layer.polyline(xs, zero - values / limit * half, TRACE_COLOR)

    def _footprint(self, layer: _Layer, footprint: Footprint, x: int, y: int, side: int) -> None:
        """The position plot in a ``side`` px square panel at (``x``, ``y``): the footprint's circle, the set point's
        cross, her track and where she is now (red once outside)."""
        layer.rect(x, y, side, side, PANEL_COLOR)
        east, north = np.asarray(footprint.east, float), np.asarray(footprint.north, float)
        now = math.hypot(east[-1], north[-1]) if east.size else 0.0
        self._text(layer, x + self.pad, y + 2, f"footprint {footprint.radius:g} m", TEXT_COLOR)
        top = y + self.line_height + 4
        half = (y + side - self.pad - top) / 2.0
        cx, cy = x + side / 2.0, top + half
        reach = max(footprint.radius, float(np.max(np.hypot(east, north))) if east.size else 0.0)
        scale = 0.9 * half / reach
        outside = now > footprint.radius
        circle = np.linspace(0.0, 2.0 * math.pi, 73)
        layer.polyline(cx + footprint.radius * scale * np.sin(circle), cy - footprint.radius * scale * np.cos(circle),
                       LEVEL_COLORS["exceeded" if outside else "ok"])
        tick = 0.12 * half
        layer.polyline(np.array([cx - tick, cx + tick]), np.array([cy, cy]), ZERO_LINE_COLOR)
        layer.polyline(np.array([cx, cx]), np.array([cy - tick, cy + tick]), ZERO_LINE_COLOR)
        if east.size > 1:
            layer.polyline(cx + east * scale, cy - north * scale, TRACE_COLOR)
        if east.size:
            dot = max(self.pad // 2, 2)
            layer.rect(cx + east[-1] * scale - dot, cy - north[-1] * scale - dot, 2 * dot, 2 * dot,
                       LEVEL_COLORS["exceeded" if outside else "ok"])

    def _radar(self, layer: _Layer, radar: Radar, x: int, y: int, side: int) -> None:
        """The radar picture in a ``side`` px square panel at (``x``, ``y``), north up, own ship at the centre: range
        rings labelled in nm and bearing ticks every 10 deg, her heading line, past track and velocity vector,
        each contact within range as a triangle on her heading (the AIS symbol) with her vector and name, and
        the line giving the nearest CPA among closing contacts (all of them, in range or not). Vectors are true
        (over ground), :data:`RADAR_VECTOR_S` long; a dangerous target (:func:`dangerous`) is red."""
        layer.rect(x, y, side, side, RADAR_PANEL_COLOR)
        cx, cy, radius = self.radar_scope(x, y, side)
        scale = radius / radar.range_m  # px per m

        def scope_line(east: np.ndarray, north: np.ndarray, color: Color) -> None:
            """A polyline through E points relative to own ship (m), broken outside the outer ring."""
            outside = np.hypot(east, north) > radar.range_m * (1.0 + 1e-9)
            layer.polyline(np.where(outside, np.nan, cx + east * scale), cy - north * scale, color)

        def vector(start: np.ndarray, velocity: np.ndarray, color: Color) -> None:
            along = np.linspace(0.0, RADAR_VECTOR_S, 65)[:, None]
            points = np.asarray(start, float) + along * np.asarray(velocity, float)
            scope_line(points[:, 0], points[:, 1], color)

        circle = np.linspace(0.0, 2.0 * math.pi, 181)
        interval = ring_interval_m(radar.range_m, max(min(int(radius // self.line_height), RADAR_MOST_RINGS), 1))
        count = int(radar.range_m / interval * (1.0 + 1e-9))
        rings = [k * interval for k in range(1, count + 1)]
        if not rings or rings[-1] < radar.range_m * (1.0 - 1e-9):
            rings.append(radar.range_m)  # the outer ring, off the intervals' steps
        # the rings' labels go just outside each ring on the diagonal farthest from the heading line and the track
        diagonal = min((45.0, 135.0, 225.0, 315.0), key=lambda b: abs((b - radar.heading_deg) % 180.0 - 90.0))
        east, north = math.sin(math.radians(diagonal)), math.cos(math.radians(diagonal))
        last = None  # the last label's box (x0, y0, x1, y1), px
        for ring in rings:
            r = ring * scale
            layer.polyline(cx + r * np.sin(circle), cy - r * np.cos(circle), RING_COLOR)
            label = f"{ring / NAUTICAL_MILE:.3g}"
            w, h = len(label) * self.advance, self.line_height
            lx = cx + r * east + (2 if east > 0 else -2 - w)
            ly = cy - r * north + (-h + 2 if north > 0 else 0)
            inside = x + self.pad <= lx and lx + w <= x + side - self.pad and y + h <= ly and ly + h <= y + side - h
            apart = last is None or lx >= last[2] or lx + w <= last[0] or ly >= last[3] or ly + h <= last[1]
            if inside and apart:
                self._text(layer, lx, ly, label, RING_LABEL_COLOR)
                last = (lx - self.advance / 2, ly, lx + w + self.advance / 2, ly + h)
        ticks = np.radians(np.arange(0.0, 360.0, 10.0))
        inner = np.where(np.arange(ticks.size) % 3 == 0, 0.92, 0.96) * radius
        for angle, r in zip(ticks, inner):
            layer.polyline(cx + np.array([r, radius]) * math.sin(angle), cy - np.array([r, radius]) * math.cos(angle),
                           RING_COLOR)

        heading = math.radians(radar.heading_deg)
        ahead, starboard = np.array([math.sin(heading), math.cos(heading)]), np.array([math.cos(heading),
                                                                                      -math.sin(heading)])
        length = max(self.line_height, 10)  # own ship's symbol, px
        layer.polyline(cx + np.array([0.5 * length, radius]) * ahead[0],
                       cy - np.array([0.5 * length, radius]) * ahead[1], RING_COLOR)  # the heading line
        track = np.asarray(radar.track, float).reshape(-1, 2)
        if len(track) > 1:
            scope_line(track[:, 0], track[:, 1], TRACK_COLOR)
        vector(np.zeros(2), radar.velocity, OWN_SHIP_COLOR)
        hull = np.array([(0.5, 0.0), (0.15, 0.2), (-0.5, 0.2), (-0.5, -0.2), (0.15, -0.2)]) * length
        self._polygon(layer, cx, cy, hull[:, :1] * ahead + hull[:, 1:] * starboard, OWN_SHIP_COLOR)

        dcpa, tcpa = radar.approaches()
        danger = dangerous(dcpa, tcpa)
        nearest = radar.nearest()
        size = 0.8 * self.line_height  # a contact's triangle, apex to base, px
        for contact, red in zip(radar.contacts, danger):
            position = np.asarray(contact.position, float)
            if math.hypot(*position) > radar.range_m:
                continue  # beyond the outer ring: only the CPA line tells of her
            color = DANGER_COLOR if red else CONTACT_COLOR
            vector(position, contact.velocity, color)
            course = math.radians(contact.heading_deg)
            bow, beam = np.array([math.sin(course), math.cos(course)]), np.array([math.cos(course), -math.sin(course)])
            corners = np.array([(2.0 / 3.0, 0.0), (-1.0 / 3.0, 0.35), (-1.0 / 3.0, -0.35)]) * size
            px, py = cx + position[0] * scale, cy - position[1] * scale
            self._polygon(layer, px, py, corners[:, :1] * bow + corners[:, 1:] * beam, color)
            box = 0.75 * self.line_height
            if nearest is not None and contact is nearest[0]:  # the target the CPA line names, in a square
                layer.polyline(px + box * np.array([-1, 1, 1, -1, -1]), py + box * np.array([-1, -1, 1, 1, -1]), color)
            if contact.name:
                name = contact.name[:max(int((side / 2 - box) // self.advance), 1)]
                nx = px + box + 2
                if nx + len(name) * self.advance > x + side - self.pad:
                    nx = px - box - 2 - len(name) * self.advance
                self._text(layer, nx, py - self.line_height, name, color)

        fits = max(int((side - 2 * self.pad) // self.advance), 1)
        line, color = radar.cpa_line()
        line = line if len(line) <= fits else line[:fits - 1] + "~"
        self._text(layer, x + self.pad, y + side - self.pad - self.line_height, line, color)
        scale_text = f"N UP  {radar.range_m / NAUTICAL_MILE:.3g} nm"
        vectors = f"vec {RADAR_VECTOR_S / 60:g} min"
        titles = (f"{scale_text}  rings {interval / NAUTICAL_MILE:.3g}  {vectors}", f"{scale_text}  {vectors}",
                  scale_text)
        title = next((text for text in titles if len(text) <= fits), scale_text[:fits])
        self._text(layer, x + self.pad, y + 2, title, OWN_SHIP_COLOR)

    @staticmethod
    def _polygon(layer: _Layer, x: float, y: float, corners: np.ndarray, color: Color) -> None:
        """A filled convex polygon, ``corners`` (n, 2) in E (east, north; px) about (``x``, ``y``) on the target."""
        points = np.column_stack([x + corners[:, 0], y - corners[:, 1]])
        fan = np.stack([np.repeat(points[:1], len(points) - 2, axis=0), points[1:-1], points[2:]], axis=1)
        layer.triangles.append(np.hstack([fan.reshape(-1, 2), np.tile(color, (fan.shape[0] * 3, 1))]))

    def _render(self, layer: _Layer) -> None:
        """Panels, then lines, then text of one layer."""
        empty = [np.empty((0, 6))]
        shapes = [np.concatenate(layer.triangles or empty), np.concatenate(layer.lines or empty)]
        if len(shapes[0]) + len(shapes[1]):
            _upload(self.shape_buffer, np.concatenate(shapes))
            if len(shapes[0]):
                self.shape_vao.render(moderngl.TRIANGLES, vertices=len(shapes[0]))
            if len(shapes[1]):
                self.shape_vao.render(moderngl.LINES, vertices=len(shapes[1]), first=len(shapes[0]))
        glyphs = np.concatenate(layer.glyphs) if layer.glyphs else np.empty((0, 7))
        if len(glyphs):
            _upload(self.glyph_buffer, glyphs)
            self.text_vao.render(moderngl.TRIANGLE_STRIP, vertices=4, instances=len(glyphs))


def _upload(buffer: moderngl.Buffer, data: np.ndarray) -> None:
    """Orphan ``buffer`` (growing it to the next power of two if ``data`` does not fit) and write ``data``."""
    data = np.ascontiguousarray(data, dtype=np.float32)
    needed = data.nbytes
    buffer.orphan(1 << (needed - 1).bit_length() if needed > buffer.size else -1)
    buffer.write(data)
