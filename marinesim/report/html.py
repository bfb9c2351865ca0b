"""The after-action report as one self-contained HTML file: plots embedded as PNG, CSS inline, nothing fetched.

Laid out for a debrief (IMO model course 6.10: briefing, exercise, debriefing; STCW A-I/12: against
the objectives) from the dictionary :func:`marinesim.report.debrief.debrief` makes. The same data
give the same bytes (no dates; PNG metadata left out).
"""

from __future__ import annotations

import base64
import html
import io
from pathlib import Path

import numpy as np

from marinesim.atomic import atomic_path

COLORS = {"ok": "#2e9e44", "within limits": "#2e9e44", "met": "#2e9e44", "caution": "#e0a100",
          "met with caution": "#e0a100", "exceeded": "#d0312d", "not met": "#d0312d", "settling": "#8a8f98",
          "no value": "#8a8f98"}
"""Badge colours as on a bridge alarm panel: green, amber, red, grey."""
CSS = """
body{font-family:'DejaVu Sans',Arial,sans-serif;margin:24px auto;max-width:1100px;color:#1b1f24;line-height:1.4}
h1{margin-bottom:4px} h2{border-bottom:2px solid #d6dbe1;padding-bottom:3px;margin-top:28px}
.badge{display:inline-block;padding:2px 10px;border-radius:10px;color:#fff;font-weight:bold;font-size:0.9em}
table{border-collapse:collapse;margin:8px 0;font-size:0.92em} td,th{border:1px solid #d6dbe1;padding:3px 8px;text-align:left}
th{background:#eef1f4} td.num{text-align:right;font-variant-numeric:tabular-nums}
img.plot{display:block;max-width:100%;margin:8px 0} .muted{color:#667} p.brief{white-space:pre-wrap}
@media print{body{margin:0;max-width:none} h2{page-break-after:avoid} img.plot{page-break-inside:avoid}}
"""
SCRIPT = ("window.addEventListener('load',function(){var n=0;document.querySelectorAll('img.plot').forEach("
          "function(i){if(i.complete&&i.naturalWidth>0)n++;});document.body.dataset.plotsLoaded=n;});")
"""Counts the plots the browser decoded (a test reads it from the rendered page)."""


def write_report(data: dict, out: Path) -> Path:
    """Write the report of ``data`` to ``out`` (atomically); returns ``out``."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(out) as temp:
        temp.write_text(render_report(data), encoding="utf-8")
    return out


def render_report(data: dict) -> str:
    """The report of ``data`` as HTML text."""
    e = html.escape
    verdict = data.get("verdict", "no value")
    parts = [f"<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>Debrief: {e(data['title'])}</title>"
             f"<style>{CSS}</style></head><body>",
             f"<h1>Debrief: {e(data['title'])}</h1><p class='muted'>{e(data.get('source', ''))}</p>",
             f"<p>Verdict: {_badge(verdict)}</p>"]
    briefing = data.get("briefing")
    if briefing:
        parts.append("<h2>Briefing</h2>" + "".join(f"<p class='brief'>{e(p.strip())}</p>"
                                                   for p in briefing["text"].split("\n\n") if p.strip()))
        if briefing.get("objectives"):
            rows = [(e(o["text"]), e(", ".join(o["criteria"])) or "-", _badge(o["verdict"])) for o in briefing["objectives"]]
            parts.append("<h3>Objectives</h3>" + _table(("objective", "judged by", "verdict"), rows))
    criteria = data.get("criteria", [])
    if criteria:
        parts.append("<h2>Criteria over the exercise</h2><p class='muted'>Running value at each evaluation; red: "
                     "limit; amber dashed: caution; shaded: above the limit; grey lines: events (numbered); "
                     "red ticks: alarms.</p>")
        for criterion in criteria:
            parts.append(_img(_criterion_plot(criterion, data), f"{criterion['name']} over time"))
        parts.append("<h2>Exceedance statistics</h2>" + _statistics(data))
    parts.append("<h2>Timeline</h2>" + _img(_timeline_plot(data), "timeline of events, messages and alarms"))
    alarms = data.get("alarms", [])
    if alarms:
        rows = [(e(a["criterion"]), _num(a["raised_s"], "s"), f"{a['value']:.3g} / {a['limit']:.3g}",
                 _num(a["acknowledged_s"], "s"),
                 _num(None if a["acknowledged_s"] is None else a["acknowledged_s"] - a["raised_s"], "s", ".1f"),
                 _num(a["cleared_s"], "s")) for a in alarms]
        parts.append("<h3>Alarms</h3>" + _table(("criterion", "raised", "value / limit", "acknowledged",
                                                  "acknowledgement delay", "back within limit"), rows))
    if data.get("sickness"):
        rows = [(e(s["point"]), _num(s.get("msi_percent"), "%", ".1f"), _num(s.get("msdv_m_s1_5"), "m/s^1.5", ".1f"))
                for s in data["sickness"]]
        parts.append("<h2>Motion sickness</h2><p class='muted'>MSI: O'Hanlon &amp; McCauley, 2 h exposure; MSDV: "
                     "ISO 2631-1 W_f over the exercise.</p>" + _table(("point", "MSI", "MSDV"), rows))
    log = [(m["time_s"], f"{m['source']} message", m["text"]) for m in data.get("messages", [])]
    log += [(ev["happened_s"], f"event {ev['index']} ({ev['trigger']})", ev["what"] or "")
            for ev in data.get("events", []) if ev["happened_s"] is not None]
    log += [(a["time_s"], "action", a["what"]) for a in data.get("actions", [])]
    if log:
        rows = [(_num(t, "s"), e(kind), e(text)) for t, kind, text in sorted(log, key=lambda r: r[0])]
        parts.append("<h2>Log</h2>" + _table(("time", "what", ""), rows))
    parts.append("<h2>Conditions</h2>" + _conditions(data.get("conditions", {})))
    parts.append(f"<script>{SCRIPT}</script></body></html>\n")
    return "\n".join(parts)


def _badge(level: str) -> str:
    return f"<span class='badge' style='background:{COLORS.get(level, '#8a8f98')}'>{html.escape(level)}</span>"


def _num(value: float | None, unit: str = "", fmt: str = ".0f") -> str:
    return "-" if value is None else f"{value:{fmt}} {unit}".strip()


def _table(header: tuple[str, ...], rows: list[tuple[str, ...]]) -> str:
    head = "".join(f"<th>{h}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{cell}</td>" for cell in row) + "</tr>" for row in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def _statistics(data: dict) -> str:
    duration = max(data.get("conditions", {}).get("duration_s") or 0.0, 1e-9)
    rows = []
    for c in data["criteria"]:
        alarms = sum(1 for a in data.get("alarms", []) if a["criterion"] == c["name"])
        worst = "settling" if c["value"] is None else f"{c['value']:.3g} {c['unit']} at {c['value_at_s']:.0f} s"
        rows.append((html.escape(c["name"]), worst, f"{c['limit']:.3g} {c['unit']}", _num(c["time_exceeded_s"], "s"),
                     f"{100 * c['time_exceeded_s'] / duration:.1f} %", str(alarms), _num(c["first_exceeded_s"], "s"),
                     _badge(c["level"])))
    return _table(("criterion", "worst", "limit", "time above limit", "share of the run", "alarms",
                   "first above", "level"), rows)


def _conditions(c: dict) -> str:
    e = html.escape
    rows = [("scenario", f"{e(str(c.get('scenario')))}<br><span class='muted'>sha256 {e(str(c.get('scenario_sha256')))}</span>"),
            ("seed", e(str(c.get("seed")))),
            ("run", f"{c.get('duration_s', 0):.1f} s at dt {c.get('dt_s')} s"),
            ("marinesim", e(str(c.get("marinesim"))))]
    if c.get("log"):
        rows.append(("session log", f"{e(c['log'])}<br><span class='muted'>sha256 {e(str(c.get('log_sha256')))}</span>"))
    vessel = c.get("vessel")
    if vessel:
        rows.append(("vessel", f"{e(vessel['rao'])}<br><span class='muted'>sha256 {e(vessel['rao_sha256'])}</span>"))
        rows.append(("course", f"{vessel['speed_kn']:.3g} kn, heading {vessel['heading_deg']:g} deg"))
        rows.append(("points", e("; ".join(f"{k} {v}" for k, v in vessel["points_m"].items()))))
    out = _table(("", ""), rows)
    seas = c.get("sea", [])
    if seas:
        out += "<h3>Sea at the start</h3>" + _table(
            ("Hs", "Tp", "from", "gamma", "spreading s"),
            [(f"{s['hs_m']:.2f} m", f"{s['tp_s']:.1f} s", f"{s['from_deg']:.0f} deg",
              "-" if s.get("gamma") is None else f"{s['gamma']:g}",
              "-" if s.get("spreading_s") is None else f"{s['spreading_s']:g}") for s in seas])
    return out


def _img(png: bytes, alt: str) -> str:
    return f"<img class='plot' alt='{html.escape(alt)}' src='data:image/png;base64,{base64.b64encode(png).decode()}'>"


def _figure(height: float):
    from matplotlib.figure import Figure

    return Figure(figsize=(10.5, height), dpi=100, layout="constrained")


def _png(figure) -> bytes:
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", metadata={"Software": None})
    return buffer.getvalue()


def _criterion_plot(c: dict, data: dict) -> bytes:
    figure = _figure(2.6)
    ax = figure.add_subplot()
    t = np.asarray(c["series"]["time_s"], float)
    v = np.array([np.nan if x is None else x for x in c["series"]["value"]], float)
    ax.plot(t, v, color="#1f5fa8", lw=1.4, label="running value")
    ax.axhline(c["limit"], color="#d0312d", lw=1.5, label=f"limit {c['limit']:.3g}")
    ax.axhline(c["caution"] * c["limit"], color="#e0a100", lw=1.2, ls="--", label="caution")
    ax.fill_between(t, c["limit"], np.where(v > c["limit"], v, c["limit"]), color="#d0312d", alpha=0.25, lw=0)
    for event in data.get("events", []):
        if event["happened_s"] is not None:
            ax.axvline(event["happened_s"], color="#777", lw=0.8)
            ax.annotate(str(event["index"]), (event["happened_s"], 1.0), xycoords=("data", "axes fraction"),
                        fontsize=8, color="#555", ha="left", va="top")
    for alarm in data.get("alarms", []):
        if alarm["criterion"] == c["name"]:
            ax.plot([alarm["raised_s"]], [alarm["value"]], marker="v", color="#d0312d", ms=8)
    top = np.nanmax(np.append(v, c["limit"])) if np.isfinite(v).any() else c["limit"]
    ax.set_ylim(0.0, 1.15 * top)
    ax.set_xlim(0.0, max(data.get("conditions", {}).get("duration_s") or 0.0, t.max() if t.size else 1.0, 1.0))
    where = f" ({c['point']})" if c.get("point") else ""
    window = "whole run" if c.get("window_s") is None else f"{c['window_s']:g} s window"
    ax.set_title(f"{c['name']}{where}: {c['quantity']}, {window}", fontsize=10, loc="left")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(c["unit"] or "-")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8, ncols=3, framealpha=0.8)
    return _png(figure)


def _timeline_plot(data: dict) -> bytes:
    figure = _figure(1.9)
    ax = figure.add_subplot()
    rows = {"events": 3, "messages": 2, "alarms": 1}
    for event in data.get("events", []):
        if event["happened_s"] is not None:
            ax.plot([event["happened_s"]], [rows["events"]], "D", color="#555")
            ax.annotate(str(event["index"]), (event["happened_s"], rows["events"] + 0.25), fontsize=8, ha="center")
    for message in data.get("messages", []):
        ax.plot([message["time_s"]], [rows["messages"]], "o", color="#e0a100")
    for alarm in data.get("alarms", []):
        end = alarm["acknowledged_s"] if alarm["acknowledged_s"] is not None else alarm["cleared_s"]
        if end is not None and end > alarm["raised_s"]:
            ax.barh(rows["alarms"], end - alarm["raised_s"], left=alarm["raised_s"], height=0.4,
                    color="#d0312d", alpha=0.5)
        ax.plot([alarm["raised_s"]], [rows["alarms"]], "v", color="#d0312d")
    ax.set_yticks(list(rows.values()), ["events", "messages", "alarms (bar: to acknowledgement)"], fontsize=8)
    ax.set_ylim(0.4, 3.7)
    ax.set_xlim(0.0, max(data.get("conditions", {}).get("duration_s") or 0.0, 1.0))
    ax.set_xlabel("time (s)")
    ax.grid(axis="x", alpha=0.3)
    return _png(figure)
