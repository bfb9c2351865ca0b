"""Engineering studies over many sea states: scatter diagrams, operability, their time-domain checks."""
