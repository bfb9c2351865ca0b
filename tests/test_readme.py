"""The README is a front door: short, with the two commands CI runs, links that lead somewhere in the repository,
only commands that exist, and no internal history in any of the project's prose."""

from __future__ import annotations

import re
import shlex

from conftest import ROOT
from marinesim.cli import build_parser

README = ROOT / "README.md"
MAX_LINES = 250
HISTORY = re.compile(r"\bissues? #?\d+|\bsince then\b", re.IGNORECASE)
"""Words that tell the project's history rather than what it is (git and benchmarks/RESULTS.md hold that)."""


def prose_files() -> list:
    """The project's prose: the README and docs, the package, its resources, the tests and the benchmarks'
    code (benchmarks/RESULTS.md is the record of measurements, history by design)."""
    files = [README, *ROOT.glob("docs/**/*.md"), *ROOT.glob("marinesim/**/*.py"), *ROOT.glob("configs/**/*.toml"),
             *ROOT.glob("shaders/*"), *ROOT.glob("tests/*.py"), *ROOT.glob("benchmarks/*.py"),
             *ROOT.glob("rao/**/README.md"), *ROOT.glob("hulls/**/README.md")]
    return sorted(path for path in files if path.is_file())


def test_readme_is_short():
    """If this fails, the README grew past a front door's length: move the detail into docs/."""
    lines = README.read_text(encoding="utf-8").splitlines()
    assert len(lines) <= MAX_LINES, f"README.md has {len(lines)} lines, more than {MAX_LINES}"


def test_no_internal_history_in_prose():
    """If this fails, a file tells which issue or session made something instead of what it is."""
    found = []
    for path in prose_files():
        text = path.read_text(encoding="utf-8", errors="replace")
        found += [f"{path.relative_to(ROOT)} line {text.count(chr(10), 0, m.start()) + 1}: {m.group(0)!r}"
                  for m in HISTORY.finditer(text)]
    assert not found, found


def test_readme_test_command_is_what_ci_runs():
    """If this fails, CI (.ci/run) runs other tests, or installs Chromium otherwise, than the README's second
    command tells a user to: the README's promise that command 2 is CI's would not hold."""
    readme = README.read_text(encoding="utf-8")
    command = next(line for line in readme.splitlines() if "pytest" in line and not line.startswith("#"))
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    browser, _, rest = command.rpartition("; ")
    assert browser in ci, "the README installs Chromium otherwise than .ci/run"
    test = rest.split(" && ")[-1]
    assert ci[-1] == test, f"README's test command {test!r} is not .ci/run's {ci[-1]!r}"


def test_links_lead_into_the_repository():
    """If this fails, a page links to a file that is not in the repository (moved, renamed, or outside it), so a
    reader of a clone follows it into nothing."""
    missing = []
    for page in [README, *ROOT.glob("docs/*.md")]:
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", page.read_text(encoding="utf-8")):
            if "://" in target:
                continue
            path = (page.parent / target).resolve()
            if ROOT not in path.parents or not path.exists():
                missing.append(f"{page.relative_to(ROOT)} -> {target}")
    assert not missing, missing


def test_readme_commands_exist():
    """If this fails, the README shows a command or an option the command line does not have."""
    parser = build_parser()
    commands = parser._subparsers._group_actions[0].choices
    readme = README.read_text(encoding="utf-8")
    blocks = "\n".join(re.findall(r"```bash\n(.*?)```", readme.replace("\\\n", " "), re.DOTALL))
    shown = re.findall(r"^marinesim ([^#\n]+?)(?:\s+#.*)?$", blocks, re.MULTILINE)
    assert len(shown) >= 15, shown
    for line in shown:
        words = shlex.split(line)
        assert words[0] in commands, f"README shows marinesim {words[0]}, which is no command"
        known = {option for action in commands[words[0]]._actions for option in action.option_strings}
        if words[0] == "examples" and len(words) > 1:
            continue  # a sub-command of its own
        for word in words[1:]:
            if word.startswith("--"):
                assert word.split("=")[0] in known, f"README shows marinesim {words[0]} {word}, which it does not take"
