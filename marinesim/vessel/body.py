"""The vessel as a rigid body, as a scenario may give it: mass, centre of gravity, radii of gyration, and external
stiffness and damping (moorings, a DP system's linear part, roll damping from tank tests).

Readers that solve the equation of motion (WAMIT force sets, Capytaine datasets) take it in place of the mass of
their own files, and add the external matrices: ``[-w^2 (M + A) + i w (B + B_ext) + C + C_ext] X = F``. The centre
of gravity is in the body frame (x forward, y port, z up, the waterline at z = 0); the mass matrix and the external
matrices are about the RAO table's reference point (the rotation centre of the file); SI units.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def rigid_body_mass(mass: float, cog: tuple[float, float, float], inertia: np.ndarray) -> np.ndarray:
    """The 6 x 6 rigid-body mass matrix about the origin: ``mass`` (kg) at ``cog`` (m, body frame), ``inertia``
    (3 x 3, kg m^2) about the origin."""
    x, y, z = cog
    skew = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    matrix = np.zeros((6, 6))
    matrix[:3, :3] = mass * np.eye(3)
    matrix[:3, 3:] = -mass * skew
    matrix[3:, :3] = mass * skew
    matrix[3:, 3:] = inertia
    return matrix


def gravity_stiffness(mass: np.ndarray, g: float) -> np.ndarray:
    """The restoring of the body's weight (6 x 6, SI, about the origin) for the 6 x 6 mass matrix ``mass``
    (:func:`rigid_body_mass`, which holds ``m`` and ``m x_g``): ``C44 = C55 = -m g z_g``, ``C46 = m g x_g``,
    ``C56 = m g y_g`` (WAMIT user manual, hydrostatics; the rest of the restoring is the water's)."""
    m_xg, m_yg, m_zg = mass[1, 5], -mass[0, 5], mass[0, 4]
    matrix = np.zeros((6, 6))
    matrix[3, 3] = matrix[4, 4] = -g * m_zg
    matrix[3, 5], matrix[4, 5] = g * m_xg, g * m_yg
    return matrix


@dataclass(frozen=True)
class RigidBody:
    """``mass_kg`` at ``cog_m`` with ``radii_of_gyration_m`` (roll, pitch, yaw, about the centre of gravity along
    the body axes), all three or none; ``external_stiffness`` and ``external_damping`` (6, 6), SI (N/m, N m/rad,
    N s/m, N m s/rad), or None."""

    mass_kg: float | None = None
    cog_m: tuple[float, float, float] | None = None
    radii_of_gyration_m: tuple[float, float, float] | None = None
    external_stiffness: np.ndarray | None = None
    external_damping: np.ndarray | None = None

    @property
    def given(self) -> bool:
        """Whether the scenario gave anything (a mass, or an external matrix)."""
        return not (self.mass_kg is None and self.external_stiffness is None and self.external_damping is None)

    def mass_matrix(self, about: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> np.ndarray | None:
        """The 6 x 6 mass matrix about the point ``about`` (the RAO table's reference point, body frame, m; the
        parallel-axis theorem from the centre of gravity), or None when no mass is given."""
        if self.mass_kg is None:
            return None
        m, c = self.mass_kg, np.asarray(self.cog_m, dtype=float) - np.asarray(about, dtype=float)
        at_cog = m * np.diag(np.square(self.radii_of_gyration_m))
        return rigid_body_mass(m, tuple(c), at_cog + m * (c @ c * np.eye(3) - np.outer(c, c)))

    def stiffness(self) -> np.ndarray:
        return np.zeros((6, 6)) if self.external_stiffness is None else np.asarray(self.external_stiffness, float)

    def damping(self) -> np.ndarray:
        return np.zeros((6, 6)) if self.external_damping is None else np.asarray(self.external_damping, float)

    def describe(self) -> str:
        """What the scenario gave, for the table's notes."""
        parts = []
        if self.mass_kg is not None:
            parts.append(f"mass {self.mass_kg:.6g} kg at ({', '.join(f'{v:g}' for v in self.cog_m)}) m, radii of "
                         f"gyration ({', '.join(f'{v:g}' for v in self.radii_of_gyration_m)}) m")
        if self.external_stiffness is not None:
            parts.append("external stiffness")
        if self.external_damping is not None:
            parts.append("external damping")
        return "from the scenario: " + ", ".join(parts)
