"""The pictures of an operability study (PNG bytes, :mod:`marinesim.figures`): operability per heading
on a polar plot, the limiting-Hs curves over the scatter diagram, and the criterion that governs each
(heading, Tp). Headings are the RAO convention's relative wave directions: 180 head seas, drawn at the top."""

from __future__ import annotations

import math

import numpy as np

from marinesim import figures
from marinesim.study.operability import Operability
from marinesim.study.scatter import Scatter


def _figure(width_in: float, height_in: float, polar: bool = False):
    """A figure ``width_in`` x ``height_in`` (in) with one axes, polar or not."""
    figure = figures.figure(width_in, height_in)
    return figure, figure.add_subplot(projection="polar" if polar else None)


def polar_plot(result: Operability, title: str) -> bytes:
    """Operability (%) against the relative wave heading: 180 deg (head seas) at the top, 90 (waves
    travelling to port, from starboard) to the right, as a bridge officer pictures the sea on the bow."""
    figure, ax = _figure(6.16, 6.16, polar=True)
    theta = np.radians(np.append(result.headings_deg, result.headings_deg[0]))
    r = np.append(result.operability_pct, result.operability_pct[0])
    ax.set_theta_zero_location("S")
    ax.set_theta_direction(1)
    ax.plot(theta, r, color="#1f5fa8", linewidth=2.0)
    ax.fill(theta, r, color="#1f5fa8", alpha=0.18)
    best = int(np.argmax(result.operability_pct))
    ax.plot([np.radians(result.headings_deg[best])], [result.operability_pct[best]], "o", color="#c0392b")
    ax.set_ylim(0, 100)
    ax.set_yticks([25, 50, 75, 100], labels=["25 %", "50 %", "75 %", "100 %"], fontsize=8)
    ax.set_xticks(np.radians(np.arange(0, 360, 30)),
                  labels=[f"{d}°" + (" following" if d == 0 else " head" if d == 180 else "")
                          for d in range(0, 360, 30)], fontsize=8)
    ax.set_title(f"{title}: operability by wave heading\n{result.overall_pct:.1f} % with the best heading in "
                 f"each sea state; best single heading {result.best_heading_deg:g}° "
                 f"({result.operability_pct[best]:.1f} %)", fontsize=9)
    figure.tight_layout()
    return figures.png(figure)


def limiting_hs_plot(result: Operability, scatter: Scatter, cell_tp: np.ndarray, title: str,
                     headings: int = 5) -> bytes:
    """The scatter diagram's probabilities (shaded cells, Hs against Tp) under the operation's limiting-Hs
    curves at up to ``headings`` headings spread over the study's range (the sea states below a curve are
    workable at that heading)."""
    figure, ax = _figure(8.25, 5.5)
    hs_values, tp_values = np.unique(scatter.hs), np.unique(cell_tp)
    grid = np.zeros((hs_values.size, tp_values.size))
    np.add.at(grid, (np.searchsorted(hs_values, scatter.hs), np.searchsorted(tp_values, cell_tp)),
              scatter.probability)
    shade = ax.pcolormesh(_edges(tp_values), _edges(hs_values), np.ma.masked_equal(grid, 0.0) * 100,
                          cmap="Blues", vmin=0.0, vmax=1.6 * grid.max() * 100, shading="flat")
    figure.colorbar(shade, ax=ax, label="occurrence (%)", pad=0.02)
    chosen = np.unique(np.linspace(0, result.headings_deg.size - 1, min(headings, result.headings_deg.size))
                       .round().astype(int))
    colours = ["#1f5fa8", "#c0392b", "#27864a", "#d68910", "#7d3c98", "#17a2b8"]
    for colour, index in zip(colours * 2, chosen):
        limit = np.minimum(result.limiting_hs_all[index], hs_values.max() * 1.5)
        ax.plot(result.tp, limit, color=colour, linewidth=2.0, marker="o", markersize=3,
                label=f"{result.headings_deg[index]:g}°: {result.operability_pct[index]:.1f} %")
    ax.set_ylim(0, hs_values.max() + 0.5)
    ax.set_xlim(tp_values.min() - 0.5, tp_values.max() + 0.5)
    ax.set_xlabel("peak period Tp (s)")
    ax.set_ylabel("significant wave height Hs (m)")
    ax.grid(alpha=0.3)
    ax.legend(title="heading: operability", fontsize=8, title_fontsize=8, loc="upper left")
    ax.set_title(f"{title}: limiting Hs over the scatter diagram ", fontsize=9)
    figure.tight_layout()
    return figures.png(figure)


def governing_plot(result: Operability, names: list[str], title: str) -> bytes:
    """Which criterion sets the limit at each (Tp, heading), as a coloured table with its limiting Hs."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    figure, ax = _figure(8.25, max(2.86, 1.32 + 0.264 * result.headings_deg.size))
    colours = ListedColormap(["#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#b07aa1", "#edc948", "#76b7b2",
                              "#9c755f"][:max(len(names), 1)])
    ax.pcolormesh(_edges(result.tp), _edges(result.headings_deg), result.governing, cmap=colours,
                  vmin=-0.5, vmax=len(names) - 0.5, shading="flat")
    if result.tp.size * result.headings_deg.size <= 400:
        for i, heading in enumerate(result.headings_deg):
            for j, tp in enumerate(result.tp):
                hs = result.limiting_hs_all[i, j]
                ax.text(tp, heading, "-" if not np.isfinite(hs) else f"{hs:.1f}", ha="center", va="center",
                        fontsize=6, color="white")
    handles = [Patch(color=colours(k), label=name) for k, name in enumerate(names)]
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    if result.headings_deg.size <= 24:
        ax.set_yticks(result.headings_deg, labels=[f"{h:g}" for h in result.headings_deg], fontsize=7)
    shown = result.tp[::max(1, int(math.ceil(result.tp.size / 12)))]
    ax.set_xticks(shown, labels=[f"{t:g}" for t in shown], fontsize=7)
    ax.set_xlabel("peak period Tp (s)")
    ax.set_ylabel("relative heading (deg)")
    ax.set_title(f"{title}: governing criterion and limiting Hs (m)", fontsize=9)
    figure.tight_layout()
    return figures.png(figure)


def _edges(centres: np.ndarray) -> np.ndarray:
    """Cell edges around sorted ``centres`` (midpoints; the outer cells as wide as their neighbours)."""
    centres = np.asarray(centres, float)
    if centres.size == 1:
        return np.array([centres[0] - 0.5, centres[0] + 0.5])
    mid = 0.5 * (centres[:-1] + centres[1:])
    return np.concatenate([[2 * centres[0] - mid[0]], mid, [2 * centres[-1] - mid[-1]]])
