"""Standard motor sizes: the NEMA horsepower ratings a beam-pump motor is chosen from.

A beam pumping unit is driven by a NEMA design D induction motor (high slip, high
starting torque, [DurhamLockard1988]); its nameplate rating is chosen from the standard
horsepower ratings of polyphase induction motors, NEMA MG 1 section 10.32.4 ([NEMAMG1]),
the same steps as the motor rows of the full-load-current table of the National
Electrical Code, Table 430.250 ([NEC430250]). The size that covers a duty is the smallest
rating not below the motor power the RMS-equivalent rule asks for
(:mod:`pumpjack_cli.core.beam.loading`).
"""

from __future__ import annotations

from ..quantities import HORSEPOWER

#: Standard horsepower ratings of polyphase induction motors, 1 to 500 hp ([NEMAMG1] 10.32.4;
#: [NEC430250]).
NEMA_HORSEPOWER = (1.0, 1.5, 2.0, 3.0, 5.0, 7.5, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 75.0, 100.0, 125.0,
                   150.0, 200.0, 250.0, 300.0, 350.0, 400.0, 450.0, 500.0)


def nema_motor_size(power: float) -> float | None:
    """The smallest standard NEMA rating [W] not below ``power`` [W]; None above 500 hp.

    >>> round(nema_motor_size(24.9 * HORSEPOWER) / HORSEPOWER, 6), round(nema_motor_size(12.2 * HORSEPOWER) / HORSEPOWER, 6)
    (25.0, 15.0)
    >>> nema_motor_size(501 * HORSEPOWER) is None
    True
    """
    if not power >= 0:
        raise ValueError(f"motor power must be >= 0, got {power!r} W")
    for rating in NEMA_HORSEPOWER:
        if rating * HORSEPOWER >= power * (1.0 - 1e-12):
            return rating * HORSEPOWER
    return None
