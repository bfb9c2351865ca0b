"""Compass <-> internal angles (docs/CONVENTIONS.md): one pair of conversions, tested once."""

import math

import pytest

from marinesim.angles import (compass_to_math, math_to_compass, wave_beta_from_compass,
                              wave_compass_from_beta, wrap_angle)


@pytest.mark.parametrize("compass, expected", [(0.0, 90.0), (90.0, 0.0), (180.0, -90.0), (270.0, 180.0)])
def test_compass_north_is_plus_y_and_east_is_plus_x(compass, expected):
    # north must be the +y axis (math 90 deg), east +x (0 deg); a swap would rotate every sea
    assert math.degrees(compass_to_math(compass)) == pytest.approx(expected)


def test_waves_from_north_travel_south():
    # "coming from 0" travels towards -y: beta = -90 deg; a from/towards mix-up gives +90
    assert math.degrees(wave_beta_from_compass(0.0)) == pytest.approx(-90.0)
    # "coming from 30" travels towards compass 210
    assert math_to_compass(wave_beta_from_compass(30.0)) == pytest.approx(210.0)


@pytest.mark.parametrize("compass", [0.0, 30.0, 135.5, 270.0, 359.0])
def test_round_trip(compass):
    assert wave_compass_from_beta(wave_beta_from_compass(compass)) == pytest.approx(compass % 360.0)
    assert math_to_compass(compass_to_math(compass)) == pytest.approx(compass % 360.0)


def test_wrap_angle_range():
    assert wrap_angle(3.0 * math.pi) == pytest.approx(math.pi)
    assert wrap_angle(-math.pi) == pytest.approx(math.pi)
    assert wrap_angle(-0.5) == pytest.approx(-0.5)
