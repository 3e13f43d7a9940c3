//! Bounding volume hierarchy (binned SAH, flattened compact nodes).
