"""The after-action report's figures as PNG bytes: a criterion's running value over the run, the timeline, and
the ship's track over the ground (to scale, north up) and her handling (heading, speed, rudder, propeller).

Made and written by :mod:`marinesim.figures` (its dpi, and no version or date in the file: the same data give the
same bytes), 1000 px wide (the track as tall as its shape needs), every font size given. Time runs along x as
elapsed min:s (h:min:s past an hour), the way the report's tables give it (:func:`clock`).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from marinesim import figures
from marinesim.figures import DPI

if TYPE_CHECKING:
    from marinesim.report.debrief import Action, CriterionTrace, Message
    from marinesim.session.exercise import AlarmResult, EventResult

OK, CAUTION, EXCEEDED, NONE = "#2e9e44", "#f0a800", "#d0312d", "#6b7280"
"""The bridge alarm panel's colours: green, amber, red, and grey for no value."""
INK, MUTED, GRID = "#1b1f24", "#5b6470", "#e3e7ec"
VALUE = "#1f4e8c"
"""The running value's line: a dark blue that none of the alarm colours is confused with."""
EVENT, MESSAGE, ACTION = "#3d4651", "#1f6fb2", "#7a4fa0"
WIDTH_IN = 10.0
"""Figures are 1000 px wide: the page's text column, sharp at 100 % zoom and on A4."""
LEFT_PX, RIGHT_PX, BOTTOM_PX = 72, 22, 44
"""Fixed margins, the same in every figure: the time axes of all the plots line up one under the other."""
UNITS = {"deg": "°", "m/s^2": "m/s²", "m/s^1.5": "m/s¹·⁵", "1/min": "/min"}
"""Units as printed (the data give them as written in scenario files)."""
STEPS_S = (5, 10, 15, 30, 60, 120, 300, 600, 900, 1200, 1800, 3600, 7200, 10800, 21600)


def unit_text(unit: str | None) -> str:
    """``unit`` as printed: ° for deg, superscripts for powers."""
    return UNITS.get(unit or "", unit or "")


def with_unit(value: float, unit: str | None, digits: int = 3) -> str:
    """``value`` (see :func:`number`) followed by its unit; degrees without a space, as on a bridge display."""
    shown, text = unit_text(unit), number(value, digits)
    if not shown:
        return text
    return f"{text}{shown}" if shown == "°" else f"{text} {shown}"


def number(value: float, digits: int = 3) -> str:
    """``digits`` significant figures (3, 2.4, 3.35, 30.1, 1250, 0.000085), never in e-notation."""
    if not math.isfinite(value):
        return str(value)
    if value == 0:
        return "0"
    decimals = max(digits - 1 - math.floor(math.log10(abs(value))), 0)
    text = f"{round(value, decimals):.{decimals}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def compass(deg: float) -> str:
    """A compass direction as a bridge reads it: three whole degrees (005°, 360° read as 000°)."""
    return f"{round(deg) % 360:03d}°"


def clock(t_s: float, long: bool = False) -> str:
    """Elapsed time as min:s (``long``: h:min:s), a tenth shown only where the time has one."""
    tenths = round(t_s * 10)
    sign = "-" if tenths < 0 else ""
    seconds, tenth = divmod(abs(tenths), 10)
    minutes, sec = divmod(seconds, 60)
    frac = f".{tenth}" if tenth else ""
    if long:
        hours, minutes = divmod(minutes, 60)
        return f"{sign}{hours}:{minutes:02d}:{sec:02d}{frac}"
    return f"{sign}{minutes}:{sec:02d}{frac}"


def criterion_png(criterion: CriterionTrace, duration_s: float, events: list[EventResult],
                  alarms: list[tuple[int, AlarmResult]]) -> bytes:
    """``criterion``'s running value over a run of ``duration_s``: its limit (red) and caution (amber, dashed)
    lines, the spans above the limit shaded, the settling start greyed, ``events`` and the numbered ``alarms``
    ((number, alarm) pairs raised by this criterion) marked."""
    figure, ax = _figure(2.9, top_px=30)
    t = np.asarray(criterion.series.time_s, float)
    v = np.array([np.nan if x is None else x for x in criterion.series.value], float)[: t.size]
    t = t[: v.size]
    limit, unit = criterion.limit, criterion.unit
    caution = None if limit is None or criterion.caution is None else criterion.caution * limit
    span = _span(duration_s, t)
    finite = np.isfinite(v)
    values = [x for x in (np.nanmax(v) if finite.any() else None, limit) if x is not None]
    top = max(values) if values else 1.0
    bottom = min(0.0, float(np.nanmin(v)) if finite.any() else 0.0)
    top = top if top > bottom else bottom + 1.0
    ax.set_ylim(bottom, top + 0.30 * (top - bottom))  # the upper band keeps the event and alarm tags off the line
    ax.set_xlim(0.0, span)
    _time_axis(ax, span)

    if t.size and not finite.all():  # the window still filling: no value yet
        first = t[np.argmax(finite)] if finite.any() else span
        ax.axvspan(0.0, first, color="#eef0f3", lw=0, zorder=0)
        narrow = first < 0.12 * span
        ax.text(first / 2, 0.04 if narrow else 0.5, "settling" if finite.any() else "no value: the window never filled",
                transform=ax.get_xaxis_transform(), ha="center", va="bottom" if narrow else "center", fontsize=9,
                color=MUTED, rotation=90 if narrow else 0, clip_on=True)
    elif not t.size:
        ax.text(0.5, 0.5, "no value recorded", transform=ax.transAxes, ha="center", va="center", fontsize=9,
                color=MUTED)
    if limit is not None and finite.any():
        for start, end in _runs_above(t, v, limit):
            ax.axvspan(start, end, color=EXCEEDED, alpha=0.13, lw=0, zorder=0)
    ax.plot(t, v, color=VALUE, lw=1.3, zorder=3, solid_joinstyle="round")
    if limit is not None:
        ax.plot(t, np.where(v > limit, v, np.nan), color=EXCEEDED, lw=1.6, zorder=4)
        ax.axhline(limit, color=EXCEEDED, lw=1.6, zorder=2)
        _line_label(ax, (t, v, span), limit, f"limit {with_unit(limit, unit)}", EXCEEDED, "bottom")
    if caution is not None:
        ax.axhline(caution, color=CAUTION, lw=1.4, ls=(0, (5, 3)), zorder=2)
        _line_label(ax, (t, v, span), caution, f"caution {with_unit(caution, unit)}", "#8a5e00", "top")

    happened = _happened(events)
    for event, lane in zip(happened, _lanes([e.happened_s for e in happened], 0.03 * span, 2)):
        at = event.happened_s
        ax.axvline(at, color=EVENT, lw=0.9, ls=(0, (2, 2)), zorder=1)
        _tag(ax, at, 0.975 - 0.075 * lane, f"E{event.index}", EVENT, _align(at, span))
    for (number_, alarm), lane in zip(alarms, _lanes([a.raised_s for _, a in alarms], 0.05 * span, 2)):
        y = 0.83 - 0.07 * lane
        ax.axvline(alarm.raised_s, color=EXCEEDED, lw=0.9, zorder=1)
        ax.plot([alarm.raised_s], [y], marker="v", ms=7, color=EXCEEDED, transform=ax.get_xaxis_transform(),
                zorder=5, clip_on=False)
        right = alarm.raised_s > 0.95 * span
        ax.text(alarm.raised_s, y, f"A{number_} " if right else f" A{number_}", transform=ax.get_xaxis_transform(),
                ha="right" if right else "left", va="center", fontsize=9, color=EXCEEDED, fontweight="bold", zorder=5)

    point = f" ({criterion.point})" if criterion.point else ""
    title = f"{criterion.name}{point} — {criterion.quantity}, {window_text(criterion.window_s)}"
    ax.set_title(title, fontsize=12, loc="left", color=INK, pad=7, fontweight="bold")
    if unit_text(unit) == "°":  # degrees on the ticks, as on an inclinometer
        from matplotlib.ticker import FuncFormatter

        ax.yaxis.set_major_formatter(FuncFormatter(lambda y, _: f"{y:g}°"))
    else:
        ax.set_ylabel(unit_text(unit) or "value", fontsize=10.5, color=INK)
    ax.grid(color=GRID, lw=0.8)
    ax.set_axisbelow(True)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    return figures.png(figure)


def timeline_png(duration_s: float, events: list[EventResult], messages: list[Message], actions: list[Action],
                 alarms: list[tuple[int, AlarmResult]]) -> bytes:
    """The run as a strip: events (diamonds, E-numbered), messages, instructor actions, and each criterion's
    numbered alarms as bars, dark from raised to acknowledged (the delay written beside it), light on to
    back within the limit."""
    criteria = list(dict.fromkeys(alarm.criterion for _, alarm in alarms))
    rows = ["events", "messages", "actions"] + [f"alarms: {name}" for name in criteria]
    y = {row: len(rows) - i for i, row in enumerate(rows)}
    figure, ax = _figure(0.62 + 0.46 * len(rows), top_px=8)
    span = _span(duration_s, np.asarray([], float))
    ax.set_xlim(0.0, span)
    ax.set_ylim(0.3, len(rows) + 0.5)
    _time_axis(ax, span)
    for row in rows:  # the rows' names inside the plot, over their left end: the time axis lines up with the plots'
        ax.text(0.004 * span, y[row] + 0.26, row.upper(), fontsize=8, color=MUTED, va="bottom", ha="left",
                fontweight="bold", zorder=1)
        ax.axhline(y[row], color="#e6e9ed", lw=0.8, zorder=0)
    happened = _happened(events)
    times = [e.happened_s for e in happened]
    gap = 0.03 * span
    for i, event in enumerate(happened):
        at, label = event.happened_s, f"E{event.index}"
        ax.plot([at], [y["events"]], "D", ms=6.5, color=EVENT, zorder=3, clip_on=False)
        # beside the marker (clear of the row's name above it): to the right, or to the left where the next event
        # is close, or under it where both neighbours are
        after = i + 1 < len(times) and times[i + 1] - at < gap or at > 0.96 * span
        before = i > 0 and at - times[i - 1] < gap
        if not after or not before:
            ax.text(at + (-1 if after else 1) * 0.007 * span, y["events"], label, fontsize=9, color=EVENT,
                    va="center", ha="right" if after else "left", fontweight="bold")
        else:
            ax.text(at, y["events"] - 0.17, label, fontsize=9, color=EVENT, va="top", ha="center", fontweight="bold")
    for message in messages:
        instructor = message.source == "instructor"
        ax.plot([message.time_s], [y["messages"]], "o", ms=6, zorder=3, color=MESSAGE, clip_on=False,
                markerfacecolor=MESSAGE if instructor else "white", markeredgewidth=1.4)
    for action in actions:
        ax.plot([action.time_s], [y["actions"]], "s", ms=5.5, color=ACTION, zorder=3, clip_on=False)
    lanes = {}  # an alarm's label goes above its bar, or below where the row's previous label is near
    for name in criteria:
        mine = [(n, a) for n, a in alarms if a.criterion == name]
        lanes.update(zip((n for n, _ in mine), _lanes([a.raised_s for _, a in mine], 0.3 * span, 2)))
    for number_, alarm in alarms:
        row = y[f"alarms: {alarm.criterion}"]
        raised, acked, cleared = alarm.raised_s, alarm.acknowledged_s, alarm.cleared_s
        end = span if cleared is None else max(cleared, acked if acked is not None else raised)
        ax.barh(row, end - raised, left=raised, height=0.42, color=EXCEEDED, alpha=0.22, lw=0, zorder=2)
        if acked is not None:
            ax.barh(row, max(acked - raised, 0.0), left=raised, height=0.42, color=EXCEEDED, lw=0, zorder=3)
            note = f"A{number_}  ack {acked - raised:.1f} s"
        else:  # never acknowledged: hatched to the end of the run
            ax.barh(row, span - raised, left=raised, height=0.42, fill=False, hatch="////", edgecolor=EXCEEDED,
                    lw=0, zorder=3)
            note = f"A{number_}  not acknowledged"
        ax.plot([raised], [row], "|", ms=11, mew=2, color=EXCEEDED, zorder=4)
        right = raised > 0.8 * span
        x = raised - 0.004 * span if right else (acked if acked is not None else raised) + 0.006 * span
        if lanes[number_]:
            at, va = row - 0.26, "top"
        elif raised < 0.22 * span:  # the row's name is above: on the bar, on white
            at, va = row, "center"
        else:
            at, va = row + 0.26, "bottom"
        ax.text(x, at, note, fontsize=9, color="#9b1f1a", va=va, ha="right" if right else "left", zorder=5,
                bbox={"boxstyle": "square,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.9} if va == "center"
                else None)
    ax.set_yticks([])
    ax.grid(axis="x", color=GRID, lw=0.8)
    ax.set_axisbelow(True)
    for side in ("top", "right", "left"):
        ax.spines[side].set_visible(False)
    return figures.png(figure)


TRACK = VALUE
ORDER = "#c26b00"
"""The rudder order's and the autopilot's set course's dashed lines: an orange apart from the blue actual values."""
SHIP_OUTLINE = ((0.0, 0.5), (0.15, 0.2), (0.15, -0.5), (-0.15, -0.5), (-0.15, 0.2))
"""A ship's outline, bow up, one length long and centred on midship (as an ECDIS draws own ship's symbol)."""
SHIP_PX = 24.0
"""The ship symbol's length on the track (not to scale: she would be a speck on a track of some miles)."""
STATION_M = 5.0
"""A track that never leaves this circle round the start is drawn as held on station."""
KM_ABOVE_M = 5000.0
"""A track wider or taller than this is drawn in km."""


def heading_curve(heading_deg, course_deg=None) -> tuple[np.ndarray, np.ndarray]:
    """(heading, set course) in degrees as one continuous curve each: the heading unwrapped from its first value
    (a turn through north goes on to 365°, not back to 5°), the course (None where hand steering: NaN) on the
    same turn as the heading at each sample, so neither jumps by 360° where the ship crosses north."""
    h = np.asarray(heading_deg, float)
    h = np.degrees(np.unwrap(np.radians(h))) if h.size else h
    if h.size and np.isfinite(h[0]):
        h = h - 360.0 * math.floor(h[0] / 360.0)
    c = np.array([np.nan if x is None else x for x in (course_deg or [])], float)[: h.size]
    c = np.concatenate((c, np.full(h.size - c.size, np.nan)))
    c = c + 360.0 * np.round((h - c) / 360.0)
    return h, c


def track_png(ship: dict, events: list[EventResult],
              alarms: list[tuple[int, AlarmResult]] | list[AlarmResult]) -> bytes:
    """``ship``'s track over the ground (midship, from the start; east right, north up, to scale, in m or in km
    past :data:`KM_ABOVE_M`): the start (open circle), her outline every few minutes along her heading with the
    time beside it, her outline at the end (filled), each event that happened (E-numbered diamond) and each of the
    numbered ``alarms`` ((number, alarm) pairs, or alarms numbered from 1; red, A-numbered) where she was at the
    time. A ship that never leaves :data:`STATION_M` of the start is drawn held on station, her events and alarms
    listed by time."""
    t = np.asarray(ship.get("time_s") or [], float)
    north = np.asarray(ship.get("north_m") or [], float)[: t.size]
    east = np.asarray(ship.get("east_m") or [], float)[: t.size]
    heading = np.asarray(ship.get("heading_deg") or [], float)[: t.size]
    t = t[: min(north.size, east.size, heading.size)]
    north, east, heading = north[: t.size], east[: t.size], heading[: t.size]
    name = ship.get("name") or "the ship"
    numbered = [a if isinstance(a, tuple) else (n, a) for n, a in enumerate(alarms, start=1)]
    marks = [(e.happened_s, "E", e.index) for e in _happened(events)]
    marks += [(a.raised_s, "A", n) for n, a in numbered]
    marks.sort(key=lambda m: (m[0], m[1] == "A", m[2]))
    reach = float(np.hypot(north, east).max()) if t.size else 0.0
    if reach < STATION_M:
        return _station_png(name, t, heading, reach, marks)

    spread = max(float(np.ptp(east)), float(np.ptp(north)))
    km = spread > KM_ABOVE_M
    unit = 1000.0 if km else 1.0
    x, y = east / unit, north / unit
    width_px = WIDTH_IN * DPI - LEFT_PX - RIGHT_PX
    pad_px = 46.0  # room for the symbols and labels round the track
    de, dn = max(float(np.ptp(x)), 1e-9), max(float(np.ptp(y)), 1e-9)
    height_px = min(max((width_px - 2 * pad_px) * dn / de + 2 * pad_px, 380.0), 700.0)
    per_px = max(de / (width_px - 2 * pad_px), dn / (height_px - 2 * pad_px))  # data units a pixel, both ways
    top_px = 34.0
    figure, ax = _figure((height_px + BOTTOM_PX + top_px) / DPI, top_px=top_px)
    cx, cy = (x.min() + x.max()) / 2, (y.min() + y.max()) / 2
    ax.set_xlim(cx - per_px * width_px / 2, cx + per_px * width_px / 2)
    ax.set_ylim(cy - per_px * height_px / 2, cy + per_px * height_px / 2)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_autoscale_on(False)
    _grid_steps(ax, per_px * width_px, per_px * height_px)
    ax.set_xlabel(f"east of the start ({'km' if km else 'm'})", fontsize=10, color=MUTED)
    ax.set_ylabel(f"north of the start ({'km' if km else 'm'})", fontsize=10, color=MUTED, labelpad=2)
    ax.tick_params(labelsize=10, colors=INK)
    ax.tick_params(axis="y", labelsize=9.5, pad=2)  # '−4000' and the label fit the margin the time axes keep
    ax.grid(color=GRID, lw=0.8)
    ax.set_axisbelow(True)

    ax.plot(x, y, color=TRACK, lw=1.8, zorder=3, solid_joinstyle="round", solid_capstyle="round")
    at = lambda s: (float(np.interp(s, t, x)), float(np.interp(s, t, y)))  # noqa: E731 (position at time s)
    ground = _ground_directions(x, y, heading)  # unit vectors of the way she goes over the ground, per sample

    def sides(s: float, *which: str) -> list[tuple[float, float]]:
        """Unit vectors ahead, astern, to port or to starboard of her way over the ground at time ``s``."""
        i = int(np.clip(np.searchsorted(t, s), 0, t.size - 1))
        gx, gy = ground[i]
        vectors = {"ahead": (gx, gy), "astern": (-gx, -gy), "port": (-gy, gx), "starboard": (gy, -gx)}
        return [vectors[w] for w in which]

    turned, _ = heading_curve(heading)  # interpolated across north without swinging the long way round
    span = float(t[-1] - t[0])
    step = next((s for s in STEPS_S if span / s <= 10), STEPS_S[-1])
    long = span >= 3600
    labels = _Placer(ax, x, y)
    labels.taken.append(_north_arrow(ax, x, y))
    outlines = [(t[0], (x[0], y[0]))]  # her outline every step, where it would not sit on the one before
    for s in np.arange(t[0] + step, t[-1] - 0.4 * step, step):
        p = at(s)
        if math.hypot(p[0] - outlines[-1][1][0], p[1] - outlines[-1][1][1]) >= 34 * per_px:
            outlines.append((s, p))
    outlines = outlines[1:]
    groups = _clusters(marks, at, 30 * per_px)
    labels.block((x[0], y[0]), 8)
    labels.block((x[-1], y[-1]), 12)
    for s, p in outlines:
        labels.block(p, 12)
    for s, _, _ in marks:
        labels.block(at(s), 6)

    ax.plot([x[0]], [y[0]], "o", ms=9, mfc="white", mec=INK, mew=1.8, zorder=6)
    labels.place((x[0], y[0]), sides(t[0], "astern", "port", "starboard"), 10, f"start {clock(t[0], long)}", INK,
                 bold=True)
    _ship_symbol(ax, (x[-1], y[-1]), float(heading[-1]), fc=INK, ec=INK)
    labels.place((x[-1], y[-1]), sides(t[-1], "ahead", "starboard", "port", "astern"), 14,
                 f"end {clock(t[-1], long)}", INK, bold=True)
    for group in groups:
        times = [m[0] for m in group]
        middle = (times[0] + times[-1]) / 2
        for s, kind, _ in group:
            px, py = at(s)
            if kind == "E":
                ax.plot([px], [py], "D", ms=7, color=EVENT, mec="white", mew=1.0, zorder=7)
            else:
                ax.plot([px], [py], "o", ms=7.5, color=EXCEEDED, mec="white", mew=1.0, zorder=8)
        tags = [(kind, colour, [m[2] for m in group if m[1] == kind]) for kind, colour in (("E", EVENT),
                                                                                           ("A", EXCEEDED))]
        text = [(_numbered(kind, numbers), colour) for kind, colour, numbers in tags if numbers]
        labels.place(at(middle), sides(middle, "port", "starboard", "astern", "ahead"), 12, text[0][0], text[0][1],
                     bold=True, boxed=True, then=text[1:])
    for s, p in outlines:  # last: an outline whose time finds no clear place is left out
        if labels.place(p, sides(s, "starboard", "port"), 12, clock(s, long), MUTED, optional=True):
            _ship_symbol(ax, p, float(np.interp(s, t, turned)), fc="white", ec=INK)
    ax.set_title(f"{name} — track over the ground", fontsize=12, loc="left", color=INK, pad=8, fontweight="bold")
    ax.set_title(f"midship, from the start · her outline every {_every(step)}", fontsize=9.5, loc="right",
                 color=MUTED, pad=9)
    return figures.png(figure)


def handling_png(ship: dict, events: list[EventResult], duration_s: float) -> bytes:
    """``ship``'s handling over a run of ``duration_s``, four panels on one time axis: heading (with the autopilot's
    set course dashed where it steers), speed over ground, rudder angle and order (+ starboard), propeller rpm
    (astern negative); ``events`` that happened as dashed verticals, E-numbered."""
    from matplotlib.ticker import FixedLocator, FuncFormatter, MultipleLocator

    t = np.asarray(ship.get("time_s") or [], float)

    def series(key: str) -> np.ndarray:
        values = np.array([np.nan if v is None else v for v in ship.get(key) or []], float)[: t.size]
        return np.concatenate((values, np.full(t.size - values.size, np.nan)))

    heading, course = heading_curve(series("heading_deg"), list(ship.get("course_deg") or []))
    heading = np.concatenate((heading, np.full(t.size - heading.size, np.nan)))[: t.size]
    course = np.concatenate((course, np.full(t.size - course.size, np.nan)))[: t.size]
    sog, rudder, order, rpm = (series(k) for k in ("speed_over_ground_kn", "rudder_deg", "rudder_order_deg",
                                                   "propeller_rpm"))
    panel_px, gap_px, top_px = 118.0, 30.0, 60.0
    height = top_px + 4 * panel_px + 3 * gap_px + BOTTOM_PX
    figure = figures.figure(WIDTH_IN, height / DPI, facecolor="white")
    width = WIDTH_IN * DPI
    figure.subplots_adjust(left=LEFT_PX / width, right=1 - RIGHT_PX / width, bottom=BOTTOM_PX / height,
                           top=1 - top_px / height, hspace=gap_px / panel_px)
    axes = figure.subplots(4, 1, sharex=True)
    span = _span(duration_s, t)
    for ax in axes:
        ax.set_xlim(0.0, span)
        ax.grid(color=GRID, lw=0.8)
        ax.set_axisbelow(True)
        ax.tick_params(labelsize=10, colors=INK)
        for side in ("top", "right"):
            ax.spines[side].set_visible(False)
    _time_axis(axes[-1], span)
    for ax in axes[:-1]:
        ax.tick_params(labelbottom=False)

    ax = axes[0]
    both = np.concatenate((heading[np.isfinite(heading)], course[np.isfinite(course)]))
    low, high = (float(both.min()), float(both.max())) if both.size else (0.0, 360.0)
    folded = not both.size or high - low > 360.0
    if folded:  # more than a full turn: the compass card, the line broken where she passes north
        (th, heading), (tc, course) = _broken(t, heading % 360.0), _broken(t, course % 360.0)
        low, high = 0.0, 360.0
    else:
        th = tc = t
    middle, half = (low + high) / 2, max((high - low) / 2, 5.0)
    ax.set_ylim(middle - 1.12 * half, middle + 1.12 * half + 0.9 * half)  # the top band keeps the E tags clear
    step = 90 if folded else next((s for s in (1, 2, 5, 10, 15, 30, 45, 90) if 2 * half / s <= 5), 90)
    ax.yaxis.set_major_locator(FixedLocator([0.0, 90.0, 180.0, 270.0, 360.0]) if folded else MultipleLocator(step))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: "360°" if folded and v >= 360 else compass(v)))
    ax.plot(th, heading, color=TRACK, lw=1.5, zorder=3)
    ax.plot(tc, course, color=ORDER, lw=1.5, ls=(0, (5, 3)), zorder=4)  # over the heading: seen where she holds it
    _panel_titles(ax, "Heading", [("heading", TRACK, "-"), ("autopilot's set course", ORDER, "--")])

    ax = axes[1]
    top = float(np.nanmax(sog)) if np.isfinite(sog).any() else 1.0
    ax.set_ylim(min(0.0, float(np.nanmin(sog)) if np.isfinite(sog).any() else 0.0), max(top * 1.18, 1.0))
    ax.plot(t, sog, color=TRACK, lw=1.5, zorder=3)
    _panel_titles(ax, "Speed over ground (kn)", [])

    ax = axes[2]
    angles = np.concatenate((rudder[np.isfinite(rudder)], order[np.isfinite(order)]))
    reach = max(float(np.abs(angles).max()) if angles.size else 0.0, 5.0) * 1.22
    ax.set_ylim(-reach, reach)
    ax.yaxis.set_major_locator(MultipleLocator(next((s for s in (2, 5, 10, 15, 20) if reach / s <= 2.6), 20)))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{abs(v):g}° {'S' if v > 0 else 'P'}" if round(v, 6)
                                               else "0°"))  # as the rudder angle indicator reads
    ax.axhline(0.0, color=MUTED, lw=0.8, zorder=1)
    ax.plot(t, rudder, color=TRACK, lw=1.5, zorder=3)
    ax.plot(t, order, color=ORDER, lw=1.5, ls=(0, (5, 3)), zorder=4, drawstyle="steps-post")
    _panel_titles(ax, "Rudder (°, P port −, S starboard +)", [("rudder angle", TRACK, "-"), ("order", ORDER, "--")])

    ax = axes[3]
    finite = rpm[np.isfinite(rpm)]
    low, high = (min(float(finite.min()), 0.0), max(float(finite.max()), 0.0)) if finite.size else (0.0, 1.0)
    extent = max(high - low, 10.0)
    ax.set_ylim(low - 0.12 * extent * (low < 0), high + 0.18 * extent)
    ax.axhline(0.0, color=MUTED, lw=0.8, zorder=1)
    if low < 0:
        ax.axhspan(ax.get_ylim()[0], 0.0, color="#eef0f3", lw=0, zorder=0)
        ax.text(0.004, 0.03, "astern", transform=ax.transAxes, ha="left", va="bottom", fontsize=8.5, color=MUTED)
    ax.plot(t, rpm, color=TRACK, lw=1.5, zorder=3)
    _panel_titles(ax, "Propeller (rpm, astern −)", [])

    happened = _happened(events)
    for event in happened:
        for ax in axes:
            ax.axvline(event.happened_s, color=EVENT, lw=0.9, ls=(0, (2, 2)), zorder=1)
    groups: list[list[EventResult]] = []  # events closer than a tag's width share one tag
    for event in happened:
        if groups and event.happened_s - groups[-1][0].happened_s < 0.025 * span:
            groups[-1].append(event)
        else:
            groups.append([event])
    for group, lane in zip(groups, _lanes([g[0].happened_s for g in groups], 0.06 * span, 2)):
        at = group[0].happened_s
        _tag(axes[0], at, 0.975 - 0.16 * lane, _numbered("E", [e.index for e in group]), EVENT, _align(at, span))
    figure.text(LEFT_PX / width, 1 - 8 / height, f"{ship.get('name') or 'the ship'} — handling", fontsize=12,
                color=INK, fontweight="bold", ha="left", va="top")
    return figures.png(figure)


def _happened(events: list[EventResult]) -> list[EventResult]:
    """The events that happened, in the order they did."""
    return sorted((e for e in events if e.happened_s is not None), key=lambda e: e.happened_s)


def _panel_titles(ax, title: str, keys: list[tuple[str, str, str]]) -> None:
    """A panel's name over its left end and the key to its lines ((text, colour, '-' or '--')) over its right."""
    ax.set_title(title, fontsize=10, loc="left", color=INK, pad=5, fontweight="bold")
    anchor, where, offset = (1.0, 1.0), "axes fraction", (0, 5)
    for text, colour, style in reversed(keys):  # right to left: each text, then its line sample to its left
        label = ax.annotate(text, anchor, xycoords=where, xytext=offset, textcoords="offset points", ha="right",
                            va="bottom" if where == "axes fraction" else "center", fontsize=9, color=MUTED,
                            annotation_clip=False)
        ax.annotate("", (0, 0.45), xycoords=label, xytext=(-22, 0), textcoords="offset points",
                    arrowprops={"arrowstyle": "-", "color": colour, "lw": 1.6, "shrinkA": 0, "shrinkB": 3,
                                "ls": (0, (3, 2)) if style == "--" else "-"}, annotation_clip=False)
        anchor, where, offset = (0, 0.5), label, (-34, 0)


def _station_png(name: str, t: np.ndarray, heading: np.ndarray, reach: float, marks: list) -> bytes:
    """The track of a ship held on station: her outline at the start position on her last heading, heading lines
    for her first (dashed) and last headings, said in words, and her events and alarms listed by time (on the
    track they would all sit on one point)."""
    height_in, top_px = 3.8, 34.0
    figure, ax = _figure(height_in, top_px=top_px)
    long = bool(t.size) and t[-1] >= 3600
    width_px = WIDTH_IN * DPI - LEFT_PX - RIGHT_PX
    height_px = height_in * DPI - BOTTOM_PX - top_px
    per_px = 0.5
    ax.set_xlim(-per_px * width_px / 2, per_px * width_px / 2)
    ax.set_ylim(-per_px * height_px * 0.42, per_px * height_px * 0.58)  # the words above her
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_autoscale_on(False)
    _grid_steps(ax, per_px * width_px, per_px * height_px)
    ax.set_xlabel("east of the start (m)", fontsize=10, color=MUTED)
    ax.set_ylabel("north of the start (m)", fontsize=10, color=MUTED)
    ax.tick_params(labelsize=10, colors=INK)
    ax.grid(color=GRID, lw=0.8)
    ax.set_axisbelow(True)
    words = ("the run recorded no position" if not t.size else "at the start position over the whole run"
             if reach < 0.05 else f"within {reach:.1f} m of the start")
    if heading.size:
        first, last = float(heading[0]), float(heading[-1])
        lines = [(last, "-", INK, f"{compass(last)} at the end")]
        if compass(first) != compass(last):
            lines.insert(0, (first, (0, (4, 3)), MUTED, f"{compass(first)} at the start"))
            words += f" · heading {compass(first)} → {compass(last)}"
        else:
            words += f" · heading {compass(last)}"
        labels = _Placer(ax, np.zeros(0), np.zeros(0))
        for bearing, style, colour, label in lines:
            bow = (math.sin(math.radians(bearing)), math.cos(math.radians(bearing)))
            ax.annotate("", (0.0, 0.0), xytext=(bow[0] * 62, bow[1] * 62), textcoords="offset points",
                        arrowprops={"arrowstyle": "-", "color": colour, "lw": 1.4, "ls": style, "shrinkA": 0,
                                    "shrinkB": 0}, zorder=4)
            labels.place((0.0, 0.0), [bow], 64, label, colour)
        _ship_symbol(ax, (0.0, 0.0), last, fc=INK, ec=INK, size_px=34.0)
    ax.text(0.5, 0.95, "held on station" if t.size else "no track recorded", transform=ax.transAxes, ha="center",
            va="top", fontsize=13, color=INK, fontweight="bold",
            bbox={"boxstyle": "square,pad=0.2", "fc": "white", "ec": "none"})
    ax.text(0.5, 0.84, words, transform=ax.transAxes, ha="center", va="top", fontsize=10, color=MUTED,
            bbox={"boxstyle": "square,pad=0.2", "fc": "white", "ec": "none"})
    y = 0.04
    for kind, colour, title in (("A", EXCEEDED, "alarms"), ("E", EVENT, "events")):
        mine = [(s, n) for s, k, n in marks if k == kind]
        if mine:
            listed = "   ".join(f"{kind}{n} {clock(s, long)}" for s, n in mine[:12])
            more = f"   … {len(mine) - 12} more" if len(mine) > 12 else ""
            ax.text(0.012, y, f"{title}:  {listed}{more}", transform=ax.transAxes, ha="left", va="bottom",
                    fontsize=9.5, color=colour, fontweight="bold",
                    bbox={"boxstyle": "square,pad=0.2", "fc": "white", "ec": "none"})
            y += 0.085
    _north_arrow(ax, np.zeros(1), np.zeros(1))
    ax.set_title(f"{name} — track over the ground", fontsize=12, loc="left", color=INK, pad=8, fontweight="bold")
    ax.set_title("midship, from the start", fontsize=9.5, loc="right", color=MUTED, pad=9)
    return figures.png(figure)


def _broken(t: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(t, v) with a gap (NaN) wherever ``v`` (compass degrees) steps by more than half a turn: passing north."""
    jumps = np.flatnonzero(np.abs(np.diff(v)) > 180.0) + 1
    return np.insert(t, jumps, (t[jumps - 1] + t[jumps]) / 2), np.insert(v, jumps, np.nan)


def _ground_directions(x: np.ndarray, y: np.ndarray, heading: np.ndarray) -> np.ndarray:
    """Per sample, the unit vector of her way over the ground (over the neighbouring samples), her heading where
    she hardly moves."""
    dx, dy = np.gradient(x) if x.size > 1 else np.zeros(1), np.gradient(y) if y.size > 1 else np.zeros(1)
    length = np.hypot(dx, dy)
    bow = np.radians(heading)
    still = length < 1e-9 * max(float(np.ptp(x)), float(np.ptp(y)), 1e-12)
    gx = np.where(still, np.sin(bow), dx / np.where(still, 1.0, length))
    gy = np.where(still, np.cos(bow), dy / np.where(still, 1.0, length))
    return np.stack((gx, gy), axis=1)


def _clusters(marks: list, at, radius: float) -> list[list]:
    """``marks`` (time, kind, number) in time order, grouped where each lies within ``radius`` (data units) of
    its group's first: marks at one place share one label."""
    groups: list[list] = []
    for mark in marks:
        if groups:
            head = at(groups[-1][0][0])
            here = at(mark[0])
            if math.hypot(here[0] - head[0], here[1] - head[1]) < radius:
                groups[-1].append(mark)
                continue
        groups.append([mark])
    return groups


def _numbered(kind: str, numbers: list[int]) -> str:
    """E1, E2, E3, E5 as 'E1–E3 E5': runs of consecutive numbers shortened."""
    runs: list[list[int]] = []
    for n in sorted(set(numbers)):
        if runs and n == runs[-1][-1] + 1:
            runs[-1].append(n)
        else:
            runs.append([n])
    return " ".join(" ".join(f"{kind}{n}" for n in r) if len(r) < 3 else f"{kind}{r[0]}–{kind}{r[-1]}" for r in runs)


def _every(step: float) -> str:
    return f"{step / 60:g} min" if step >= 60 else f"{step:g} s"


def _grid_steps(ax, width: float, height: float) -> None:
    """The same round tick step on both axes (square grid cells, as on a chart): about 8 along x, 2 or more up y."""
    from matplotlib.ticker import FuncFormatter, MultipleLocator

    def nice(raw: float, up: bool) -> float:
        power = 10.0 ** math.floor(math.log10(raw))
        steps = [m * power for m in (1, 2, 2.5, 5, 10)]
        return next(s for s in steps if s >= raw) if up else max(s for s in steps if s <= raw)

    step = nice(width / 8, True)
    if height / step < 2.5:  # a flat track: finer, for some ticks up y
        step = nice(height / 2.5, False)
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(MultipleLocator(step))
        axis.set_major_formatter(FuncFormatter(lambda v, _: number(round(v / step) * step, 6).replace("-", "−")))


def _ship_symbol(ax, at: tuple[float, float], heading_deg: float, fc: str, ec: str, size_px: float = SHIP_PX) -> None:
    """Her outline (:data:`SHIP_OUTLINE`, ``size_px`` long) at data point ``at``, bow on ``heading_deg`` (compass)."""
    from matplotlib.patches import Polygon
    from matplotlib.transforms import Affine2D, ScaledTranslation

    place = (Affine2D().scale(size_px / DPI).rotate_deg(-heading_deg) + ax.figure.dpi_scale_trans
             + ScaledTranslation(at[0], at[1], ax.transData))
    ax.add_patch(Polygon(SHIP_OUTLINE, closed=True, transform=place, fc=fc, ec=ec, lw=1.2, zorder=5,
                         joinstyle="miter"))


class _Placer:
    """Puts the track's labels beside their points where they are clear of one another, of the track and of its
    marks, and inside the axes, measured with the figure's own renderer; where no place is clear, the least bad."""

    def __init__(self, ax, x: np.ndarray, y: np.ndarray) -> None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        self.ax = ax
        self.renderer = FigureCanvasAgg(ax.figure).get_renderer()
        points = ax.transData.transform(np.column_stack((x, y))) if x.size else np.zeros((0, 2))
        if len(points) > 1:  # the track every 2 px, so that no label slips in between two of its samples
            along = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(points, axis=0).T))))
            at = np.arange(0.0, along[-1] + 2.0, 2.0)
            points = np.column_stack((np.interp(at, along, points[:, 0]), np.interp(at, along, points[:, 1])))
        self.line = points
        self.taken: list[tuple[float, float, float, float]] = []
        """Boxes (x0, y0, x1, y1; display px) already used by labels and marks."""

    def block(self, at: tuple[float, float], half_px: float) -> None:
        """Keep labels off a mark of ``half_px`` round data point ``at``."""
        x, y = self.ax.transData.transform(at)
        self.taken.append((x - half_px, y - half_px, x + half_px, y + half_px))

    def place(self, at: tuple[float, float], directions: list[tuple[float, float]], distance_pt: float, text: str,
              color: str, bold: bool = False, boxed: bool = False, optional: bool = False,
              then: list[tuple[str, str]] = ()) -> bool:
        """``text`` about ``distance_pt`` from data point ``at`` along one of the unit ``directions`` (the first that
        is clear, nearest first), anchored on the side facing ``at``; ``then`` (text, colour) pairs follow it on
        its line. Returns whether it was placed: an ``optional`` label with no clear place is left out."""
        pieces = [(text, color)] + list(then)
        style = {"fontsize": 9, "fontweight": "bold" if bold else "normal", "zorder": 9, "annotation_clip": False}
        texts = []
        for words, colour in pieces:
            look = ({"color": "white", "bbox": {"boxstyle": "round,pad=0.22", "fc": colour, "ec": "none"}} if boxed
                    else {"color": colour, "bbox": {"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none",
                                                    "alpha": 0.85}})
            texts.append(self.ax.annotate(words, at, xytext=(0, 0), textcoords="offset points", **style, **look))
        widths = [t.get_window_extent(self.renderer).width for t in texts]
        gap = 6.0  # px between the pieces
        width = sum(widths) + gap * (len(texts) - 1) + (6.0 if boxed else 2.0) * len(texts)
        height = texts[0].get_window_extent(self.renderer).height + (6.0 if boxed else 2.0)
        x, y = self.ax.transData.transform(at)
        best = None
        for extra in (0.0, 8.0, 18.0, 30.0):
            for dx, dy in directions:
                d = (distance_pt + extra) * DPI / 72  # px
                cx, cy = x + dx * d, y + dy * d  # where the label's near side sits
                x0 = cx - (0.0 if dx > 0.38 else 1.0 if dx < -0.38 else 0.5) * width
                y0 = cy - (0.0 if dy > 0.38 else 1.0 if dy < -0.38 else 0.5) * height
                box = (x0, y0, x0 + width, y0 + height)
                cost = self._cost(box)
                if best is None or cost < best[0]:
                    best = (cost, box)
                if cost == 0:
                    break
            if best[0] == 0:
                break
        if best[0] > 0 and optional:
            for text_ in texts:
                text_.remove()
            return False
        x0, y0, x1, y1 = best[1]
        self.taken.append(best[1])
        left = x0 + (3.0 if boxed else 1.0)
        for text_, w in zip(texts, widths):  # each piece from the left of the box, on its middle line
            text_.xyann = ((left - x) * 72 / DPI, ((y0 + y1) / 2 - y) * 72 / DPI)
            text_.set_ha("left")
            text_.set_va("center")
            left += w + gap + (6.0 if boxed else 2.0)
        return True

    def _cost(self, box: tuple[float, float, float, float]) -> float:
        x0, y0, x1, y1 = box
        frame = self.ax.bbox
        cost = 1000.0 if x0 < frame.x0 or x1 > frame.x1 or y0 < frame.y0 or y1 > frame.y1 else 0.0
        cost += 50.0 * sum(1 for a0, b0, a1, b1 in self.taken if a0 < x1 + 2 and x0 - 2 < a1 and b0 < y1 + 2
                           and y0 - 2 < b1)
        if len(self.line):
            inside = ((self.line[:, 0] > x0 - 2) & (self.line[:, 0] < x1 + 2) & (self.line[:, 1] > y0 - 2)
                      & (self.line[:, 1] < y1 + 2))
            cost += float(inside.sum())
        return cost


def _north_arrow(ax, x: np.ndarray, y: np.ndarray) -> tuple[float, float, float, float]:
    """An arrow marked N in the corner of the axes the track keeps clearest of; returns the box it takes
    (x0, y0, x1, y1; display px)."""
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    u, v = (x - x0) / (x1 - x0), (y - y0) / (y1 - y0)
    corners = ((0.965, 0.80), (0.035, 0.80), (0.965, 0.06), (0.035, 0.06))
    near = [int(((np.abs(u - cu) < 0.08) & (v > cv - 0.04) & (v < cv + 0.2)).sum()) for cu, cv in corners]
    cu, cv = corners[int(np.argmin(near))]
    ax.annotate("", (cu, cv + 0.12), xycoords="axes fraction", xytext=(cu, cv), textcoords="axes fraction",
                arrowprops={"arrowstyle": "-|>,head_length=0.7,head_width=0.35", "color": INK, "lw": 1.6}, zorder=9)
    ax.annotate("N", (cu, cv + 0.12), xycoords="axes fraction", xytext=(0, 2), textcoords="offset points",
                ha="center", va="bottom", fontsize=11, fontweight="bold", color=INK, zorder=9)
    (px, py0), (_, py1) = ax.transAxes.transform([(cu, cv), (cu, cv + 0.12)])
    return px - 10.0, py0 - 2.0, px + 10.0, py1 + 20.0


def window_text(window_s: float | None) -> str:
    """A criterion's running window in words (None: a dose over the whole run)."""
    if window_s is None:
        return "over the whole run"
    if window_s >= 120 and window_s % 60 == 0:
        return f"{window_s / 60:g} min window"
    return f"{window_s:g} s window"


def _figure(height_in: float, top_px: float):
    """A figure ``height_in`` tall with one axes in the fixed margins (``top_px`` above it, for a title)."""
    figure = figures.figure(WIDTH_IN, height_in, facecolor="white")
    width, height = WIDTH_IN * DPI, height_in * DPI
    figure.subplots_adjust(left=LEFT_PX / width, right=1 - RIGHT_PX / width, bottom=BOTTOM_PX / height,
                           top=1 - top_px / height)
    return figure, figure.add_subplot()


def _span(duration_s: float | None, t: np.ndarray) -> float:
    """The x extent: the run's length, at least the last evaluation, never zero."""
    return max(duration_s or 0.0, float(t.max()) if t.size else 0.0, 1.0)


def _time_axis(ax, span: float) -> None:
    """Ticks at round minutes (or seconds in a short run), labelled as elapsed min:s."""
    from matplotlib.ticker import FuncFormatter, MultipleLocator

    step = next((s for s in STEPS_S if span / s <= 12), STEPS_S[-1])
    long = span >= 3600
    ax.xaxis.set_major_locator(MultipleLocator(step))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: clock(x, long)))
    ax.set_xlabel("elapsed time (h:min:s)" if long else "elapsed time (min:s)", fontsize=10, color=MUTED)
    ax.tick_params(labelsize=10, colors=INK)


def _runs_above(t: np.ndarray, v: np.ndarray, limit: float) -> list[tuple[float, float]]:
    """The time spans over which the value is above ``limit``, each evaluation holding half a step either side."""
    above = np.concatenate(([False], v > limit, [False]))
    starts = np.flatnonzero(~above[:-1] & above[1:])
    ends = np.flatnonzero(above[:-1] & ~above[1:]) - 1
    half = np.diff(t) / 2 if t.size > 1 else np.array([0.5])
    out = []
    for i, j in zip(starts, ends):
        before = half[i - 1] if i > 0 else half[0]
        after = half[j] if j < half.size else half[-1]
        out.append((float(t[i] - before), float(t[j] + after)))
    return out


def _lanes(xs: list[float], gap: float, count: int) -> list[int]:
    """A lane (0 .. ``count`` - 1) for each of ``xs`` (in order) so that tags closer than ``gap`` take different
    lanes, as far as ``count`` lanes allow."""
    last: list[float | None] = [None] * count
    out = []
    for x in xs:
        free = [i for i, seen in enumerate(last) if seen is None or abs(x - seen) >= gap]
        lane = free[0] if free else min(range(count), key=lambda i: last[i])  # all taken: the oldest
        last[lane] = x
        out.append(lane)
    return out


def _line_label(ax, curve: tuple, y: float, text: str, color: str, side: str) -> None:
    """``text`` on the horizontal line at ``y``, above it (``side`` bottom) or below (top): at the right end,
    or at the left (past the settling start) where the ``curve`` (t, v, span) runs through fewer of its points."""
    t, v, span = curve
    low, high = ax.get_ylim()
    band = (y, y + 0.12 * (high - low)) if side == "bottom" else (y - 0.12 * (high - low), y)
    near = (v >= band[0]) & (v <= band[1])
    start = float(t[np.argmax(np.isfinite(v))]) if np.isfinite(v).any() else 0.0
    right = int((near & (t >= 0.82 * span)).sum())
    left = int((near & (t >= start) & (t <= start + 0.18 * span)).sum())
    at_left = left < right
    ax.annotate(text, (start if at_left else 1.0, y), xycoords=("data" if at_left else "axes fraction", "data"),
                xytext=(4 if at_left else -4, 3 if side == "bottom" else -3), textcoords="offset points",
                ha="left" if at_left else "right", va=side, fontsize=10, color=color, fontweight="bold",
                bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.85}, zorder=6)


def _align(x: float, span: float) -> str:
    """How a label at ``x`` aligns: centred on it, or wholly inside the axes near either end."""
    return "left" if x < 0.02 * span else "right" if x > 0.98 * span else "center"


def _tag(ax, x: float, y_axes: float, text: str, color: str, ha: str) -> None:
    """A small boxed tag (an event's number) at data ``x``, axes-fraction ``y_axes``."""
    ax.text(x, y_axes, text, transform=ax.get_xaxis_transform(), ha=ha, va="top", fontsize=9, color="white",
            fontweight="bold", bbox={"boxstyle": "round,pad=0.22", "fc": color, "ec": "none"}, zorder=6)


def footprint_png(ship: dict) -> bytes:
    """A vessel keeping station: where her midship was around the set point over the run (east right, north up,
    to scale, m), the track coloured from light (start) to dark (end), the footprint's circle (red where she went
    outside it), the set point (a cross) and her outline at the end along her heading."""
    station = ship["station"]
    t = np.asarray(ship.get("time_s") or [], float)
    east = np.asarray(station.get("east_from_set_point_m") or [], float)[: t.size]
    north = np.asarray(station.get("north_from_set_point_m") or [], float)[: t.size]
    footprint = float(station["footprint_m"])
    reach = float(np.hypot(east, north).max()) if east.size else 0.0
    half = max(1.25 * footprint, 1.1 * reach, 1.0)
    height_in, top_px = 6.2, 34.0
    figure, ax = _figure(height_in, top_px=top_px)
    wide = (WIDTH_IN * DPI - LEFT_PX - RIGHT_PX) / (height_in * DPI - BOTTOM_PX - top_px)  # the axes' own shape
    ax.set_xlim(-half * wide, half * wide)
    ax.set_ylim(-half, half)
    ax.set_aspect("equal", adjustable="box")
    ax.grid(color=GRID, lw=0.8)
    ax.set_axisbelow(True)
    ax.set_xlabel("east of the set point (m)", fontsize=10, color=MUTED)
    ax.set_ylabel("north of the set point (m)", fontsize=10, color=MUTED)
    ax.tick_params(labelsize=10, colors=INK)
    outside = reach > footprint
    circle = np.linspace(0.0, 2.0 * math.pi, 181)
    ax.plot(footprint * np.sin(circle), footprint * np.cos(circle), color=EXCEEDED if outside else OK, lw=1.6,
            ls=(0, (5, 3)), zorder=2)
    ax.text(footprint * math.sin(math.radians(45.0)), footprint * math.cos(math.radians(45.0)),
            f"  footprint {footprint:g} m", color=EXCEEDED if outside else OK, fontsize=9.5, va="bottom")
    if east.size > 1:
        from matplotlib.collections import LineCollection

        points = np.column_stack([east, north])
        shade = np.linspace(0.25, 1.0, len(points) - 1)
        colours = np.column_stack([0.12 + 0.5 * (1 - shade), 0.31 + 0.45 * (1 - shade), 0.55 + 0.35 * (1 - shade),
                                   np.ones_like(shade)])
        ax.add_collection(LineCollection(np.stack([points[:-1], points[1:]], axis=1), colors=colours, lw=1.5,
                                         zorder=3))
    ax.plot([0.0], [0.0], marker="+", ms=14, mew=2.0, color=INK, zorder=4)
    heading = ship.get("heading_deg") or []
    if east.size and heading:
        _ship_symbol(ax, (float(east[-1]), float(north[-1])), float(heading[-1]), fc=INK, ec=INK, size_px=30.0)
    words = (f"largest offset {reach:.1f} m" + (f", outside the {footprint:g} m footprint" if outside
                                                    else f", within the {footprint:g} m footprint"))
    ax.set_title(f"{ship.get('name') or 'the vessel'} — footprint around the set point", fontsize=12, loc="left",
                 color=INK, pad=8, fontweight="bold")
    ax.set_title(words, fontsize=9.5, loc="right", color=EXCEEDED if outside else MUTED, pad=9)
    return figures.png(figure)


def station_use_png(ship: dict, duration_s: float) -> bytes:
    """A vessel keeping station over the run, on the report's time axis: each thruster's use (% of its rating), or
    each mooring line's tension (kN), and the wind speed (m/s) above it."""
    station = ship["station"]
    t = np.asarray(ship.get("time_s") or [], float)
    groups = [(name, np.asarray(values, float)[: t.size]) for name, values in (station.get("thrusters") or {}).items()]
    lines = not groups
    if lines:
        groups = [(f"line {name}", np.asarray(values, float)[: t.size])
                  for name, values in (station.get("lines") or {}).items()]
    height = 60.0 + 2 * 150.0 + 44.0 + BOTTOM_PX
    figure = figures.figure(WIDTH_IN, height / DPI, facecolor="white")
    figure.subplots_adjust(left=LEFT_PX / (WIDTH_IN * DPI), right=1 - RIGHT_PX / (WIDTH_IN * DPI),
                           bottom=BOTTOM_PX / height, top=1 - 60.0 / height, hspace=44.0 / 150.0)
    wind_ax, use_ax = figure.subplots(2, 1, sharex=True)
    span = _span(duration_s, t)
    wind = np.asarray(station.get("wind_speed_m_s") or [], float)[: t.size]
    wind_ax.plot(t[: wind.size], wind, color=VALUE, lw=1.2)
    wind_ax.set_ylabel("wind (m/s)", fontsize=10, color=MUTED)
    for name, values in groups:
        use_ax.plot(t[: values.size], values, lw=1.3, label=name)
    use_ax.set_ylabel("tension (kN)" if lines else "thrust (% of rating)", fontsize=10, color=MUTED)
    if not lines:
        use_ax.set_ylim(0.0, 105.0)
        use_ax.axhline(100.0, color=EXCEEDED, lw=1.0, ls=(0, (4, 3)))
    use_ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.0), fontsize=8.5, ncol=min(len(groups), 6), frameon=False,
                  borderaxespad=0.2)
    for ax in (wind_ax, use_ax):
        ax.grid(color=GRID, lw=0.8)
        ax.set_axisbelow(True)
        ax.tick_params(labelsize=10, colors=INK)
        ax.set_xlim(0.0, span)
    _time_axis(use_ax, span)
    figure.suptitle(f"{ship.get('name') or 'the vessel'} — wind and " + ("mooring line tensions" if lines else
                    "thruster use"), x=LEFT_PX / (WIDTH_IN * DPI), ha="left", fontsize=12, color=INK,
                    fontweight="bold")
    return figures.png(figure)
