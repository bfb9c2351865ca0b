"""The exercise's keys in a scenario file: ``[[events]]`` and ``[[criteria]]`` are read into the
scenario, and a bad one is refused before anything runs, naming the entry and the key."""

from __future__ import annotations

import pytest

from conftest import ROOT, VESSEL_SCENARIO, cli, write
from marinesim.constants import KNOT
from marinesim.errors import ScenarioError
from marinesim.scenario import load_scenario

S175 = f"""
[[sea]]
type = "jonswap"
hs_m = 3.0
tp_s = 9.0
from_deg = 0.0

[vessel]
rao = "{ROOT / 'rao' / 's175' / 'input.re1'}"
manoeuvring = "s175"
speed_kn = 15.0

[vessel.points]
bridge = [-70.0, 0.0, 20.0]
bow = [80.0, 0.0, 8.0]

[run]
duration_s = 900.0
"""

GOOD = S175 + """
[[events]]
at_s = 300.0
ramp_s = 30.0
sea = [{ type = "jonswap", hs_m = 4.0, tp_s = 9.0, from_deg = 290.0, spreading_s = 12.0 }]
message = "Gale warning"

[[events]]
when = "bridge vertical acceleration > 1.0"
speed_kn = 10.0

[[events]]
at_s = 600.0
heading_deg = 20.0

[[events]]
at_s = 700.0
rudder_deg = -20.0
engine = "half ahead"

[[criteria]]
name = "bridge vertical acceleration"
point = "bridge"
quantity = "vertical_acc_rms_m_s2"
limit = 1.47

[[criteria]]
quantity = "roll_rms_deg"
limit = 6.0
window_s = 300.0
caution = 0.7

[[criteria]]
point = "bow"
quantity = "relative_motion_exceedance"
threshold_m = 6.0
limit = 0.05
"""


def test_events_and_criteria_are_read(tmp_path):
    """The timeline and the criteria as the file gives them, defaults filled in (ramp 10 s, window of
    the quantity, caution 0.8, names point.quantity)."""
    scenario = load_scenario(write(tmp_path, GOOD))
    first, second, third, fourth = scenario.events
    assert first.at_s == 300.0 and first.ramp_s == 30.0 and first.message == "Gale warning"
    assert first.sea.hs == pytest.approx(4.0, rel=1e-3) and first.speed_m_s is None
    assert second.at_s is None and str(second.condition) == "bridge vertical acceleration > 1"
    assert second.speed_m_s == pytest.approx(10.0 * KNOT) and second.ramp_s == 10.0
    assert third.heading_deg == 20.0 and third.sea is None and third.orders == {"course_deg": 20.0}
    assert fourth.orders == {"rudder_deg": -20.0, "engine": "half ahead"}
    assert fourth.describe() == "at 700 s: rudder 20 deg to port, half ahead"
    bridge, roll, bow = scenario.criteria
    assert (bridge.label, bridge.window, bridge.caution) == ("bridge vertical acceleration", 600.0, 0.8)
    assert (roll.label, roll.window, roll.caution, roll.point) == ("roll_rms_deg", 300.0, 0.7, None)
    assert (bow.label, bow.options.threshold_m) == ("bow.relative_motion_exceedance", 6.0)


def _criterion(**keys) -> str:
    return "\n[[criteria]]\n" + "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in keys.items())


REFUSED = {
    "unknown event key": (S175 + '\n[[events]]\nat_s = 10.0\nmesage = "x"\n', "events[0].mesage: unknown key"),
    "both triggers": (S175 + '\n[[events]]\nat_s = 10.0\nwhen = "roll_rms_deg > 1"\nmessage = "x"\n',
                      "events[0].at_s: give exactly one of at_s and when"),
    "no trigger": (S175 + '\n[[events]]\nmessage = "x"\n', "events[0].at_s: give exactly one"),
    "nothing to do": (S175 + "\n[[events]]\nat_s = 10.0\n", "events[0].message: an event needs something to do"),
    "out of order": (S175 + '\n[[events]]\nat_s = 200.0\nmessage = "a"\n[[events]]\nat_s = 100.0\nmessage = "b"\n',
                     "events[1].at_s: 100 s comes before the event before it (200 s)"),
    "after the run": (S175 + '\n[[events]]\nat_s = 1000.0\nmessage = "a"\n',
                      "events[0].at_s: 1000 s is after the run's end"),
    "sea change without ramp": (S175 + '\n[[events]]\nat_s = 10.0\nramp_s = 0.0\n'
                                'sea = [{ type = "jonswap", hs_m = 4.0, tp_s = 9.0, from_deg = 0.0 }]\n',
                                "events[0].ramp_s: a sea change blends in over ramp_s > 0 s"),
    "bad sea in an event": (S175 + '\n[[events]]\nat_s = 10.0\nsea = [{ type = "jonswap", hs_m = 4.0 }]\n',
                            "events[0].sea[0].from_deg: required"),
    "speed outside the table": (S175 + "\n[[events]]\nat_s = 10.0\nspeed_kn = 30.0\n",
                                "events[0].speed_kn: 30 kn is outside the RAO table's speeds"),
    "condition not a comparison": (S175 + '\n[[events]]\nwhen = "roll is high"\nmessage = "x"\n',
                                   "events[0].when: expected '<criterion or [point.]quantity> <op> <number>'"),
    "condition on an unknown quantity": (S175 + '\n[[events]]\nwhen = "bridge.rolling > 1"\nmessage = "x"\n',
                                         "events[0].when: 'bridge.rolling' is neither a criterion"),
    "condition at an unknown point": (S175 + '\n[[events]]\nwhen = "mast.msi_pct > 10"\nmessage = "x"\n',
                                      "events[0].when: unknown point 'mast' (known: bridge, bow)"),
    "unknown quantity": (S175 + _criterion(quantity="roll_rms", limit=6.0), "criteria[0].quantity: expected"),
    "unknown point": (S175 + _criterion(point="mast", quantity="msi_pct", limit=10.0),
                      "criteria[0].point: unknown point 'mast' (known: bridge, bow)"),
    "point quantity without a point": (S175 + _criterion(quantity="msi_pct", limit=10.0),
                                       "criteria[0].point: msi_pct is measured at a point"),
    "vessel quantity at a point": (S175 + _criterion(point="bow", quantity="roll_rms_deg", limit=6.0),
                                   "criteria[0].point: roll_rms_deg is a motion of the whole vessel"),
    "missing threshold": (S175 + _criterion(point="bow", quantity="relative_motion_exceedance", limit=0.05),
                          "criteria[0].threshold_m: required by relative_motion_exceedance"),
    "option of another quantity": (S175 + _criterion(quantity="roll_rms_deg", limit=6.0, threshold_m=3.0),
                                   "criteria[0].threshold_m: roll_rms_deg takes no threshold_m"),
    "no limit": (S175 + _criterion(quantity="roll_rms_deg"), "criteria[0].limit: required"),
    "negative limit": (S175 + _criterion(quantity="roll_rms_deg", limit=-1.0), "criteria[0].limit: must be > 0"),
    "two of one name": (S175 + _criterion(quantity="roll_rms_deg", limit=6.0) * 2,
                        "criteria[1].name: 'roll_rms_deg' names two criteria"),
    "dose at a coarse step": (S175.replace("duration_s = 900.0", "duration_s = 900.0\ndt_s = 0.5")
                              + _criterion(point="bridge", quantity="msdv_m_s1_5", limit=30.0),
                              "criteria[0]: msdv_m_s1_5 filters the acceleration up to 0.63 Hz"),
    "rudder past hard over": (S175 + "\n[[events]]\nat_s = 10.0\nrudder_deg = 40.0\n",
                              "events[0].rudder_deg: rudder order must be in -35..35 deg (positive to starboard)"),
    "rudder past 45": (S175 + "\n[[events]]\nat_s = 10.0\nrudder_deg = 50.0\n", "events[0].rudder_deg: must be in -45..45"),
    "unknown telegraph order": (S175 + '\n[[events]]\nat_s = 10.0\nengine = "flank speed"\n',
                                "events[0].engine: expected 'full astern'"),
    "a course with the autopilot off": (S175 + "\n[[events]]\nat_s = 10.0\nheading_deg = 90.0\nautopilot = false\n",
                                        "events[0].autopilot: heading_deg is a course for the autopilot"),
    "helm and autopilot together": (S175 + "\n[[events]]\nat_s = 10.0\nrudder_deg = 5.0\nautopilot = true\n",
                                    "events[0].rudder_deg: a rudder order by hand takes the helm"),
    "orders without a model": (S175.replace('manoeuvring = "s175"\n', "") + "\n[[events]]\nat_s = 10.0\nrudder_deg = 5.0\n",
                               "events[0].rudder_deg: the vessel: no manoeuvring model: a steady course and speed"),
    "an unknown shipped vessel": (S175.replace('manoeuvring = "s175"', 'manoeuvring = "titanic"'),
                                  "vessel.manoeuvring: 'titanic': expected \"station\", a shipped vessel (kvlcc2, s175"),
    "station keeping under way": (S175.replace('manoeuvring = "s175"', 'manoeuvring = "station"'),
                                  "vessel.manoeuvring: a vessel held on station has no speed"),
    "criteria without a vessel": ('[[sea]]\ntype = "pm"\nhs_m = 2.0\ntp_s = 8.0\nfrom_deg = 0.0\n'
                                  + _criterion(quantity="roll_rms_deg", limit=6.0),
                                  "criteria[0]: criteria need a [vessel]"),
}


@pytest.mark.parametrize("text, expected", REFUSED.values(), ids=REFUSED.keys())
def test_bad_events_and_criteria_are_refused(tmp_path, text, expected):
    """Each mistake is one line naming the entry and key; otherwise the exercise would run with a
    silently dropped event or a criterion that measures nothing."""
    with pytest.raises(ScenarioError) as error:
        load_scenario(write(tmp_path, text))
    assert expected in str(error.value), str(error.value)
    assert "\n" not in str(error.value)


def test_assess_refuses_a_bad_event_before_running(tmp_path):
    """The command line: exit 2, one line, no traceback and no progress (nothing ran)."""
    path = write(tmp_path, VESSEL_SCENARIO + '\n[[events]]\nat_s = 50.0\nmessage = "a"\n[[events]]\nat_s = 10.0\n'
                                            'message = "b"\n')
    done = cli("assess", str(path))
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == [
        f"marinesim assess: error: {path}: events[1].at_s: 10 s comes before the event before it (50 s): "
        "give events in time order"]
