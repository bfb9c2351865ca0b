"""The after-action report as one self-contained HTML file: plots embedded as PNG, CSS inline, nothing fetched.

Laid out for a debrief (IMO model course 6.10: briefing, exercise, debriefing; STCW A-I/12: against the
objectives), from the :class:`~marinesim.report.debrief.Debrief` that :func:`marinesim.report.debrief.debrief`
makes: the title and the overall verdict, the briefing with a verdict per objective, each criterion over the
run, exceedance statistics, the ship's track and handling (with a vessel), the timeline and the alarms with their
acknowledgement delays, motion sickness, the log of events, messages and actions, and the conditions. A
debrief of a session log says at the top whether the log is verified; one that is not gets a red
"UNVERIFIED LOG" banner above everything else, saying why, and the page's title says so too. A run stopped
before its planned duration says so under the title, with the share that ran; its verdict reads INCOMPLETE
unless a criterion went above its limit, and each objective and criterion it could not judge NOT JUDGED. A
part the data leave out (or give empty) is left out of the page. The markup is Jinja2's templates in ``templates/``,
autoescaped: every text from the data is HTML-escaped by the engine.
The same data give the same bytes: no dates, and the PNGs carry no metadata (:mod:`marinesim.report.plots`).
The one script counts the plots the browser decoded into ``body[data-plots-loaded]``, for a test to read the
rendered page.
"""

from __future__ import annotations

import base64
import math
from pathlib import Path

import jinja2
from markupsafe import Markup

from marinesim.atomic import atomic_path
from marinesim.constants import NAUTICAL_MILE
from marinesim.criteria.monitor import Level
from marinesim.report.debrief import Conditions, Debrief
from marinesim.scenario.schema import briefing_paragraphs
from marinesim.session.exercise import share_words
from marinesim.report.plots import (CAUTION, EXCEEDED, NONE, OK, STATION_M, clock, compass, criterion_png,
                                    footprint_png, handling_png, number, station_use_png, timeline_png, track_png,
                                    with_unit)

BADGES = {"within limits": "ok", "met": "ok", "caution": "caution", "met with caution": "caution",
          "exceeded": "exceeded", "not met": "exceeded", "no value": "none", "incomplete": "none", "not judged": "none"}
"""A verdict or objective verdict -> its badge's colour class."""
LEVEL_BADGES = {Level.EXCEEDED: "exceeded", Level.CAUTION: "caution", Level.OK: "ok", Level.SETTLING: "none",
                None: "none"}
"""A criterion's reading (its level; None: not judged) -> its badge's colour class."""
SHOWN = {Level.EXCEEDED: "exceeded", Level.CAUTION: "caution", Level.OK: "within limits",
         Level.SETTLING: "no value yet", None: "not judged"}
"""A criterion's reading in the words a badge shows, worst first (the order the header counts them in)."""
CSS = f"""
:root{{--ok:{OK};--caution:{CAUTION};--exceeded:{EXCEEDED};--none:{NONE};--ink:#1b1f24;--muted:#5b6470;
--rule:#d6dbe1;--head:#eef1f4;--band:#f6f7f9}}
*{{box-sizing:border-box}}
html{{-webkit-print-color-adjust:exact;print-color-adjust:exact}}
body{{margin:0;background:#fff;color:var(--ink);font:15px/1.5 "DejaVu Sans","Segoe UI",Roboto,"Helvetica Neue",Arial,
sans-serif}}
main{{max-width:1040px;margin:0 auto;padding:28px 20px 40px}}
header.top{{border-bottom:3px solid var(--ink);padding-bottom:14px;margin-bottom:8px}}
.kicker{{text-transform:uppercase;letter-spacing:.12em;font-size:12px;color:var(--muted);font-weight:bold}}
.titlerow{{display:flex;align-items:center;gap:18px;flex-wrap:wrap;margin:4px 0 2px}}
h1{{font-size:30px;line-height:1.2;margin:0}} h1::first-letter{{text-transform:uppercase}}
.source{{margin:2px 0 0;color:var(--muted);font-size:13px;word-break:break-all}}
h2{{font-size:20px;margin:34px 0 8px;padding-bottom:4px;border-bottom:2px solid var(--rule)}}
h3{{font-size:16px;margin:22px 0 6px}}
p{{margin:6px 0 10px;max-width:78ch}}
.intro{{color:var(--muted);font-size:13.5px;max-width:none}}
.badge{{display:inline-block;padding:2px 10px;border-radius:4px;font-weight:bold;font-size:12.5px;line-height:1.5;
text-transform:uppercase;letter-spacing:.04em;white-space:nowrap;color:#fff;background:var(--none)}}
.badge.ok{{background:var(--ok)}} .badge.caution{{background:var(--caution);color:#1b1f24}}
.badge.exceeded{{background:var(--exceeded)}}
.badge.verdict{{font-size:17px;padding:5px 16px;border-radius:6px}}
.facts{{display:grid;grid-template-columns:repeat(auto-fit,minmax(190px,1fr));gap:10px;margin:14px 0 0}}
.facts div{{background:var(--band);border-left:4px solid var(--rule);padding:7px 12px}}
.facts div.ok{{border-left-color:var(--ok)}} .facts div.caution{{border-left-color:var(--caution)}}
.facts div.exceeded{{border-left-color:var(--exceeded)}}
.facts dt{{font-size:12px;text-transform:uppercase;letter-spacing:.06em;color:var(--muted)}}
.facts dd{{margin:0;font-size:19px;font-weight:bold}} .facts dd small{{font-size:12.5px;font-weight:normal;
color:var(--muted);display:block}}
table{{border-collapse:collapse;margin:8px 0 14px;font-size:13.5px;width:100%}}
table.narrow{{width:auto;min-width:50%}} .intro .k{{white-space:nowrap}}
th,td{{border-bottom:1px solid var(--rule);padding:5px 8px;text-align:left;vertical-align:top}}
th{{background:var(--head);font-weight:bold;border-bottom:2px solid #c3cad3;vertical-align:bottom}}
.wide{{overflow-x:auto}}
td.num,th.num{{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}}
td.tag{{white-space:nowrap;font-weight:bold}} tr.missed td{{color:var(--muted);font-style:italic}}
.warn{{color:#9b1f1a;font-weight:bold}} .muted{{color:var(--muted)}} td .warn,td .muted{{white-space:normal}}
code,.hash{{font-family:"DejaVu Sans Mono",Menlo,Consolas,monospace;font-size:12px}} .hash{{color:var(--muted);
word-break:break-all}}
figure{{margin:14px 0 18px;break-inside:avoid;page-break-inside:avoid}}
img.plot{{display:block;width:100%;max-width:1000px;height:auto;outline:1px solid var(--rule)}}
figcaption{{font-size:13.5px;margin-top:5px;display:flex;gap:10px;align-items:baseline;flex-wrap:wrap}}
.key{{display:inline-block;width:22px;height:0;vertical-align:middle;margin:0 4px 0 10px}}
.key.limit{{border-top:3px solid var(--exceeded)}} .key.caution{{border-top:3px dashed var(--caution)}}
.key.value{{border-top:3px solid #1f4e8c}} .key.span{{height:12px;background:rgba(208,49,45,.16)}}
.key.event{{border-top:2px dotted #3d4651}}
.unverified{{background:var(--exceeded);color:#fff;padding:12px 18px;border-radius:6px;margin:0 0 16px}}
.unverified strong{{display:block;font-size:24px;letter-spacing:.08em}}
.unverified p{{margin:4px 0;max-width:none}} .unverified ul{{margin:4px 0 6px;padding-left:22px}}
.logcheck{{margin:4px 0 0;max-width:none;font-size:13px;font-weight:bold;color:var(--ok)}}
.stopped{{margin:6px 0 0;max-width:none;font-size:14px;border-left:4px solid var(--none);padding:4px 10px;
background:var(--band)}} .facts div.none{{border-left-color:var(--none)}}
footer{{margin-top:36px;padding-top:8px;border-top:1px solid var(--rule);color:var(--muted);font-size:12px}}
@page{{size:A4;margin:14mm 12mm}}
@media print{{body{{font-size:10pt}} main{{max-width:none;padding:0}} h1{{font-size:20pt}} h2{{font-size:14pt;
break-after:avoid;page-break-after:avoid}} h3{{font-size:11pt;break-after:avoid}} tr{{break-inside:avoid}}
table{{font-size:8.5pt}} th,td{{padding:3px 5px}} .badge{{font-size:7.5pt;padding:1px 6px}}
.badge.verdict{{font-size:12pt;padding:3px 12px}} .facts{{grid-template-columns:repeat(4,1fr)}}
.facts dd{{font-size:13pt}}
.wide{{overflow:visible}} img.plot{{outline:none}} .intro,figcaption{{font-size:9pt}}}}
"""
SCRIPT = ("addEventListener('load',function(){var n=0;document.querySelectorAll('img.plot').forEach("
          "function(i){if(i.complete&&i.naturalWidth>0)n++});document.body.dataset.plotsLoaded=n})")
"""Counts the plots the browser decoded (a test reads it from the rendered page)."""
TEMPLATES = jinja2.Environment(loader=jinja2.PackageLoader("marinesim.report", "templates"), autoescape=True,
                               undefined=jinja2.StrictUndefined, keep_trailing_newline=True)
"""The report's templates (``templates/``: the page, report.html.j2, and a macro per section), every value escaped."""


def write_report(data: Debrief, out: Path) -> Path:
    """Write the report of ``data`` to ``out`` (atomically: a complete file or none); returns ``out``."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    text = render_report(data)
    with atomic_path(out) as temp:
        temp.write_bytes(text.encode("utf-8"))
    return out


def render_report(data: Debrief) -> str:
    """The report of ``data`` (see the module's docstring) as the text of one HTML page."""
    page = _Page(data)
    check = data.log_check
    # CSS and SCRIPT are this module's constants, no data in them, and go into <style> and <script>, raw text where
    # an entity is not decoded: escaping their quotes would break them, so they are marked safe.
    return TEMPLATES.get_template("report.html.j2").render(
        title=data.title or "exercise", unverified=bool(check and not check.verified), css=Markup(CSS),
        script=Markup(SCRIPT), marinesim=page.conditions.marinesim or "", header=page.header_section(),
        briefing=page.briefing_section(), criteria=page.criteria_section(), statistics=page.statistics_section(),
        ship=page.ship_section(), alarms=page.alarms_section(), sickness=page.sickness_section(),
        log=page.log_section(), conditions=page.conditions_section())


class _Page:
    """The values of the report's sections, for its templates: each a dict or list, or None when the data have
    nothing for it."""

    def __init__(self, data: Debrief) -> None:
        self.data = data
        self.criteria = list(data.criteria)
        self.events = list(data.events)
        self.messages = list(data.messages)
        self.actions = list(data.actions)
        self.alarms = list(enumerate(data.alarms or [], start=1))
        self.conditions = data.conditions or Conditions()
        self.units = {c.name: c.unit for c in self.criteria}
        self.ship = data.ship
        last = [t for c in self.criteria for t in c.series.time_s[-1:]]
        last += ((self.ship or {}).get("time_s") or [])[-1:]
        self.duration = float(self.conditions.duration_s or max(last, default=0.0))
        self.long = self.duration >= 3600

    def clock(self, t: float | None) -> str:
        return "—" if t is None else clock(t, self.long)

    def header_section(self) -> dict:
        """The title, the overall verdict, the facts; the problems of a log that is not verified (None: no banner)."""
        stopped = self.data.stopped_early
        ran = stopped or (f"{self.duration:g} s" if self.duration else "")
        facts = [_fact("Run", self.clock(self.duration) if self.duration else "—",
                       " · ".join(x for x in (ran, _seed(self.conditions.seed)) if x), "none" if stopped else "")]
        if self.criteria:
            readings = [c.reading for c in self.criteria]
            worst = next((LEVEL_BADGES[lv] for lv in (Level.EXCEEDED, Level.CAUTION, Level.OK) if lv in readings),
                         "none" if stopped else "")
            counts = ", ".join(f"{readings.count(reading)} {words}" for reading, words in SHOWN.items()
                               if reading in readings)
            facts.append(_fact("Criteria", str(len(self.criteria)), counts, worst))
        alarms = [a for _, a in self.alarms]
        acked = [a.acknowledged_s - a.raised_s for a in alarms if a.acknowledged_s is not None]
        if self.data.alarms is not None:
            missed = len(alarms) - len(acked)
            detail = ([f"{len(acked)} acknowledged" + (f", slowest {max(acked):.1f} s" if acked else "")]
                      + ([f"{missed} not acknowledged"] if missed else []) if alarms else ["none raised"])
            facts.append(_fact("Alarms", str(len(alarms)), detail,
                               LEVEL_BADGES[Level.EXCEEDED if alarms else Level.OK]))
        objectives = self.data.briefing.objectives if self.data.briefing is not None else []
        if objectives:
            met = sum(o.verdict in ("met", "met with caution") for o in objectives)
            verdicts = [o.verdict for o in objectives]
            worst = next((BADGES[v] for v in ("not met", "not judged", "met with caution") if v in verdicts),
                         BADGES["met"])
            facts.append(_fact("Objectives", f"{met} of {len(objectives)} met",
                               _count(verdicts, "not met", "not judged", "met with caution"), worst))
        check = self.data.log_check
        return {"unverified": list(check.problems) if check and not check.verified else None,
                "title": self.data.title or "exercise", "verdict": _badge(self.data.verdict or "no value"),
                "source": self.data.source, "stopped": stopped, "verified": bool(check and check.verified),
                "facts": facts}

    def briefing_section(self) -> dict | None:
        """The briefing's paragraphs (each its lines) and its objectives with their verdicts."""
        briefing = self.data.briefing
        if briefing is None:
            return None
        objectives = [{"number": i, "text": o.text, "why": o.why, "criteria": ", ".join(o.criteria),
                       "verdict": _badge(o.verdict or "no value")}
                      for i, o in enumerate(briefing.objectives, start=1)]
        return {"paragraphs": briefing_paragraphs(briefing.text or ""), "objectives": objectives}

    def criteria_section(self) -> list[dict] | None:
        """Each criterion's plot over the run and its caption."""
        if not self.criteria:
            return None
        out = []
        for criterion in self.criteria:
            mine = [(n, a) for n, a in self.alarms if a.criterion == criterion.name]
            png = criterion_png(criterion, self.duration, self.events, mine)
            point = f" ({criterion.point})" if criterion.point else ""
            unit = criterion.unit
            bits = []
            if criterion.value is not None:
                worst = with_unit(criterion.value, unit)
                bits.append(f"worst {worst} at {self.clock(criterion.value_at_s)}")
            if criterion.limit is not None:
                bits.append(f"limit {with_unit(criterion.limit, unit)}")
            if criterion.time_exceeded_s:
                bits.append(f"{criterion.time_exceeded_s:.0f} s above the limit")
            if mine:
                bits.append(f"{len(mine)} alarm{'s' if len(mine) > 1 else ''}")
            if criterion.expected is not None:
                bits.append(f"expected {with_unit(criterion.expected, unit)} in this sea"
                            + (f", this run at the {_ordinal(criterion.percentile)} percentile"
                               if criterion.percentile is not None else ""))
            out.append({"plot": _img(png, f"{criterion.name}{point} over the run"),
                        "badge": _level_badge(criterion.reading), "name": criterion.name, "caption": " · ".join(bits)})
        return out

    def statistics_section(self) -> dict | None:
        """Each criterion's worst, time above its limit and alarms; ``odds``: against the sea it met, where known."""
        if not self.criteria:
            return None
        rows = []
        for c in self.criteria:
            unit, limit = c.unit, c.limit
            above = c.time_exceeded_s
            share = "—" if above is None or not self.duration else f"{100 * above / self.duration:.1f} %"
            rows.append({"name": c.name, "point": c.point, "badge": _level_badge(c.reading),
                         "worst": "—" if c.value is None else with_unit(c.value, unit),
                         "at": self.clock(c.value_at_s) if c.value is not None else "—",
                         "limit": "—" if limit is None else with_unit(limit, unit),
                         "above": "—" if above is None else f"{above:.0f} s",
                         "share": share,
                         "alarms": sum(1 for _, a in self.alarms if a.criterion == c.name),
                         "first": self.clock(c.first_exceeded_s)})
        odds = [{"name": c.name, "worst": "—" if c.value is None else with_unit(c.value, c.unit),
                 "limit": "—" if c.limit is None else with_unit(c.limit, c.unit),
                 "expected": with_unit(c.expected, c.unit),
                 "percentile": "—" if c.percentile is None else _ordinal(c.percentile),
                 "chance": "—" if c.chance_exceeded is None else share_words(c.chance_exceeded)}
                for c in self.criteria if c.expected is not None]
        return {"clock": "h:min:s" if self.long else "min:s", "rows": rows, "odds": odds}

    def ship_section(self) -> dict | None:
        """The ship's track over the ground and her handling (heading, speed, rudder, propeller), with a vessel; on
        station, her footprint and her thrusters' or mooring lines' work."""
        ship = self.ship
        if not ship:
            return None
        name = ship.get("name") or "the ship"
        track = track_png(ship, self.events, self.alarms)
        handling = handling_png(ship, self.events, self.duration)
        time = ship.get("time_s") or []
        north, east = _floats(ship.get("north_m")), _floats(ship.get("east_m"))
        heading = _floats(ship.get("heading_deg"))
        reach = max((math.hypot(n, e) for n, e in zip(north, east)), default=0.0)
        if reach < STATION_M:
            moved = ["held on station" + (" at the start position" if reach < 0.05 else f", within {reach:.1f} m")]
        else:
            run = sum(math.hypot(n1 - n0, e1 - e0) for n0, e0, n1, e1 in zip(north, east, north[1:], east[1:]))
            moved = [f"{number(run / NAUTICAL_MILE)} nm over the ground in {self.clock(time[-1] - time[0])}"]
        if heading:
            moved.append(f"heading {compass(heading[0])} → {compass(heading[-1])}")
        handled = []
        sog = _floats(ship.get("speed_over_ground_kn"))
        if sog:
            handled.append(f"speed over ground {min(sog):.1f}–{max(sog):.1f} kn")
        rudder = _floats(ship.get("rudder_deg"))
        if rudder and max(map(abs, rudder)) >= 0.5:
            worst = max(rudder, key=abs)
            handled.append(f"largest rudder {abs(worst):.0f}° {'starboard' if worst > 0 else 'port'}")
        course = ship.get("course_deg") or []
        if course:
            share = sum(c is not None for c in course) / len(course)
            handled.append("autopilot throughout" if share == 1 else "hand steering throughout" if share == 0
                           else f"on autopilot {100 * share:.0f} % of the run")
        rpm = _floats(ship.get("propeller_rpm"))
        if rpm and min(rpm) < 0:
            handled.append(f"astern to {min(rpm):.0f} rpm")
        out = {"name": name, "model": ship.get("model") or "no model given",
               "track": _img(track, f"track of {name} over the ground"), "moved": " · ".join(moved),
               "handling": _img(handling, f"heading, speed, rudder and propeller of {name} over the run"),
               "handled": " · ".join(handled), "station": None}
        station = ship.get("station")
        if station:
            offset = max((math.hypot(n, e) for n, e in zip(station["north_from_set_point_m"],
                                                            station["east_from_set_point_m"])), default=0.0)
            kept = "within" if offset <= station["footprint_m"] else "outside"
            work = "thruster use" if station.get("thrusters") else "mooring line tensions"
            out["station"] = {"footprint": _img(footprint_png(ship), f"footprint of {name} around the set point"),
                              "offset": f"{offset:.1f}", "kept": kept, "size": f"{station['footprint_m']:g}",
                              "use": _img(station_use_png(ship, self.duration), f"wind and {work} of {name}"),
                              "work": work}
        return out

    def alarms_section(self) -> dict | None:
        """The timeline of events, messages, actions and alarms, and the alarms one by one (``recorded``: the
        debrief records the alarms, so that none raised is said)."""
        if not (self.alarms or self.events or self.messages or self.actions):
            return None
        rows = []
        for n, a in self.alarms:
            acked = a.acknowledged_s
            value, limit = _value_limit(a.value, a.limit, self.units.get(a.criterion))
            rows.append({"tag": f"A{n}", "criterion": a.criterion, "raised": self.clock(a.raised_s),
                         "value_limit": f"{value} / {limit}",
                         "acknowledged": None if acked is None else self.clock(acked),
                         "delay": "—" if acked is None else f"{acked - a.raised_s:.1f} s",
                         "cleared": None if a.cleared_s is None else self.clock(a.cleared_s)})
        timeline = timeline_png(self.duration, self.events, self.messages, self.actions, self.alarms)
        return {"timeline": _img(timeline, "timeline of events, messages, actions and alarms"), "rows": rows,
                "recorded": self.data.alarms is not None}

    def sickness_section(self) -> list[dict] | None:
        """MSI (%) and MSDV (m/s^1.5) at each of the vessel's points."""
        if not self.data.sickness:
            return None
        return [{"point": s.point, "msi": "—" if s.msi_percent is None else f"{s.msi_percent:.1f} %",
                 "msdv": "—" if s.msdv_m_s1_5 is None else f"{s.msdv_m_s1_5:.1f}"} for s in self.data.sickness]

    def log_section(self) -> list[dict] | None:
        """The events, alarms, messages and actions in time order; an event that did not happen last."""
        entries = []  # (time, order, tag, kind, text, class)
        for event in self.events:
            what = event.what or ""
            trigger = f" ({event.trigger})" if event.trigger else ""
            if event.happened_s is not None:
                entries.append((event.happened_s, 0, f"E{event.index}", "event" + trigger, what, ""))
            else:
                entries.append((None, 0, f"E{event.index}", "event" + trigger, f"{what} — did not happen",
                                "missed"))
        for n, alarm in self.alarms:
            unit = self.units.get(alarm.criterion)
            value, limit = _value_limit(alarm.value, alarm.limit, unit)
            entries.append((alarm.raised_s, 1, f"A{n}", "alarm raised", f"{alarm.criterion}: {value}, limit {limit}",
                            ""))
        said = {(e.happened_s, e.message) for e in self.events}
        for message in self.messages:
            if message.source == "event" and (message.time_s, message.text) in said:
                continue  # the event's own row says it
            entries.append((message.time_s, 2, "", f"message ({message.source or 'event'})", message.text or "", ""))
        for action in self.actions:
            entries.append((action.time_s, 3, "", "action", action.what or "", ""))
        if not entries:
            return None
        entries.sort(key=lambda r: (r[0] is None, r[0] or 0.0, r[1]))
        return [{"time": self.clock(t), "tag": tag, "kind": kind, "text": text, "css": css}
                for t, _, tag, kind, text, css in entries]

    def conditions_section(self) -> dict | None:
        """What the run was made from (a row each), the vessel's points (m) and the sea at the start."""
        c = self.data.conditions
        if c is None:
            return None
        rows = []
        if c.scenario:
            rows.append(_row("scenario", file=_file(c.scenario, c.scenario_sha256)))
        if c.log:
            check = self.data.log_check
            rows.append(_row("session log", file=_file(c.log, c.log_sha256),
                             check=None if check is None else "verified" if check.verified else "unverified"))
        if c.seed is not None:
            rows.append(_row("random seed", str(c.seed)))
        if c.duration_s is not None:
            step = f", time step {c.dt_s:g} s" if c.dt_s is not None else ""
            early = self.data.stopped_early
            ran = f", stopped early: ran {early}" if early else ""
            rows.append(_row("run", f"{c.duration_s:g} s ({self.clock(c.duration_s)}){ran}{step}"))
        if c.marinesim:
            rows.append(_row("marinesim", str(c.marinesim)))
        vessel = c.vessel
        if vessel is not None and vessel.rao:
            rows.append(_row("vessel (RAO)", file=_file(vessel.rao, vessel.rao_sha256)))
        if vessel is not None and (vessel.speed_kn is not None or vessel.heading_deg is not None):
            rows.append(_row("speed, heading", f"{_plain(vessel.speed_kn)} kn, {_plain(vessel.heading_deg)}°"))
        points = vessel.points_m if vessel is not None else {}
        seas = [[str(i), _unit(s.hs_m, " m", ".2f"), _unit(s.tp_s, " s", ".1f"), _unit(s.from_deg, "°", ".0f"),
                 _unit(s.gamma, "", "g"), _unit(s.spreading_s, "", "g")] for i, s in enumerate(c.sea or [], start=1)]
        return {"rows": rows, "seas": seas,
                "points": [{"name": name, "xyz": [_plain(x) for x in (list(p) + [None] * 3)[:3]]}
                           for name, p in (points or {}).items()]}


def _fact(name: str, value: str, detail: str | list[str] = "", level: str = "") -> dict:
    """A fact of the header: its name, value, lines of detail and colour class ('' for none)."""
    lines = [detail] if isinstance(detail, str) else detail
    return {"name": name, "value": value, "details": [line for line in lines if line], "level": level}


def _row(name: str, text: str | None = None, file: dict | None = None, check: str | None = None) -> dict:
    """A row of the conditions: its ``text`` or ``file`` (:func:`_file`); ``check``: a session log's "verified",
    "unverified" or None."""
    return {"name": name, "text": text, "file": file, "check": check}


def _value_limit(value: float | None, limit: float | None, unit: str | None) -> tuple[str, str]:
    """An alarm's value and limit, with as many figures as it takes to tell them apart (3.001 over 3)."""
    if value is None or limit is None:
        shown = ["—" if x is None else with_unit(x, unit) for x in (value, limit)]
        return shown[0], shown[1]
    digits = next((d for d in range(3, 7) if number(value, d) != number(limit, d)), 6)
    return with_unit(value, unit, digits), with_unit(limit, unit)


def _floats(values: list | None) -> list[float]:
    """The numbers of a ship's series, its gaps (None) left out."""
    return [float(v) for v in values or [] if v is not None]


def _seed(seed: object) -> str:
    return "" if seed is None else f"seed {seed}"


def _count(values: list, *names: str) -> str:
    return ", ".join(f"{values.count(n)} {n}" for n in names if n in values)


def _plain(value: float | None) -> str:
    return "—" if value is None else number(value)


def _unit(value: float | None, unit: str, fmt: str) -> str:
    return "—" if value is None else f"{value:{fmt}}{unit}"


def _badge(verdict: str) -> dict:
    """``verdict`` (an overall or an objective's verdict) and its colour class: green, amber, red, grey."""
    return {"word": verdict, "kind": BADGES.get(verdict, "none")}


def _ordinal(percentile: float) -> str:
    """A percentile in words: '3rd', '64th', '99th' (rounded, within 1 to 99)."""
    n = int(min(max(round(percentile), 1), 99))
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def _level_badge(reading: Level | None) -> dict:
    """A criterion's reading (:attr:`~marinesim.session.exercise.CriterionResult.reading`) in words
    (:data:`SHOWN`) and its colour class."""
    return {"word": SHOWN[reading], "kind": LEVEL_BADGES[reading]}


def _file(path: str, digest: str | None) -> dict:
    return {"path": path, "digest": digest}


def _img(png: bytes, alt: str) -> dict:
    """A plot: its ``alt`` text and the PNG as a data: URI (``src``)."""
    return {"alt": alt, "src": f"data:image/png;base64,{base64.b64encode(png).decode('ascii')}"}
