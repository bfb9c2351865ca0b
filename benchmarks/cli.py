"""Benchmark: how long ``marinesim --version`` and ``marinesim --help`` take, against a bare interpreter.

Each command runs in a fresh process, as a user types it; the baseline is ``python -c "import
argparse"`` timed in the same run, so the ratio is what marinesim adds to starting Python. Printed:
the median wall time of each over ``--repeats`` runs (alternating), and the ratio. The target is
under 0.3 s for both. Run: ``python benchmarks/cli.py [--repeats 15]``.
"""

from __future__ import annotations

import argparse
import platform
import statistics
import subprocess
import sys
import time

COMMANDS = {
    "baseline: python -c 'import argparse'": [sys.executable, "-c", "import argparse"],
    "marinesim --version": [sys.executable, "-m", "marinesim", "--version"],
    "marinesim --help": [sys.executable, "-m", "marinesim", "--help"],
}


def wall(command: list[str]) -> float:
    """Seconds from start to exit of ``command``."""
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeats", type=int, default=15)
    args = parser.parse_args()
    times: dict[str, list[float]] = {name: [] for name in COMMANDS}
    for command in COMMANDS.values():
        wall(command)  # warm the file cache and the bytecode
    for _ in range(args.repeats):
        for name, command in COMMANDS.items():
            times[name].append(wall(command))
    print(f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, "
          f"median of {args.repeats} runs each")
    baseline = statistics.median(next(iter(times.values())))
    for name, samples in times.items():
        median = statistics.median(samples)
        print(f"{name:40s} {1000 * median:7.1f} ms   ratio {median / baseline:5.2f}")


if __name__ == "__main__":
    main()
