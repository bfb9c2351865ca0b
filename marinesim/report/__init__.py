"""The debrief: what an exercise run shows, and its after-action report."""
