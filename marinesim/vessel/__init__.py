"""The vessel: RAO tables from real programs and the 6-DOF response they give in the ocean.

``read_rao`` reads WAMIT, VERES, Capytaine and marinesim's own tables into :class:`RaoTable`
(internal convention, docs/CONVENTIONS.md); :class:`Response` turns the ocean's wave components
and a :class:`Track` into motions of the vessel and of points on board.
"""

from marinesim.vessel.rao import DOFS, RaoTable, long_wave_limit, make_table
from marinesim.vessel.read import read_rao
from marinesim.vessel.response import Response, Track, motion_columns

__all__ = ["DOFS", "RaoTable", "Response", "Track", "long_wave_limit", "make_table", "motion_columns",
           "read_rao"]
