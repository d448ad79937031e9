"""Scene construction (paper §3.3): floor plans, object selection, relation checks, layout, export."""
