//! Exact event-driven billiards physics.
