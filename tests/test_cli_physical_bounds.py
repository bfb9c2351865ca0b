"""Inputs no sea or ship can have, unbounded lists, and a Ctrl-C in Dask's start-up, staged for real through the
command line on the shipped RAO tables, hulls and scatter diagrams: each must end as one line on stderr naming the
key or option and the physical bound, exit status 2, no traceback, the inputs unchanged and nothing written."""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import HANG_S, ROOT, wait_for
from test_cli_operability import FOLLOWER, HAND_SCATTER
from test_criteria_spectral import constant_heave
from test_cli_bounds import TANKER_HULL, TANKER_RAO, marinesim, refused, scenario

SUPPLY_HULL = ROOT / "hulls" / "supply_hull.stl"
S175 = ROOT / "rao" / "s175" / "input.re1"
WIND_SEA = 'type = "jonswap"\nu10_m_s = {u10}\nfetch_km = {fetch}\nfrom_deg = 0.0'


def refused_untouched(args: list[str], inputs: list[Path], *words: str, folder: Path | None = None) -> str:
    """``marinesim ARGS`` refused (see :func:`refused`) with ``inputs`` byte-identical afterwards and, if given,
    nothing new in ``folder``."""
    before = {path: path.read_bytes() for path in inputs}
    listed = sorted(folder.iterdir()) if folder is not None else None
    line = refused(marinesim(*args), *words)
    assert {path: path.read_bytes() for path in inputs} == before, "an input changed"
    if folder is not None:
        assert sorted(folder.iterdir()) == listed, "something was written"
    return line


# Tracebacks ------------------------------------------------------------------------------------


@pytest.mark.parametrize("u10, fetch, words", [("1e-300", "100", "peak period"),
                                             ("20", "1e-300", "a few wave lengths"),
                                             ("60", "0.1", "a few wave lengths")])
def test_a_wind_sea_outside_fetch_limited_growth_is_refused(tmp_path, u10, fetch, words):
    """Without this, ``sea --u10 1e-300`` divides by zero, ``--fetch-km 1e-300`` too (after building the ocean);
    60 m/s over 100 m is a fetch shorter than its waves."""
    refused_untouched(["sea", "--resolution", "16", "--tiles", "1", "--u10", u10, "--fetch-km", fetch], [],
                      "u10", "fetch_km", words, folder=tmp_path)
    path = scenario(tmp_path, sea=WIND_SEA.format(u10=u10, fetch=fetch))
    refused_untouched(["export", str(path), "--out", str(tmp_path / "m.csv")], [path],
                      "sea[0].u10_m_s", "fetch_km", words, folder=tmp_path)


def test_a_fully_developed_wind_sea_grows_no_more_with_fetch():
    """Beyond g F / U10^2 = 2.2e4 the sea is fully developed: 15 m/s over 1000 km and over 5000 km are one sea (the
    growth law extrapolated gave a 6 km wave for 2 m/s over 5000 km), and 10 m/s over 300 km, an ordinary ocean
    wind sea, is built (it was refused for a while)."""
    from marinesim.sea.spectra import JonswapFetch

    long, longer = JonswapFetch(15.0, 1000e3), JonswapFetch(15.0, 5000e3)
    assert (long.hs, long.tp) == (longer.hs, longer.tp)
    assert JonswapFetch(2.0, 5000e3).hs < 0.2
    result = marinesim("sea", "--resolution", "16", "--tiles", "1", "--u10", "10", "--fetch-km", "300", "--json")
    assert result.returncode == 0, result.stderr


def test_a_wind_sea_within_fetch_limited_growth_is_built():
    """The bound must leave a real wind sea alone: 15 m/s over 200 km (README) gives Hs 4.5 m, Tp 9 s."""
    result = marinesim("sea", "--resolution", "16", "--tiles", "1", "--u10", "15", "--fetch-km", "200", "--json")
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    assert report["hs_spectrum_m"] == pytest.approx(4.5, abs=0.05) and report["tp_spectrum_s"] == pytest.approx(9.0,
                                                                                                           abs=0.1)


def test_a_draft_deeper_than_the_hull_is_refused(tmp_path):
    """Without this, ``wake --draft 1e308`` dies in a ValueError: the tanker's mesh is 10 m from keel to top."""
    refused_untouched(["wake", str(TANKER_HULL), "--speed-kn", "10", "--draft", "1e308", "--no-cache", "--quiet",
                       "--out", str(tmp_path / "w.npz")], [TANKER_HULL], "draft", "height, keel to top (10 m)",
                      folder=tmp_path)
    path = scenario(tmp_path, hull=TANKER_HULL, vessel="hull_draft_m = 1e308")
    refused_untouched(["export", str(path), "--out", str(tmp_path / "m.csv")], [path, TANKER_HULL],
                      "vessel.hull", "draft", "10 m", folder=tmp_path)


def test_a_trim_that_sinks_one_end_is_refused():
    """Without this, ``hull --trim-deg 29.9 --draft 0.1`` reports a 14.9 m draft for 0.1 m asked, with the supply
    vessel's bow deck (10.6 m above her keel) under water; a real trim of 2 deg at her 6 m draft still reads."""
    refused_untouched(["hull", str(SUPPLY_HULL), "--trim-deg", "29.9", "--draft", "0.1"], [SUPPLY_HULL],
                      "trim 29.9 deg", "14.85 m deep", "10.6 m, keel to top")
    result = marinesim("hull", str(SUPPLY_HULL), "--trim-deg", "2", "--draft", "6", "--json")
    assert result.returncode == 0, result.stderr
    assert 6.0 < json.loads(result.stdout)["draft_m"] < 8.0


# No size caps ----------------------------------------------------------------------------------


def test_too_many_wave_systems_are_refused(tmp_path):
    """Without the cap, 1,000 [[sea]] systems build 1,000 spectra and an ocean for minutes."""
    system = '[[sea]]\ntype = "jonswap"\nhs_m = 0.5\ntp_s = 9.0\nfrom_deg = 0.0\n'
    path = scenario(tmp_path, ocean="resolution = 64\n" + system * 999)
    refused_untouched(["export", str(path), "--out", str(tmp_path / "m.csv")], [path], "sea", "at most 10",
                      folder=tmp_path)


def test_too_many_points_are_refused(tmp_path):
    """Without the cap, 10,000 named points make an export of 90,000 columns, for minutes."""
    points = "".join(f"p{i} = [0.0, 0.0, 1.0]\n" for i in range(10_000))
    path = scenario(tmp_path, run="duration_s = 10.0\ndt_s = 0.5\n[vessel.points]\n" + points)
    refused_untouched(["export", str(path), "--out", str(tmp_path / "m.csv")], [path], "vessel.points", "at most 64",
                      folder=tmp_path)


def test_a_repeated_wake_speed_is_computed_once(tmp_path):
    """Without this, each of 1,000 copies of one speed is computed again (--no-cache): here 12 kn given 1,000
    times and 14 kn twice give exactly two wakes, in the order first given."""
    speeds = ",".join(["12"] * 1000 + ["14", "12", "14"])
    result = marinesim("wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", speeds, "--no-cache", "--quiet",
                       "--nx", "64", "--ny", "32", "--json")
    assert result.returncode == 0, result.stderr
    assert [report["speed_kn"] for report in json.loads(result.stdout)] == [12.0, 14.0]


def test_too_many_wake_speeds_are_refused(tmp_path):
    """Without the cap, 1,000 different speeds compute 1,000 wakes."""
    speeds = ",".join(f"{1 + 0.01 * i:g}" for i in range(1000))
    refused_untouched(["wake", str(TANKER_HULL), "--speed-kn", speeds, "--quiet", "--out", str(tmp_path / "w.npz")],
                      [TANKER_HULL], "--speed-kn", "1000 different speeds", "more than 40", folder=tmp_path)


# Physically impossible inputs ------------------------------------------------------------------


def test_water_too_shallow_for_the_sea_is_refused_without_a_hull(tmp_path):
    """Without this, the tanker (RAOs, no hull) rides Hs 3 m in a nanometre of water and the export exits 0 with a
    sea whose tiles are a millimetre long."""
    path = scenario(tmp_path, ocean="resolution = 64\ndepth_m = 1e-9")
    refused_untouched(["export", str(path), "--out", str(tmp_path / "m.csv")], [path], "ocean.depth_m",
                      "0.78 x depth", "3.85 m", folder=tmp_path)
    refused_untouched(["sea", "--resolution", "16", "--tiles", "1", "--depth", "1e-9"], [], "depth", "3.85 m")


def test_water_shallower_than_the_rao_files_draft_is_refused_without_a_hull(tmp_path):
    """The supply vessel's VERES file gives her draft, T = 6 m: in 1 m of water (a low sea, so the breaking bound
    says nothing) her keel would be on the sea bed, which only a hull used to tell; 7 m is deep enough."""
    supply = ROOT / "rao" / "supply" / "input.re1"
    low = 'type = "jonswap"\nhs_m = 0.5\ntp_s = 6.0\nfrom_deg = 0.0'
    path = scenario(tmp_path, ocean="resolution = 64\ndepth_m = 1.0", rao=supply, sea=low)
    refused_untouched(["export", str(path), "--out", str(tmp_path / "m.csv")], [path], "ocean.depth_m",
                      "draft (6 m, vessel.rao)", folder=tmp_path)
    path = scenario(tmp_path, ocean="resolution = 64\ndepth_m = 7.0", rao=supply, sea=low)
    result = marinesim("export", str(path), "--out", str(tmp_path / "m.csv"), "--quiet")
    assert result.returncode == 0, result.stderr


@pytest.mark.parametrize("vessel, words", [
    ("[vessel.points]\nbridge = [1e308, 0, 0]", ["vessel.points.bridge", "-1000..1000 m"]),
    (f'visual_mesh = "{ROOT / "hulls" / "tanker_visual.glb"}"\nvisual_mesh_offset_m = [1e308, 0, 0]',
     ["vessel.visual_mesh_offset_m", "-1000..1000 m"]),
])
def test_a_point_far_off_the_ship_is_refused(tmp_path, vessel, words):
    """Without this, a bridge at x = 1e308 m gives 201 NaN in the CSV, a visual mesh there a picture of nothing."""
    path = scenario(tmp_path, vessel=vessel)
    refused_untouched(["export", str(path), "--out", str(tmp_path / "m.csv")], [path], *words, folder=tmp_path)


@pytest.mark.parametrize("rao, args, words", [
    (S175, ["--speed-kn", "1e308"], ["--speed-kn", "the RAO table's speeds", "0..20 kn"]),
    (TANKER_RAO, ["--speed-kn", "1e308"], ["--speed-kn", "a ship's speeds", "0..40 kn"]),
    (S175, ["--headings", "180,1e308"], ["--headings", "-360..360 deg"]),
])
def test_rao_plot_speed_and_headings_out_of_range_are_refused(tmp_path, rao, args, words):
    """Without this, ``rao --speed-kn 1e308`` plots the 20 kn RAOs as if at 1e308 kn, ``--headings 1e308`` a
    heading nobody asked for."""
    refused_untouched(["rao", str(rao), "--plot", str(tmp_path / "r.png"), *args], [rao], *words, folder=tmp_path)


@pytest.fixture
def follower(tmp_path):
    """The operability tests' vessel that heaves with the sea, its heave limit 0.5 m."""
    constant_heave(tmp_path)
    return (tmp_path / "follower.toml", FOLLOWER.format(limit=0.5))


@pytest.mark.parametrize("rows, words", [
    ("1,6,10\n1e308,10,20\n", ["line 3", "hs_m 1e+308", "0..30 m"]),
    ("50,6,10\n1500,10,20\n", ["line 2", "hs_m 50", "0..30 m", "other units"]),
    ("1,6,10\n20,3,20\n", ["Hs 20 m, Tp 3 s", "steeper than breaking", "1/7"]),
])
def test_a_scatter_no_sea_can_have_is_refused(tmp_path, follower, rows, words):
    """Without this, Hs 1e308 m dies in matplotlib with nothing written, a table in centimetres reads 0 %
    operability and Hs 20 m at Tp 3 s (Hs / Lp = 1.4) 100 %."""
    path, text = follower
    path.write_text(text)
    scatter = tmp_path / "site.csv"
    scatter.write_text("hs_m,tp_s,count\n" + rows)
    refused_untouched(["operability", str(path), "--scatter", str(scatter), "--out", str(tmp_path / "out"),
                       "--headings", "0,180"], [path, scatter, tmp_path / "heave.csv"], str(scatter), *words,
                      folder=tmp_path)


def test_a_scatter_that_breaks_in_the_scenarios_depth_is_refused_before_the_study(tmp_path, follower):
    """In 20 m of water a sea of Hs 18 m has broken (H > 0.78 depth); refused when the study is prepared, it no
    longer fails inside a time-domain cell after the work before it was spent."""
    path, text = follower
    path.write_text("[ocean]\ndepth_m = 20.0\n" + text)
    scatter = tmp_path / "site.csv"
    scatter.write_text("hs_m,tp_s,count\n2,8,10\n18,14,1\n")
    refused_untouched(["operability", str(path), "--scatter", str(scatter), "--out", str(tmp_path / "out"),
                       "--headings", "0,180"], [path, scatter], str(scatter), "Hs 18 m", "20 m of water",
                      folder=tmp_path)


@pytest.mark.parametrize("name", ["north_atlantic", "world_wide", "northern_north_sea"])
def test_every_shipped_scatter_is_a_real_sea(tmp_path, follower, name):
    """The bounds must not refuse the shipped diagrams (their joint models' tails included)."""
    from marinesim.scenario import load_scenario
    from marinesim.study.run import prepare

    path, text = follower
    path.write_text(text)
    study = prepare(load_scenario(path), ROOT / "configs" / "scatter" / f"{name}.csv", np.array([0.0, 180.0]), 3.0)
    assert study.scatter.hs.size > 100


# Ctrl-C ----------------------------------------------------------------------------------------


def _worker_started(pid: int) -> bool:
    """Whether process ``pid`` has started a Dask worker (a multiprocessing child of its own)."""
    children = []
    for thread in os.listdir(f"/proc/{pid}/task"):
        try:
            children += Path(f"/proc/{pid}/task/{thread}/children").read_text().split()
        except OSError:
            continue
    for child in children:
        try:
            if b"spawn_main" in Path(f"/proc/{child}/cmdline").read_bytes():
                return True
        except OSError:
            continue
    return False


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="needs Linux's /proc to see the worker start")
def test_ctrl_c_while_dask_starts_is_one_line_and_130(tmp_path, follower):
    """Without holding Ctrl-C through the LocalCluster's start-up, a SIGINT there is swallowed by Dask: the study
    then hangs, or ends with Dask's CommClosedError tracebacks (a worker's heartbeat to the closed scheduler).
    Port 8787 is held here, as another study (or CI's other worker) holds it: the scheduler's HTTP server took it
    by default and warned on stderr when it was taken."""
    pytest.importorskip("distributed")
    taken = socket.socket()
    with contextlib.suppress(OSError):  # already taken by something else: the same condition
        taken.bind(("127.0.0.1", 8787))
        taken.listen(1)
    path, text = follower
    path.write_text(text)
    (tmp_path / "site.csv").write_text(HAND_SCATTER)
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    process = subprocess.Popen(
        [sys.executable, "-m", "marinesim", "operability", str(path), "--scatter", str(tmp_path / "site.csv"),
         "--out", str(tmp_path / "out"), "--headings", "90,180", "--time-domain", "1000", "--workers", "2",
         "--duration-h", "0.2", "--quiet"], stderr=subprocess.PIPE, text=True, env=env)
    try:
        wait_for(lambda: _worker_started(process.pid), process, "no Dask worker started")
        process.send_signal(signal.SIGINT)
        _, stderr = process.communicate(timeout=HANG_S)
    finally:
        taken.close()
        if process.poll() is None:
            process.kill()
            process.wait()
    lines = stderr.strip().splitlines()
    assert process.returncode == 130, stderr
    assert "Traceback" not in stderr and "CommClosedError" not in stderr, stderr
    assert len(lines) == 1 and re.fullmatch(r"marinesim operability: interrupted.*", lines[0]), stderr
