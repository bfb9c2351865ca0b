"""The instructor's page in a real browser (headless Chromium driven by Playwright) on a real server on the loopback,
with a headless station following the same exercise: what the instructor does on the page reaches the exercise once
and the station within a second of simulated time."""

from __future__ import annotations

import os
import threading
from pathlib import Path

from chromium import CHROMIUM
from served import WAIT_S, ServedInThread
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
                browser = playwright.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
                page = browser.new_page(viewport={"width": 1400, "height": 900})
                errors: list[str] = []
                page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
                page.goto(page_url)
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
