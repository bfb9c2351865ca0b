"""Motion criteria for operations and training: each formula in one module with its source
(REFERENCES section 8), the quantities a scenario's ``[[criteria]]`` name, and the running monitor
that evaluates them over a motion record."""
