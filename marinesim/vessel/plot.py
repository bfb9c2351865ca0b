"""Pictures of the vessel's data: RAO amplitude and phase, motion time series."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Mapping

import numpy as np

from marinesim.constants import KNOT
from marinesim.figures import figure, save
from marinesim.vessel.rao import DOFS, ROTATIONS, RaoTable
from marinesim.vessel.summary import resonance_periods

if TYPE_CHECKING:
    from matplotlib.figure import Figure


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


PHASE_SHOWN_FROM = 0.05
"""An RAO's phase is drawn where its amplitude is at least this fraction of the DOF's peak over the headings
plotted: the phase of a response near zero is noise."""


def rao_figure(table: RaoTable, headings_deg: list[float], speed_m_s: float = 0.0) -> Figure:
    """Amplitude (m/m, deg/m) and phase (deg, lead) of all six DOFs against period (to :func:`period_axis_end`), one
    curve per relative heading (deg, waves towards: 180 head seas), at ``speed_m_s`` (m/s; the title gives kn).
    The phase is unwrapped along frequency from the long waves and drawn only where the amplitude reaches
    :data:`PHASE_SHOWN_FROM` of the DOF's peak."""
    from matplotlib.ticker import MaxNLocator

    omega = np.geomspace(table.omega[0], table.omega[-1], 400)
    period = 2 * math.pi / omega
    h = np.array([table(omega, np.full(omega.size, math.radians(heading)), speed_m_s) for heading in headings_deg])
    peak = np.abs(h).max(axis=(0, 1))
    fig = figure(9.9, 12.6)
    axes = fig.subplots(6, 2, sharex=True)
    for i, heading in enumerate(headings_deg):
        for j in range(len(DOFS)):
            amp = np.abs(h[i, :, j])
            axes[j, 0].plot(period, amp * (180 / math.pi if j in ROTATIONS else 1.0), label=f"{heading:g} deg")
            shown = amp >= PHASE_SHOWN_FROM * peak[j]
            phase = np.full(omega.size, np.nan)
            phase[shown] = np.degrees(np.unwrap(np.angle(h[i, shown, j])))
            axes[j, 1].plot(period, phase, lw=0.8)
    for j, dof in enumerate(DOFS):
        axes[j, 0].set_ylabel(f"{dof} [{'deg/m' if j in ROTATIONS else 'm/m'}]")
        axes[j, 1].set_ylabel(f"{dof} phase [deg]")
        axes[j, 1].yaxis.set_major_locator(MaxNLocator(nbins=8, steps=[1.8, 4.5, 9.0]))
        for ax in axes[j]:
            ax.grid(alpha=0.3)
    axes[0, 0].legend(title="heading (180 = head)", fontsize=8)
    axes[0, 0].set_title("amplitude", fontsize=8)
    axes[0, 1].set_title(f"phase lead, unwrapped; where the amplitude is {PHASE_SHOWN_FROM:.0%} of the DOF's peak "
                         "or more", fontsize=8)
    for ax in axes[-1]:
        ax.set_xlabel("wave period [s]")
        ax.set_xlim(0.0, period_axis_end(table))
    fig.suptitle(f"RAOs: {Path(table.source).name} ({table.source_format}), {speed_m_s / KNOT:.3g} kn")
    fig.tight_layout()
    return fig


def plot_rao(table: RaoTable, path: Path, headings_deg: list[float], speed_m_s: float = 0.0) -> None:
    """:func:`rao_figure` as a PNG at ``path`` (``speed_m_s`` in m/s)."""
    save(rao_figure(table, headings_deg, speed_m_s), path)


def plot_motions(frame: Mapping[str, np.ndarray], path: Path, title: str) -> None:
    """Wave elevation, heave, roll and pitch against time (columns of a motion frame)."""
    rows = [("wave_elevation_m", "wave elevation [m]"), ("heave_m", "heave [m]"), ("roll_deg", "roll [deg]"),
            ("pitch_deg", "pitch [deg]")]
    fig = figure(10.8, 8.1)
    axes = fig.subplots(len(rows), 1, sharex=True)
    for ax, (column, label) in zip(axes, rows):
        ax.plot(frame["time_s"], frame[column], lw=0.7)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("time [s]")
    axes[0].set_title(title)
    fig.tight_layout()
    save(fig, path)
