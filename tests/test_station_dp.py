"""Dynamic positioning: the supply vessel of configs/station/supply.toml holding station under wind and current,
losing a thruster, following a drifting position reference, filtering the waves out of her measured position; the
capability envelope and the simulation telling the same story; bad station files refused."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pandas as pd
import pytest

from conftest import ROOT
from marinesim.cli import main
from marinesim.errors import ScenarioError
from marinesim.manoeuvring.voyage import Voyage
from marinesim.scenario import load_scenario
from marinesim.scenario.station_file import load_station
from marinesim.station.capability import CURRENT_M_S, envelope
from marinesim.station.dp import Dp
from marinesim.station.environment import Weather, current_vector
from marinesim.station.vessel import EXTRA, Calm, Station
from marinesim.station.wind import WindLoads

SUPPLY = ROOT / "configs" / "station" / "supply.toml"
HEADING = math.radians(30.0)


@pytest.fixture(scope="module")
def supply():
    file = load_station(SUPPLY)
    m, d = file.matrices()
    wind = file.wind
    loads = WindLoads.blendermann(wind.vessel_type, wind.frontal_area_m2, wind.lateral_area_m2, file.length_m,
                                  wind.lateral_centroid_m)
    return file, m, d, file.thruster_set(), loads


def _voyage(supply, wind_m_s: float, wind_from_deg: float, current=(0.0, 0.0), wave_motion=None) -> Voyage:
    file, m, d, thrusters, loads = supply
    weather = Weather(loads, wind_m_s, math.radians(wind_from_deg), current=current, wave_motion=wave_motion)
    station = Station(file.name, m, d, weather, thrusters, Dp(m, d, file.tuning()))
    state, orders = dataclasses.replace(station, environment=Calm()).start(0.0, HEADING)  # the weather then hits
    return Voyage(station, state, orders, 0.1)


def _thrust(voyage: Voyage, t: float) -> np.ndarray:
    return voyage.ship.thrusters.b @ np.array(voyage.state(t).extra[len(EXTRA):])


def test_in_steady_wind_and_current_the_thrust_balances_the_environment_and_she_holds_station(supply):
    """12 m/s from 20 deg and 0.5 m/s of current setting 225 deg, all at once on a DP settled in calm water: after
    the DP's integral has settled (its natural periods are 80-100 s), the thrusters' force equals the wind's load
    and the current's (``D nu_c``) to 2 %, and she has never left a 5 m footprint. What would be wrong if not: a controller without integral action
    (a standing offset), a thrust allocation that does not give what is asked, or loads of the wrong sign."""
    voyage = _voyage(supply, 12.0, 20.0, current=current_vector(0.5, 225.0))
    times = np.arange(0.0, 1500.0, 5.0)
    path = voyage.sample(times)
    offset = np.hypot(path["north"], path["east"])
    assert offset.max() < 5.0, f"she left the footprint: {offset.max():.2f} m"
    state = voyage.state(1500.0)
    weather, d = voyage.ship.environment, voyage.ship.d
    cn, ce = weather.current(1500.0)
    c, s = math.cos(state.psi), math.sin(state.psi)
    current_load = d @ np.array([cn * c + ce * s, -cn * s + ce * c, 0.0])
    environment = weather.wind_load(1500.0, state.psi, 0.0, 0.0) + current_load
    thrust = _thrust(voyage, 1500.0)
    np.testing.assert_allclose(thrust[:2], -environment[:2], rtol=0.02)
    assert abs(thrust[2] + environment[2]) < 0.02 * abs(environment[2]) + 1e4
    assert offset[-60:].max() < 0.2, "at steady state she sits on her set point"


def test_after_a_thruster_failure_she_drifts_off_where_the_capability_envelope_says_she_must(supply):
    """18 m/s and the envelope's 0.75 m/s current on the starboard beam: the intact envelope holds it (limit above
    18 m/s there), the envelope without the first bow tunnel does not (its limit below 18): in the simulation the
    intact vessel holds within 5 m for 20 minutes; with the thruster lost from the start she is pushed off station
    beyond 20 m, downwind. What would be wrong if not: an envelope and a simulation that disagree on what the
    thrusters can do (allocation, limits, loads)."""
    file, m, d, thrusters, loads = supply
    beam = (90.0,)
    intact = envelope(thrusters, loads, d, None, directions_deg=beam).limiting_wind_m_s[0]
    lost = envelope(thrusters, loads, d, None, ("bow tunnel 1",), directions_deg=beam).limiting_wind_m_s[0]
    assert lost < 18.0 < intact, (intact, lost)
    wind_from = math.degrees(HEADING) + 90.0
    current = current_vector(CURRENT_M_S, wind_from + 180.0)
    holding = _voyage(supply, 18.0, wind_from, current=current)
    times = np.arange(0.0, 1200.0, 10.0)
    held = holding.sample(times)
    kept = np.hypot(held["north"], held["east"])
    assert kept[times >= 600.0].max() < 1.0, "the intact vessel settles back on her set point"
    assert kept.max() < 10.0, "after the weather's first push (all of it at once at t = 0)"
    failing = _voyage(supply, 18.0, wind_from, current=current)
    failing.order(0.0, fault="thruster:bow tunnel 1")
    drifted = failing.sample(times)
    reach = np.hypot(drifted["north"], drifted["east"])
    assert reach[-1] > 20.0, f"she should have been blown off: {reach[-1]:.1f} m"
    downwind = np.array([-math.cos(math.radians(wind_from)), -math.sin(math.radians(wind_from))])
    assert np.dot([drifted["north"][-1], drifted["east"][-1]], downwind) > 0.9 * reach[-1], "not downwind"


def test_a_drifting_position_reference_walks_her_off_the_other_way(supply):
    """The position reference drifts north at 0.05 m/s from 60 s: the DP holds the *measured* position, so the
    vessel moves south by as much (15 m after five minutes, to within the loop's lag). What would be wrong if not:
    a fault that does not reach the measurement, or a DP that reads the true position."""
    voyage = _voyage(supply, 0.0, 0.0)
    voyage.order(60.0, fault="reference drift")
    state = voyage.state(660.0)
    drift = state.extra[EXTRA.index("drift_north")]
    assert drift == pytest.approx(30.0, abs=0.2)
    assert state.north == pytest.approx(-drift, abs=3.0)
    assert abs(state.east) < 1.0


def test_the_observer_keeps_the_wave_frequency_motion_out_of_the_thrusters(supply):
    """A 1 m surge and sway at the wave period (9 s, the observer's wave model) in the measured position: the
    thrust's wave-frequency ripple stays below a tenth of what a controller on the raw measurement would ask
    (``Kp`` times 1 m). What would be wrong if not: thrusters chasing every wave (wear, power) because the observer
    does not notch the wave frequency."""
    omega = 2.0 * math.pi / 9.0

    def waves(t: float) -> tuple[float, float, float]:
        return math.sin(omega * t), math.cos(omega * t), 0.0

    voyage = _voyage(supply, 0.0, 0.0, wave_motion=waves)
    times = np.arange(600.0, 900.0, 0.5)
    thrust = np.array([_thrust(voyage, t) for t in times])
    raw = voyage.ship.dp.kp[:2] * 1.0
    assert np.all(thrust[:, :2].std(axis=0) * math.sqrt(2.0) < 0.1 * raw), (thrust[:, :2].std(axis=0), raw)
    path = voyage.sample(times)
    assert np.hypot(path["north"], path["east"]).max() < 0.5


def test_the_shipped_dp_exercise_records_its_thrusters_and_wind(tmp_path, capsys):
    """``marinesim export`` of configs/supply_dp.toml (two minutes) writes the station's columns: thruster use
    (0-100 %), the wind and its load, the offset from the set point, read back with pandas. What would be wrong if
    not: a record without what a DP operator watches."""
    out = tmp_path / "dp.csv"
    code = main(["export", str(ROOT / "configs" / "supply_dp.toml"), "--duration", "120", "--out", str(out)])
    assert code == 0, capsys.readouterr().err
    frame = pd.read_csv(out)
    thrusters = [c for c in frame.columns if c.startswith("thruster_") and c.endswith("_pct")]
    assert len(thrusters) == 5
    assert frame[thrusters].to_numpy().min() >= 0.0 and frame[thrusters].to_numpy().max() <= 100.0
    assert frame[thrusters].to_numpy().max() > 1.0, "the thrusters work against the weather"
    assert frame["wind_speed_m_s"].std() > 0.2, "the wind gusts"
    assert (frame["wind_force_x_kn"] < 0).mean() > 0.9, "wind from 50 deg on the starboard bow pushes her astern"
    assert (frame["wind_force_y_kn"] < 0).mean() > 0.9, "... and to port"
    assert frame["set_point_offset_m"].max() < 5.0


def test_thrusters_that_cannot_hold_a_heading_are_refused(tmp_path):
    """Two main propellers and nothing sideways: no position and heading can be held; the file is refused with one
    line naming the key. What would be wrong if not: a DP vessel silently unable to hold station."""
    text = SUPPLY.read_text()
    cut = text.index("[[thrusters]]")
    mains = "\n".join(block for block in text[cut:].split("\n\n") if 'kind = "main"' in block)
    bad = tmp_path / "mains_only.toml"
    bad.write_text(text[:cut] + mains + "\n")
    with pytest.raises(ScenarioError, match=r"mains_only\.toml: thrusters: .*no\s+position and heading"):
        load_station(bad)


def test_a_scenario_on_dp_loads_with_its_station_and_takes_faults_it_can_have():
    scenario = load_scenario(ROOT / "configs" / "supply_dp.toml")
    ship = scenario.vessel.ship
    assert ship.label == "DP" and len(ship.thrusters.units) == 5
    state, orders = ship.start(0.0, HEADING)
    with pytest.raises(Exception, match="no thruster 'bow 9'"):
        ship.order(orders, state, fault="thruster:bow 9")
    with pytest.raises(Exception, match="takes set points, not helm"):
        ship.order(orders, state, rudder_deg=10.0)


def test_the_shuttle_tankers_thrust_balances_wind_current_and_the_waves_drift_on_average():
    """configs/tanker_dp.toml, 20 minutes after the first five: the DP's thrust averaged over them equals the
    average of the loads the weather put on her (wind with gusts, current, the waves' slowly varying drift from
    her WAMIT .9 table) to 2 % in surge and sway; the drift's average is near its expected mean ``sum |a|^2 D``
    (within a third: slow drift has periods of minutes). What would be wrong if not: drift forces that do not reach
    the vessel, of the wrong sign, or a DP that leaves a standing offset."""
    from marinesim.scenario.schema import with_run
    from marinesim.session.timeline import Simulation
    from marinesim.station.drift import SlowDrift

    scenario = with_run(load_scenario(ROOT / "configs" / "tanker_dp.toml"), duration=1500.0)
    sim = Simulation(scenario, wake=False)
    ship, weather = sim.voyage.ship, sim.station.weather
    times = np.arange(300.0, 1500.0, 1.0)
    states = [sim.voyage.state(t) for t in times]
    thrust = np.array([ship.thrusters.b @ np.array(s.extra[len(EXTRA):]) for s in states]).mean(axis=0)
    loads = np.array([weather.wind_load(t, s.psi, s.u, s.v) + weather.drift(t, s.psi) for t, s in zip(times, states)])
    wind = np.array([weather.wind_load(t, s.psi, s.u, s.v) for t, s in zip(times, states)])
    cn, ce = weather.current(0.0)
    current = np.array([ship.d @ np.array([cn * math.cos(s.psi) + ce * math.sin(s.psi),
                                           -cn * math.sin(s.psi) + ce * math.cos(s.psi), 0.0]) for s in states])
    environment = (loads + current).mean(axis=0)
    np.testing.assert_allclose(thrust[:2], -environment[:2], rtol=0.02)
    drift = (loads - wind).mean(axis=0)
    psi = float(np.mean([s.psi for s in states]))
    expected = SlowDrift.from_components(sim.components(0), scenario.station.drift).mean(0.5 * math.pi - psi)
    assert expected[0] < -1e5, "waves from ahead push a tanker astern"
    np.testing.assert_allclose(drift[:2], expected[:2], rtol=0.35)


def test_a_step_follows_her_equations_of_motion_with_every_load_the_weather_gives():
    """The offshore loading exercise (her DP, her hawser, gusting wind, current, the waves' slow drift): at states
    along her run, the derivatives her compiled step starts from equal her equations of motion assembled here from
    the weather's and the lines' own loads, ``eta' = R(psi) nu``, ``M nu' = B f + wind + drift + D (nu_c - nu) +
    lines``; and over the step her state moves as scipy's adaptive Runge-Kutta integrates those equations (the
    thrusters' forces following their orders, the wind and the drift at each time), to 1e-6 of the move. What
    would be wrong if not: a load left out of the compiled stages or taken at another time, a current or a line's
    pull in the wrong axes, a stage at the wrong time or weight."""
    from scipy.integrate import solve_ivp

    from marinesim.scenario.schema import with_run
    from marinesim.session.timeline import Simulation

    scenario = with_run(load_scenario(ROOT / "configs" / "training" / "offshore_loading.toml"), duration=300.0)
    sim = Simulation(scenario, wake=False)
    ship, weather = sim.voyage.ship, sim.station.weather
    assert ship.moorings is not None and ship.pull == 0.0
    for t in (40.0, 150.0, 290.0):
        s = sim.voyage.state(t)
        _, rates = ship.step(s, sim.voyage.orders_at(t), 0.1, t)
        cn, ce = weather.current(t)
        c, sn = math.cos(s.psi), math.sin(s.psi)
        through_water = np.array([s.u - (cn * c + ce * sn), s.v - (ce * c - cn * sn), s.r])
        force = (ship.thrusters.b @ np.array(s.extra[len(EXTRA):]) + weather.wind_load(t, s.psi, s.u, s.v)
                 + weather.drift(t, s.psi) - ship.d @ through_water + ship.moorings.force(s.north, s.east, s.psi))
        assert np.abs(weather.drift(t, s.psi)).max() > 1e4 and np.abs(ship.moorings.force(s.north, s.east,
                                                                                           s.psi)).max() > 1e4
        expected = [s.u * c - s.v * sn, s.u * sn + s.v * c, s.r, *np.linalg.solve(ship.m, force)]
        np.testing.assert_allclose(rates[:6], expected, rtol=1e-9, atol=1e-12)

    t, h = 150.0, 0.1
    s = sim.voyage.state(t)
    after, _ = ship.step(s, sim.voyage.orders_at(t), h, t)
    lag, b = ship.thrusters.lag(), ship.thrusters.b
    f_now, f_end = np.array(s.extra[len(EXTRA):]), np.array(after.extra[len(EXTRA):])
    f_order = (f_end - f_now * np.exp(-h / lag)) / (1.0 - np.exp(-h / lag))  # what the DP ordered for the step

    def equations(tau: float, y: np.ndarray) -> list[float]:
        north, east, psi, u, v, r = y
        cn, ce = weather.current(t + tau)
        c, sn = math.cos(psi), math.sin(psi)
        through_water = np.array([u - (cn * c + ce * sn), v - (ce * c - cn * sn), r])
        force = (b @ (f_order + (f_now - f_order) * np.exp(-tau / lag)) + weather.wind_load(t + tau, psi, u, v)
                 + weather.drift(t + tau, s.psi) - ship.d @ through_water + ship.moorings.force(north, east, psi))
        return [u * c - v * sn, u * sn + v * c, r, *np.linalg.solve(ship.m, force)]

    y0 = np.array([s.north, s.east, s.psi, s.u, s.v, s.r])
    exact = solve_ivp(equations, (0.0, h), y0, rtol=1e-12, atol=1e-14).y[:, -1]
    stepped = np.array([after.north, after.east, after.psi, after.u, after.v, after.r])
    np.testing.assert_allclose(stepped - y0, exact - y0, rtol=1e-6, atol=1e-15)


def test_a_session_log_keeps_the_station_files_and_its_replay_refuses_them_changed(tmp_path):
    """A session of the shuttle tanker on DP: its log keeps the sha256 of her station-keeping file and of the drift
    table beside her RAO set, as of her RAO and hull; once the station file has changed, replaying the log is
    refused. What would be wrong if not: a replay of other physics (other thrusters, another DP tuning) passed off
    as the session."""
    import shutil

    from marinesim.errors import ScenarioError as Refused
    from marinesim.session.exercise import Exercise
    from marinesim.session.log import read_log, vessel_files, write_log
    from marinesim.session.replay import session_scenario
    from marinesim.session.timeline import Simulation

    shutil.copy(ROOT / "configs" / "station" / "tanker.toml", tmp_path / "tanker.toml")
    text = (ROOT / "configs" / "tanker_dp.toml").read_text().replace('"../', f'"{ROOT.as_posix()}/')
    scenario_path = tmp_path / "tanker_dp.toml"
    scenario_path.write_text(text.replace('vessel = "tanker"', 'vessel = "tanker.toml"'))
    scenario = load_scenario(scenario_path)
    assert set(vessel_files(scenario)) == {"rao", "hull", "station", "drift"}
    assert vessel_files(scenario)["drift"].name == "tanker.9"
    exercise = Exercise(Simulation(scenario, wake=False), duration_s=2.0)
    exercise.advance(2.0)
    log = write_log(tmp_path / "session.jsonl", exercise)
    session_scenario(read_log(log), log)
    station = tmp_path / "tanker.toml"
    station.write_text(station.read_text().replace("periods_s = [150.0, 150.0, 120.0]",
                                                   "periods_s = [90.0, 90.0, 80.0]"))
    with pytest.raises(Refused, match="station file .*tanker.toml has changed since the session"):
        session_scenario(read_log(log), log)


TANKER = ROOT / "configs" / "station" / "tanker.toml"
HAWSER = ROOT / "configs" / "moorings" / "tanker_hawser.toml"


def _tanker_on_her_hawser(turn_about: str | None) -> Voyage:
    """The shuttle tanker on DP made fast by her bow hawser (configs/moorings/tanker_hawser.toml) in calm water,
    heading 260, turning about the hawser's far end (``turn_about = "hawser"``) or about her origin (None)."""
    from marinesim.scenario.moorings_file import load_moorings

    file = load_station(TANKER)
    m, d = file.matrices()
    moorings = load_moorings(HAWSER, math.inf)
    station = Station(file.name, m, d, Calm(), file.thruster_set(), Dp(m, d, file.tuning()), moorings,
                      turn_about=turn_about)
    state, orders = station.start(0.0, moorings.heading)
    return Voyage(station, state, orders, 0.1)


def _chock_span(voyage: Voyage, times: np.ndarray) -> np.ndarray:
    """The horizontal distance (m) from her bow chock to the hawser's fixed point at ``times``."""
    moorings = voyage.ship.moorings
    line = moorings.lines[0]
    x, y = line.fairlead[:2]
    out = []
    for t in times:
        s = voyage.state(t)
        c, sn = math.cos(s.psi), math.sin(s.psi)
        out.append(math.hypot(line.anchor[0] - (s.north + x * c - y * sn), line.anchor[1] - (s.east + x * sn + y * c)))
    return np.array(out)


def test_a_tanker_on_dp_turns_about_her_hawsers_far_end_and_keeps_it_taut_not_overstretched():
    """Her DP's tandem mode (``turn_about``): a heading order of 40 deg to starboard moves her set point along the
    arc about the hawser's fixed point, 213 m from her origin, at the DP's 0.3 m/s (4.8 deg/min, slower than its
    10 deg/min) and on the arc to 1e-9 m at every step; she follows and settles on the new heading, her bow chock
    never closing on the fixed point by 3 m (a set point cutting the chord would bring it 13 m closer) and the hawser
    never pulled past a quarter of its breaking load. Before the order she sits on her set point: the DP starts with
    the hawser's 190 kN pretension in its bias. Turning about her origin instead, the same order would swing her bow
    53 m off the line: the hawser holds it, her thrusters saturate and she stops short of the heading by more than
    15 deg. What would be wrong if not: a set point off the arc, a turn faster than the DP may move her, or a start
    that jerks her off station."""
    voyage = _tanker_on_her_hawser("hawser")
    station = voyage.ship
    pivot = station.moorings.lines[0].anchor
    before = voyage.sample(np.arange(0.0, 120.0, 1.0))
    assert np.hypot(before["north"], before["east"]).max() < 0.05, "the DP holds her on the hawser from the start"
    voyage.order(120.0, course_deg=300.0)
    times = np.arange(0.0, 1800.0, 0.5)
    ref = station.set_point(np.array([voyage.state(t).extra for t in times]))
    radius = np.hypot(ref[:, 0] - pivot[0], ref[:, 1] - pivot[1])
    np.testing.assert_allclose(radius, math.hypot(*pivot), atol=1e-9)
    rate = np.abs(np.diff(ref[:, 2])) / 0.5
    assert rate.max() <= 0.3 / math.hypot(*pivot) * (1.0 + 1e-9)
    assert rate.max() == pytest.approx(0.3 / math.hypot(*pivot), rel=1e-6), "the arc at the DP's speed limit"
    assert math.degrees(ref[-1, 2]) % 360.0 == pytest.approx(300.0, abs=1e-9)
    span = _chock_span(voyage, times)
    assert span.min() > span[0] - 3.0, f"the bow closed {span[0] - span.min():.1f} m on the FPSO"
    assert math.degrees(voyage.state(1800.0).psi) % 360.0 == pytest.approx(300.0, abs=0.5)
    tension = np.array([station.line_tensions(voyage.state(t), frozenset())[0] for t in times[::4]])
    assert tension.max() < 0.25 * station.moorings.mbl[0]

    about_origin = _tanker_on_her_hawser(None)
    about_origin.order(120.0, course_deg=300.0)
    late = [about_origin.state(t) for t in np.arange(600.0, 1800.0, 10.0)]
    assert max(math.degrees(s.psi) % 360.0 for s in late) < 285.0, "the hawser holds her bow"
    assert about_origin.ship.thruster_use(np.array([s.extra for s in late])).max() > 0.99


def test_a_tanker_turning_about_her_hawser_takes_no_position_set_point():
    """What would be wrong if not: a position order that pulls her set point off the arc her heading orders keep
    it on, fighting the hawser."""
    from marinesim.errors import ParameterError

    voyage = _tanker_on_her_hawser("hawser")
    with pytest.raises(ParameterError, match="turns about line hawser's far end: she takes heading set points"):
        voyage.order(10.0, set_north_m=5.0)
