"""What an RAO table holds, checked against physics: ranges, long-wave limits, resonances."""

from __future__ import annotations

import math

import numpy as np

from marinesim.constants import KNOT
from marinesim.vessel.rao import DOFS, RaoTable, long_wave_limit

LIMIT_TOLERANCE = 0.15
"""A long-wave ratio within this of 1 is reported ``ok``; otherwise ``check`` (units, ULEN...)."""
RESONANCE_HEADINGS = {"heave": 90.0, "roll": 90.0, "pitch": 180.0}
"""Relative heading (deg) at which each DOF's resonance shows best."""


def long_wave_check(table: RaoTable) -> dict[str, dict]:
    """Ratio of |H| to :func:`long_wave_limit` at the lowest tabulated frequency (first speed).

    Surge and pitch in head seas, sway and roll in beam seas (waves towards port), heave as the
    mean over all headings; yaw has limit 0 and is not checked.
    """
    omega = float(table.omega[0])
    headings = np.array([math.pi, math.pi / 2])
    (head, beam) = np.abs(table(np.full(2, omega), headings, table.speed[0]))
    limit_head, limit_beam = np.abs(long_wave_limit(np.full(2, omega), headings, table.g))
    heave = float(np.mean(np.abs(table.values[0, :, 0, 2])))
    ratios = {"surge": head[0] / limit_head[0], "sway": beam[1] / limit_beam[1], "heave": heave,
              "roll": beam[3] / limit_beam[3], "pitch": head[4] / limit_head[4]}
    out = {}
    for dof, ratio in ratios.items():
        out[dof] = {"ratio": float(ratio), "status": "ok" if abs(ratio - 1.0) <= LIMIT_TOLERANCE else "check"}
    out["yaw"] = {"ratio": None, "status": "n/a"}
    return {"omega_rad_s": omega, "period_s": 2 * math.pi / omega, **out}


def resonance_periods(table: RaoTable) -> dict[str, float | None]:
    """Period (s) of the largest interior peak of |H| for heave, roll and pitch at zero/first speed,
    refined by a parabola through the peak and its neighbours; None where there is no peak."""
    out: dict[str, float | None] = {}
    for dof, heading in RESONANCE_HEADINGS.items():
        j = DOFS.index(dof)
        amp = np.abs(table(table.omega, np.full(table.omega.size, math.radians(heading)), table.speed[0])[:, j])
        inner = np.flatnonzero((amp[1:-1] > amp[:-2]) & (amp[1:-1] >= amp[2:])) + 1
        if inner.size == 0:
            out[dof] = None
            continue
        i = int(inner[np.argmax(amp[inner])])
        w0, w1, w2 = table.omega[i - 1:i + 2]
        a0, a1, a2 = amp[i - 1:i + 2]
        denominator = (w0 - w1) * (w0 - w2) * (w1 - w2)
        # vertex of the parabola through the three points
        a = (w2 * (a1 - a0) + w1 * (a0 - a2) + w0 * (a2 - a1)) / denominator
        b = (w2 ** 2 * (a0 - a1) + w1 ** 2 * (a2 - a0) + w0 ** 2 * (a1 - a2)) / denominator
        peak = -b / (2 * a) if a < 0 else w1
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
        "heading_step_deg": float(np.degrees(np.max(np.diff(np.append(table.beta, table.beta[0] + 2 * math.pi))))),
        "mirrored_from_half_range": table.mirrored,
        "speeds_kn": [float(s / KNOT) for s in table.speed],
        "reference_point_m": list(table.reference_point),
        "rho_kg_m3": table.rho,
        "g_m_s2": table.g,
        "long_wave_limits": long_wave_check(table),
        "resonance_period_s": resonance_periods(table),
        "notes": list(table.notes),
    }


def format_rao_summary(s: dict) -> str:
    """Human-readable form of :func:`rao_summary`."""
    lines = [f"RAO table   {s['source']} ({s['format']})",
             f"DOFs        {', '.join(s['dofs'])}",
             f"frequencies {s['frequencies']}: {s['omega_rad_s'][0]:.4g}..{s['omega_rad_s'][1]:.4g} rad/s "
             f"(periods {s['period_s'][0]:.3g}..{s['period_s'][1]:.4g} s)",
             f"headings    {s['headings']} over the circle, step <= {s['heading_step_deg']:g} deg"
             + (" (0..180 mirrored to port)" if s["mirrored_from_half_range"] else ""),
             f"speeds      {', '.join(f'{v:.3g}' for v in s['speeds_kn'])} kn",
             f"reference   {', '.join(f'{v:g}' for v in s['reference_point_m'])} m; rho {s['rho_kg_m3']:g} kg/m^3, "
             f"g {s['g_m_s2']:g} m/s^2"]
    limits = s["long_wave_limits"]
    lines.append(f"long-wave limits at T = {limits['period_s']:.4g} s (|H| / limit):")
    for dof in s["dofs"]:
        entry = limits[dof]
        value = "   -  " if entry["ratio"] is None else f"{entry['ratio']:6.3f}"
        lines.append(f"  {dof:6s} {value}  {entry['status']}")
    lines.append("resonance periods: " + ", ".join(
        f"{dof} {'none' if period is None else f'{period:.3g} s'}" for dof, period in s["resonance_period_s"].items()))
    lines += [f"note: {note}" for note in s["notes"]]
    return "\n".join(lines)
