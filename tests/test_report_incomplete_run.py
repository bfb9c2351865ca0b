"""A run stopped early is not a pass. The shipped crane lift, shortened to 300 s and with an objective judged by
each of its three criteria, run as a session to its end is debriefed as before; the same session closed at 60 s
(20 %) is debriefed INCOMPLETE, says how much of it ran and marks each objective it could not judge NOT JUDGED;
with the roll limit made tight enough to be exceeded in the first minute, that objective stays NOT MET and the
verdict EXCEEDED. Real runs, real logs,
the real ``marinesim report`` and ``replay``; the header looked at in Chromium."""

from __future__ import annotations

import re

import numpy as np
import pytest
from PIL import Image

from chromium import screenshot
from conftest import ROOT
from marinesim.cli import main
from marinesim.criteria.monitor import Level
from marinesim.criteria.quantities import CRANE_QUANTITIES
from marinesim.report.plots import NONE, OK
from marinesim.scenario import load_scenario, with_run
from marinesim.session.exercise import Exercise, ran_words
from marinesim.session.log import write_log
from marinesim.session.timeline import Simulation

CRANE_LIFT = ROOT / "configs" / "training" / "crane_lift.toml"
PLANNED_S = 300.0
"""The exercise's run, shortened from 1,200 s (s)."""
STOP_S = 60.0
"""When the early session closes: 20 % of the run (s)."""
CRITERIA = 4
"""The crane lift's criteria here: its objectives' three and her DP footprint."""
TIGHT_ROLL_DEG = 1.5
"""A roll limit the crane lift's roll goes above within its first minute (about 1.9 deg by 36 s)."""
FRAME_S = 1.0
"""The session's frames (s): the viewer's, coarser (the record and the criteria do not depend on them)."""


def session(path, folder, until_s: float) -> tuple:
    """The exercise of ``path`` over :data:`PLANNED_S` as the viewer runs it, frame by frame (:data:`FRAME_S`),
    closed at ``until_s`` and its log written to ``folder``: (the log, the exercise's assessment)."""
    with Simulation(with_run(load_scenario(path), PLANNED_S), wake=False) as simulation:
        exercise = Exercise(simulation)
        while simulation.time < until_s - 1e-9:
            exercise.advance(min(FRAME_S, until_s - simulation.time))
        exercise.note("end")
    folder.mkdir(parents=True, exist_ok=True)
    return write_log(folder / "session.jsonl", exercise), exercise.assessment()


def report(log, capsys) -> tuple[str, str]:
    """``marinesim report`` of ``log``: (the page, what the command printed)."""
    out = log.with_name("debrief.html")
    assert main(["report", str(log), "--out", str(out), "--quiet"]) == 0
    return out.read_text(encoding="utf-8"), capsys.readouterr().out


def header_of(page: str) -> str:
    return page[page.index("<header class='top'>"):page.index("</header>")]


def verdict_badge(page: str) -> str:
    return re.search(r"<span class='badge (\w+) verdict'>([^<]*)</span>", page).group(2)


def objective_verdicts(page: str) -> list[str]:
    start = page.index("<section id='briefing'>")
    briefing = page[start:page.index("</section>", start)]
    return re.findall(r"<span class='badge \w+'>([^<]*)</span></td></tr>", briefing)


OBJECTIVES = "objectives = [\n" + "".join(
    f'    {{ text = "{text}", criteria = ["{name}"] }},\n' for text, name in (
        ("Lift only while the crane tip's vertical velocity is within its limit", "crane tip vertical velocity"),
        ("Keep the crane tip's vertical acceleration within its limit", "crane tip vertical acceleration"),
        ("Keep the roll within the deck-cargo limit", "roll"))) + "]"


def crane_lift(folder, roll_limit_deg: float | None = None):
    """The crane lift with :data:`OBJECTIVES` and the vessel's criteria only (the crane's load's, which the crane
    operator's hoisting decides, left out), its roll limit at ``roll_limit_deg`` if given, its files named from the
    checkout: its path in ``folder``."""
    text = CRANE_LIFT.read_text(encoding="utf-8").replace('"../../', f'"{ROOT}/')
    blocks = text.split("[[criteria]]")
    kept = (b for b in blocks[1:] if not any(f'"{q}"' in b for q in CRANE_QUANTITIES))
    text = "[[criteria]]".join([blocks[0], *kept])
    start = text.index("objectives = [")
    text = text[:start] + OBJECTIVES + text[text.index("]", text.index("\n]", start)) + 1:]
    if roll_limit_deg is not None:
        roll = text.index('name = "roll"')
        text = text[:roll] + re.sub(r"limit = [0-9.]+", f"limit = {roll_limit_deg}", text[roll:], count=1)
    path = folder / "crane_lift.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def tight(tmp_path_factory):
    """The crane lift with its roll limit at :data:`TIGHT_ROLL_DEG`."""
    return crane_lift(tmp_path_factory.mktemp("tight"), TIGHT_ROLL_DEG)


@pytest.fixture(scope="module")
def full(tmp_path_factory):
    folder = tmp_path_factory.mktemp("full")
    return session(crane_lift(folder), folder, PLANNED_S)


@pytest.fixture(scope="module")
def early(tmp_path_factory):
    folder = tmp_path_factory.mktemp("early")
    return session(crane_lift(folder), folder, STOP_S)


def test_the_share_that_ran_in_words():
    assert ran_words(386.0, 1800.0) == "386 s of 1,800 s (21 %)"
    assert ran_words(1799.9, 1800.0) == "1,799 s of 1,800 s (99 %)", "short of the end never reads as all of it"


def test_a_full_run_is_debriefed_as_before(full, capsys):
    """Run to its end: complete, every criterion judged, the verdict from the levels alone, all objectives met."""
    log, result = full
    assert result.complete and result.duration_s == result.planned_s == PLANNED_S
    assert all(c.judged for c in result.criteria)
    levels = {c.level for c in result.criteria}
    assert levels == {Level.OK} and result.verdict == "within limits"
    page, printed = report(log, capsys)
    assert verdict_badge(page) == "within limits" and "verdict: within limits\n" in printed
    assert objective_verdicts(page) == ["met"] * 3 and "3 of 3 met" in header_of(page)
    assert "Stopped early" not in page and "stopped early" not in page and "not judged" not in page


def test_a_run_stopped_at_a_fifth_is_incomplete(early, capsys):
    """Closed at 60 s of 300 s with every criterion within its limit so far: not WITHIN LIMITS but INCOMPLETE,
    the share that ran in the header and the conditions, every objective and criterion NOT JUDGED."""
    log, result = early
    assert not result.complete and result.duration_s == STOP_S and result.planned_s == PLANNED_S
    assert {c.level for c in result.criteria} == {Level.OK} and not any(c.judged for c in result.criteria)
    assert result.verdict == "incomplete"
    page, printed = report(log, capsys)
    header = header_of(page)
    assert verdict_badge(page) == "incomplete" and "within limits" not in header
    assert "<span class='badge none verdict'>incomplete</span>" in header, "a grey badge, not the green of a pass"
    assert "60 s of 300 s (20 %)" in header and "<b>Stopped early:</b>" in header
    assert objective_verdicts(page) == ["not judged"] * 3 and "0 of 3 met" in header and "3 not judged" in header
    assert "stopped early: ran 60 s of 300 s (20 %)" in page[page.index("<section id='conditions'>"):]
    statistics = page[page.index("<section id='statistics'>"):]
    assert statistics.count("<span class='badge none'>not judged</span>") == CRITERIA
    assert "verdict: incomplete (stopped early: ran 60 s of 300 s (20 %))" in printed


def test_replay_prints_the_share_and_the_verdict(early, capsys):
    log, _ = early
    assert main(["replay", str(log), "--headless", "--quiet"]) == 0
    printed = capsys.readouterr().out
    assert "stopped early: ran 60 s of 300 s (20 %)" in printed and "verdict: incomplete" in printed
    assert printed.count("ok (not judged)") == CRITERIA


def test_an_objective_failed_before_the_stop_stays_failed(tight, tmp_path, capsys):
    """The roll goes above the tight limit within the first minute: a fact the stop does not undo, so the roll
    objective is NOT MET and the verdict EXCEEDED; the crane tip's objectives, within their limits so far, are
    NOT JUDGED."""
    log, result = session(tight, tmp_path, STOP_S)
    roll = next(c for c in result.criteria if c.name == "roll")
    assert roll.level is Level.EXCEEDED and roll.judged and roll.first_exceeded_s < STOP_S
    assert result.verdict == "exceeded" and not result.complete
    page, _ = report(log, capsys)
    assert verdict_badge(page) == "exceeded" and "60 s of 300 s (20 %)" in header_of(page)
    assert objective_verdicts(page) == ["not judged", "not judged", "not met"]


def solid_block(image: np.ndarray, colour: str, run_px: int = 100) -> tuple[int, int, int, int] | None:
    """The bounding box (top, bottom, left, right px) of the rows of ``image`` that hold ``colour`` (#rrggbb) over
    ``run_px`` pixels in a row without a break, as a badge's block does and a line of text or a border does not."""
    rgb = [int(colour[i:i + 2], 16) for i in (1, 3, 5)]
    mask = (np.abs(image - rgb) < 12).all(axis=2)
    rows = []
    for y, row in enumerate(mask):
        edges = np.flatnonzero(np.diff(np.concatenate(([0], row.astype(int), [0]))))
        starts, ends = edges[::2], edges[1::2]
        if starts.size and (ends - starts).max() >= run_px:
            longest = int(np.argmax(ends - starts))
            rows.append((y, int(starts[longest]), int(ends[longest])))
    if not rows:
        return None
    return rows[0][0], rows[-1][0], min(r[1] for r in rows), max(r[2] for r in rows)


def test_chromium_shows_the_incomplete_badge(full, early, tmp_path, capsys):
    """In the browser the header's verdict badge beside the title is a grey block with its word in white where the
    run stopped early (no green block at all), and the green one where it ran to its end."""
    images = {}
    for name, (log, _) in {"full": full, "early": early}.items():
        page_path = log.with_name("debrief.html")
        if not page_path.exists():
            report(log, capsys)
        png = screenshot(page_path, tmp_path / f"{name}.png", (1200, 700))
        images[name] = np.asarray(Image.open(png).convert("RGB")).astype(int)[:300]
    box = solid_block(images["early"], NONE)
    assert box is not None, "no grey verdict badge in the header"
    top, bottom, left, right = box
    assert 20 < bottom - top + 1 < 60 and 100 < right - left < 300 and top < 120, box
    white = (images["early"][top:bottom + 1, left:right] > 235).all(axis=2).sum()
    assert white > 150, f"the badge's word is drawn in white on the grey ({white} px)"
    assert solid_block(images["early"], OK) is None, "nothing green says the stopped run passed"
    full_box = solid_block(images["full"], OK)
    assert full_box is not None and abs(full_box[0] - top) <= 2, "the full run's badge, green, in the same place"
