"""Physical constants used by the numerical core, each with its source.

This module imports nothing, so any layer may use it without start-up cost.
"""

#: Standard acceleration of gravity g_n [m/s^2], the conventional value adopted by the
#: 3rd CGPM (1901) [BIPM2019].
STANDARD_GRAVITY = 9.80665
