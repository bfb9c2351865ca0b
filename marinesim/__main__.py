"""``python -m marinesim`` and the ``marinesim`` command's entry point.

The command line's own modules are imported inside :func:`main`, so that a Ctrl-C while Python
loads them ends with one line (status 130) rather than a traceback.
"""

import sys


def main() -> int:
    """Run the command line of this process; the exit status."""
    try:
        from marinesim.cli import main as run
    except KeyboardInterrupt:
        print("marinesim: interrupted", file=sys.stderr)
        return 130
    return run()


if __name__ == "__main__":
    raise SystemExit(main())
