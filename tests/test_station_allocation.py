"""The thrust allocation when the thrusters saturate: the bounded least squares the DP solves each cycle, tried
first with the bounds the last cycle's answer held, is scipy's BVLS's answer (an independent solver), and its bits
do not depend on whether that hint held. What would be wrong: a hint accepted where it is not the optimum (a
thruster held at its limit that should ease off, so less of the demand is met than the thrusters can give), or
an answer that depends on the cycles before it (a run that does not repeat itself)."""

from __future__ import annotations

import numpy as np
from scipy.optimize import lsq_linear

from conftest import ROOT
from marinesim.scenario.station_file import load_station
from marinesim.station.thrusters import bounded_least_squares


def _problems(count: int):
    """Random bounded problems shaped as the allocation's: three load rows and a small penalty on every force."""
    rng = np.random.default_rng(7)
    for _ in range(count):
        m = int(rng.integers(3, 9))
        a = np.vstack([rng.normal(size=(3, m)), 1e-3 * np.eye(m)])
        target = np.concatenate([rng.normal(size=3) * rng.uniform(0.1, 5.0), np.zeros(m)])
        yield a, target, -rng.uniform(0.2, 1.5, m), rng.uniform(0.2, 1.5, m)


def test_the_answer_is_bvls_whatever_the_hint():
    held_somewhere = 0
    for a, target, lower, upper in _problems(400):
        reference = lsq_linear(a, target, bounds=(lower, upper), method="bvls").x
        x, held = bounded_least_squares(a, target, lower, upper)
        assert np.abs(x - reference).max() <= 1e-10 * np.abs(reference).max()
        assert np.array_equal(held, np.where(x <= lower, -1, np.where(x >= upper, 1, 0)))
        hinted, _ = bounded_least_squares(a, target, lower, upper, held)
        assert np.array_equal(hinted, x), "the same bits with the right hint"
        wrong = np.where(held == 0, 1, 0)  # every free force held at its upper limit, every held one let go
        misled, again = bounded_least_squares(a, target, lower, upper, wrong)
        assert np.array_equal(misled, x) and np.array_equal(again, held), "a wrong hint is not taken"
        held_somewhere += bool(np.any(held))
    assert held_somewhere > 100, "most problems saturate some force"


def test_beyond_her_capability_the_supply_vessels_allocation_does_not_depend_on_the_demands_before_it():
    thrusters = load_station(ROOT / "configs" / "station" / "supply.toml").thruster_set()
    lo, hi = thrusters.bounds()
    top = float(hi.max())
    for angle in np.radians(np.arange(0.0, 360.0, 7.5)):  # a demand swinging round, beyond what she can give
        tau = 3.0 * top * np.array([np.cos(angle), np.sin(angle), 0.02 * thrusters.length * np.sin(3 * angle)])
        f = thrusters.allocate(tau)
        assert np.all(f >= lo - 1e-6) and np.all(f <= hi + 1e-6)
        fresh = type(thrusters)(thrusters.units, thrusters.length).allocate(tau)  # no hint from earlier demands
        assert np.array_equal(f, fresh), "the answer does not depend on the demands before it"
        assert np.abs(thrusters.b @ f - tau).max() > 0.1 * top, "the demand is beyond her"
