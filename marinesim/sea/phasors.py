"""Tables of phasors ``exp(i w t)`` on a time grid: the vessel response's block sums of wave components in time
(:meth:`~marinesim.vessel.response.Response.linear_steps`) are products with them.

A component's phasor at ``t = j dt`` is the product of one at a coarse time ``g q dt`` and one at a fine offset
``r dt`` (``j = g q + r``, ``r < q``): ``exp(i w j dt) = exp(i w g q dt) exp(i w r dt)``. With ``q`` about the square
root of the rows, a table of ``rows`` grid times costs ``2 sqrt(rows)`` complex exponentials per component and one
complex product per entry, where computing each entry directly costs a cosine and a sine; each entry carries one
rounding more (about 1e-16 relative, against a sum's own rounding of ``1e-16 sqrt(n)``).
"""

from __future__ import annotations

import math

import numpy as np


def phasor_table(omega: np.ndarray, dt: float, rows: int) -> np.ndarray:
    """``exp(i omega j dt)`` for ``j < rows``: complex (rows, n) for frequencies ``omega`` (n,) rad/s and the step
    ``dt`` (s)."""
    omega = np.asarray(omega, dtype=float).ravel()
    fine = max(1, math.isqrt(max(rows - 1, 0)) + 1)
    coarse = -(-rows // fine)
    near = np.exp(1j * np.outer(np.arange(fine) * dt, omega))               # (fine, n)
    far = np.exp(1j * np.outer(np.arange(coarse) * (fine * dt), omega))     # (coarse, n)
    return (far[:, None, :] * near[None, :, :]).reshape(coarse * fine, omega.size)[:rows]
