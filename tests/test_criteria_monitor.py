"""The running monitor: windows, settling, levels, time above the limit, doses, and values that do
not depend on how the record is cut into blocks (the viewer's frames vs. ``assess``'s blocks)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.criteria.monitor import Criterion, Monitor, parse_condition, watched
from marinesim.criteria.quantities import QUANTITIES, Options
from marinesim.errors import ParameterError

DT = 0.1
POINTS = {"bridge": (-70.0, 0.0, 20.0)}


def _record(seconds: float, roll_amplitude=lambda t: 6.0 * math.sqrt(2.0) + 0.0 * t) -> dict[str, np.ndarray]:
    """A motion record (export columns) of a regular roll of 10 s period whose amplitude may vary with t."""
    t = np.arange(0.0, seconds + DT / 2, DT)
    w = 2.0 * math.pi / 10.0
    amplitude = roll_amplitude(t)
    columns = {"time_s": t}
    for dof in ("surge", "sway", "heave", "pitch", "yaw"):
        unit, rate, acc = ("m", "m_s", "m_s2") if dof in ("surge", "sway", "heave") else ("deg", "deg_s", "deg_s2")
        columns |= {f"{dof}_{unit}": 0.0 * t, f"{dof}_vel_{rate}": 0.0 * t, f"{dof}_acc_{acc}": 0.0 * t}
    columns |= {"roll_deg": amplitude * np.sin(w * t), "roll_vel_deg_s": amplitude * w * np.cos(w * t),
                "roll_acc_deg_s2": -amplitude * w * w * np.sin(w * t)}
    columns |= {"bridge_az_m_s2": np.sin(2.0 * math.pi * t / 6.0), "bridge_vz_m_s": 0.0 * t, "bridge_z_m": 0.0 * t,
                "bridge_relative_m": 0.0 * t}
    return columns


def _feed(monitor: Monitor, record: dict[str, np.ndarray], cuts: list[int]) -> dict[float, list]:
    """Feed ``record`` cut at ``cuts``, evaluating where due; the values by evaluation time."""
    seen = {}
    rows = record["time_s"].size
    evaluations = list(range(1, rows + 1, monitor.stride))   # block ends just after each evaluation row
    edges = sorted(set([0, rows] + [c for c in cuts if 0 < c < rows] + evaluations))
    for lo, hi in zip(edges[:-1], edges[1:]):
        monitor.append({k: v[lo:hi] for k, v in record.items()})
        if monitor.due(hi - 1):
            seen[round((hi - 1) * DT, 6)] = monitor.evaluate()
    return seen


def test_a_regular_roll_reads_its_rms_once_the_window_settles():
    """RMS roll of an 8.49 deg regular roll is 6.0 deg; the value is None (settling) until a quarter
    of the 600 s window is recorded, then counts."""
    monitor = Monitor([Criterion("roll_rms_deg", 6.5)], POINTS, DT, 1200.0)
    seen = _feed(monitor, _record(400.0), [])
    assert seen[149.0] == [None] and seen[150.0][0] == pytest.approx(6.0, abs=0.05)
    assert seen[400.0][0] == pytest.approx(6.0, abs=0.01)


def test_time_above_the_limit_and_levels():
    """The roll amplitude doubles at 300 s: RMS over the 100 s window passes the 9 deg limit once the
    window holds enough of the larger roll, and every evaluation above adds a second."""
    criterion = Criterion("roll_rms_deg", 9.0, window_s=100.0, caution=0.8)
    monitor = Monitor([criterion], POINTS, DT, 600.0)
    record = _record(600.0, lambda t: np.where(t < 300.0, 6.0 * math.sqrt(2.0), 12.0 * math.sqrt(2.0)))
    seen = _feed(monitor, record, [])
    tally = monitor.tallies[0]
    first = min(t for t, (v,) in seen.items() if v is not None and v > 9.0)
    assert 300.0 < first < 400.0 and tally.first_exceeded_s == first
    assert tally.time_exceeded_s == pytest.approx(sum(1.0 for v, in seen.values() if v is not None and v > 9.0))
    assert tally.worst == pytest.approx(12.0, abs=0.05)
    assert [criterion.level(v) for v in (None, 7.0, 7.2, 9.0, 9.01)] == ["settling", "ok", "caution", "caution",
                                                                         "exceeded"]


def test_values_do_not_depend_on_the_blocks():
    """Fed a few rows at a time (the viewer) or in big blocks (assess), the values at each evaluation
    agree to 1e-12; MSDV runs over the whole record, the others over their windows."""
    criteria = [Criterion("roll_rms_deg", 6.0), Criterion("msdv_m_s1_5", 30.0, point="bridge"),
                Criterion("mii_per_min", 1.0, point="bridge"), Criterion("msi_pct", 20.0, point="bridge"),
                Criterion("lateral_acc_rms_m_s2", 1.0, point="bridge")]
    record = _record(700.0)
    rng = np.random.default_rng(1)
    small = _feed(Monitor(criteria, POINTS, DT, 700.0), record, list(np.cumsum(rng.integers(1, 4, 4000))))
    large = _feed(Monitor(criteria, POINTS, DT, 700.0), record, list(range(0, 7001, 512)))
    assert small.keys() == large.keys()
    for t in small:
        assert [v is None for v in small[t]] == [v is None for v in large[t]], t
        assert [v for v in small[t] if v is not None] == pytest.approx([v for v in large[t] if v is not None],
                                                                       rel=1e-12, abs=1e-15), t


def test_msdv_accumulates_over_the_run():
    """A 1/6 Hz vertical acceleration of 1 m/s^2 (|W_f(1/6 Hz)| = 1.006 within 0.2 %) over 700 s:
    MSDV = 1.006 sqrt(700 / 2)."""
    monitor = Monitor([Criterion("msdv_m_s1_5", 30.0, point="bridge")], POINTS, DT, 700.0)
    _feed(monitor, _record(700.0), [])
    assert monitor.tallies[0].value == pytest.approx(1.006 * math.sqrt(350.0), rel=0.01)


def test_a_short_run_counts_its_whole_record():
    """A 60 s run with a 600 s window: the value counts at the end (the whole run), not never."""
    monitor = Monitor([Criterion("roll_rms_deg", 6.0)], POINTS, DT, 60.0)
    seen = _feed(monitor, _record(60.0), [])
    assert seen[59.0] == [None] and seen[60.0][0] == pytest.approx(6.0, abs=0.1)


def test_lateral_acceleration_includes_gravity_from_roll():
    """At the bridge, 20 m above the origin, a regular roll of 8.49 deg at 10 s: the lateral specific
    force is g sin(roll) - 20 m x roll acceleration = (g + 20 w^2) roll, gravity and the roll's
    acceleration adding above the roll axis; its RMS is (g + 20 w^2) x 6 deg in rad."""
    monitor = Monitor([Criterion("lateral_acc_rms_m_s2", 5.0, point="bridge")], POINTS, DT, 600.0)
    _feed(monitor, _record(600.0), [])
    w = 2.0 * math.pi / 10.0
    assert monitor.tallies[0].value == pytest.approx((9.80665 + 20.0 * w * w) * math.radians(6.0), rel=0.01)


def test_conditions():
    """A condition reads a criterion by name, or a [point.]quantity with its default window."""
    named = Criterion("roll_rms_deg", 6.0, name="roll")
    condition = parse_condition("roll >= 5.5")
    assert watched(condition, [named], POINTS) is named
    assert condition.holds(5.5) and not condition.holds(5.4) and not condition.holds(None)
    other = watched(parse_condition("bridge.msi_pct > 10"), [named], POINTS)
    assert (other.quantity, other.point, other.limit, other.window) == ("msi_pct", "bridge", None, 600.0)
    with pytest.raises(ParameterError, match="unknown point 'mast'"):
        watched(parse_condition("mast.msi_pct > 10"), [], POINTS)
    with pytest.raises(ParameterError, match="expected '<criterion"):
        parse_condition("roll is 5")


def test_windows_are_bounded_before_anything_is_kept():
    with pytest.raises(ParameterError, match="86400000 rows, more than 2000000"):
        Monitor([Criterion("roll_rms_deg", 6.0, window_s=86400.0)], POINTS, 0.001, 1e6)


def test_every_quantity_has_a_unit_and_a_meaning():
    """The panel and the report print them; a quantity without would print a bare number."""
    for name, measure in QUANTITIES.items():
        assert measure.what and (measure.unit or name.endswith(("exceedance", "probability"))), name
        assert (measure.value is None) == (measure.dose is not None), name
    assert Options().tipping_coefficient == 0.25
