"""The instructor's page in a real browser (headless Chromium driven by Playwright) on a real server on the loopback,
with a headless station following the same exercise: what the instructor does on the page reaches the exercise once
and the station within a second of simulated time; the other bodies are listed and drawn where the record puts
them."""

from __future__ import annotations

import json
import os
import threading
from pathlib import Path

import numpy as np

from chromium import CHROMIUM
from served import WAIT_S, ServedInThread
from test_net_server import traffic_scenario
from marinesim.net.station import Station, follow_headless
from marinesim.resources import resource_dir
from marinesim.scenario import load_scenario, with_run
from marinesim.session.exercise import Exercise
from marinesim.session.timeline import Simulation

TRANSIT = resource_dir("configs") / "training" / "heavy_weather_transit.toml"
WAIT_MS = 1000 * WAIT_S
"""ms: what the page waits for at most (a hang; a page on a loaded machine answers within seconds)."""
SHOTS = os.environ.get("MARINESIM_SHOTS")
"""A folder to keep the page's screenshot in (for a person to look at), if set."""

PIXELS = """([points, r]) => {
  const canvas = document.getElementById("chart");
  const d = window.devicePixelRatio || 1;
  const ctx = canvas.getContext("2d");
  return points.map(([x, y]) => {
    const side = Math.round(2 * r * d) + 1;
    const data = ctx.getImageData(Math.round((x - r) * d), Math.round((y - r) * d), side, side).data;
    const out = [];
    for (let i = 0; i < data.length; i += 4) out.push([data[i], data[i + 1], data[i + 2]]);
    return out;
  });
}"""
"""The chart's pixels (r, g, b) in a square of half-side ``r`` (CSS px) round each of ``points`` (CSS px)."""


def _red(pixels: list[list[int]]) -> int:
    """How many of ``pixels`` are the page's danger red (#e2574c, blended with the chart's dark blue by
    anti-aliasing), not its grey grid, white own-ship or teal bodies."""
    return sum(r > 100 and r - g > 50 and r - b > 50 for r, g, b in pixels)


def _open(playwright, url: str):
    """Headless Chromium on ``url`` at 1400x900: (the browser, the page, the console's errors as they come)."""
    browser = playwright.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(url)
    return browser, page, errors


def test_the_instructors_page_changes_the_sea_triggers_an_event_and_messages_a_station(tmp_path):
    """On the page: the sea made 1.5 times higher, the next scripted event triggered, the visibility brought down to
    2 km over a minute and a message sent to the bridge. Each is journaled once, within a second of simulated time of the click, and the bridge station applies
    it at that time; a page or server that lost, doubled or delayed them would leave the trainee in another sea
    than the instructor set."""
    from playwright.sync_api import sync_playwright

    scenario = with_run(load_scenario(TRANSIT), 600.0)
    served = ServedInThread(scenario, tmp_path / "served.jsonl", scale=1.0)
    url = f"ws://127.0.0.1:{served.port}/ws?token={served.server.token}"
    page_url = f"http://127.0.0.1:{served.port}/?token={served.server.token}"
    with Simulation(scenario, wake=False) as local:
        bridge = Station.join(Exercise(local), url, "bridge")
        ended = threading.Event()
        follower = threading.Thread(target=lambda: (follow_headless(bridge, wait_s=1.0), ended.set()), daemon=True)
        follower.start()
        clicked: dict[str, float] = {}
        try:
            with sync_playwright() as playwright:
                browser, page, errors = _open(playwright, page_url)
                page.wait_for_function("document.body.dataset.connected === 'yes' && +document.body.dataset.t > 0",
                                       timeout=WAIT_MS)
                page.wait_for_function("[...document.querySelectorAll('#message-to option')]"
                                       ".some(o => o.value === 'bridge')", timeout=WAIT_MS)
                assert "heavy weather transit" in page.inner_text("#title").lower()

                def click(action: str, button: str) -> None:
                    """Click ``button`` as the page's own script sees it, noting the exercise's time the page
                    showed at that moment (the browser's latency is the test's, not the server's)."""
                    page.wait_for_selector(button, state="visible", timeout=WAIT_MS)
                    clicked[action] = float(page.evaluate(
                        "b => { const t = +document.body.dataset.t; document.querySelector(b).click(); return t; }",
                        button))

                page.fill("#sea-hs-factor", "1.5")
                click("change", "#sea-apply")
                pending = served.server.exercise.pending_events()
                click("trigger", f"#trigger-{pending[0]}")
                page.fill("#weather-visibility", "2000")
                click("weather", "#weather-apply")
                page.fill("#message-text", "Bridge, reduce speed to 8 kn")
                page.select_option("#message-to", "bridge")
                click("message", "#message-send")
                page.wait_for_function("[...document.querySelectorAll('#journal *')]"
                                       ".some(e => e.textContent.includes('reduce speed to 8 kn'))", timeout=WAIT_MS)
                if SHOTS:
                    page.wait_for_timeout(1500)  # a few more states drawn: the strip charts and the track
                    page.screenshot(path=str(Path(SHOTS) / "instructor_page.png"))
                assert not errors, errors
                browser.close()
            actions = [e for e in served.server.exercise.journal if e["kind"] == "action"]
            assert [a["action"] for a in actions] == ["change", "trigger", "weather", "message"]
            change, trigger, weather, message = actions
            assert change["hs_factor"] == 1.5 and trigger["index"] == pending[0]
            assert weather == weather | {"visibility_m": 2000, "ramp_s": 60}  # fog over a minute
            assert message == message | {"text": "Bridge, reduce speed to 8 kn", "to": "bridge"}
            for action in actions:
                assert 0.0 <= action["t"] - clicked[action["action"]] <= 1.0, (action, clicked)
        finally:
            served.close()  # the server's last state says the exercise ended: the station follows it there
            assert ended.wait(WAIT_S), "the station did not follow the exercise to its end"
            bridge.close()
        assert [e for e in bridge.journal if e["kind"] == "action"] == actions
        assert local.time == served.server.exercise.sim.time


def test_the_page_lists_the_other_bodies_and_draws_each_where_it_is(tmp_path):
    """A coaster crossing ahead (CPA 147 m in under 2 min) and a buoy 2.5 km ahead (CPA 100 m in 16 min): the page
    lists both, the coaster red (dangerous) and the buoy shaded (the nearest CPA ahead, off the chart), with the
    record's range, bearing, CPA and TCPA at the state's time; on the frozen chart the coaster is drawn in red where
    her east/north put her at the scale own-ship is drawn at (own-ship's white hull at hers), her vector pointing
    north. A page that swapped east and north, flipped a sign, or listed one body's values under another's name
    would send the instructor's eye to the wrong ship."""
    from playwright.sync_api import sync_playwright

    scenario = traffic_scenario(tmp_path)
    served = ServedInThread(scenario, tmp_path / "served.jsonl", scale=1.0)
    page_url = f"http://127.0.0.1:{served.port}/?token={served.server.token}"
    try:
        with sync_playwright() as playwright:
            browser, page, errors = _open(playwright, page_url)
            page.wait_for_function("+document.body.dataset.t > 0 && document.querySelectorAll('#others tr').length "
                                   "=== 2", timeout=WAIT_MS)
            page.click("#freeze")
            page.wait_for_function("!document.getElementById('frozen').hidden", timeout=WAIT_MS)
            page.wait_for_timeout(600)  # the frozen state's chart drawn
            t = float(page.evaluate("document.body.dataset.t"))
            view = json.loads(page.evaluate("document.getElementById('chart').dataset.view"))
            rows = page.evaluate("[...document.querySelectorAll('#others tr')].map(tr => [tr.className, "
                                 "[...tr.children].map(td => td.textContent)])")
            if SHOTS:
                page.screenshot(path=str(Path(SHOTS) / "instructor_page_others.png"))

            def px(east: float, north: float) -> tuple[float, float]:
                """Where the page's chart puts (east, north) (m), by the scale and centre it drew at."""
                return (view["width_px"] / 2 + (east - view["centre_east_m"]) / view["m_per_px"],
                        view["height_px"] / 2 - (north - view["centre_north_m"]) / view["m_per_px"])

            with Simulation(scenario, wake=False) as sim:
                row = {name: float(column[0]) for name, column in sim.frame(np.array([t])).items()}
            own = px(row["east_m"], row["north_m"])
            coaster = px(row["coaster_east_m"], row["coaster_north_m"])
            (own_pixel,), = page.evaluate(PIXELS, [[own], 0])
            at, ahead, astern, mirrored = page.evaluate(PIXELS, [[
                coaster, (coaster[0], coaster[1] - 40), (coaster[0], coaster[1] + 40),
                (2 * own[0] - coaster[0], coaster[1])], 5])
            assert not errors, errors
            browser.close()
    finally:
        served.close()
    assert all(channel > 200 for channel in own_pixel), (own_pixel, view)  # her white hull where her record says
    assert _red(at) >= 4 and _red(ahead) >= 2, (coaster, view)  # the coaster's hull, her vector north of her
    assert _red(astern) == 0 and _red(mirrored) == 0, (coaster, view)
    (coaster_class, coaster_cells), (buoy_class, buoy_cells) = rows
    assert "other-danger" in coaster_class.split() and "other-nearest" not in coaster_class.split()
    assert "other-nearest" in buoy_class.split() and "other-danger" not in buoy_class.split()
    for name, kind, cells, chart in (("coaster", "ship", coaster_cells, ""), ("fairway", "buoy", buoy_cells,
                                                                            "off chart")):
        tcpa = round(row[f"{name}_tcpa_s"])
        assert cells == [name, kind, f"{row[f'{name}_range_m'] / 1852:.2f}",
                         f"{round(row[f'{name}_bearing_deg']) % 360:03d}°", f"{row[f'{name}_cpa_m'] / 1852:.2f}",
                         f"{tcpa // 60}:{tcpa % 60:02d}", chart], name


def test_the_instructor_drives_the_crossing_tanker_from_the_page(tmp_path):
    """The crossing exercise's tanker sails under her own model: the page offers her in its Traffic box; course 320 and
    8 kn ordered there reach her as one journaled order after the click, and the served simulation's record has her
    turning to starboard (270 to 320) and slowing within four minutes. A page that sent the order to own-ship, or a
    server that dropped the vessel's name, would leave the instructor unable to make the stand-on vessel act."""
    from playwright.sync_api import sync_playwright

    scenario = with_run(load_scenario(resource_dir("configs") / "training" / "crossing_situation.toml"), 900.0)
    served = ServedInThread(scenario, tmp_path / "served.jsonl", scale=8.0)
    page_url = f"http://127.0.0.1:{served.port}/?token={served.server.token}"
    try:
        with sync_playwright() as playwright:
            browser, page, errors = _open(playwright, page_url)
            page.wait_for_function("document.body.dataset.connected === 'yes' && +document.body.dataset.t > 0",
                                   timeout=WAIT_MS)
            page.wait_for_selector("#drive-box", state="visible", timeout=WAIT_MS)
            assert page.evaluate("[...document.querySelectorAll('#drive-ship option')].map(o => o.value)") == \
                ["tanker"]
            page.fill("#drive-course", "320")
            page.fill("#drive-speed", "8")
            clicked = float(page.evaluate("() => { const t = +document.body.dataset.t; "
                                          "document.getElementById('drive-order').click(); return t; }"))
            page.wait_for_function("[...document.querySelectorAll('#journal *')]"
                                   ".some(e => e.textContent.includes('course 320'))", timeout=WAIT_MS)
            if SHOTS:
                page.wait_for_timeout(3000)  # the tanker drawn turning on the chart
                page.screenshot(path=str(Path(SHOTS) / "instructor_page_drive.png"))
            assert not errors, errors
            browser.close()
        orders = [e for e in served.server.exercise.journal if e["kind"] == "action"]
        assert len(orders) == 1
        order = orders[0]
        assert order == order | {"action": "order", "vessel": "tanker", "course_deg": 320, "speed_kn": 8}
        assert order["t"] >= clicked, (order, clicked)
        sim = served.server.exercise.sim
        later = order["t"] + 240.0
        rows = sim.frame(np.array([order["t"], later]))
    finally:
        served.close()
    assert rows["tanker_heading_deg"][0] == np.float64(270.0)
    assert 290.0 < rows["tanker_heading_deg"][1] <= 320.5, "turning to starboard, to 320"
    assert rows["tanker_speed_kn"][1] < rows["tanker_speed_kn"][0] - 0.3, "slowing for 8 kn"
