"""One plotting style (marinesim/figures.py): every plot is a matplotlib ``Figure`` written at one dpi with no version
or date in the file, so the same plot gives the same bytes; no module uses pyplot or picks a backend, so a notebook
that draws the package's plots keeps its own backend."""

from __future__ import annotations

import ast
import io
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from conftest import ROOT
from marinesim import figures

PACKAGE = ROOT / "marinesim"
NOTEBOOK_BACKEND = "svg"
"""A backend the package would never pick itself, standing in for a notebook's inline backend."""


def _sample_figure():
    """A figure with text, a clip path and an image: what a plot holds."""
    plot = figures.figure(2.0, 1.5)
    ax = plot.subplots()
    ax.plot([0.0, 1.0, 2.0], [0.0, 1.0, 0.5], label="a line")
    ax.imshow(np.arange(12.0).reshape(3, 4), extent=(0.0, 2.0, 0.0, 1.0))
    ax.set_title("a title")
    ax.legend()
    return plot


@pytest.mark.parametrize("file_format", sorted(figures.METADATA))
def test_the_same_figure_saved_twice_is_the_same_bytes(file_format):
    """If this fails, a saved plot carries something that changes between writes: the time of writing (PDF, SVG),
    or the SVG's ids salted afresh each time; and the file names the matplotlib version that wrote it."""
    plot = _sample_figure()
    first, second, rebuilt = io.BytesIO(), io.BytesIO(), io.BytesIO()
    figures.save(plot, first, file_format)
    figures.save(plot, second, file_format)
    figures.save(_sample_figure(), rebuilt, file_format)
    assert first.getvalue() == second.getvalue() == rebuilt.getvalue()
    import matplotlib

    assert matplotlib.__version__.encode() not in first.getvalue()
    assert b"CreationDate" not in first.getvalue() and b"<dc:date>" not in first.getvalue()


def test_a_png_is_written_at_the_projects_dpi_without_text_chunks():
    """A figure 2 x 1.5 in is 200 x 150 px at 100 dpi, and its PNG has no ``Software`` (or any other) text."""
    image = Image.open(io.BytesIO(figures.png(_sample_figure())))
    assert figures.DPI == 100 and image.size == (200, 150)
    assert image.text == {}
    assert image.info["dpi"] == pytest.approx((figures.DPI, figures.DPI), abs=0.01)


def test_a_format_without_a_metadata_policy_is_refused():
    with pytest.raises(ValueError, match="png, pdf, svg"):
        figures.save(_sample_figure(), io.BytesIO(), "jpg")


def global_matplotlib_uses(source: str) -> list[str]:
    """What ``source`` does to matplotlib's global state: imports of pyplot (or pylab), calls of
    ``matplotlib.use`` (however imported); each as ``line: what``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found += [f"{node.lineno}: import {a.name}" for a in node.names
                      if a.name.startswith(("matplotlib.pyplot", "matplotlib.pylab", "pylab"))]
        elif isinstance(node, ast.ImportFrom) and node.module:
            if node.module.startswith(("matplotlib.pyplot", "matplotlib.pylab", "pylab")):
                found.append(f"{node.lineno}: from {node.module} import ...")
            elif node.module == "matplotlib":
                found += [f"{node.lineno}: from matplotlib import {a.name}" for a in node.names
                          if a.name in ("pyplot", "pylab", "use")]
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "use"
              and isinstance(node.func.value, ast.Name) and node.func.value.id in ("matplotlib", "mpl")):
            found.append(f"{node.lineno}: {node.func.value.id}.use(...)")
    return sorted(found, key=lambda use: int(use.split(":")[0]))


@pytest.mark.parametrize("source", ["import matplotlib.pyplot as plt", "from matplotlib import pyplot",
                                    "import matplotlib\nmatplotlib.use('Agg')", "from matplotlib import use",
                                    "def f():\n    import matplotlib as mpl\n    mpl.use('Agg')"])
def test_the_scan_finds_pyplot_and_a_chosen_backend(source):
    """The scan below can fail: pyplot imported or a backend chosen, at module level or inside a function."""
    assert global_matplotlib_uses(source)


def test_no_module_uses_pyplot_or_chooses_a_backend():
    """If this fails, a module imports pyplot (a global list of figures, a backend chosen on import) or calls
    ``matplotlib.use`` (a notebook user's backend switched under them): draw on ``marinesim.figures.figure``."""
    found = {str(path.relative_to(ROOT)): uses for path in sorted(PACKAGE.rglob("*.py"))
             if (uses := global_matplotlib_uses(path.read_text(encoding="utf-8")))}
    assert not found, found


def _record(n: int = 50):
    """A manoeuvre's time series: a quarter circle of 500 m radius at 5 m/s, the rudder hard over."""
    from marinesim.manoeuvring.trials import Record

    t = np.linspace(0.0, 157.0, n)
    angle = t / 100.0
    return Record(t, 500.0 * np.sin(angle), 500.0 * (1.0 - np.cos(angle)), np.degrees(angle), np.full(n, 35.0),
                  np.full(n, 5.0), 5.0 * t)


def draw_every_plot(folder: Path) -> None:
    """Every plot of the package once, on small hand-made data, written into ``folder``."""
    from conftest import synthetic_table
    from marinesim.criteria.monitor import Level
    from marinesim.manoeuvring.plot import plot_trials
    from marinesim.manoeuvring.trials import Stopping, Trials, Turning, Zigzag
    from marinesim.report import plots as report
    from marinesim.report.debrief import CriterionTrace, Series
    from marinesim.sea import Cos2s, Jonswap, Ocean, SeaState, WaveSystem
    from marinesim.sea.plot import plot_sea, plot_series
    from marinesim.station.capability import Envelope
    from marinesim.station.plot import plot_capability
    from marinesim.study import plots as study
    from marinesim.study.operability import operability
    from marinesim.study.scatter import Scatter
    from marinesim.vessel.plot import plot_motions, plot_rao
    from marinesim.wake.compute import Wake
    from marinesim.wake.plot import plot_wake

    sea = SeaState((WaveSystem(Jonswap(3.0, 8.0, 3.3), 1.0, Cos2s(10.0)),))
    plot_sea(Ocean(sea, seed=3, tile_count=2, resolution=32, threads=1), folder / "sea.png")
    t = np.linspace(0.0, 60.0, 121)
    plot_series(t, np.sin(t), "elevation [m]", "a series", folder / "series.png")

    y, x = np.indices((32, 64))
    field = np.cos(0.3 * x + 0.2 * y).astype(np.float32)
    plot_wake(Wake(field, np.zeros_like(field), x[0] * 5.0 - 250.0, (y[:, 0] - 16) * 5.0, np.linspace(1.0, 3.0, 20),
                   np.ones(20, complex), {"bow_x_m": 60.0, "speed_kn": 10.0, "froude": 0.2, "wave_resistance_N": 1e5,
                                          "hull_source": "x.stl"}), folder / "wake.png")

    directions = tuple(float(d) for d in range(0, 360, 30))
    intact = Envelope(directions, tuple(20.0 + 5.0 * math.cos(math.radians(2 * d)) for d in directions), (), False)
    lost = Envelope(directions, tuple(0.7 * w for w in intact.limiting_wind_m_s), ("bow tunnel",), False)
    plot_capability(lost, folder / "capability.png", "a supply vessel", intact)

    turn = Turning(35.0, 480.0, 220.0, 510.0, 450.0, 6.0, _record())
    zigzag = Zigzag(10.0, 10.0, 5.0, 12.0, 400.0, _record())
    criteria = [{"name": "advance, port", "value": 2.0, "unit": "L", "limit": 4.5, "pass": True}]
    plot_trials(Trials("a ship", 200.0, 7.7, turn, turn, zigzag, zigzag, Stopping(1500.0, 1400.0, 400.0, _record()),
                       criteria), folder / "trials.png")

    table, _ = synthetic_table()
    plot_rao(table, folder / "rao.png", [180.0, 90.0])
    plot_motions({"time_s": t, "wave_elevation_m": np.sin(t), "heave_m": np.cos(t), "roll_deg": t / 60.0,
                  "pitch_deg": -t / 60.0}, folder / "motions.png", "motions")

    hs, tp = np.meshgrid([1.0, 2.0, 3.0], [6.0, 9.0, 12.0], indexing="ij")
    scatter = Scatter(hs.ravel(), tp.ravel(), np.arange(1.0, 10.0) / 45.0, "tp")
    limiting = np.array([0.5, 4.0]) / np.linspace(0.05, 3.0, 12).reshape(3, 2, 2)
    result = operability(limiting, np.array([6.0, 9.0, 12.0]), np.array([90.0, 180.0]), scatter, scatter.period)
    pictures = {"polar.png": study.polar_plot(result, "a study"),
                "limiting_hs.png": study.limiting_hs_plot(result, scatter, scatter.period, "a study"),
                "governing.png": study.governing_plot(result, ["heave", "roll"], "a study")}

    ship = {"name": "a ship", "time_s": t.tolist(), "north_m": (5.0 * t).tolist(), "east_m": np.zeros_like(t).tolist(),
            "heading_deg": np.zeros_like(t).tolist(), "speed_over_ground_kn": np.full(t.size, 9.7).tolist(),
            "rudder_deg": np.sin(t).tolist(), "rudder_order_deg": np.zeros_like(t).tolist(),
            "propeller_rpm": np.full(t.size, 80.0).tolist()}
    criterion = CriterionTrace(name="roll", point=None, quantity="roll_max_deg", unit="deg", window_s=10.0, value=2.5,
                               value_at_s=15.7, limit=2.0, caution=0.8, exceeded=True, time_exceeded_s=24.0,
                               first_exceeded_s=9.0, level=Level.EXCEEDED, judged=True,
                               series=Series(t.tolist(), np.abs(2.5 * np.sin(t / 10.0)).tolist()))
    pictures |= {"track.png": report.track_png(ship, [], []), "handling.png": report.handling_png(ship, [], 60.0),
                 "timeline.png": report.timeline_png(60.0, [], [], [], []),
                 "criterion.png": report.criterion_png(criterion, 60.0, [], [])}
    for name, data in pictures.items():
        (folder / name).write_bytes(data)


def test_drawing_every_plot_leaves_a_notebooks_backend_alone(tmp_path):
    """If this fails, drawing one of the package's plots switched the backend a notebook had chosen (its inline
    figures would stop showing), or imported pyplot (figures kept in its global list). In a fresh process with
    its own backend chosen first, as a notebook has, every plot module is imported and used."""
    script = "\n".join([
        "import json, sys", "from pathlib import Path", "import matplotlib", f"matplotlib.use({NOTEBOOK_BACKEND!r})",
        "import test_figures", f"test_figures.draw_every_plot(Path({str(tmp_path)!r}))",
        "print(json.dumps({'backend': matplotlib.get_backend(), 'pyplot': 'matplotlib.pyplot' in sys.modules}))"])
    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    env |= {"MARINESIM_CACHE_DIR": str(tmp_path / "cache"),
            "PYTHONPATH": os.pathsep.join([str(ROOT / "tests"), str(ROOT)])}
    done = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    state = json.loads(done.stdout.strip().splitlines()[-1])
    assert state == {"backend": NOTEBOOK_BACKEND, "pyplot": False}
    drawn = {p.name for p in tmp_path.glob("*.png")}
    assert drawn == {"sea.png", "series.png", "wake.png", "capability.png", "trials.png", "rao.png", "motions.png",
                     "polar.png", "limiting_hs.png", "governing.png", "track.png", "handling.png", "timeline.png",
                     "criterion.png"}
    for path in tmp_path.glob("*.png"):
        with Image.open(path) as image:
            assert image.text == {}, f"{path.name} carries {image.text}"
            assert image.info["dpi"] == pytest.approx((figures.DPI, figures.DPI), abs=0.01), path.name
