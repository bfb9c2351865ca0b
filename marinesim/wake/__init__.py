"""The Kelvin wake: Tuck's amplitude function over the hull, wave resistance, the far-field wake."""

from marinesim.wake.amplitude import amplitude, wave_resistance, wavenumber

__all__ = ["amplitude", "wave_resistance", "wavenumber"]
