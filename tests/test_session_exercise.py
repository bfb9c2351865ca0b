"""The exercise engine: scripted events change the run as the scenario says, at their times or on
their conditions, and the criteria the viewer shows at t are the ones ``assess`` reports at t."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from conftest import ROOT, VESSEL_SCENARIO, offscreen, write
from marinesim.constants import KNOT
from marinesim.criteria.monitor import Level, parse_condition
from marinesim.errors import ParameterError
from marinesim.manoeuvring.ship import STEP_S
from marinesim.manoeuvring.voyage import CHUNK_STEPS
from marinesim.scenario import load_scenario, with_run
from marinesim.session.exercise import AHEAD_ON_CONDITION_S, Exercise
from marinesim.session.timeline import Simulation

RAMP = """
[ocean]
resolution = 64
tiles = 3

[[sea]]
type = "jonswap"
hs_m = 2.0
tp_s = 8.0
gamma = 3.3
from_deg = 0.0
spreading_s = 12.0

[vessel]
rao = "{rao}"

[vessel.points]
bridge = [-100.0, 0.0, 30.0]

[run]
duration_s = 1800.0
dt_s = 0.25
seed = {seed}

[[events]]
at_s = 900.0
ramp_s = 60.0
sea = [{{ type = "jonswap", hs_m = 4.0, tp_s = 8.0, gamma = 3.3, from_deg = 0.0, spreading_s = 12.0 }}]
message = "the sea builds"
"""


def _record(scenario) -> tuple[dict[str, np.ndarray], Simulation]:
    simulation = Simulation(scenario, wake=False)
    blocks = list(Exercise(simulation).blocks())
    simulation.close()
    return {name: np.concatenate([b[name] for b in blocks]) for name in blocks[0]}, simulation


def _at_the_point(components) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies, complex amplitudes) of the elevation at the origin: components of one frequency
    (equal |k| on the ocean's grid) add into one sinusoid there."""
    omega, group = np.unique(np.round(components.omega, 9), return_inverse=True)
    amplitude = np.zeros(omega.size, complex)
    np.add.at(amplitude, group, components.amplitude)
    return omega, amplitude


def _hs_bounds(components, seconds: float) -> tuple[float, float, float]:
    """(low, expected, high) of 4 std of the elevation at the origin over a record of ``seconds``: the
    expected value is 4 sqrt(sum |A|^2 / 2) of its sinusoids. Over a finite record the product of two of
    them averages to |A_i A_j| sinc((w_i - w_j) T / 2) times the cosine of a random phase, so these
    terms add in quadrature: the bounds are 3 of their standard deviations."""
    omega, amplitude = _at_the_point(components)
    a = np.abs(amplitude)
    variance = float(np.sum(a * a) / 2.0)
    half = 0.5 * (omega[:, None] - omega[None, :]) * seconds
    cross = np.outer(a, a) * np.abs(np.sinc(half / np.pi))
    spread = 3.0 * np.sqrt(np.sum(np.triu(cross, 1) ** 2) / 2.0)
    return 4.0 * np.sqrt(max(variance - spread, 0.0)), 4.0 * np.sqrt(variance), 4.0 * np.sqrt(variance + spread)


@pytest.mark.parametrize("seed", [1, 2])
def test_an_event_ramps_the_sea_from_2_to_4_m(tmp_path, seed):
    """The event at 900 s doubles Hs over 60 s. 4 std of the recorded elevation is, before it and after
    its ramp, the Hs of the sinusoids that make the record (within the scatter of a finite record);
    those of the second sea are exactly twice those of the first (same noise, heights x 2); and the
    first is 2 m within the scatter of the ocean's random amplitudes (3 sigma)."""
    scenario = load_scenario(write(tmp_path, RAMP.format(rao=ROOT / "rao" / "tanker" / "tanker.4", seed=seed)))
    record, simulation = _record(scenario)
    t, eta = record["time_s"], record["wave_elevation_m"]
    before, after = simulation.components(simulation.legs[0].after), simulation.components(simulation.legs[1].after)
    low, expected_before, high = _hs_bounds(before, 900.0)
    assert low <= 4.0 * eta[t < 900.0].std() <= high
    low, expected_after, high = _hs_bounds(after, 840.0)
    assert low <= 4.0 * eta[t >= 960.0].std() <= high
    assert expected_after == pytest.approx(2.0 * expected_before, rel=1e-9)
    share = np.abs(_at_the_point(before)[1]) ** 2 / 2.0   # each sinusoid's variance: exponential about its mean
    scatter = 4.0 * 0.5 * np.sqrt(np.sum(share ** 2)) / np.sqrt(np.sum(share))
    assert expected_before == pytest.approx(2.0, abs=3.0 * scatter)


CONDITIONAL = VESSEL_SCENARIO.replace("duration_s = 120.0", "duration_s = 400.0") + """
[[criteria]]
name = "bridge acceleration"
point = "bridge"
quantity = "vertical_acc_rms_m_s2"
limit = 0.5
window_s = 120.0

[[events]]
when = "bridge acceleration > {threshold}"
speed_kn = 2.0
heading_deg = 90.0
message = "slow down and turn"

[[events]]
at_s = 200.0
message = "two hundred seconds"
"""


def test_a_condition_fires_once_at_its_first_evaluation_that_holds(tmp_path):
    """The event happens at the first whole-second evaluation where the criterion's value passes the
    threshold, its orders (the engine for 2 kn, the autopilot's course 90 deg) are given then and she starts to
    turn, and it does not happen again."""
    scenario = load_scenario(write(tmp_path, CONDITIONAL.format(threshold=0.0)))
    lines: list[str] = []
    simulation = Simulation(scenario, wake=False)
    exercise = Exercise(simulation, log=lines.append)
    exercise.run()
    fired = [h for h in exercise.happened if h.index == 0]
    assert len(fired) == 1
    assert fired[0].time_s == pytest.approx(30.0)  # settled at a quarter of the 120 s window
    orders = simulation.voyage.orders_at(30.0)
    assert orders.autopilot and math.degrees(orders.course) == pytest.approx(90.0)
    assert orders.rps == pytest.approx(scenario.vessel.ship.rps_for_speed(2.0 * KNOT))
    assert simulation.voyage.orders_at(29.9).rps > orders.rps
    record = simulation.frame(np.array([29.9, 40.0, 120.0]))
    turn, heading = record["rate_of_turn_deg_min"], record["heading_deg"] + record["yaw_deg"]
    assert turn[0] == 0.0 and turn[1] > 0.0  # from 30 deg she turns to starboard, towards 90
    assert heading[2] > heading[0] + 2.0  # slowly: she is slowing to 2 kn
    assert [h.index for h in exercise.happened] == [0, 1]
    assert lines[1].startswith("t   200.0 s  event 1: at 200 s: 'two hundred seconds'")
    assert exercise.messages(t=210.0) == ["t    200 s  two hundred seconds"]
    simulation.close()


def test_seeking_to_a_time_whose_row_rounds_past_it_lands_on_it(tmp_path):
    """396.2 s is row 3962 at 0.1 s, whose time 3962 x 0.1 rounds to 396.20000000000005: the seek stops at the
    time asked for, not past it (it stopped past it and then refused to step the clock back)."""
    scenario = load_scenario(write(tmp_path, CONDITIONAL.format(threshold=100.0)))
    assert 3962 * scenario.run.dt_s > 396.2
    simulation = Simulation(scenario, wake=False)
    exercise = Exercise(simulation)
    exercise.seek(396.2)
    assert simulation.time == 396.2 and exercise.evaluated_s[-1] <= 396.2
    simulation.close()


def test_a_condition_that_never_holds_changes_nothing(tmp_path):
    scenario = load_scenario(write(tmp_path, CONDITIONAL.format(threshold=100.0)))
    with Simulation(scenario, wake=False) as simulation:
        exercise = Exercise(simulation)
        exercise.run()
        assert [h.index for h in exercise.happened] == [1] and len(simulation.legs) == 1
        result = exercise.assessment()
        assert result.events[0].happened_s is None and result.events[1].happened_s == 200.0


def test_the_viewer_shows_what_assess_reports(tmp_path):
    """A scene stepped frame by frame (the viewer's session) and the exercise run in blocks (``assess``)
    give the same criteria at the same times to 1e-9, the conditional event included."""
    scenario = load_scenario(write(tmp_path, CONDITIONAL.format(threshold=0.3)))
    simulation = Simulation(scenario, wake=False)
    reference = Exercise(simulation)
    seen = {}
    for t in (60.0, 150.0, 300.0):
        reference.run(until=t)
        seen[t] = ([tally.value for tally in reference.monitor.tallies], [h.time_s for h in reference.happened])
    simulation.close()
    with offscreen(scenario, wake=False) as view:
        rng = np.random.default_rng(5)
        for t, (values, happened) in seen.items():
            while view.scene.sim.time < t - 1e-9:
                view.scene.step(min(rng.uniform(0.01, 0.7), t - view.scene.sim.time))
            live = [tally.value for tally in view.scene.exercise.monitor.tallies]
            assert live == pytest.approx(values, rel=1e-9, abs=1e-12)
            assert [h.time_s for h in view.scene.exercise.happened] == happened
        assert view.scene.criteria_panel()[0][0].startswith("bridge acceleration")


def _coloured(image: np.ndarray, colour: tuple[float, ...]) -> int:
    """Pixels within 40 levels of ``colour`` (RGB in 0..1) in each channel."""
    target = np.array(colour[:3]) * 255.0
    return int(np.count_nonzero(np.all(np.abs(image.astype(float) - target) < 40.0, axis=-1)))


def test_the_picture_shows_the_criteria_and_the_message(tmp_path):
    """Rendered, the criteria panel sits at the top in its level's colour (beside the text block, or under it on
    the left in a narrow picture) and the event's message in amber: a hundred pixels or more of each colour than
    in the same scene without them."""
    from marinesim.render.hud import LEVEL_COLORS, MESSAGE_COLOR

    size = (1280, 720)  # the HUD's 14 px font (a smaller target draws a smaller one, and fewer pixels)
    scenario = load_scenario(write(tmp_path, CONDITIONAL.format(threshold=100.0)))
    with offscreen(scenario, size=size, wake=False) as view:
        view.go_to(205.0)
        image = view.frame()
        level = view.scene.exercise.readings()[0][2]
    plain = load_scenario(write(tmp_path, VESSEL_SCENARIO, "plain.toml"))
    with offscreen(plain, size=size, wake=False) as view:
        view.go_to(205.0)
        bare = view.frame()
    top = slice(0, 500)
    assert level in (Level.OK, Level.CAUTION, Level.EXCEEDED)
    assert _coloured(image[top], LEVEL_COLORS[level]) > _coloured(bare[top], LEVEL_COLORS[level]) + 100
    assert _coloured(image[top], MESSAGE_COLOR) > _coloured(bare[top], MESSAGE_COLOR) + 100


def test_fog_rolls_in_when_its_event_happens_and_the_instructor_clears_it(tmp_path):
    """A scripted event brings the visibility down to 800 m and the cloud to 8 oktas from its time, not before (a
    fog that came early or never would make a different exercise), over its ramp (10 s): halfway, the fog's
    extinction (1 / visibility) and the cloud are halfway; the instructor's weather action lifts the fog at once;
    the run's scenario keeps its own [environment] for a second run."""
    text = CONDITIONAL.format(threshold=100.0).replace(
        'message = "two hundred seconds"', 'message = "fog"\nvisibility_m = 800.0\ncloud_cover_oktas = 8.0')
    scenario = load_scenario(write(tmp_path, text))
    lines: list[str] = []
    simulation = Simulation(scenario, wake=False)
    exercise = Exercise(simulation, log=lines.append)
    exercise.advance_to(199.0)
    assert simulation.environment == scenario.environment
    exercise.advance_to(205.0)
    halfway = simulation.environment
    assert 1.0 / halfway.visibility_m == pytest.approx(0.5 / 40_000.0 + 0.5 / 800.0)
    assert halfway.cloud_cover_oktas == pytest.approx(0.5 * scenario.environment.cloud_cover_oktas + 4.0)
    exercise.advance_to(210.0)
    assert (simulation.environment.visibility_m, simulation.environment.cloud_cover_oktas) == (800.0, 8.0)
    assert lines[-1].endswith("at 200 s: visibility 800 m cloud 8 oktas; 'fog'")
    exercise.act("weather", visibility_m=5000.0)
    assert simulation.environment.visibility_m == 5000.0 and simulation.environment.cloud_cover_oktas == 8.0
    assert scenario.environment.visibility_m == 40_000.0
    for hours in ("x", float("nan"), 1e300):  # a hand-edited session log: one line, not a traceback
        with pytest.raises(ParameterError, match="hours"):
            exercise.act("weather", hours=hours)
    simulation.close()


@pytest.mark.parametrize("change", ["timed", "on condition"])
def test_a_vessel_on_dp_is_stepped_once_past_a_scripted_change(change):
    """``assess`` computes the record ahead of the clock, but not into the next scripted change (nor more than
    :data:`AHEAD_ON_CONDITION_S` on while a change waits on its condition): the change throws away what lay beyond
    it, and a vessel keeping station is stepped over that stretch again. configs/supply_dp.toml for three minutes,
    its thruster trip moved to 30 s, or a set point moved 5 m north when her offset first passes 0.01 m (a few
    seconds in): the 0.1 s steps taken twice are at most the few the voyage takes ahead of the clock
    (:data:`CHUNK_STEPS`) and the condition's horizon, and none beyond those past the end. What would be wrong: the
    DP stepped twice over the rest of the run after the change (in the shipped exercises, minutes of it)."""
    scenario = load_scenario(ROOT / "configs" / "supply_dp.toml")
    trip = next(event for event in scenario.events if event.fault is not None)
    event = (dataclasses.replace(trip, at_s=30.0) if change == "timed" else
             dataclasses.replace(trip, at_s=None, condition=parse_condition("offset_max_m > 0.01"), fault=None,
                                 set_north_m=5.0))
    scenario = with_run(dataclasses.replace(scenario, events=(event,)), 180.0)
    simulation = Simulation(scenario, wake=False)
    stepped = []

    class Counted:
        """Her station keeping as it is, each step's number noted."""

        def __init__(self, ship) -> None:
            self.ship = ship

        def __getattr__(self, name: str):
            return getattr(self.ship, name)

        def step(self, s, orders, h, t=0.0):
            stepped.append(round(t / h))
            return self.ship.step(s, orders, h, t)

    simulation.voyage.ship = Counted(simulation.voyage.ship)
    exercise = Exercise(simulation)
    exercise.run()
    simulation.close()
    assert [e.index for e in exercise.happened] == [0], "the change happened"
    horizon = 0 if change == "timed" else round(AHEAD_ON_CONDITION_S / STEP_S)
    again = len(stepped) - len(set(stepped))
    assert again <= CHUNK_STEPS + horizon, f"{again} steps taken twice (the voyage steps {CHUNK_STEPS} ahead)"
    assert max(stepped) <= round(180.0 / STEP_S) + CHUNK_STEPS


def test_an_assessment_computes_only_the_columns_its_criteria_read_and_the_same_criteria():
    """The offshore loading's tanker keeps station beside the FPSO: an assessment's run computes her motions and her
    ship's columns and, of the rest, only what its criteria read (none of the station's, nor the FPSO's), while an
    export's run computes every column; the criteria and the alarms are the same bits either way. What would be
    wrong: an assessment paying for columns nobody reads (the FPSO's response, the station's wind and thrust each
    tenth of a second), or a criterion reading a column the record left out."""
    scenario = with_run(load_scenario(ROOT / "configs" / "training" / "offshore_loading.toml"), 120.0, seed=3)
    runs = {}
    for how in ("assess", "export"):
        with Simulation(scenario, wake=False) as simulation:
            computed: list[set[str]] = []
            record = simulation.frame_steps

            def frame_steps(*args, record=record, computed=computed):  # the real record, its columns noted
                out = record(*args)
                computed.append(set(out))
                return out
            simulation.frame_steps = frame_steps
            exercise = Exercise(simulation)
            if how == "assess":
                exercise.run()
            else:
                for _ in exercise.blocks():
                    pass
            runs[how] = (exercise.values, list(exercise.alarms), computed)
    (values, alarms, assessed), (export_values, export_alarms, exported) = runs["assess"], runs["export"]
    assert values == export_values and alarms == export_alarms
    assert any(value is not None for row in values for value in row), "the criteria have values"
    left_out = {"fpso_heave_m", "set_point_offset_m", "wind_speed_m_s", "thruster_bow_tunnel_1_pct",
                "line_hawser_tension_kn"}
    assert assessed and all(not left_out & columns and {"heave_m", "manifold_vz_m_s"} <= columns
                            for columns in assessed)
    assert exported and all(left_out <= columns for columns in exported)
