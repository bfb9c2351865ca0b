"""Other vessels and structures in the session's sea: each responds through her own RAO table at her own place, the
record carries them by name, and own-ship's closest point of approach to each."""

import math

import numpy as np
import pytest

from conftest import ROOT, write
from marinesim.constants import G
from marinesim.errors import ScenarioError
from marinesim.offshore.route import Route
from marinesim.scenario import load_scenario
from marinesim.scenario.schema import OtherVessel
from marinesim.sea.ocean import Components
from marinesim.session.log import vessel_files
from marinesim.session.others import Body
from marinesim.session.timeline import Simulation
from marinesim.vessel.read import read_rao

TANKER = ROOT / "rao" / "tanker" / "tanker.4"
SCENARIO = f"""
[ocean]
resolution = 64
tiles = 2

[[sea]]
type = "jonswap"
hs_m = 3.0
tp_s = 10.0
from_deg = {{from_deg}}

[vessel]
rao = "{TANKER}"
speed_kn = 5.0
heading_deg = 90.0

[run]
duration_s = 60.0
dt_s = 0.1
seed = 4

[[vessels]]
name = "sister"
kind = "ship"
rao = "{TANKER}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
position_m = [0.0, -150.0]
speed_kn = 5.0
heading_deg = 90.0

[[vessels]]
name = "crossing"
kind = "ship"
rao = "{ROOT / 'rao' / 's175' / 'input.re1'}"
visual_mesh = "{ROOT / 'hulls' / 's175_visual.glb'}"
position_m = [2500.0, -2000.0]
speed_kn = 12.0
heading_deg = 330.0

[[vessels]]
name = "buoy"
kind = "buoy"
position_m = [400.0, 300.0]
"""


def one_wave(omega: float, heading: float, amplitude: complex) -> Components:
    """A single deep-water component travelling along the math angle ``heading``."""
    k = omega**2 / G
    return Components(np.array([omega]), np.array([k * math.cos(heading)]), np.array([k * math.sin(heading)]),
                      np.array([amplitude]), np.array([0]))


def fpso(x: float, y: float, rao) -> OtherVessel:
    return OtherVessel("fpso", "fpso", Route((x, y), 0.0, heading=0.0), TANKER, rao)


def test_a_body_lags_by_the_phase_its_distance_gives():
    """Two identical moored bodies d apart along a regular wave: the second heaves, rolls and pitches as the first
    ``k d cos(theta) / w`` seconds later, at ``|H(w, beta)| a`` (the RAO phase shift formula for the RAO's
    reference point: e^{-i k . x}). A body placed by anything but its own position would fail the lag."""
    rao = read_rao(TANKER)
    omega, theta, a = 0.6, math.radians(30.0), 1.5 * np.exp(0.4j)
    wave = one_wave(omega, theta, a)
    d = 180.0
    first, second = (Body(fpso(x, 0.0, rao), lambda index: wave) for x in (0.0, d))
    t = np.arange(0.0, 60.0, 0.25)
    lag = (omega**2 / G) * d * math.cos(theta) / omega
    np.testing.assert_allclose(second.along(0, t)[:, :6], first.along(0, t - lag)[:, :6], atol=1e-9)
    transfer = rao(np.array([omega]), np.array([theta]), 0.0)[0]
    expected = (transfer[2] * a * np.exp(1j * omega * t)).real
    np.testing.assert_allclose(first.along(0, t)[:, 2], expected, atol=1e-9)


def test_a_buoy_heaves_with_the_water():
    """A buoy is a wave follower: its heave is the elevation at its place, its acceleration -w^2 times it."""
    wave = one_wave(0.8, 1.0, 0.7 + 0.2j)
    buoy = Body(OtherVessel("buoy", "buoy", Route((50.0, -20.0), 0.0)), lambda index: wave)
    t = np.linspace(0.0, 30.0, 121)
    out = buoy.along(0, t)
    np.testing.assert_allclose(out[:, 2], wave.elevation(50.0, -20.0, t), atol=1e-12)
    np.testing.assert_allclose(out[:, 14], -0.64 * out[:, 2], atol=1e-12)
    assert not np.any(out[:, [0, 1, 3, 4, 5]])


@pytest.fixture(scope="module")
def abeam(tmp_path_factory):
    """Own-ship and her sister 150 m to starboard on the same course (east), the waves long-crested from ahead:
    the offset is along the crests."""
    path = write(tmp_path_factory.mktemp("others"), SCENARIO.format(from_deg=90.0))
    return load_scenario(path)


def test_a_sister_abeam_along_the_crests_moves_as_own_ship(abeam):
    """With the offset along the crests (k . d = 0) the sister's record is own-ship's, through a sea change that
    blends two component sets: her response is the same RAO on the same track, blended the same way."""
    with Simulation(abeam, wake=False) as sim:
        plain = sim.frame_steps(0.0, 0.1, 600)
    with Simulation(abeam, wake=False) as sim:
        sim.change(hs_factor=1.6, tp_factor=1.2, ramp_s=20.0, at=10.0)
        sim.advance_to(60.0)
        rows = sim.frame_steps(0.0, 0.1, 600)
    for dof in ("heave_m", "pitch_deg"):
        assert np.abs(rows[dof][300:] - plain[dof][300:]).max() > 0.5 * np.std(plain[dof])  # the change took
        np.testing.assert_allclose(rows[f"sister_{dof}"], rows[dof], atol=1e-9 * np.abs(rows[dof]).max())
    np.testing.assert_allclose(rows["sister_range_m"], 150.0)
    np.testing.assert_allclose(rows["sister_bearing_deg"], 180.0)
    # in company: the range never changes (the tracks' velocities differ by rounding alone), the CPA is now
    np.testing.assert_allclose(rows["sister_cpa_m"], 150.0)
    assert not np.any(rows["sister_tcpa_s"])


def test_the_closest_point_of_approach_is_the_straight_tracks(abeam):
    """Own-ship east at 5 kn, the other on 330 deg at 12 kn: CPA and TCPA each row equal the closed form of two
    straight tracks from where both are (relative position r, velocity v: t = -r.v / |v|^2), and the range falls
    to the CPA at the TCPA."""
    with Simulation(abeam, wake=False) as sim:
        rows = sim.frame(np.array([0.0, 30.0]))
        knot = 1852.0 / 3600.0
        own_v = np.array([5.0 * knot, 0.0])
        heading = math.radians(330.0)
        v = 12.0 * knot * np.array([math.sin(heading), math.cos(heading)]) - own_v
        for i, t in enumerate((0.0, 30.0)):
            r = np.array([2500.0, -2000.0]) + v * t
            tcpa = -(r @ v) / (v @ v)
            assert rows["crossing_tcpa_s"][i] == pytest.approx(tcpa, rel=1e-9)
            assert rows["crossing_cpa_m"][i] == pytest.approx(np.linalg.norm(r + v * tcpa), rel=1e-9, abs=1e-6)
        at = float(rows["crossing_tcpa_s"][0])
        closest = sim.frame(np.array([at]))
    assert closest["crossing_range_m"][0] == pytest.approx(rows["crossing_cpa_m"][0], abs=1e-6)


def test_the_bodies_and_their_files_are_recorded(abeam):
    """The record has every body's columns (the sidecar's units come from their names), the buoy heaves, and the
    session log keeps the other ships' RAO files' hashes (a replay refuses a changed one)."""
    with Simulation(abeam, wake=False) as sim:
        rows = sim.frame_steps(0.0, 0.1, 100)
        columns = sim.columns
    assert set(columns) == set(rows)
    assert [c for c in columns if c.startswith("buoy_")] == [f"buoy_{s}" for s in (
        "east_m", "north_m", "heading_deg", "speed_kn", "heave_m", "roll_deg", "pitch_deg", "range_m", "bearing_deg",
        "cpa_m", "tcpa_s")]
    assert np.std(rows["buoy_heave_m"]) > 0.1
    files = vessel_files(abeam)
    assert files["sister rao"] == TANKER and files["crossing rao"].name == "input.re1"


@pytest.mark.parametrize("body, words", [
    ('name = "tug"\nkind = "ship"\nposition_m = [1.0, 2.0]\nhull = "x.stl"', "vessels[0].rao: a ship responds"),
    ('name = "rig"\nkind = "platform"\nposition_m = [1.0, 2.0]', "vessels[0].visual_mesh: a platform is drawn"),
    ('name = "mark"\nkind = "buoy"\nposition_m = [1.0, 2.0]\nspeed_kn = 3.0', "a buoy does not sail"),
    ('name = "tug"\nkind = "ship"\nposition_m = [1.0, 2.0]\nrao = "r"\nhull = "h"\nheading_deg = 10.0\n'
     'waypoints_m = [[100.0, 100.0]]', "heads along her first leg"),
    ('name = "bridge"\nkind = "buoy"\nposition_m = [1.0, 2.0]', "'bridge' is taken"),
    ('name = "crane"\nkind = "buoy"\nposition_m = [1.0, 2.0]', "'crane' is taken"),
    ('name = "far"\nkind = "buoy"\nposition_m = [1.0e6, 2.0]', "vessels[0].position_m"),
])
def test_bad_bodies_are_refused_in_one_line(tmp_path, body, words):
    """What a body of each kind cannot take, a name already used, a place beyond 100 km: one line naming the key."""
    text = SCENARIO.format(from_deg=0.0).split("[[vessels]]")[0] + "[vessel.points]\nbridge = [0.0, 0.0, 20.0]\n"
    with pytest.raises(ScenarioError) as error:
        load_scenario(write(tmp_path, text + "\n[[vessels]]\n" + body + "\n"))
    message = str(error.value)
    assert words in message and "\n" not in message
