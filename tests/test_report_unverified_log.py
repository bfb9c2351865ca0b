"""The debrief of a session log says whether the log is verified: a real session's log, unedited, is said to be;
edited (the acknowledgement moved earlier, the sidecar's hash written again, the end cut off and the sidecar
deleted), its debrief carries a red UNVERIFIED LOG banner at the top, saying why, drawn across the page."""

from __future__ import annotations

import re

import numpy as np
import pytest
from PIL import Image

from chromium import dump_dom, screenshot
from marinesim.cli import main
from marinesim.report.debrief import Debrief, LogCheck
from marinesim.report.html import render_report
from test_report_html import RED
from test_session_log_verification import (config, copy, cut_end, delete_sidecar, move_acknowledgement,  # noqa: F401
                                           rehash, session)

EDITED = {
    "acknowledgement moved": ([move_acknowledgement], ["the log was changed after the session wrote it"]),
    "acknowledgement moved, re-hashed": ([move_acknowledgement, rehash], ["both changed after the session wrote them"]),
    "end cut off, sidecar deleted": ([cut_end, delete_sidecar], ["session.jsonl.json is missing", "no end entry"]),
}


def report(log, out) -> str:
    assert main(["report", str(log), "--out", str(out), "--quiet"]) == 0
    return out.read_text(encoding="utf-8")


def header_of(page: str) -> str:
    return page[page.index("<header class='top'>"):page.index("</header>")]


def delay_cell(delay_s: float) -> str:
    return f"<td class='num'>{delay_s:.1f} s</td>"


@pytest.fixture(scope="module")
def verified_page(session, tmp_path_factory):
    """The debrief of the unedited log: (its path, its text)."""
    log, _ = session
    out = tmp_path_factory.mktemp("verified") / "debrief.html"
    return out, report(log, out)


@pytest.fixture(scope="module")
def unverified_page(session, tmp_path_factory):
    """The debrief of the log with its acknowledgement moved: (its path, its text)."""
    log, _ = session
    folder = tmp_path_factory.mktemp("unverified")
    edited = folder / log.name
    edited.write_bytes(log.read_bytes())
    (folder / (log.name + ".json")).write_bytes(log.with_name(log.name + ".json").read_bytes())
    move_acknowledgement(edited)
    return folder / "debrief.html", report(edited, folder / "debrief.html")


def test_the_debrief_of_the_unedited_log_says_it_is_verified(session, verified_page):
    _, exercise = session
    _, page = verified_page
    assert "Session log verified" in header_of(page) and "UNVERIFIED" not in page
    alarm = exercise.alarms[0]
    assert delay_cell(alarm.acknowledged_s - alarm.raised_s) in page, "the trainee's acknowledgement delay"
    assert "<b>verified</b>" in page[page.index("<section id='conditions'>"):]


@pytest.mark.parametrize("name", EDITED)
def test_the_debrief_of_an_edited_log_carries_the_banner(copy, tmp_path, name):  # noqa: F811
    """The banner opens the header, before the title, and says why; the page's title and the conditions say so
    too. What would be wrong: the forged record shown as the trainee's with nothing to tell it apart."""
    edits, reasons = EDITED[name]
    for edit in edits:
        edit(copy)
    page = report(copy, tmp_path / "debrief.html")
    header = header_of(page)
    banner = re.search(r"<div class='unverified' role='alert'><strong>UNVERIFIED LOG</strong>(.*?)</div>", header,
                       re.S)
    assert banner and header.index("<div class='unverified'") < header.index("<h1>"), "the banner opens the page"
    assert all(reason in banner.group(1) for reason in reasons), banner.group(1)
    assert "<title>Debrief (UNVERIFIED LOG): " in page and "Session log verified" not in page
    assert "<span class='warn'>UNVERIFIED</span>" in page[page.index("<section id='conditions'>"):]


def test_the_forged_acknowledgement_is_what_the_banner_warns_of(session, unverified_page):
    """The moved acknowledgement makes the debrief show a 0.1 s delay where the trainee took 1.2 s: the banner is
    all that tells the instructor so."""
    _, exercise = session
    _, page = unverified_page
    alarm = exercise.alarms[0]
    assert delay_cell(0.1) in page and delay_cell(alarm.acknowledged_s - alarm.raised_s) not in page
    assert "UNVERIFIED LOG" in header_of(page)


def test_chromium_draws_the_banner_across_the_top(verified_page, unverified_page, tmp_path):
    """In the browser the banner is a red band across the page's column at its top, its words in the page
    once loaded; the verified debrief has none (its red verdict badge is narrow)."""
    widest = {}
    for name, (path, _) in {"verified": verified_page, "unverified": unverified_page}.items():
        image = np.asarray(Image.open(screenshot(path, tmp_path / f"{name}.png", (1200, 900))).convert("RGB"))
        red = (np.abs(image.astype(int) - RED) < 20).all(axis=2)
        widest[name] = int(red[:200].sum(axis=1).max())
    assert widest["unverified"] > 900, f"the banner spans {widest['unverified']} px of the 1000 px column"
    assert widest["verified"] < 300, widest
    dom = dump_dom(unverified_page[0])
    assert re.search(r"<strong>UNVERIFIED LOG</strong>\s*<p>This debrief was made from a session log", dom)


def test_the_banner_escapes_what_the_log_says():
    """A problem's words can carry text from the sidecar (a key's name): escaped, never markup."""
    page = render_report(Debrief(title="t", log_check=LogCheck(False, ["key <img src=x>"])))
    assert "<li>key &lt;img src=x&gt;</li>" in page and "<img src=x>" not in page
