"""One entry point for RAO files: the format from the registry (:mod:`marinesim.formats`)."""

from __future__ import annotations

from pathlib import Path

from marinesim import formats
from marinesim.errors import ParameterError
from marinesim.vessel.body import RigidBody
from marinesim.vessel.rao import RaoTable

OPTION_LIMITS = {"ulen": "ULEN applies to WAMIT files only",
                 "roll_damping": "extra roll damping applies to Capytaine datasets only (their RAOs are solved here)",
                 "body": "a body name applies to Capytaine datasets of several bodies only",
                 "rigid_body": "a mass or external stiffness and damping from the scenario apply to RAOs solved "
                               "here (WAMIT force sets and reports, Capytaine datasets) only"}


def detect_format(path: Path) -> str:
    """The name of the RAO format of ``path``: by extension, else by sniffing its first bytes."""
    return formats.detect(Path(path), "rao").name


def read_rao(path: str | Path, *, ulen: float | None = None, roll_damping: float = 0.0, body: str | None = None,
             rigid_body: RigidBody | None = None, file_format: str | None = None) -> RaoTable:
    """Read any supported RAO file into the internal convention (docs/CONVENTIONS.md).

    ``ulen`` overrides WAMIT's length scale; ``roll_damping`` (fraction of critical) applies to
    Capytaine datasets, whose RAOs are solved here, and ``body`` names the body of a Capytaine dataset of
    several; ``rigid_body`` (the scenario's mass, external stiffness and damping) applies to the formats whose
    RAOs are solved here. Each option is refused for a format that does not declare it.
    """
    path = Path(path)
    formats.check_file(path)
    fmt = formats.get(file_format, "rao") if file_format else formats.detect(path, "rao")
    options: dict[str, float | str | RigidBody] = {}
    if ulen is not None:
        options["ulen"] = ulen
    if roll_damping:
        options["roll_damping"] = roll_damping
    if body is not None:
        options["body"] = body
    if rigid_body is not None and rigid_body.given:
        options["rigid_body"] = rigid_body
    for name in options:
        if name not in fmt.options:
            raise ParameterError(f"{OPTION_LIMITS[name]}, not {fmt.name}")
    return formats.reader(fmt)(path, **options)
