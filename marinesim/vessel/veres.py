"""VERES (ShipX) ``.re1`` motion transfer functions -> :class:`RaoTable`.

Layout: six title lines; ``RHO G``; ``LPP B T``; ``LCG VCG``; ``NVEL NHEAD NFREQ NDOF``; then
for each speed ``VEL SINK TRIM XMTN ZMTN`` and, for each heading, ``HEAD``, then for each
frequency ``FREQ`` followed by NDOF lines ``I RE IM``.

The source convention, established from the files in ``rao/`` (``tests/test_vessel_readers.py``
repeats each check on the S175 and the supply vessel):

* ``FREQ`` is the **wave** frequency in rad/s, the same list at every speed. At the lowest
  frequency |pitch| / k(FREQ) stays at 1.02 in following seas and within 10 % (1.09) in head
  seas for every speed up to 20 kn; read as encounter frequency the ratio would rise to 1.32
  in head seas and fall to 0.78 in following seas at 20 kn.
* ``HEAD`` is the direction the waves travel towards relative to the bow in degrees, 0 following,
  90 towards port, 180 head seas (marinesim's ``beta_rel``): at speed the head-sea pitch peak
  moves to lower wave frequency (higher encounter frequency) and the following-sea heave at
  0.6 rad/s rises towards the quasi-static 1 (encounter frequency near zero).
* Phases lead with time factor ``exp(+i w t)``: surge tends to ``-i`` in following seas, sway
  to ``-i`` and roll to ``-i k`` for waves towards port, as marinesim's long-wave limits.
* Rotations are in rad/m (pitch / k -> 1; in deg/m it would be 57).

So the only conversion is degrees -> radians for ``HEAD``. The reference point is the motion
reference ``(XMTN, 0, ZMTN)`` in VERES's frame (x from midships, z above the baseline). ``LPP`` and ``T`` are kept
as the table's ``length`` and ``draft``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError, ParameterError
from marinesim.vessel.rao import RaoTable, make_table
from marinesim.tokens import Tokens, by_content, read_text

TITLE_LINES = 6
MAGIC = "MOTION TRANSFER FUNCTIONS"


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes hold VERES's title :data:`MAGIC`."""
    return MAGIC in head.decode("utf-8", errors="replace").upper()


@by_content
def read_veres(path: str | Path) -> RaoTable:
    """Read a VERES ``.re1`` file (all speeds, headings and frequencies it holds)."""
    path = Path(path)
    lines = read_text(path).splitlines()
    if len(lines) <= TITLE_LINES:
        raise FileFormatError(path, len(lines) or None, f"file ends in the {TITLE_LINES} title lines")
    if MAGIC not in lines[0].upper():
        raise FileFormatError(path, 1, f"expected the title {MAGIC!r}")
    tokens = Tokens(path, lines, TITLE_LINES)
    rho, g = tokens.float("RHO (kg/m^3)"), tokens.float("G (m/s^2)")
    lpp, beam, draught = (tokens.float(name) for name in ("LPP (m)", "B (m)", "T (m)"))
    lcg, vcg = tokens.float("LCG (m)"), tokens.float("VCG (m)")
    counts = [tokens.int(name) for name in ("NVEL", "NHEAD", "NFREQ", "NDOF")]
    line = tokens.line
    if min(counts) < 1 or max(counts) > 10_000:
        raise FileFormatError(path, line - 1, f"NVEL NHEAD NFREQ NDOF must be 1..10000, got {counts}")
    nvel, nhead, nfreq, ndof = counts
    if ndof != 6:
        raise FileFormatError(path, line - 1, f"expected NDOF = 6 (all rigid-body modes), got {ndof}")
    if rho <= 0 or g <= 0:
        raise FileFormatError(path, TITLE_LINES + 1, f"RHO and G must be > 0, got {rho:g} {g:g}")
    needed = nvel * (5 + nhead * (1 + nfreq * (1 + 6 * 3)))
    if needed > tokens.remaining:  # refused before the table is allocated
        raise FileFormatError(path, line - 1, f"file ends early: expected {needed} numbers for NVEL NHEAD NFREQ NDOF "
                                              f"{counts}, the file holds {tokens.remaining}")
    speeds, heads, freqs = [], None, None
    values = np.zeros((nvel, nhead, nfreq, 6), dtype=complex)
    reference = (0.0, 0.0, 0.0)
    for v in range(nvel):
        line = tokens.line
        speed = tokens.float("VEL (m/s)")
        for name in ("SINK", "TRIM"):
            tokens.float(name)
        reference = (tokens.float("XMTN (m)"), 0.0, tokens.float("ZMTN (m)"))
        if speeds and speed <= speeds[-1]:
            raise FileFormatError(path, line, f"speed {speed:g} m/s after {speeds[-1]:g}: speeds must increase")
        if speed < 0:
            raise FileFormatError(path, line, f"speed must be >= 0 m/s, got {speed:g}")
        speeds.append(speed)
        these_heads = []
        for h in range(nhead):
            line = tokens.line
            head = tokens.float("HEAD (deg)")
            if not 0.0 <= head <= 360.0:
                raise FileFormatError(path, line, f"heading must be in 0..360 deg, got {head:g}")
            if these_heads and head <= these_heads[-1]:
                raise FileFormatError(path, line, f"heading {head:g} after {these_heads[-1]:g}: "
                                                  "headings must increase")
            if heads is not None and head != heads[h]:
                raise FileFormatError(path, line, f"heading {head:g} differs from {heads[h]:g} at the first speed")
            these_heads.append(head)
            these_freqs = []
            for f in range(nfreq):
                line = tokens.line
                freq = tokens.float("FREQ (rad/s)")
                if freq <= 0 or (these_freqs and freq <= these_freqs[-1]):
                    raise FileFormatError(path, line, f"frequency {freq:g} rad/s: frequencies must be > 0 "
                                                      "and increase (no duplicates)")
                if freqs is not None and freq != freqs[f]:
                    raise FileFormatError(path, line, f"frequency {freq:g} differs from {freqs[f]:g} "
                                                      "at the first speed and heading")
                these_freqs.append(freq)
                for dof in range(1, 7):
                    line = tokens.line
                    index = tokens.int(f"DOF number {dof}")
                    if index != dof:
                        raise FileFormatError(path, line, f"expected DOF number {dof}, got {index}")
                    values[v, h, f, dof - 1] = complex(tokens.float(f"Re of DOF {dof}"),
                                                       tokens.float(f"Im of DOF {dof}"))
            freqs = freqs or these_freqs
        heads = heads or these_heads
    if not tokens.at_end():
        raise FileFormatError(path, tokens.line, "unexpected data after the last table")
    notes = (f"VERES {lines[2].strip()}; Lpp {lpp:g} m, B {beam:g} m, T {draught:g} m, "
             f"LCG {lcg:g} m, VCG {vcg:g} m; reference point (XMTN, 0, ZMTN)",)
    try:
        return make_table(np.array(freqs), np.radians(heads), np.array(speeds), values, reference_point=reference,
                          rho=rho, g=g, source=str(path), source_format="veres", notes=notes, draft=draught,
                          length=lpp)
    except ParameterError as error:
        raise FileFormatError(path, None, str(error)) from None
