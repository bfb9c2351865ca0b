"""One entry point for RAO files: the format from the registry (:mod:`marinesim.formats`)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from marinesim import formats
from marinesim.errors import FileFormatError, ParameterError
from marinesim.vessel.body import RigidBody
from marinesim.vessel.rao import RaoTable

ACCEPT = "marinesim rao --accept-resonance, [vessel] accept_resonance = true"
"""How a user accepts a lightly damped resonance beyond the plausibility limits."""

OPTION_LIMITS = {"ulen": "ULEN applies to WAMIT files only",
                 "roll_damping": "extra roll damping applies to Capytaine datasets only (their RAOs are solved here)",
                 "body": "a body applies to Capytaine datasets and WAMIT runs of several bodies only",
                 "rigid_body": "a mass or external stiffness and damping from the scenario apply to RAOs solved "
                               "here (WAMIT force sets and reports, Capytaine datasets) only"}


def detect_format(path: Path) -> str:
    """The name of the RAO format of ``path``: by extension, else by sniffing its first bytes."""
    return formats.detect(Path(path), "rao").name


def read_rao(path: str | Path, *, ulen: float | None = None, roll_damping: float = 0.0, body: str | None = None,
             rigid_body: RigidBody | None = None, file_format: str | None = None,
             accept_resonance: bool = False) -> RaoTable:
    """Read any supported RAO file into the internal convention (docs/CONVENTIONS.md).

    ``ulen`` overrides WAMIT's length scale; ``roll_damping`` (fraction of critical) applies to
    Capytaine datasets, whose RAOs are solved here, and ``body`` names the body of a Capytaine dataset or a WAMIT
    run of several; ``rigid_body`` (the scenario's mass, external stiffness and damping) applies to the formats
    whose RAOs are solved here. Each option is refused for a format that does not declare it. A lightly damped
    resonance beyond the plausibility limits (:class:`~marinesim.vessel.rao.Resonance`) is refused, or noted for
    surge and sway beyond the wave orbit, unless ``accept_resonance``.
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
    return judge_resonances(path, formats.reader(fmt)(path, **options), accept_resonance)


def judge_resonances(path: Path, table: RaoTable, accept: bool) -> RaoTable:
    """``table`` with its resonances beyond the plausibility limits accepted (noted as such), or, unless
    ``accept``, the first beyond the amplitudes no floating body has refused and the others noted as implausible
    unless real."""
    if not accept:
        refused = next((r for r in table.resonances if r.refused), None)
        if refused is not None:
            raise FileFormatError(path, None, f"{refused.text}: if it is real (a moored body's surge, a flap's "
                                              f"roll), accept it ({ACCEPT}), else check the file's units")
    notes = tuple(f"resonance accepted: {r.text}" if accept else
                  f"implausible unless real: {r.text}; accept it if it is ({ACCEPT}), else check the file's units and "
                  "reference point" for r in table.resonances)
    return replace(table, notes=table.notes + notes, resonances=()) if notes else table
