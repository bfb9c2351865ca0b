"""Pictures of the vessel's data: RAO amplitude and phase, motion time series."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Mapping

import numpy as np

from marinesim.vessel.rao import DOFS, ROTATIONS, RaoTable
from marinesim.vessel.summary import resonance_periods


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


PERIOD_SHOWN_S = 30.0
"""The period axis of an RAO plot ends here (s), where ocean waves carry little energy, unless a resonance lies
beyond it (:func:`period_axis_end`)."""


def period_axis_end(table: RaoTable) -> float:
    """Where an RAO plot's period axis ends (s): :data:`PERIOD_SHOWN_S`, or 1.5 times the longest heave, roll or
    pitch resonance period if that is longer, never beyond the table's longest period (a table to 160 s would
    otherwise squeeze the 5-25 s where the waves are into the plot's left edge)."""
    longest = 2 * math.pi / table.omega[0]
    resonances = [p for p in resonance_periods(table).values() if p is not None]
    return min(max(PERIOD_SHOWN_S, 1.5 * max(resonances, default=0.0)), longest)


def plot_rao(table: RaoTable, path: Path, headings_deg: list[float], speed: float = 0.0) -> None:
    """Amplitude (m/m, deg/m) and phase (deg, lead) of all six DOFs against period (to
    :func:`period_axis_end`), one curve per relative heading (deg, waves towards: 180 head seas), at ``speed``
    (m/s)."""
    plt = _pyplot()
    omega = np.geomspace(table.omega[0], table.omega[-1], 400)
    period = 2 * math.pi / omega
    fig, axes = plt.subplots(6, 2, figsize=(11, 14), sharex=True)
    for heading in headings_deg:
        h = table(omega, np.full(omega.size, math.radians(heading)), speed)
        for j, dof in enumerate(DOFS):
            scale = 180 / math.pi if j in ROTATIONS else 1.0
            axes[j, 0].plot(period, np.abs(h[:, j]) * scale, label=f"{heading:g} deg")
            amp = np.abs(h[:, j])
            phase = np.where(amp > 0.01 * amp.max(), np.degrees(np.angle(h[:, j])), np.nan)  # noise where ~0
            axes[j, 1].plot(period, phase, lw=0.8)
    for j, dof in enumerate(DOFS):
        axes[j, 0].set_ylabel(f"{dof} [{'deg/m' if j in ROTATIONS else 'm/m'}]")
        axes[j, 1].set_ylabel(f"{dof} phase [deg]")
        axes[j, 1].set_ylim(-180, 180)
        for ax in axes[j]:
            ax.grid(alpha=0.3)
    axes[0, 0].legend(title="heading (180 = head)", fontsize=8)
    for ax in axes[-1]:
        ax.set_xlabel("wave period [s]")
        ax.set_xlim(0.0, period_axis_end(table))
    fig.suptitle(f"RAOs: {Path(table.source).name} ({table.source_format}), {speed:.3g} m/s")
    fig.tight_layout()
    fig.savefig(path, dpi=90, format="png")
    plt.close(fig)


def plot_motions(frame: Mapping[str, np.ndarray], path: Path, title: str) -> None:
    """Wave elevation, heave, roll and pitch against time (columns of a motion frame)."""
    plt = _pyplot()
    rows = [("wave_elevation_m", "wave elevation [m]"), ("heave_m", "heave [m]"), ("roll_deg", "roll [deg]"),
            ("pitch_deg", "pitch [deg]")]
    fig, axes = plt.subplots(len(rows), 1, figsize=(12, 9), sharex=True)
    for ax, (column, label) in zip(axes, rows):
        ax.plot(frame["time_s"], frame[column], lw=0.7)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("time [s]")
    axes[0].set_title(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90, format="png")
    plt.close(fig)
