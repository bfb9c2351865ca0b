"""Linear dispersion of surface gravity waves: ``w^2 = g k tanh(k h)`` (REFERENCES §3).

``depth = math.inf`` means deep water (``w^2 = g k``). All functions are vectorised over
numpy arrays; units rad/s, rad/m, m.
"""

from __future__ import annotations

import math

import numpy as np

from marinesim.constants import G


def omega_from_k(k: np.ndarray | float, depth: float = math.inf, g: float = G) -> np.ndarray:
    """Angular frequency (rad/s) of wave number ``k`` (rad/m) in water of ``depth`` (m)."""
    k = np.asarray(k, dtype=float)
    if math.isinf(depth):
        return np.sqrt(g * k)
    return np.sqrt(g * k * np.tanh(k * depth))


def k_from_omega(omega: np.ndarray | float, depth: float = math.inf, g: float = G) -> np.ndarray:
    """Wave number (rad/m) of angular frequency ``omega`` (rad/s); Newton to machine precision."""
    omega = np.asarray(omega, dtype=float)
    k_deep = omega**2 / g
    if math.isinf(depth):
        return k_deep
    y = k_deep * depth  # = w^2 h / g
    with np.errstate(divide="ignore", invalid="ignore"):
        x = np.where(y > 0, y / np.sqrt(np.tanh(np.maximum(y, 1e-300))), 0.0)  # Eckart's start
        for _ in range(8):
            t = np.tanh(x)
            f = x * t - y
            df = t + x * (1.0 - t * t)
            x = np.where(df > 0, x - f / df, x)
    return x / depth


def group_velocity(k: np.ndarray | float, depth: float = math.inf, g: float = G) -> np.ndarray:
    """``dw/dk = g (tanh(kh) + kh sech^2(kh)) / (2 w)`` in m/s (deep water: ``g / (2 w)``)."""
    k = np.asarray(k, dtype=float)
    omega = omega_from_k(k, depth, g)
    if math.isinf(depth):
        with np.errstate(divide="ignore"):
            return g / (2.0 * omega)
    kh = k * depth
    t = np.tanh(kh)
    with np.errstate(divide="ignore", invalid="ignore"):
        return g * (t + kh * (1.0 - t * t)) / (2.0 * omega)
