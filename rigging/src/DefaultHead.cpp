// Replaced by the default-head converter.
