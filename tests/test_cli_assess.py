"""``marinesim assess`` on the shipped exercise: what it prints, in JSON and as a table, agrees with the
criteria and events it ran; the headless run writes the same assessment; the same seed gives the same bytes."""

from __future__ import annotations

import json

import pytest

from conftest import ROOT, VESSEL_SCENARIO, cli, write

EXERCISE = ROOT / "configs" / "s175_heavy_weather.toml"


@pytest.fixture(scope="module")
def assessed():
    done = cli("assess", str(EXERCISE), "--json", "--duration", "500", "--quiet")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout), done


def test_assess_reports_every_criterion_and_event(assessed):
    """One entry per [[criteria]] with its worst value and limit; exceeded exactly when time was spent
    above the limit; the verdict follows the levels; the events say when they happened."""
    result, done = assessed
    names = [c["name"] for c in result["criteria"]]
    assert names == ["bridge vertical acceleration", "bridge lateral acceleration", "roll", "green water", "slamming",
                     "seasickness on the bridge"]
    for c in result["criteria"]:
        assert c["value"] is not None and c["value"] >= 0.0
        assert c["exceeded"] == (c["value"] > c["limit"]) == (c["time_exceeded_s"] > 0.0)
        assert (c["first_exceeded_s"] is not None) == c["exceeded"]
    roll = result["criteria"][2]
    assert (roll["unit"], roll["window_s"], roll["point"]) == ("deg", 600.0, None)
    levels = {c["level"] for c in result["criteria"]}
    assert result["verdict"] == ("exceeded" if "exceeded" in levels else "caution" if "caution" in levels
                                 else "within limits")
    happened = [e["happened_s"] for e in result["events"]]
    assert happened[0] == 0.0 and happened[1] == 480.0
    assert result["events"][2]["trigger"] == "when bridge lateral acceleration > 1"
    assert "t   480.0 s  event 1: at 480 s: sea Hs" in done.stderr  # the log goes to stderr with --json
    assert result["duration_s"] == 500.0


@pytest.mark.slow
def test_assess_is_reproducible(assessed):
    again = cli("assess", str(EXERCISE), "--json", "--duration", "500", "--quiet")
    assert again.stdout == assessed[1].stdout


def test_assess_prints_a_table(tmp_path):
    path = write(tmp_path, VESSEL_SCENARIO + '\n[[criteria]]\nquantity = "roll_rms_deg"\nlimit = 0.001\n'
                                            'window_s = 20.0\n')
    done = cli("assess", str(path), "--quiet")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert any("ALARM roll_rms_deg" in line for line in lines), "the alarm is logged as it is raised"
    head = next(i for i, line in enumerate(lines) if line.startswith("criterion"))
    assert lines[head].split() == ["criterion", "worst", "limit", "unit", "level", "above", "limit", "first", "above",
                                   "expected", "percentile", "chance", "above", "limit"]
    row = lines[head + 1].split()
    assert row[:5] == ["roll_rms_deg", row[1], "0.001", "deg", "exceeded"]
    assert float(row[-4]) == pytest.approx(float(row[1]), rel=0.5), "the sea's expected RMS roll, near the run's"
    assert 0 <= int(row[-3]) <= 100 and row[-2:] == [">99", "%"], "a limit of 0.001 deg is passed whatever the seed"
    assert lines[-1] == "verdict: exceeded"


def test_assess_needs_criteria(tmp_path):
    done = cli("assess", str(write(tmp_path, VESSEL_SCENARIO)))
    assert done.returncode == 2 and done.stderr.strip().endswith("no [[criteria]]: nothing to assess")


@pytest.mark.slow
def test_the_headless_run_writes_what_assess_prints(tmp_path, assessed):
    """The headless run (``marinesim run`` without a display) on the exercise writes assessment.json equal
    to ``assess --json`` (one code path), and logs the events as they happen."""
    from marinesim.scenario import load_scenario, with_run
    from marinesim.session.assembly import Assembly
    from marinesim.session.headless import run_headless

    lines: list[str] = []
    result = run_headless(Assembly(with_run(load_scenario(EXERCISE), duration=500.0)), tmp_path, log=lines.append)
    assert json.loads(result.files["assessment"].read_text()) == assessed[0]
    assert any(line.startswith("t   480.0 s  event 1: at 480 s") for line in lines)
