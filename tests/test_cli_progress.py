"""Progress where stderr is not a terminal (a log, a pipe): plain lines, no carriage returns or escape sequences
(tqdm's bars would write escape junk into logs)."""

import io
import re

from conftest import ROOT, cli_process as cli
from marinesim.progress import lines, reporting, task

SHARE = re.compile(r"^export m\.csv: (\d+)% \((\d+)/2001 step\)$")
DONE = re.compile(r"^export m\.csv: done \(2001 step, \d+\.\d s\)$")


def test_an_export_into_a_pipe_reports_progress_as_plain_lines(tmp_path):
    """The helideck exercise (its criteria cut the run into blocks) exported with stderr to a pipe: each line of
    stderr is a share done or the final 'done', in order; a carriage return or an escape sequence would be a
    terminal's bar written into the log."""
    scenario = ROOT / "configs" / "training" / "helideck_landing.toml"
    result = cli("export", str(scenario), "--out", "m.csv", "--duration", "20", "--dt", "0.01", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "\r" not in result.stderr and "\x1b" not in result.stderr
    progress = result.stderr.splitlines()
    assert DONE.match(progress[-1]), progress
    shares = [SHARE.match(line) for line in progress[:-1]]
    assert shares and all(shares), progress
    done = [int(share[2]) for share in shares]
    assert done == sorted(done) and done[-1] < 2001


def test_the_reporter_writes_a_line_per_tenth_and_one_when_done():
    """Updates of 7 % of the total: a line each time another tenth is done (not one per update: a log of a long
    run would drown), none at the end but 'done' with the units and seconds; a task cut short says where it
    stopped instead of 'done'."""
    stream = io.StringIO()
    with reporting(lines(stream, interval_s=3600.0)):
        with task("work", 100, "row") as bar:
            for _ in range(15):
                bar.update(7)  # 7, 14, ..., 105 (the last update passes the total, as a rounded one may)
        try:
            with task("cut", 10) as bar:
                bar.update(4)
                raise KeyboardInterrupt
        except KeyboardInterrupt:
            pass
    out = stream.getvalue().splitlines()
    assert out[:9] == [f"work: {p}% ({p}/100 row)" for p in (14, 21, 35, 42, 56, 63, 70, 84, 91)]
    assert re.fullmatch(r"work: done \(105 row, \d+\.\d s\)", out[9]), out
    assert out[10] == "cut: 40% (4/10 step)" and len(out) == 12
    assert re.fullmatch(r"cut: stopped at 40% \(4/10 step, \d+\.\d s\)", out[11]), out


def test_the_reporter_writes_a_line_after_its_interval_whatever_the_share():
    """With no interval to wait, every update that moves the task on is a line: a slow task shows it is alive
    between its tenths."""
    stream = io.StringIO()
    with reporting(lines(stream, interval_s=0.0)):
        with task("slow", 1000) as bar:
            for _ in range(3):
                bar.update(1)
            bar.update(0)
    assert stream.getvalue().splitlines()[:-1] == [f"slow: 0% ({n}/1000 step)" for n in (1, 2, 3)]
