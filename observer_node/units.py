"""Units shared by every stage: one constant, so the run-time model needs nothing else.

Model convention (see :mod:`observer_node.data.crashtest` for the signs): accelerations in g,
deflections in mm, spindle angles in rad, times in s.
"""

STANDARD_GRAVITY = 9.80665  # m/s^2 per g (ISO 80000-3, the value SAE J211 uses)
