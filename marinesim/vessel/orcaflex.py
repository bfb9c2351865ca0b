"""OrcaFlex vessel-type displacement RAOs from an OrcaFlex text data file (``.yml``) -> :class:`RaoTable`.

OrcaFlex saves a model or a vessel type as YAML text. The displacement RAOs sit in a draught of a vessel type::

    UnitsSystem: SI
    VesselTypes:
      - Name: Cylinder
        WavesReferredToBy: period (s)           # or frequency (rad/s), frequency (Hz)
        RAOResponseUnits: degrees               # rotational RAOs in deg/m, or radians (rad/m)
        RAOWaveUnit: amplitude                  # per unit wave amplitude (height: per unit wave height)
        RAOPhaseConvention: lags                # or leads
        RAOPhaseUnitsConvention: degrees        # or radians
        RAOPhaseRelativeToConvention: crest     # or trough, zero up-crossing, zero down-crossing
        SurgePositive: forward                  # SwayPositive port, HeavePositive up,
        RollPositiveStarboard: down             # PitchPositiveBow down, YawPositiveBow port
        Draughts:
          - Name: Draught1
            DisplacementRAOs:
              RAOOrigin: [0, 0, 0]              # vessel axes, m: the point the RAOs refer to
              PhaseOrigin: [~, ~, ~]            # ~: the RAO origin
              RAOs:
                - RAODirection: 180
                  RAOPeriodOrFrequency, RAOSurgeAmp, RAOSurgePhase, ..., RAOYawAmp, RAOYawPhase:
                    - [10, 0.98, 90.1, ...]

**OrcaFlex's conventions** (OrcaFlex help, "Vessel types: Conventions" and "RAOs and phases"), converted here once
to CONVENTIONS.md's:

* Vessel axes x forward, y to port, z up; with the default positive directions above, roll (starboard down),
  pitch (bow down) and yaw (bow to port) are marinesim's. A DOF whose positive direction is set the other way
  (aft, starboard, down; roll starboard up, pitch bow up, yaw bow to starboard) changes sign.
* ``RAODirection`` is the direction the waves *progress towards*, degrees anticlockwise from the vessel x axis:
  0 following seas, 90 waves travelling to port (from starboard), 180 head seas: marinesim's ``beta_rel``.
* Phases: with ``lags`` the response is ``R cos(w t - phi)`` for the wave ``a cos(w t)`` at the phase origin
  (the time from the crest passing to the maximum response), so ``H = R exp(-i phi)``; ``leads`` gives
  ``H = R exp(+i phi)``. Relative to the trough, zero up-crossing or zero down-crossing the reference event
  happens at ``w t = pi``, ``-pi/2`` or ``+pi/2`` of the crest-referred wave, adding that angle to the lag.
* Rotations per unit amplitude in deg/m (``degrees``) or rad/m (``radians``); ``RAOWaveUnit: height`` means per
  unit wave height (2 a): values are doubled. Only ``UnitsSystem: SI`` (lengths in metres) is read.
* The RAO origin is the table's reference point. A ``PhaseOrigin`` other than the RAO origin (in x, y) is
  re-referred to the RAO origin with the deep-water wavenumber (an OrcaFlex vessel type holds no depth).

Rows of period 0 or infinity (frequency 0) carry no RAO and are skipped. YAML is parsed with PyYAML's safe
composer (an installed dependency of this environment), keeping line numbers for every error.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.constants import G
from marinesim.errors import FileFormatError, HeadingError, MarinesimError, ParameterError
from marinesim.formats import check_file
from marinesim.tokens import parse_float, read_text
from marinesim.vessel.rao import RaoTable, make_table

MAX_ROWS = 1_000_000
"""Most RAO rows (directions x periods) read from one draught."""
TABLE_KEY = ("RAOPeriodOrFrequency, RAOSurgeAmp, RAOSurgePhase, RAOSwayAmp, RAOSwayPhase, RAOHeaveAmp, "
             "RAOHeavePhase, RAORollAmp, RAORollPhase, RAOPitchAmp, RAOPitchPhase, RAOYawAmp, RAOYawPhase")
COLUMNS = [c.strip() for c in TABLE_KEY.split(",")]
DEFAULTS = {
    "WavesReferredToBy": "period (s)", "RAOResponseUnits": "degrees", "RAOWaveUnit": "amplitude",
    "RAOPhaseConvention": "lags", "RAOPhaseUnitsConvention": "degrees", "RAOPhaseRelativeToConvention": "crest",
    "SurgePositive": "forward", "SwayPositive": "port", "HeavePositive": "up", "RollPositiveStarboard": "down",
    "PitchPositiveBow": "down", "YawPositiveBow": "port",
}
"""OrcaFlex's defaults of the RAO conventions, used (with a note) where a file omits them."""
CHOICES = {
    "WavesReferredToBy": ("period (s)", "frequency (rad/s)", "frequency (hz)"),
    "RAOResponseUnits": ("degrees", "radians"),
    "RAOWaveUnit": ("amplitude", "height"),
    "RAOPhaseConvention": ("lags", "leads"),
    "RAOPhaseUnitsConvention": ("degrees", "radians"),
    "RAOPhaseRelativeToConvention": ("crest", "trough", "zero up-crossing", "zero down-crossing"),
}
POSITIVE = {  # key -> (DOF index, value meaning marinesim's positive, value meaning the opposite)
    "SurgePositive": (0, "forward", "aft"), "SwayPositive": (1, "port", "starboard"), "HeavePositive": (2, "up", "down"),
    "RollPositiveStarboard": (3, "down", "up"), "PitchPositiveBow": (4, "down", "up"),
    "YawPositiveBow": (5, "port", "starboard"),
}
REFERENCE_EVENT = {"crest": 0.0, "trough": math.pi, "zero up-crossing": -math.pi / 2, "zero down-crossing": math.pi / 2}
"""w t of the phase's reference event for the wave a cos(w t) at the phase origin."""


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes look like an OrcaFlex text data file with displacement RAOs."""
    text = head.decode("utf-8", errors="replace")
    return "DisplacementRAOs" in text or ("VesselType" in text and "RAOPhaseConvention" in text)


def read_orcaflex(path: str | Path, *, vessel_type: str | None = None, draught: str | None = None) -> RaoTable:
    """Read the displacement RAOs of ``vessel_type`` and ``draught`` (names; default the first of each, noted when
    there are several) from an OrcaFlex ``.yml`` file (module docstring)."""
    path = Path(path)
    root = _compose(path)
    notes: list[str] = []
    vt = _pick(path, _vessel_types(path, root), vessel_type, "vessel type", notes)
    draughts = _get(path, vt, "Draughts")
    if draughts is None or not isinstance(draughts, _yaml().SequenceNode) or not draughts.value:
        raise FileFormatError(path, _line(vt), "the vessel type has no Draughts list")
    d = _pick(path, [(_name(node), node) for node in draughts.value], draught, "draught", notes)
    units = _get(path, root, "UnitsSystem") or _get(path, _get(path, root, "General"), "UnitsSystem")
    if units is not None and _text(units).lower() != "si":
        raise FileFormatError(path, _line(units), f"UnitsSystem {_text(units)!r}: only SI (metres) is read; "
                                                  "save the vessel type with SI units")
    settings, defaulted = {}, []
    for key, default in DEFAULTS.items():
        node = _get(path, vt, key)
        value = default if node is None else _text(node).strip().lower()
        if node is None:
            defaulted.append(key)
        allowed = CHOICES.get(key) or POSITIVE[key][1:]
        if value not in allowed:
            raise FileFormatError(path, _line(node), f"{key} {value!r} is not supported (supported: "
                                                     f"{', '.join(allowed)})")
        settings[key] = value
    if defaulted:
        notes.append("OrcaFlex defaults assumed for " + ", ".join(defaulted))
    raos = _get(path, d, "DisplacementRAOs")
    if raos is None:
        raise FileFormatError(path, _line(d), "the draught has no DisplacementRAOs")
    origin = _point(path, _get(path, raos, "RAOOrigin"), (0.0, 0.0, 0.0), "RAOOrigin")
    phase_origin = _point(path, _get(path, raos, "PhaseOrigin"), origin, "PhaseOrigin")
    directions, frequencies, values = _tables(path, _get(path, raos, "RAOs"), raos, settings)
    omega, values, skipped = _to_omega(frequencies, values, settings["WavesReferredToBy"])
    if skipped:
        notes.append(f"{skipped} row(s) of zero frequency / infinite period per direction skipped")
    values = _convert(values, settings)
    shift = np.array(phase_origin[:2]) - np.array(origin[:2])
    if np.any(shift != 0.0):
        k = omega**2 / G
        b = np.radians(directions)
        values *= np.exp(-1j * (shift[0] * np.cos(b) + shift[1] * np.sin(b))[:, None, None] * k[None, :, None])
        notes.append(f"PhaseOrigin {phase_origin} differs from RAOOrigin {origin}: phases re-referred to the RAO "
                     "origin with the deep-water wavenumber")
    notes.append("OrcaFlex conventions: " + "; ".join(f"{k} {v}" for k, v in settings.items()))
    try:
        return make_table(omega, np.mod(np.radians(directions), 2 * math.pi), [0.0], values[None],
                          reference_point=origin, source=str(path), source_format="orcaflex", notes=tuple(notes))
    except HeadingError as error:
        raise FileFormatError(path, _line(raos), f"{error} (the file covers direction(s) "
                              f"{', '.join(f'{h:g}' for h in directions)} deg)") from None
    except ParameterError as error:
        raise FileFormatError(path, _line(raos), str(error)) from None


def _convert(values: np.ndarray, settings: dict[str, str]) -> np.ndarray:
    """(directions, frequencies, 6, 2) amplitude and phase as OrcaFlex gives them -> complex (directions,
    frequencies, 6) in marinesim's lead convention, m/m and rad/m, marinesim's positive directions."""
    amplitude, phase = values[..., 0].copy(), values[..., 1]
    if settings["RAOPhaseUnitsConvention"] == "degrees":
        phase = np.radians(phase)
    if settings["RAOResponseUnits"] == "degrees":
        amplitude[..., 3:] = np.radians(amplitude[..., 3:])
    if settings["RAOWaveUnit"] == "height":
        amplitude *= 2.0
    event = REFERENCE_EVENT[settings["RAOPhaseRelativeToConvention"]]
    lead = -phase if settings["RAOPhaseConvention"] == "lags" else phase
    h = amplitude * np.exp(1j * (lead - event))
    for key, (j, same, _) in POSITIVE.items():
        if settings[key] != same:
            h[..., j] = -h[..., j]
    return h


def _to_omega(x: np.ndarray, values: np.ndarray, kind: str) -> tuple[np.ndarray, np.ndarray, int]:
    """Frequencies (rad/s, increasing) of the column ``x`` (periods or frequencies), values reordered; rows of
    zero frequency (period 0 or infinity, frequency 0) dropped and counted."""
    with np.errstate(divide="ignore"):
        omega = {"period (s)": 2 * math.pi / x, "frequency (rad/s)": x, "frequency (hz)": 2 * math.pi * x}[kind]
    keep = np.isfinite(omega) & (omega > 0)
    order = np.argsort(omega[keep])
    return omega[keep][order], values[:, keep][:, order], int((~keep).sum())


def _tables(path: Path, node, parent, settings) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Directions (deg), the period/frequency column (file order of the first direction) and the values
    (directions, rows, 6, amplitude/phase) of the ``RAOs`` list."""
    yaml = _yaml()
    if node is None or not isinstance(node, yaml.SequenceNode) or not node.value:
        raise FileFormatError(path, _line(node if node is not None else parent), "DisplacementRAOs has no RAOs list")
    directions: list[float] = []
    first: np.ndarray | None = None
    tables = []
    total = 0
    for item in node.value:
        if not isinstance(item, yaml.MappingNode):
            raise FileFormatError(path, _line(item), "each RAOs entry must be a mapping with RAODirection and a table")
        direction_node = _get(path, item, "RAODirection")
        if direction_node is None:
            raise FileFormatError(path, _line(item), "RAOs entry without RAODirection")
        direction = _float(path, direction_node, "RAODirection (deg)")
        if not -360.0 <= direction <= 360.0:
            raise FileFormatError(path, _line(direction_node), f"RAODirection must be in -360..360 deg, got {direction:g}")
        table = _table_node(path, item)
        if not isinstance(table, yaml.SequenceNode) or not table.value:
            raise FileFormatError(path, _line(table), "the RAO table must be a list of rows")
        total += len(table.value)
        if total > MAX_ROWS:
            raise FileFormatError(path, _line(table), f"more than {MAX_ROWS} RAO rows")
        rows = np.empty((len(table.value), 13))
        for r, row in enumerate(table.value):
            if not isinstance(row, yaml.SequenceNode) or len(row.value) != 13:
                count = len(row.value) if isinstance(row, yaml.SequenceNode) else 1
                raise FileFormatError(path, _line(row), f"expected a row of 13 numbers ({', '.join(COLUMNS)}), "
                                                        f"got {count}")
            for c, cell in enumerate(row.value):
                rows[r, c] = _float(path, cell, COLUMNS[c], allow_infinity=c == 0)
            if np.any(rows[r, 1::2] < 0):
                raise FileFormatError(path, _line(row), "negative RAO amplitude")
            if rows[r, 0] < 0:
                raise FileFormatError(path, _line(row), f"{COLUMNS[0]} must be >= 0, got {rows[r, 0]:g}")
        if first is None:
            first = rows[:, 0]
        elif rows.shape[0] != first.size or np.any(rows[:, 0] != first):
            raise FileFormatError(path, _line(table), f"direction {direction:g}: the periods/frequencies differ from "
                                                      f"those of direction {directions[0]:g}")
        if direction in directions:
            raise FileFormatError(path, _line(direction_node), f"RAODirection {direction:g} given twice")
        if np.unique(rows[:, 0]).size != rows.shape[0]:
            raise FileFormatError(path, _line(table), f"direction {direction:g}: a period/frequency is repeated")
        directions.append(direction)
        tables.append(rows[:, 1:].reshape(-1, 6, 2))
    return np.array(directions), first, np.array(tables)


def _table_node(path: Path, item):
    """The value of the entry's table key (the 13 column names joined by commas, any spacing)."""
    for key, value in item.value:
        names = [n.strip() for n in _text(key).split(",")]
        if len(names) > 1:
            if names != COLUMNS:
                raise FileFormatError(path, _line(key), f"RAO table columns {', '.join(names)}: expected "
                                                        f"{', '.join(COLUMNS)}")
            return value
    raise FileFormatError(path, _line(item), f"RAOs entry without the table '{TABLE_KEY}'")


def _vessel_types(path: Path, root) -> list[tuple[str, object]]:
    """(name, node) of every vessel type: the ``VesselTypes`` list, or top-level objects with ``Draughts``."""
    yaml = _yaml()
    if not isinstance(root, yaml.MappingNode):
        raise FileFormatError(path, _line(root), "not an OrcaFlex data file (expected a mapping at the top)")
    listed = _get(path, root, "VesselTypes")
    if listed is not None:
        if not isinstance(listed, yaml.SequenceNode) or not listed.value:
            raise FileFormatError(path, _line(listed), "VesselTypes must be a non-empty list")
        return [(_name(node), node) for node in listed.value]
    found = [(_text(key), value) for key, value in root.value
             if isinstance(value, yaml.MappingNode) and _get(path, value, "Draughts") is not None]
    if not found:
        raise FileFormatError(path, None, "no VesselTypes (no vessel type with Draughts): not an OrcaFlex vessel "
                                          "type file")
    return found


def _pick(path: Path, items: list[tuple[str, object]], wanted: str | None, what: str, notes: list[str]):
    names = [name for name, _ in items]
    if wanted is None:
        if len(items) > 1:
            notes.append(f"{what} {names[0]!r} used (the file has {', '.join(map(repr, names))})")
        return items[0][1]
    for name, node in items:
        if name == wanted:
            return node
    raise ParameterError(f"{path}: no {what} {wanted!r}; the file has {', '.join(map(repr, names))}")


def _compose(path: Path):
    """The YAML node tree of ``path`` (size bounded first: :data:`~marinesim.formats.SIZE_LIMITS`); YAML errors name
    the line."""
    yaml = _yaml()
    check_file(path, "RAO file")
    text = read_text(path).lstrip("\ufeff")
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    try:
        documents = list(yaml.compose_all(text, Loader=loader))
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        problem = getattr(error, "problem", None) or str(error).splitlines()[0]
        raise FileFormatError(path, mark.line + 1 if mark else None, f"not valid YAML: {problem}") from None
    except RecursionError:
        raise FileFormatError(path, None, "YAML nested too deeply") from None
    documents = [d for d in documents if d is not None]
    if not documents:
        raise FileFormatError(path, None, "empty YAML file")
    return documents[0]


def _yaml():
    try:
        import yaml
    except ImportError:
        raise MarinesimError("reading OrcaFlex .yml files needs PyYAML: pip install pyyaml") from None
    return yaml


def _get(path: Path, node, key: str):
    """The value node of ``key`` in the mapping ``node`` (None if absent or ``node`` is not a mapping)."""
    if node is None or not isinstance(node, _yaml().MappingNode):
        return None
    for k, v in node.value:
        if isinstance(k, _yaml().ScalarNode) and k.value == key:
            return v
    return None


def _name(node) -> str:
    value = _get(None, node, "Name")
    return _text(value) if value is not None else ""


def _text(node) -> str:
    return str(node.value) if isinstance(node, _yaml().ScalarNode) else ""


def _line(node) -> int | None:
    return node.start_mark.line + 1 if node is not None and getattr(node, "start_mark", None) else None


def _float(path: Path, node, expected: str, allow_infinity: bool = False) -> float:
    if not isinstance(node, _yaml().ScalarNode):
        raise FileFormatError(path, _line(node), f"expected {expected} (a number)")
    text = node.value.strip()
    if allow_infinity and text.lower() in ("infinity", ".inf", "inf"):
        return math.inf
    return parse_float(path, _line(node), text, expected)


def _point(path: Path, node, default: tuple[float, ...], what: str) -> tuple[float, float, float]:
    """A point ``[x, y, z]`` (m); ``~`` entries (or no node) take ``default``'s."""
    if node is None:
        return tuple(default)
    if not isinstance(node, _yaml().SequenceNode) or len(node.value) != 3:
        raise FileFormatError(path, _line(node), f"{what} must be [x, y, z]")
    out = []
    for i, cell in enumerate(node.value):
        if isinstance(cell, _yaml().ScalarNode) and cell.value.strip() in ("~", "", "null"):
            out.append(float(default[i]))
        else:
            out.append(_float(path, cell, f"{what} coordinate (m)"))
    return tuple(out)
