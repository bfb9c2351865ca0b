"""What an RAO table holds, checked against physics: ranges, long-wave limits, resonances."""

from __future__ import annotations

import math

import numpy as np

from marinesim.constants import KNOT
from marinesim.vessel.rao import DOFS, MAX_HEADING_GAP, RaoTable, long_wave_limit

LIMIT_TOLERANCE = 0.15
"""A long-wave ratio within this of 1 is reported ``ok``; otherwise ``check`` (units, ULEN, depth...) or,
next to a resonance, :data:`RESONANCE_NEAR_END`."""
RESONANCE_NEAR_END = "resonance near the table's end"
"""Status of a ratio off by more than :data:`LIMIT_TOLERANCE` next to a resonance (:func:`long_wave_check`):
the lowest tabulated frequency is not yet in the long-wave range, so the ratio says nothing of the units."""
RESONANCE_SPAN = 2.0
"""A resonance within this factor of the table's longest period (either side) explains an off ratio."""
FIT_POINTS = 3
"""Lowest frequencies through which the oscillator model finds a resonance beyond the table's end."""
RESONANCE_HEADINGS = {"heave": 90.0, "roll": 90.0, "pitch": 180.0}
"""Relative heading (deg) at which each DOF's resonance shows best."""
CHECK_HEADINGS = {"surge": math.pi, "sway": math.pi / 2, "heave": None, "roll": math.pi / 2, "pitch": math.pi}
"""Relative heading (rad) at which each DOF's long-wave ratio is taken; None: mean over the table's."""


def long_wave_check(table: RaoTable) -> dict[str, dict]:
    """Ratio of |H| to :func:`long_wave_limit` (in the table's water depth) at the lowest tabulated
    frequency w0 (first speed).

    Surge and pitch in head seas, sway and roll in beam seas (waves towards port), heave as the
    mean over all headings; yaw has limit 0 and is not checked, nor is a DOF whose heading a partial table
    does not cover. A ratio within
    :data:`LIMIT_TOLERANCE` of 1 is ``ok``. One further off is :data:`RESONANCE_NEAR_END` (with
    ``resonance_period_s``) where the DOF's ratio, taken at every tabulated frequency, shows a
    resonance wn within :data:`RESONANCE_SPAN` of w0 (:func:`_resonance_near_end`), else ``check``.
    """
    omega = table.omega
    out = {}
    for dof, beta in CHECK_HEADINGS.items():
        if beta is not None and not table.covers(np.array([beta]))[0]:
            out[dof] = {"ratio": None, "status": f"not tabulated at {math.degrees(beta):g} deg"}
            continue
        ratio = _ratio_curve(table, dof, beta)
        entry: dict = {"ratio": float(ratio[0]), "status": "ok" if abs(ratio[0] - 1.0) <= LIMIT_TOLERANCE else "check"}
        natural = _resonance_near_end(omega, ratio) if entry["status"] == "check" else None
        if natural is not None:
            entry.update(status=RESONANCE_NEAR_END, resonance_period_s=2 * math.pi / natural)
        out[dof] = entry
    out["yaw"] = {"ratio": None, "status": "n/a"}
    return {"omega_rad_s": float(omega[0]), "period_s": 2 * math.pi / float(omega[0]), **out}


def _ratio_curve(table: RaoTable, dof: str, beta: float | None) -> np.ndarray:
    """|H| / |long-wave limit| of ``dof`` at every tabulated frequency (first speed), shape (n,)."""
    j = DOFS.index(dof)
    omega = table.omega
    if beta is None:  # heave: limit 1, mean over the tabulated headings
        return np.mean(np.abs(table.values[0, :, :, j]), axis=0)
    headings = np.full(omega.size, beta)
    limit = np.abs(long_wave_limit(omega, headings, table.g, table.depth)[:, j])
    return np.abs(table(omega, headings, table.speed[0])[:, j]) / limit


def _resonance_near_end(omega: np.ndarray, ratio: np.ndarray) -> float | None:
    """Natural frequency (rad/s) of a resonance within :data:`RESONANCE_SPAN` of ``omega[0]``, or None.

    Inside the table: the first peak of ``ratio`` (an amplification: above ``1 + LIMIT_TOLERANCE``)
    at most :data:`RESONANCE_SPAN` times ``omega[0]``, refined by a parabola. Beyond its end: a
    single-DOF oscillator, whose ratio is ``c / |1 - w^2 / wn^2|`` in long waves, so
    ``1 / ratio = a + b w^2``, fitted over the lowest :data:`FIT_POINTS` frequencies where the
    ratio, amplified at ``omega[0]`` (above ``1 + LIMIT_TOLERANCE``), falls monotonically, with
    ``a < 0 < b`` (above the resonance) and ``wn = sqrt(-a / b)`` at least ``omega[0] / RESONANCE_SPAN``.
    """
    peaks = np.flatnonzero((ratio[1:-1] > ratio[:-2]) & (ratio[1:-1] >= ratio[2:])) + 1
    peaks = peaks[(omega[peaks] <= RESONANCE_SPAN * omega[0]) & (ratio[peaks] > 1.0 + LIMIT_TOLERANCE)]
    if peaks.size:
        return _vertex(omega, ratio, int(peaks[0]))
    falling = np.flatnonzero(np.diff(ratio) >= 0.0)
    end = min(FIT_POINTS, int(falling[0]) + 1 if falling.size else omega.size)
    if end < 2 or ratio[0] <= 1.0 + LIMIT_TOLERANCE or not np.all(ratio[:end] > 0.0):
        return None
    slope, intercept = np.polyfit(omega[:end] ** 2, 1.0 / ratio[:end], 1)
    if not intercept < 0.0 < slope:
        return None
    natural = math.sqrt(-intercept / slope)
    return natural if natural >= omega[0] / RESONANCE_SPAN else None


def _vertex(omega: np.ndarray, amp: np.ndarray, i: int) -> float:
    """Frequency (rad/s) of the vertex of the parabola through ``amp`` at ``i - 1, i, i + 1``
    (``omega[i]`` where it opens upwards)."""
    w0, w1, w2 = omega[i - 1:i + 2]
    a0, a1, a2 = amp[i - 1:i + 2]
    denominator = (w0 - w1) * (w0 - w2) * (w1 - w2)
    a = (w2 * (a1 - a0) + w1 * (a0 - a2) + w0 * (a2 - a1)) / denominator
    b = (w2 ** 2 * (a0 - a1) + w1 ** 2 * (a2 - a0) + w0 ** 2 * (a1 - a2)) / denominator
    return float(-b / (2 * a) if a < 0 else w1)


def resonance_periods(table: RaoTable) -> dict[str, float | None]:
    """Period (s) of the largest interior peak of |H| for heave, roll and pitch at zero/first speed,
    refined by a parabola through the peak and its neighbours; None where there is no peak, or where a
    partial table does not cover the DOF's heading."""
    out: dict[str, float | None] = {}
    for dof, heading in RESONANCE_HEADINGS.items():
        j = DOFS.index(dof)
        if not table.covers(np.array([math.radians(heading)]))[0]:
            out[dof] = None
            continue
        amp = np.abs(table(table.omega, np.full(table.omega.size, math.radians(heading)), table.speed[0])[:, j])
        inner = np.flatnonzero((amp[1:-1] > amp[:-2]) & (amp[1:-1] >= amp[2:])) + 1
        if inner.size == 0:
            out[dof] = None
            continue
        i = int(inner[np.argmax(amp[inner])])
        peak = _vertex(table.omega, amp, i)
        out[dof] = float(2 * math.pi / peak)
    return out


def rao_summary(table: RaoTable) -> dict:
    """A JSON-ready summary of ``table``."""
    return {
        "source": table.source,
        "format": table.source_format,
        "dofs": list(DOFS),
        "frequencies": int(table.omega.size),
        "omega_rad_s": [float(table.omega[0]), float(table.omega[-1])],
        "period_s": [float(2 * math.pi / table.omega[-1]), float(2 * math.pi / table.omega[0])],
        "headings": int(table.beta.size),
        "heading_step_deg": _heading_step_deg(table),
        "headings_covered": None if table.covered is None else table.covered_text(),
        "mirrored_from_half_range": table.mirrored,
        "speeds_kn": [float(s / KNOT) for s in table.speed],
        "reference_point_m": list(table.reference_point),
        "water_depth_m": None if math.isinf(table.depth) else table.depth,
        "rho_kg_m3": table.rho,
        "g_m_s2": table.g,
        "long_wave_limits": long_wave_check(table),
        "resonance_period_s": resonance_periods(table),
        "notes": list(table.notes),
    }


def _heading_step_deg(table: RaoTable) -> float | None:
    """The widest step between tabulated headings that interpolation bridges (deg); None for a single heading."""
    steps = np.diff(np.append(table.beta, table.beta[0] + 2 * math.pi))
    bridged = steps[steps <= MAX_HEADING_GAP + 1e-9]
    return float(np.degrees(bridged.max())) if bridged.size else None


def format_rao_summary(s: dict) -> str:
    """Human-readable form of :func:`rao_summary`."""
    lines = [f"RAO table   {s['source']} ({s['format']})",
             f"DOFs        {', '.join(s['dofs'])}",
             f"frequencies {s['frequencies']}: {s['omega_rad_s'][0]:.4g}..{s['omega_rad_s'][1]:.4g} rad/s "
             f"(periods {s['period_s'][0]:.3g}..{s['period_s'][1]:.4g} s)",
             (f"headings    {s['headings']} over the circle, step <= {s['heading_step_deg']:g} deg"
              + (" (0..180 mirrored to port)" if s["mirrored_from_half_range"] else "")
              if s["headings_covered"] is None else
              f"headings    {s['headings']}, a partial table: it covers {s['headings_covered']} only"),
             f"speeds      {', '.join(f'{v:.3g}' for v in s['speeds_kn'])} kn",
             f"reference   {', '.join(f'{v:g}' for v in s['reference_point_m'])} m; rho {s['rho_kg_m3']:g} kg/m^3, "
             f"g {s['g_m_s2']:g} m/s^2; water depth "
             + ("deep" if s["water_depth_m"] is None else f"{s['water_depth_m']:g} m")]
    limits = s["long_wave_limits"]
    lines.append(f"long-wave limits at T = {limits['period_s']:.4g} s (|H| / limit):")
    for dof in s["dofs"]:
        entry = limits[dof]
        value = "   -  " if entry["ratio"] is None else f"{entry['ratio']:6.3f}"
        fitted = f" (T {entry['resonance_period_s']:.3g} s)" if entry["status"] == RESONANCE_NEAR_END else ""
        lines.append(f"  {dof:6s} {value}  {entry['status']}{fitted}")
    lines.append("resonance periods: " + ", ".join(
        f"{dof} {'none' if period is None else f'{period:.3g} s'}" for dof, period in s["resonance_period_s"].items()))
    lines += [f"note: {note}" for note in s["notes"]]
    return "\n".join(lines)
