// Replaced by the simulation core.
