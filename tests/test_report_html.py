"""The after-action report (:mod:`marinesim.report.html`) of a realistic 20-minute helideck exercise: what the
page says, that real Chromium decodes every plot and draws the page, and that the same data give the same bytes."""

from __future__ import annotations

import copy
import dataclasses
import io
import re
from collections import Counter
from html.parser import HTMLParser

import numpy as np
import pytest
from PIL import Image

from chromium import dump_dom, screenshot
from conftest import write
from marinesim.cli import main
from marinesim.criteria.monitor import Level
from marinesim.errors import MarinesimError
from marinesim.report.debrief import (Action, Briefing, Conditions, CriterionTrace, Debrief, Message, Objective,
                                      SeaSystem, Series, Sickness, VesselConditions)
from marinesim.report.html import render_report, write_report
from marinesim.report.plots import TRACK, handling_png, heading_curve, track_png
from marinesim.scenario import load_scenario
from marinesim.session.exercise import AlarmResult, EventResult
from marinesim.session.log import write_log
from test_session_replay import SESSION, _live_session


RED = (0xd0, 0x31, 0x2d)
"""The 'exceeded' badge's red (:data:`marinesim.report.plots.EXCEEDED`)."""


def _running_max(amplitude, period_s: float, phase: float, window_s: float, noise: np.ndarray) -> Series:
    """The running largest |angle| over ``window_s`` of a wave-frequency motion of slowly varying ``amplitude``(t),
    sampled at 0.5 s and evaluated every 1 s over 1200 s (None while the window fills)."""
    t = np.arange(0.0, 1200.0, 0.5)
    motion = amplitude(t) * np.sin(2 * np.pi * t / period_s + phase) + noise[: t.size]
    window = int(window_s / 0.5)
    running = np.lib.stride_tricks.sliding_window_view(np.abs(motion), window).max(axis=1)  # ends at t[window-1:]
    times = np.arange(1.0, 1201.0)
    values = [None if ti < window_s else round(float(running[int(2 * ti) - window]), 4) for ti in times]
    return Series(times.tolist(), values)


def _criterion(name, point, quantity, unit, limit, window_s, series: Series) -> CriterionTrace:
    """A criterion's entry as :func:`~marinesim.report.debrief.debrief` gives it, its statistics taken from
    ``series``."""
    pairs = [(t, v) for t, v in zip(series.time_s, series.value) if v is not None]
    above = [t for t, v in pairs if v > limit]
    worst_t, worst = max(pairs, key=lambda p: p[1]) if pairs else (None, None)
    level = (Level.SETTLING if worst is None else Level.EXCEEDED if worst > limit
             else Level.CAUTION if worst >= 0.8 * limit else Level.OK)
    return CriterionTrace(name=name, point=point, quantity=quantity, unit=unit, window_s=window_s, value=worst,
                          value_at_s=worst_t, limit=limit, caution=0.8, exceeded=bool(above),
                          time_exceeded_s=float(len(above)), first_exceeded_s=above[0] if above else None, level=level,
                          judged=True, series=series)


def _alarms(criterion: CriterionTrace) -> list[AlarmResult]:
    """An alarm each time the series goes above its limit, cleared when it is back under."""
    out, up = [], None
    for t, v in zip(criterion.series.time_s, criterion.series.value):
        if v is not None and v > criterion.limit and up is None:
            up = len(out)
            out.append(AlarmResult(criterion.name, t, v, criterion.limit))
        elif up is not None and (v is None or v <= criterion.limit):
            out[up], up = dataclasses.replace(out[up], cleared_s=t), None
    return out


def ship_data(duration_s: float = 1200.0) -> dict:
    """The supply vessel's track and handling as :func:`~marinesim.report.debrief.debrief` gives them, one sample a
    second: on 350° at 10 kn, at 300 s the autopilot set to 020° (she turns to starboard through north, rudder 20°
    starboard at most), at 800 s the engine to half ahead (7 kn)."""
    t = np.arange(0.0, duration_s + 1.0)
    turn = np.clip((t - 300.0) / 90.0, 0.0, 1.0)
    heading = (350.0 + 30.0 * (3 * turn ** 2 - 2 * turn ** 3)) % 360.0  # a smooth 30° turn over 90 s
    rudder = np.where((t > 300.0) & (t < 390.0), 20.0 * np.sin(np.pi * np.clip((t - 300.0) / 90.0, 0.0, 1.0)), 0.0)
    speed = np.where(t < 800.0, 10.0, 7.0 + 3.0 * np.exp(-np.maximum(t - 800.0, 0.0) / 120.0))
    rpm = np.where(t < 800.0, 110.0, 77.0 + 33.0 * np.exp(-np.maximum(t - 800.0, 0.0) / 15.0))
    step = speed * 1852.0 / 3600.0
    north = np.concatenate(([0.0], np.cumsum(step * np.cos(np.radians(heading)))[:-1]))
    east = np.concatenate(([0.0], np.cumsum(step * np.sin(np.radians(heading)))[:-1]))
    rate = np.gradient(np.degrees(np.unwrap(np.radians(heading)))) * 60.0
    return {"name": "supply <PSV>", "model": "Clarke, Gedling & Hine (1983) from the hull's main particulars",
            "time_s": t.tolist(), "north_m": north.round(6).tolist(), "east_m": east.round(6).tolist(),
            "heading_deg": heading.round(6).tolist(),
            "course_deg": [350.0 if ti < 300.0 else 20.0 for ti in t],
            "speed_over_ground_kn": speed.round(6).tolist(), "rudder_deg": rudder.round(6).tolist(),
            "rudder_order_deg": np.where((t > 300.0) & (t < 390.0), 20.0, 0.0).tolist(),
            "propeller_rpm": rpm.round(6).tolist(), "rate_of_turn_deg_min": rate.round(6).tolist()}


def exercise_data() -> Debrief:
    """A 1200 s run evaluated every 1 s: the helideck pitch goes above its limit twice (two alarms, the first
    acknowledged after 6.5 s, the second never), the roll reaches caution only, the heave rate's 30 min window
    never fills; an event at 240 s, one on a condition, one that never happened; an instructor's message with
    markup in it; the vessel's track and handling (:func:`ship_data`)."""
    rng = np.random.default_rng(7)
    pitch = _running_max(lambda t: 2.3 + 0.9 * np.sin(2 * np.pi * (t - 200) / 600), 7.5, 0.3, 60.0,
                         rng.normal(0.0, 0.08, 2400))
    roll = _running_max(lambda t: 3.25 + 0.85 * np.sin(2 * np.pi * t / 900), 11.0, 1.1, 60.0,
                        rng.normal(0.0, 0.1, 2400))
    heave = Series(pitch.time_s, [None] * len(pitch.time_s))
    criteria = [_criterion("helideck pitch", "helideck", "pitch_max_deg", "deg", 3.0, 60.0, pitch),
                _criterion("helideck roll", "helideck", "roll_max_deg", "deg", 5.0, 60.0, roll),
                _criterion("helideck heave rate", "helideck", "mahr_m_s", "m/s", 1.3, 1800.0, heave)]
    alarms = _alarms(criteria[0])
    assert len(alarms) == 2, "the test's pitch must go above its limit twice"
    alarms[0] = dataclasses.replace(alarms[0], acknowledged_s=alarms[0].raised_s + 6.5)
    stand_by = next(t for t, v in zip(pitch.time_s, pitch.value) if v is not None and v > 2.5)
    return Debrief(
        title="helideck landing window",
        source="configs/training/helideck_landing.toml",
        briefing=Briefing(
            "A medium helicopter lands on the supply vessel's helideck in a building westerly sea.\n\n"
            "Keep the deck within the CAP 437 motion limits; call the helicopter off when the pitch "
            "alarm sounds, and acknowledge every alarm at once.",
            [Objective("Land the helicopter within the CAP 437 limits", ["helideck pitch", "helideck roll"], "not met"),
             Objective("Keep the roll below the caution line", ["helideck roll"], "met with caution"),
             Objective("Hold the heave rate over 30 min", ["helideck heave rate"], "no value"),
             Objective("Brief the crew before the approach", [], "met")]),
        verdict="exceeded",
        conditions=Conditions(
            scenario="configs/training/helideck_landing.toml", scenario_sha256="3f" * 32, seed=11,
            duration_s=1200.0, dt_s=0.5, log="sessions/helideck-1.jsonl", log_sha256="a7" * 32,
            marinesim="0.9",
            vessel=VesselConditions("rao/supply/supply.re1", "c4" * 32, 4.0, 270.0,
                                    {"helideck": [-28.0, 0.0, 12.5], "bridge": [22.0, 0.0, 14.0]}),
            sea=[SeaSystem(3.0, 9.0, 290.0, 3.3, 12.0), SeaSystem(1.5, 14.0, 250.0, 1.0, None)]),
        criteria=criteria,
        events=[
            EventResult(0, "at 240 s", 240.0, "sea Hs 4.0 m over 120 s", "Helicopter inbound"),
            EventResult(1, "when helideck pitch > 2.5", stand_by, "message only", "Deck crew stand by"),
            EventResult(2, "when roll > 8", None, "speed 0 kn", None)],
        alarms=alarms,
        messages=[Message(240.0, "Helicopter inbound", "event"), Message(stand_by, "Deck crew stand by", "event"),
                  Message(640.0, "<script>alert('wave')</script> & check the lashings", "instructor")],
        actions=[Action(120.4, "instructor: speed 10 kn"), Action(alarms[0].acknowledged_s, "alarms acknowledged")],
        sickness=[Sickness("bridge", 12.3, 30.1), Sickness("helideck", 21.7, None)],
        ship=ship_data(),
    )


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report") / "debrief.html"
    data = exercise_data()
    return data, write_report(data, out)


def test_the_page_says_what_the_debrief_needs(report):
    data, path = report
    page = path.read_text(encoding="utf-8")
    assert page.count("<img class='plot'") == len(data.criteria) + 3, \
        "one plot per criterion, the ship's track and handling, and the timeline"
    assert "class='badge exceeded verdict'>exceeded<" in page, "the overall verdict, as a red badge"
    for objective in data.briefing.objectives:
        assert objective.text in page and f"'>{objective.verdict}</span>" in page, objective
    assert "<td class='num'>6.5 s</td>" in page, "the alarm table gives the acknowledgement delay"
    assert "not acknowledged" in page and "did not happen" in page
    assert "&lt;script&gt;alert(&#39;wave&#39;)&lt;/script&gt; &amp; check the lashings" in page, "text is escaped"
    assert page.count("<script") == 1, "one script only: the plot counter"
    assert not re.search(r"(?:src|href)=['\"]?(?:https?:|//)", page) and "http://" not in page, "nothing fetched"
    sections = ("briefing", "criteria", "statistics", "ship", "alarms", "sickness", "log", "conditions")
    places = [page.index(f"<section id='{name}'>") for name in sections]
    assert places == sorted(places), "briefing, exercise, statistics, ship, alarms, sickness, log, conditions in order"
    ship = page[places[3]:places[4]]
    assert ship.count("<img class='plot'") == 2 and "<h2>Ship handling</h2>" in ship
    assert "<b>supply &lt;PSV&gt;</b>: Clarke, Gedling &amp; Hine (1983)" in ship, "the ship's name and model, escaped"
    assert "heading 350° → 020°" in ship and "largest rudder 20° starboard" in ship and "10.0 kn" in ship
    assert "3f" * 32 in page and "c4" * 32 in page, "the conditions name the inputs by hash"
    assert len(page) < 500_000, f"the page is {len(page)} bytes: keep the plots small"


def test_same_data_same_bytes(report, tmp_path):
    data, path = report
    again = write_report(copy.deepcopy(data), tmp_path / "again.html")
    assert again.read_bytes() == path.read_bytes()


def test_missing_parts_leave_their_sections_out():
    """A title, a verdict and one criterion that never got a value: the page renders, without the other parts."""
    lean = Debrief(title="bare", verdict="no value", criteria=[exercise_data().criteria[2]])
    page = render_report(lean)
    assert page.count("<img class='plot'") == 1 and "no value yet" in page
    for section in ("briefing", "alarms", "sickness", "log", "conditions"):
        assert f"<section id='{section}'>" not in page
    assert "<section id='ship'>" not in page
    bare = render_report(Debrief(title="bare", criteria=[], events=[], alarms=[], messages=[], ship=None))
    assert "<h1>bare</h1>" in bare and "<img" not in bare and "class='badge none verdict'>no value<" in bare


MARKUP = "<script>alert(1)</script> \"quoted\" & <b>bold</b>"
"""Text that would be a script and a bold element if the page took it for markup."""


class _Tags(HTMLParser):
    """A page's start tags (counted by name) and its text, as a browser's parser splits them."""

    def __init__(self, page: str) -> None:
        super().__init__()
        self.tags: Counter = Counter()
        self.text: list[str] = []
        self.feed(page)
        self.close()

    def handle_starttag(self, tag: str, attrs: list) -> None:
        self.tags[tag] += 1

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def test_markup_in_the_data_is_shown_as_text():
    """A criterion's name, an objective, an instructor's message and the scenario's name and file holding markup: the
    page has the same elements as with plain words in their place (one script, the plot counter), and the markup's
    characters are its text. What would be wrong: the texts written into the page unescaped, a script run."""
    def page(text: str) -> str:
        series = Series([1.0, 2.0, 3.0], [1.0, 2.5, 1.5])
        name = f"roll {text}"
        return render_report(Debrief(
            title=f"landing {text}", verdict="within limits",
            briefing=Briefing("Land on the deck.", [Objective(f"Keep the roll low {text}", [name], "met")]),
            conditions=Conditions(scenario=f"configs/{text}.toml", duration_s=3.0),
            criteria=[_criterion(name, "deck", "roll_max_deg", "deg", 3.0, 1.0, series)],
            messages=[Message(2.0, f"stand by {text}", "instructor")]))

    marked, plain = _Tags(page(MARKUP)), _Tags(page("plain"))
    assert marked.tags == plain.tags and marked.tags["script"] == 1, marked.tags - plain.tags
    for text in (f"landing {MARKUP}", f"roll {MARKUP}", f"Keep the roll low {MARKUP}", f"stand by {MARKUP}",
                 f"configs/{MARKUP}.toml"):
        assert any(text in chunk for chunk in marked.text), f"{text!r} is not the page's text"


def test_a_three_hour_run_keeps_every_point_and_a_small_page():
    t = np.arange(1.0, 10801.0)
    v = 1.0 + 0.8 * np.sin(2 * np.pi * t / 3000) + np.random.default_rng(1).normal(0.0, 0.05, t.size)
    criterion = CriterionTrace(name="bridge MSI", point="bridge", quantity="msi_pct", unit="%", limit=1.6,
                               caution=0.8, window_s=None, value=float(v.max()), value_at_s=float(t[v.argmax()]),
                               exceeded=True, time_exceeded_s=float((v > 1.6).sum()),
                               first_exceeded_s=float(t[v > 1.6][0]), level=Level.EXCEEDED, judged=True,
                               series=Series(t.tolist(), v.tolist()))
    page = render_report(Debrief(title="heavy weather transit", verdict="exceeded", criteria=[criterion],
                                 conditions=Conditions(duration_s=10800.0)))
    assert "3:00:00" in page, "past an hour, times read h:min:s"
    assert len(page) < 200_000


def test_write_refuses_a_folder(tmp_path):
    (tmp_path / "r.html").mkdir()
    with pytest.raises(MarinesimError):
        write_report(Debrief(title="x"), tmp_path / "r.html")


def test_chromium_decodes_every_plot_and_draws_the_page(report, tmp_path):
    data, path = report
    dom = dump_dom(path)
    loaded = re.search(r'data-plots-loaded="(\d+)"', dom)
    assert loaded and int(loaded.group(1)) == len(data.criteria) + 3, "the browser must decode every plot"
    png = screenshot(path, tmp_path / "report.png", (1200, 3000))
    image = np.asarray(Image.open(png).convert("RGB")).astype(int)
    assert image.shape[:2] == (3000, 1200)
    ink = (image.sum(axis=2) < 600).mean()
    assert ink > 0.03, f"the page looks blank ({ink:.1%} ink)"
    red = (np.abs(image - RED) < 20).all(axis=2)
    assert red[:250].sum() > 300, "the red 'exceeded' verdict badge must be drawn in the header"


def test_the_debrief_of_a_real_session_log(tmp_path):
    """End to end: a live session with an alarm, an acknowledgement and instructor actions, its log written,
    then ``marinesim report LOG``. What would be wrong: the report reading the log differently from the
    session (a lost action, a wrong acknowledgement delay) or varying between runs."""
    scenario = load_scenario(write(tmp_path, SESSION.format(limit=0.15)))
    exercise, _ = _live_session(scenario, tmp_path, 6)
    log = write_log(tmp_path / "session.jsonl", exercise)
    assert main(["report", str(log), "--out", str(tmp_path / "report.html"), "--quiet"]) == 0
    page = (tmp_path / "report.html").read_text()
    assert page.count("<img class='plot'") == len(scenario.criteria) + 3, \
        "one plot per criterion, the ship's track and handling, and the timeline"
    ship = page[page.index("<section id='ship'>"):page.index("<section id='alarms'>")]
    assert ship.count("<img class='plot'") == 2 and "held on station" not in ship, "she made way and turned"
    assert exercise.sim.vessel.ship.describe() in page.replace("&amp;", "&"), "the ship's model is named"
    alarm = exercise.alarms[0]
    assert f"<td class='num'>{alarm.acknowledged_s - alarm.raised_s:.1f} s</td>" in page, "acknowledgement delay"
    assert "stand by the helideck" in page and "event 1 triggered early" in page
    assert main(["report", str(log), "--out", str(tmp_path / "again.html"), "--quiet"]) == 0
    assert (tmp_path / "again.html").read_bytes() == (tmp_path / "report.html").read_bytes()


def test_a_ship_held_on_station_is_said_to_be_and_drawn_apart():
    """A vessel on station at 0 kn: her track is a point, so the page says she held station and the figure's
    events and alarms are listed, not piled on that point; no section without a vessel."""
    still = ship_data(600.0)
    for key in ("north_m", "east_m", "speed_over_ground_kn", "rudder_deg", "rudder_order_deg", "propeller_rpm"):
        still[key] = [0.0] * len(still["time_s"])
    still["heading_deg"] = [270.0] * len(still["time_s"])
    full = exercise_data()
    data = Debrief(title="on station", events=full.events, alarms=full.alarms, ship=still)
    page = render_report(data)
    ship = page[page.index("<section id='ship'>"):page.index("<section id='alarms'>")]
    assert "held on station at the start position" in ship and ship.count("<img class='plot'") == 2
    assert "nm over the ground" not in ship and "heading 270°" in ship
    assert track_png(still, data.events, []) != track_png(ship_data(600.0), data.events, [])
    assert "<section id='ship'>" not in render_report(dataclasses.replace(data, ship=None))


def test_the_ship_figures_are_the_same_bytes_from_the_same_data():
    data = exercise_data()
    alarms = list(enumerate(data.alarms, start=1))
    once = track_png(data.ship, data.events, alarms)
    assert once == track_png(copy.deepcopy(data.ship), copy.deepcopy(data.events), copy.deepcopy(alarms))
    assert handling_png(data.ship, data.events, 1200.0) == handling_png(copy.deepcopy(data.ship), data.events, 1200.0)
    assert track_png(data.ship, data.events, data.alarms) == once, "alarms alone are numbered from 1"


def test_the_track_is_to_scale_east_right_north_up():
    """An L-shaped track, 2 km east then 1 km north: the track's blue pixels span twice as wide as tall (equal
    axes), the east leg along the bottom and the north leg up the right-hand side. What would be wrong: x and y
    swapped, north down, or the axes stretched to fill the figure."""
    t = np.arange(0.0, 601.0)
    east = np.minimum(t, 400.0) * 5.0
    north = np.maximum(t - 400.0, 0.0) * 5.0
    heading = np.where(t < 400.0, 90.0, 0.0)
    ship = {"name": "probe", "time_s": t.tolist(), "north_m": north.tolist(), "east_m": east.tolist(),
            "heading_deg": heading.tolist()}
    image = np.asarray(Image.open(io.BytesIO(track_png(ship, [], []))).convert("RGB")).astype(int)
    blue = (np.abs(image - _rgb(TRACK)) < 12).all(axis=2)
    rows, cols = np.nonzero(blue)
    width, height = np.ptp(cols), np.ptp(rows)
    assert width / height == pytest.approx(2.0, rel=0.04), (width, height)
    bottom = rows > rows.max() - 0.1 * height
    right = cols > cols.max() - 0.1 * width
    assert np.ptp(cols[bottom]) > 0.85 * width, "the east leg runs along the bottom (north up)"
    assert np.ptp(rows[right]) > 0.85 * height, "the north leg runs up the right-hand side (east right)"


def test_a_heading_through_north_is_drawn_without_a_jump():
    """359° -> 1° is a 2° turn, not a 358° fall: the curve goes on to 361°, and the autopilot's course is put on
    the heading's turn; a turn the other way goes below 0° as smoothly."""
    heading, course = heading_curve([357.0, 358.0, 359.0, 0.0, 1.0, 2.0], [None, 359.0, 0.0, 0.0, 1.0, 2.0])
    assert np.diff(heading) == pytest.approx([1.0] * 5)
    assert np.isnan(course[0]) and course[1:] == pytest.approx([359.0, 360.0, 360.0, 361.0, 362.0])
    heading, _ = heading_curve([2.0, 1.0, 0.0, 359.0, 358.0])
    assert np.diff(heading) == pytest.approx([-1.0] * 4) and heading[0] == 2.0
    heading, _ = heading_curve([400.0 % 360.0, 45.0])
    assert heading == pytest.approx([40.0, 45.0]), "the curve starts on the compass"


def _rgb(colour: str) -> tuple[int, int, int]:
    return tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))
