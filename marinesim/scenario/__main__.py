"""``python -m marinesim.scenario docs/SCENARIOS.md``: rewrite the scenario reference from the model."""

import sys
from pathlib import Path

from marinesim.scenario.model import with_reference

path = Path(sys.argv[1])
path.write_text(with_reference(path.read_text(encoding="utf-8")), encoding="utf-8")
