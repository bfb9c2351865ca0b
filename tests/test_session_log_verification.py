"""A session log is evidence: a real session's log, written by a real exercise, then edited as someone might
(an acknowledgement moved earlier, the seed changed, the end cut off, the sidecar deleted, the sidecar's hash
written again, an entry put at t = 1e308), is reported as unverified by every reader and refused by ``replay``
unless asked for; the unedited log is verified; entries outside the session are refused in one line."""

from __future__ import annotations

import hashlib
import json
import logging
import shutil
import stat

import numpy as np
import pytest

from conftest import ROOT, cli, cli_process, write
from marinesim.errors import FileFormatError
from marinesim.scenario import load_scenario
from marinesim.session.exercise import Exercise
from marinesim.session.log import read_log, write_log
from marinesim.session.signing import KEY_FILE, installation_key, key_id
from marinesim.session.timeline import Simulation
from test_session_replay import SESSION

ACK_DELAY_S = 1.2
"""How long after the alarm the trainee of :func:`live_session` acknowledges it (s, to the next frame)."""


def live_session(folder, seed: int = 8):
    """A session as the viewer runs it, 160 s in random frames of 0.01-0.7 s: the instructor's message and an
    event brought forward, the trainee acknowledging the alarm 1.2 s after it sounds, then the end; its log
    written to ``folder / 'session.jsonl'`` with this installation's key. Returns (the log, the exercise)."""
    scenario = load_scenario(write(folder, SESSION.format(limit=0.15)))
    simulation = Simulation(scenario, wake=False)
    exercise = Exercise(simulation)
    plan = [(61.0, "message", {"text": "stand by the helideck"}), (80.0, "trigger", {"index": 1})]
    rng = np.random.default_rng(seed)
    while simulation.time < 160.0:
        exercise.advance(rng.uniform(0.01, 0.7))
        if plan and simulation.time >= plan[0][0]:
            _, action, fields = plan.pop(0)
            exercise.act(action, **fields)
        waiting = exercise.unacknowledged()
        if waiting and simulation.time >= waiting[0].raised_s + ACK_DELAY_S:
            exercise.note("key", key="RETURN")
            exercise.act("acknowledge")
    exercise.note("end")
    simulation.close()
    assert exercise.alarms and exercise.alarms[0].acknowledged_s is not None, "the session must hold an acknowledgement"
    return write_log(folder / "session.jsonl", exercise), exercise


@pytest.fixture(scope="module")
def config(tmp_path_factory):
    """This installation's configuration folder (its session-log key), never the user's."""
    folder = tmp_path_factory.mktemp("config")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("MARINESIM_CONFIG_DIR", str(folder))
        yield folder


@pytest.fixture(scope="module")
def session(config, tmp_path_factory):
    """(the folder of a real session's log and sidecar, the exercise); tests edit copies of them."""
    folder = tmp_path_factory.mktemp("session")
    log, exercise = live_session(folder)
    return log, exercise


@pytest.fixture
def copy(session, tmp_path):
    """A copy of the session's log and its sidecar in the test's own folder: the log's path."""
    log, _ = session
    for name in (log.name, log.name + ".json"):
        shutil.copyfile(log.parent / name, tmp_path / name)
    return tmp_path / log.name


def lines_of(log) -> tuple[dict, list[dict]]:
    lines = [json.loads(line) for line in log.read_text().splitlines()]
    return lines[0], lines[1:]


def rewrite(log, head: dict, entries: list[dict]) -> None:
    log.write_text("\n".join(json.dumps(e) for e in [head, *entries]) + "\n")


def move_acknowledgement(log) -> None:
    """The acknowledgement (the action and its record) moved to 0.1 s after the alarm, entries kept in time order."""
    head, entries = lines_of(log)
    raised = next(e["t"] for e in entries if e["kind"] == "alarm")
    for entry in entries:
        if entry["kind"] == "acknowledged" or entry.get("action") == "acknowledge":
            entry["t"] = raised + 0.1
        if entry["kind"] == "acknowledged":
            entry["delays_s"] = [0.1]
    rewrite(log, head, sorted(entries, key=lambda e: e["t"]))


def change_seed(log) -> None:
    head, entries = lines_of(log)
    rewrite(log, head | {"seed": head["seed"] + 1}, entries)


def cut_end(log) -> None:
    head, entries = lines_of(log)
    assert entries[-1]["kind"] == "end"
    rewrite(log, head, entries[:-1])


def rehash(log) -> None:
    """The sidecar's sha256 written again to match the edited log, as whoever edits it would."""
    sidecar = log.with_name(log.name + ".json")
    meta = json.loads(sidecar.read_text())
    sidecar.write_text(json.dumps(meta | {"data_sha256": hashlib.sha256(log.read_bytes()).hexdigest()}))


def unsign(log) -> None:
    sidecar = log.with_name(log.name + ".json")
    meta = json.loads(sidecar.read_text())
    del meta["signature"]
    sidecar.write_text(json.dumps(meta))


def garble_signature(log) -> None:
    """A signature no marinesim writes: a key's name in Cyrillic, which a byte-wise comparison cannot take."""
    sidecar = log.with_name(log.name + ".json")
    meta = json.loads(sidecar.read_text())
    sidecar.write_text(json.dumps(meta | {"signature": meta["signature"] | {"key_id": "ключ"}}))


def delete_sidecar(log) -> None:
    log.with_name(log.name + ".json").unlink()


EDITS = {
    "acknowledgement moved": ([move_acknowledgement], ["hash mismatch"]),
    "seed changed": ([change_seed], ["hash mismatch"]),
    "end cut off": ([cut_end], ["hash mismatch", "truncated"]),
    "sidecar deleted": ([delete_sidecar], ["no sidecar"]),
    "end cut off, sidecar deleted": ([cut_end, delete_sidecar], ["no sidecar", "truncated"]),
    "acknowledgement moved, re-hashed": ([move_acknowledgement, rehash], ["signature mismatch"]),
    "acknowledgement moved, re-hashed, unsigned": ([move_acknowledgement, rehash, unsign], ["unsigned"]),
    "signature garbled": ([garble_signature], ["bad sidecar"]),
}
WORDS = {"hash mismatch": "changed after the session wrote it", "truncated": "no end entry",
         "no sidecar": "session.jsonl.json is missing", "signature mismatch": "signature does not match",
         "unsigned": "not signed", "bad sidecar": "holds a signature marinesim does not write"}


def test_the_unedited_log_is_verified_and_signed_with_a_private_key(session, config, copy):
    """What would be wrong: a genuine log reported unverified (every debrief would cry wolf), a key others can
    read (anyone could re-sign an edited log), or the key's bytes in the log or its sidecar."""
    check = read_log(copy).verification
    assert check.verified and check.problems == () and check.summary().startswith("verified")
    assert check.sha256 == hashlib.sha256(copy.read_bytes()).hexdigest()
    key_file = config / KEY_FILE
    assert stat.S_IMODE(key_file.stat().st_mode) == 0o600
    key = installation_key()
    signed = json.loads(copy.with_name(copy.name + ".json").read_text())["signature"]
    assert signed["key_id"] == key_id(key) and len(signed["hmac_sha256"]) == 64
    for text in (copy.read_text(), copy.with_name(copy.name + ".json").read_text()):
        assert key.hex() not in text
    result = cli("replay", str(copy), "--headless", "--quiet")
    assert result.returncode == 0, result.stderr
    assert "session log verified" in result.stdout and "UNVERIFIED" not in result.stdout


@pytest.mark.parametrize("name", EDITS)
def test_an_edited_log_is_unverified_and_replay_refuses_it(copy, name):
    """Each edit is reported, with what it is, and ``replay`` refuses the log in one line (exit 2)."""
    edits, expected = EDITS[name]
    for edit in edits:
        edit(copy)
    check = read_log(copy).verification
    assert not check.verified and [code for code, _ in check.problems] == expected, check.problems
    for code, words in check.problems:
        assert WORDS[code] in words, (code, words)
    result = cli("replay", str(copy), "--headless", "--quiet")
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2 and len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    assert str(copy) in lines[0] and "UNVERIFIED LOG" in lines[0] and "--unverified" in lines[0], lines[0]
    assert all(words in lines[0] for _, words in check.problems)


def test_an_unverified_log_replays_when_asked_and_says_so(copy):
    """``--unverified`` plays the edited log, and says it is unverified: the acknowledgement moved to 0.1 s after
    the alarm is what the replay acts on."""
    move_acknowledgement(copy)
    result = cli("replay", str(copy), "--headless", "--unverified", "--quiet")
    assert result.returncode == 0, result.stderr
    assert "session log UNVERIFIED LOG: the log was changed after the session wrote it" in result.stdout


def test_a_log_signed_on_another_installation_cannot_be_checked_here(copy, tmp_path, monkeypatch):
    """Read where the key is another (or there is none yet), the genuine log is unverified, and said to be signed
    elsewhere rather than forged; back on its own installation it is verified again."""
    for elsewhere in ("no key yet", "another key"):
        monkeypatch.setenv("MARINESIM_CONFIG_DIR", str(tmp_path / elsewhere))
        if elsewhere == "another key":
            assert installation_key(create=True) is not None
        check = read_log(copy).verification
        assert [code for code, _ in check.problems] == ["signed elsewhere"], (elsewhere, check.problems)
        assert "signed on another marinesim installation, or altered" in check.problems[0][1]
        assert "forged" not in check.summary() and "changed" not in check.summary()
    monkeypatch.undo()
    assert read_log(copy).verification.verified


def test_the_same_session_gives_the_same_log_bytes_on_every_installation(session, monkeypatch):
    """The key goes in the sidecar's signature only: the log written on another installation is the same bytes,
    and on this one the sidecar is too. What would be wrong: a key (or a clock) in the log's bytes. Each is written
    where the session's was (the sidecar names its files relative to its own folder), the session's own last."""
    log, exercise = session
    sidecar = log.with_name(log.name + ".json")
    original = log.read_bytes(), sidecar.read_bytes()
    monkeypatch.setenv("MARINESIM_CONFIG_DIR", str(log.parent / "elsewhere"))
    write_log(log, exercise)
    there = log.read_bytes(), json.loads(sidecar.read_text())
    monkeypatch.undo()
    write_log(log, exercise)
    assert (log.read_bytes(), sidecar.read_bytes()) == original
    assert there[0] == original[0]
    here_side = json.loads(original[1])
    assert here_side["signature"] != there[1]["signature"]
    assert {k: v for k, v in here_side.items() if k != "signature"} == \
           {k: v for k, v in there[1].items() if k != "signature"}


def test_the_key_is_made_once_and_never_replaced(tmp_path, monkeypatch):
    monkeypatch.setenv("MARINESIM_CONFIG_DIR", str(tmp_path / "deep" / "config"))
    assert installation_key() is None, "reading makes no key"
    first = installation_key(create=True)
    assert len(first) == 32 and installation_key(create=True) == first == installation_key()
    assert stat.S_IMODE((tmp_path / "deep" / "config" / KEY_FILE).stat().st_mode) == 0o600
    assert [p.name for p in (tmp_path / "deep" / "config").iterdir()] == [KEY_FILE], "no temporary file left"


def test_a_log_is_written_unsigned_when_the_key_is_unusable(session, tmp_path, monkeypatch, caplog):
    """A damaged key must not lose the session's record: the log is written, unsigned, with a warning, and reads
    as unverified."""
    _, exercise = session
    monkeypatch.setenv("MARINESIM_CONFIG_DIR", str(tmp_path / "config"))
    (tmp_path / "config").mkdir()
    (tmp_path / "config" / KEY_FILE).write_text("not a key\n")
    with caplog.at_level(logging.WARNING, logger="marinesim.session"):
        log = write_log(tmp_path / "session.jsonl", exercise)
    assert "is not a session-log key" in caplog.text and "written unsigned" in caplog.text
    assert [code for code, _ in read_log(log).verification.problems] == ["unsigned"]


def _set_time(log, index: int, t: float) -> int:
    """Entry ``index`` of ``log`` put at ``t`` (s); returns its line number."""
    head, entries = lines_of(log)
    entries[index]["t"] = t
    rewrite(log, head, entries)
    return index % len(entries) + 2


@pytest.mark.parametrize("command", ["replay", "report"])
def test_an_entry_at_1e308_s_is_refused_at_once_naming_its_line(copy, tmp_path, command):
    """The header says the session ended at 160 s: an entry at 1e308 s would make the replay run for ever. What
    would be wrong: a hang (the process's timeout, far above the seconds a replay of 160 s takes, fails the test),
    a traceback, or a message that names no line."""
    line = _set_time(copy, -1, 1e308)
    args = ["--headless"] if command == "replay" else ["--out", str(tmp_path / "r.html")]
    result = cli_process(command, str(copy), *args, "--quiet")  # in a process of its own: a hang is stopped
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2 and len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    assert f"{copy}, line {line}: key 't'" in lines[0] and "1e+308" in lines[0], lines[0]
    assert not (tmp_path / "r.html").exists()


def test_every_entry_lies_within_the_session(copy, session):
    """Entries are bounded by the session's end in the header, plus one step (0.1 s here); a header whose run
    or end no scenario allows is refused at line 1."""
    _, exercise = session
    head, entries = lines_of(copy)
    assert head["end_s"] == exercise.sim.time == entries[-1]["t"]
    _set_time(copy, -1, head["end_s"] + 0.05)
    assert read_log(copy).entries[-1]["t"] == head["end_s"] + 0.05, "within one step of the end: read"
    for index, t in ((-1, head["end_s"] + 0.2), (-2, 1e308), (0, -1.0)):
        line = _set_time(copy, index, t)
        with pytest.raises(FileFormatError, match=rf"line {line}: key 't'"):
            read_log(copy)
        _set_time(copy, index, entries[index]["t"])
    for key, value in (("duration_s", 1e308), ("end_s", 1e308), ("end_s", -5.0), ("dt_s", 0.0)):
        rewrite(copy, head | {key: value}, entries)
        with pytest.raises(FileFormatError, match=rf"line 1: key '{key}'"):
            read_log(copy)


def test_a_log_without_its_end_time_may_run_past_the_planned_duration(copy):
    """A log written before logs said when the session ended: the viewer runs on past the planned duration, so
    its entries after ``duration_s`` are the session's, not a forgery (it reads as unverified: unsigned, edited)."""
    head, entries = lines_of(copy)
    past = head["duration_s"] + 300.0
    rewrite(copy, {k: v for k, v in head.items() if k != "end_s"}, entries[:-1] + [entries[-1] | {"t": past}])
    log = read_log(copy)
    assert log.entries[-1]["t"] == past and not log.verification.verified


def test_a_replay_of_changed_vessel_files_is_refused(tmp_path):
    """The signature covers the log's bytes, and the header names the vessel's RAO table by its sha256: a table
    changed since the session would replay other physics under a verified log."""
    from test_atomic_overwrite import SCENARIO

    shutil.copytree(ROOT / "rao" / "tanker", tmp_path / "tanker")
    simulation = Simulation(load_scenario(write(tmp_path, SCENARIO.format(duration=20.0), "s.toml")), wake=False)
    exercise = Exercise(simulation)
    exercise.advance(5.0)
    exercise.note("end")
    simulation.close()
    log = write_log(tmp_path / "l.jsonl", exercise)
    assert read_log(log).verification.verified
    with (tmp_path / "tanker" / "tanker.1").open("a") as table:
        table.write("\n")
    result = cli("replay", str(log), "--export", str(tmp_path / "m.csv"), "--quiet")
    assert result.returncode == 2 and "the vessel's rao file" in result.stderr and "changed since the session" in \
        result.stderr, result.stderr
    assert not (tmp_path / "m.csv").exists()
