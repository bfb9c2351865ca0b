"""Station keeping: environmental loads (wind, current, wave drift), dynamic positioning and moorings."""
