"""The DP capability envelope as a polar plot."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from marinesim.figures import figure, save
from marinesim.station.capability import MAX_WIND_M_S, Envelope


def plot_capability(result: Envelope, path: Path, name: str, intact: Envelope | None = None) -> None:
    """Draw ``result`` (and the ``intact`` envelope, dashed, when ``result`` has thrusters lost) to ``path`` (PNG):
    the bow up, directions clockwise as on a compass card, the limiting wind (m/s) as the radius."""
    fig = figure(6.4, 6.4)
    ax = fig.add_subplot(projection="polar")
    ax.set_theta_zero_location("N")
    ax.set_theta_direction(-1)

    def closed(envelope: Envelope) -> tuple[np.ndarray, np.ndarray]:
        theta = np.radians(np.r_[envelope.directions_deg, envelope.directions_deg[0]])
        return theta, np.r_[envelope.limiting_wind_m_s, envelope.limiting_wind_m_s[0]]

    if intact is not None:
        ax.plot(*closed(intact), "--", color="0.45", lw=1.2, label="all thrusters")
    theta, wind = closed(result)
    label = f"without {', '.join(result.lost)}" if result.lost else "all thrusters"
    ax.plot(theta, wind, color="tab:blue", lw=2.0, label=label)
    ax.fill(theta, wind, color="tab:blue", alpha=0.15)
    ax.set_ylim(0.0, MAX_WIND_M_S)
    ax.set_rlabel_position(135.0)
    ax.set_xticks(np.radians(np.arange(0, 360, 30)))
    ax.set_xticklabels(["bow"] + [f"{d}" for d in range(30, 360, 30)])
    waves = "with its sea's drift" if result.waves else "no drift table: waves left out"
    ax.set_title(f"DP capability, {name}", fontsize=11, pad=28)
    fig.text(0.5, 0.015, f"limiting mean wind (m/s) from each direction with a 0.75 m/s current; {waves}",
             ha="center", fontsize=8.5)
    ax.legend(loc="upper left", bbox_to_anchor=(-0.12, 1.12), fontsize=9, frameon=False)
    save(fig, path)
