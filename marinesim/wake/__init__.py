"""The Kelvin wake: Tuck's amplitude function over the hull, wave resistance, the far-field wake."""

from marinesim.wake.amplitude import tuck_amplitude, wave_resistance, wavenumber

__all__ = ["tuck_amplitude", "wave_resistance", "wavenumber"]
