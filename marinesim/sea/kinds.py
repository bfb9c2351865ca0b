"""The names users give wave spectra and directional spreading (CLI options, scenario keys).

Kept apart from the builders, which import scipy, so that the command line lists them at once.
"""

SPECTRUM_TYPES = ("jonswap", "pm", "tma", "regular")
SPREADING_TYPES = ("cos2s", "mitsuyasu", "cos2n-halfplane", "long-crested")
