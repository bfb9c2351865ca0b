"""The after-action report of a real session (alarms, an acknowledgement, instructor actions), rendered
in Debian's Chromium: the plots decode, the page is drawn, and the same session gives the same bytes."""

from __future__ import annotations

import re

import numpy as np
from PIL import Image

from chromium import dump_dom, screenshot
from conftest import write
from marinesim.cli import main
from marinesim.scenario import load_scenario
from marinesim.session.log import write_log
from test_session_replay import SESSION, _live_session


def test_the_debrief_of_a_session_renders_in_a_browser(tmp_path):
    scenario = load_scenario(write(tmp_path, SESSION.format(limit=0.15)))
    exercise, _ = _live_session(scenario, tmp_path, 6)
    log = write_log(tmp_path / "session.jsonl", exercise)
    assert main(["report", str(log), "--out", str(tmp_path / "report.html"), "--quiet"]) == 0
    page = (tmp_path / "report.html").read_text()
    criteria = len(scenario.criteria)
    assert page.count("<img class='plot'") == criteria + 1, "one plot per criterion, and the timeline"
    delay = exercise.alarms[0].acknowledged_s - exercise.alarms[0].raised_s
    assert f"<td>{delay:.1f} s</td>" in page, "the alarm table gives the acknowledgement delay"
    assert "stand by the helideck" in page and "event 1 triggered early" in page
    assert "http://" not in page and "https://" not in page, "the report fetches nothing"

    dom = dump_dom(tmp_path / "report.html")
    loaded = re.search(r'data-plots-loaded="(\d+)"', dom)
    assert loaded and int(loaded.group(1)) == criteria + 1, "the browser must decode every plot"
    png = screenshot(tmp_path / "report.html", tmp_path / "report.png", (1200, 2400))
    image = np.asarray(Image.open(png).convert("RGB")).astype(int)
    ink = (image.sum(axis=2) < 600).mean()
    assert ink > 0.03, f"the page looks blank ({ink:.1%} ink)"
    red = ((abs(image[..., 0] - 0xd0) < 25) & (abs(image[..., 1] - 0x31) < 25) & (abs(image[..., 2] - 0x2d) < 25))
    assert red.sum() > 200, "the exceeded verdict's red badge and limit lines must be drawn"

    assert main(["report", str(log), "--out", str(tmp_path / "again.html"), "--quiet"]) == 0
    assert (tmp_path / "again.html").read_bytes() == (tmp_path / "report.html").read_bytes()
