"""First-principles geometry: exact convex hulls, sections and clipping."""
