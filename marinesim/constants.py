"""Physical constants (SI). Files that state their own g and rho override these for that file."""

G = 9.80665
"""Standard gravity, m/s^2 (CONVENTIONS.md)."""

RHO_SEAWATER = 1025.0
"""Sea-water density, kg/m^3."""

NAUTICAL_MILE = 1852.0
"""One nautical mile in m."""

KNOT = NAUTICAL_MILE / 3600.0
"""One knot in m/s."""
