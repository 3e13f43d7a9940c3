//! Axis-aligned bounding boxes.
