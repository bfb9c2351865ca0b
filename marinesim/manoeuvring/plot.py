"""The trials drawn: the turning circles' tracks, the zig-zags' heading and rudder, the crash stop."""

from __future__ import annotations

from pathlib import Path

from marinesim.constants import KNOT
from marinesim.figures import figure, save
from marinesim.manoeuvring.trials import Trials


def plot_trials(result: Trials, path: Path) -> None:
    """A PNG of ``result``: the tracks of both turning circles and the crash stop in ship lengths (north up), the
    10/10 and 20/20 zig-zags' heading and rudder against time, each criterion's value against its limit."""
    length = result.length_m
    fig = figure(12, 10)
    axes = fig.subplots(2, 2, gridspec_kw={"width_ratios": [1, 1.3]})
    track = axes[0, 0]
    for turn, colour in ((result.port, "tab:red"), (result.starboard, "tab:green")):
        r = turn.record
        track.plot(r.east / length, r.north / length, color=colour,
                   label=f"35 deg {('port' if turn.rudder_deg < 0 else 'starboard')}: advance "
                         f"{turn.advance_m / length:.2f} L, tactical diameter "
                         f"{turn.tactical_diameter_m / length:.2f} L")
    if result.stopping is not None:
        r = result.stopping.record
        track.plot(r.east / length, r.north / length, color="k", lw=2,
                   label=f"crash stop: track reach {result.stopping.track_reach_m / length:.2f} L in "
                         f"{result.stopping.time_s:.0f} s")
    track.axhline(0.0, color="0.7", lw=0.8)
    track.axvline(0.0, color="0.7", lw=0.8)
    track.set_aspect("equal", adjustable="datalim")
    track.set_xlabel("east / L (rudder order at the origin, approach northward)")
    track.set_ylabel("north / L")
    track.set_title("turning circles and crash stop (midship)")
    track.legend(fontsize=8, loc="upper left")
    for ax, z in ((axes[0, 1], result.zigzag_10), (axes[1, 1], result.zigzag_20)):
        r = z.record
        ax.plot(r.time, r.heading, color="tab:blue", label="heading change (deg, + starboard)")
        ax.plot(r.time, r.rudder, color="tab:orange", label="rudder (deg, + starboard)")
        for level in (z.heading_deg, -z.heading_deg):
            ax.axhline(level, color="0.6", lw=0.8, ls="--")
        ax.set_title(f"{z.rudder_deg:g}/{z.heading_deg:g} zig-zag: overshoots {z.first_overshoot_deg:.1f} and "
                     f"{z.second_overshoot_deg:.1f} deg")
        ax.set_xlabel("time from the first rudder order (s)")
        ax.set_ylabel("deg")
        ax.legend(fontsize=8, loc="upper right")
        ax.grid(alpha=0.3)
    table = axes[1, 0]
    table.axis("off")
    rows = [[c["name"], f"{c['value']:.2f} {c['unit']}", f"<= {c['limit']:.3g} {c['unit']}",
             "pass" if c["pass"] else "FAIL"] for c in result.criteria]
    cells = table.table(cellText=rows, colLabels=["IMO MSC.137(76)", "value", "limit", ""], loc="center",
                        colWidths=[0.5, 0.18, 0.21, 0.11], cellLoc="left", colLoc="left")
    cells.auto_set_font_size(False)
    cells.set_fontsize(8.5)
    cells.scale(1.0, 1.5)
    for i, c in enumerate(result.criteria, start=1):
        cells[i, 3].set_text_props(color="tab:green" if c["pass"] else "tab:red", weight="bold")
    table.set_title(f"{'all criteria met' if result.passed else 'NOT all criteria met'}: "
                    f"L {length:.0f} m, approach {result.speed_m_s / KNOT:.1f} kn, calm water")
    fig.suptitle(f"{result.name}: standard manoeuvres (IMO MSC.137(76))", fontsize=13)
    fig.tight_layout()
    save(fig, path)
