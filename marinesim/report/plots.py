"""The after-action report's figures as PNG bytes: a criterion's running value over the run, and the timeline.

Drawn with :class:`matplotlib.figure.Figure` on the Agg canvas (never pyplot: no global figure state)
at a fixed size and 100 dpi, every font size given, and saved without the PNG's ``Software`` text,
so the same data give the same bytes. Time runs along x as elapsed min:s (h:min:s past an hour),
the way the report's tables give it (:func:`clock`).
"""

from __future__ import annotations

import io
import math

import numpy as np

OK, CAUTION, EXCEEDED, NONE = "#2e9e44", "#f0a800", "#d0312d", "#6b7280"
"""The bridge alarm panel's colours: green, amber, red, and grey for no value."""
INK, MUTED, GRID = "#1b1f24", "#5b6470", "#e3e7ec"
VALUE = "#1f4e8c"
"""The running value's line: a dark blue that none of the alarm colours is confused with."""
EVENT, MESSAGE, ACTION = "#3d4651", "#1f6fb2", "#7a4fa0"
DPI = 100
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


def criterion_png(criterion: dict, duration_s: float, events: list[dict], alarms: list[tuple[int, dict]]) -> bytes:
    """``criterion``'s running value over a run of ``duration_s``: its limit (red) and caution (amber, dashed)
    lines, the spans above the limit shaded, the settling start greyed, ``events`` and the numbered ``alarms``
    ((number, alarm) pairs raised by this criterion) marked."""
    figure, ax = _figure(2.9, top_px=30)
    series = criterion.get("series") or {}
    t = np.asarray(series.get("time_s") or [], float)
    v = np.array([np.nan if x is None else x for x in series.get("value") or []], float)[: t.size]
    t = t[: v.size]
    limit, unit = criterion.get("limit"), criterion.get("unit")
    caution = None if limit is None or criterion.get("caution") is None else criterion["caution"] * limit
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

    happened = sorted((e for e in events if e.get("happened_s") is not None), key=lambda e: e["happened_s"])
    for event, lane in zip(happened, _lanes([e["happened_s"] for e in happened], 0.03 * span, 2)):
        at = event["happened_s"]
        ax.axvline(at, color=EVENT, lw=0.9, ls=(0, (2, 2)), zorder=1)
        _tag(ax, at, 0.975 - 0.075 * lane, f"E{event['index']}", EVENT, _align(at, span))
    for (number_, alarm), lane in zip(alarms, _lanes([a["raised_s"] for _, a in alarms], 0.05 * span, 2)):
        y = 0.83 - 0.07 * lane
        ax.axvline(alarm["raised_s"], color=EXCEEDED, lw=0.9, zorder=1)
        ax.plot([alarm["raised_s"]], [y], marker="v", ms=7, color=EXCEEDED, transform=ax.get_xaxis_transform(),
                zorder=5, clip_on=False)
        right = alarm["raised_s"] > 0.95 * span
        ax.text(alarm["raised_s"], y, f"A{number_} " if right else f" A{number_}", transform=ax.get_xaxis_transform(),
                ha="right" if right else "left", va="center", fontsize=9, color=EXCEEDED, fontweight="bold", zorder=5)

    point = f" ({criterion['point']})" if criterion.get("point") else ""
    title = f"{criterion['name']}{point} — {criterion.get('quantity', '')}, {window_text(criterion.get('window_s'))}"
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
    return _png(figure)


def timeline_png(duration_s: float, events: list[dict], messages: list[dict], actions: list[dict],
                 alarms: list[tuple[int, dict]]) -> bytes:
    """The run as a strip: events (diamonds, E-numbered), messages, instructor actions, and each criterion's
    numbered alarms as bars, dark from raised to acknowledged (the delay written beside it), light on to
    back within the limit."""
    criteria = list(dict.fromkeys(alarm["criterion"] for _, alarm in alarms))
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
    happened = sorted((e for e in events if e.get("happened_s") is not None), key=lambda e: e["happened_s"])
    times = [e["happened_s"] for e in happened]
    gap = 0.03 * span
    for i, event in enumerate(happened):
        at, label = event["happened_s"], f"E{event['index']}"
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
        instructor = message.get("source") == "instructor"
        ax.plot([message["time_s"]], [y["messages"]], "o", ms=6, zorder=3, color=MESSAGE, clip_on=False,
                markerfacecolor=MESSAGE if instructor else "white", markeredgewidth=1.4)
    for action in actions:
        ax.plot([action["time_s"]], [y["actions"]], "s", ms=5.5, color=ACTION, zorder=3, clip_on=False)
    lanes = {}  # an alarm's label goes above its bar, or below where the row's previous label is near
    for name in criteria:
        mine = [(n, a) for n, a in alarms if a["criterion"] == name]
        lanes.update(zip((n for n, _ in mine), _lanes([a["raised_s"] for _, a in mine], 0.3 * span, 2)))
    for number_, alarm in alarms:
        row = y[f"alarms: {alarm['criterion']}"]
        raised, acked, cleared = alarm["raised_s"], alarm.get("acknowledged_s"), alarm.get("cleared_s")
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
    return _png(figure)


def window_text(window_s: float | None) -> str:
    """A criterion's running window in words (None: a dose over the whole run)."""
    if window_s is None:
        return "over the whole run"
    if window_s >= 120 and window_s % 60 == 0:
        return f"{window_s / 60:g} min window"
    return f"{window_s:g} s window"


def _figure(height_in: float, top_px: float):
    """A figure ``height_in`` tall with one axes in the fixed margins (``top_px`` above it, for a title)."""
    from matplotlib.figure import Figure  # loaded with the first plot: the package imports fast

    figure = Figure(figsize=(WIDTH_IN, height_in), dpi=DPI, facecolor="white")
    width, height = WIDTH_IN * DPI, height_in * DPI
    figure.subplots_adjust(left=LEFT_PX / width, right=1 - RIGHT_PX / width, bottom=BOTTOM_PX / height,
                           top=1 - top_px / height)
    return figure, figure.add_subplot()


def _png(figure) -> bytes:
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=DPI, metadata={"Software": None}, pil_kwargs={"optimize": True})
    return buffer.getvalue()


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
