"""Scenario files (TOML): what sea, which ocean, how long; validated before anything runs."""

from marinesim.scenario.schema import OceanOptions, RunOptions, Scenario, load_scenario

__all__ = ["OceanOptions", "RunOptions", "Scenario", "load_scenario"]
