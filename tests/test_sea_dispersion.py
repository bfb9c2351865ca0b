"""Dispersion relation w^2 = g k tanh(kh) and its group velocity."""

import math

import numpy as np
import pytest

from marinesim.constants import G
from marinesim.sea.dispersion import group_velocity, k_from_omega, omega_from_k


@pytest.mark.parametrize("depth", [math.inf, 200.0, 30.0, 2.0])
def test_k_from_omega_inverts_omega_from_k(depth):
    omega = np.linspace(0.05, 6.0, 300)
    k = k_from_omega(omega, depth)
    np.testing.assert_allclose(omega_from_k(k, depth), omega, rtol=1e-12)


def test_deep_and_shallow_limits():
    # deep water: k = w^2 / g; shallow water: phase speed sqrt(g h) (non-dispersive)
    assert k_from_omega(1.0) == pytest.approx(1.0 / G)
    assert k_from_omega(1.0, 1e5) == pytest.approx(1.0 / G, rel=1e-12)
    h = 1.0
    k = k_from_omega(0.01, h)
    assert 0.01 / k == pytest.approx(math.sqrt(G * h), rel=1e-4)


@pytest.mark.parametrize("depth", [math.inf, 20.0])
def test_group_velocity_is_dw_dk(depth):
    k = np.linspace(0.01, 1.0, 50)
    dk = 1e-6
    numeric = (omega_from_k(k + dk, depth) - omega_from_k(k - dk, depth)) / (2 * dk)
    np.testing.assert_allclose(group_velocity(k, depth), numeric, rtol=1e-6)


def test_deep_group_velocity_is_half_phase_speed():
    k = np.array([0.01, 0.1, 1.0])
    np.testing.assert_allclose(group_velocity(k), 0.5 * omega_from_k(k) / k, rtol=1e-12)
