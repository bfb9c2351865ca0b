"""marinesim: ship motion and wake simulator (waves, RAO response, Kelvin wake, rendering)."""

__version__ = "0.1.0"
