"""Physical constants used by the numerical core, each with its source.

This module imports nothing, so any layer may use it without start-up cost.
"""

#: Standard acceleration of gravity g_n [m/s^2], the conventional value adopted by the
#: 3rd CGPM (1901) [BIPM2019].
STANDARD_GRAVITY = 9.80665

#: Density of steel sucker rods and sinker bars for their buoyancy [kg/m^3]: 490 lb/ft^3,
#: the steel of [API11L], whose buoyancy factor 1 - 0.128 G is 1 - 62.4 G / 490 rounded.
STEEL_DENSITY = 7850.0
