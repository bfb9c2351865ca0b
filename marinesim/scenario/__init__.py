"""Scenario files (TOML): what sea, which ocean, how long; validated before anything runs."""

from marinesim.scenario.model import OceanOptions, RunOptions, reference
from marinesim.scenario.schema import Scenario, load_scenario, with_run

__all__ = ["OceanOptions", "RunOptions", "Scenario", "load_scenario", "reference", "with_run"]
