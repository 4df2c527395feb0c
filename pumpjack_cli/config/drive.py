"""Schema of a unit file's ``[drive]``: the motor's nameplate, the V-belt and the gearbox, and the
core's drive built from them ([SK8Rotation2013] eqs. 25-26)."""

from __future__ import annotations

import math
from typing import Annotated

from pydantic import Field, model_validator

from ..core.dynamics.drive import belt_ratio, rated_crank_speed, total_ratio
from ..quantities import SPM_RANGE
from .quantities import Length, MomentOfInertia, Number, Power, RotationalSpeed, Section, at_least


class Motor(Section):
    """Induction motor nameplate data ([SK8Rotation2013] eqs. 25-26)."""

    model: str = Field(description="motor type designation")
    rated_power: Annotated[Power, at_least(10.0, "10 W")] = Field(gt=0, le=1e6, description="rated shaft power [W]")
    synchronous_speed: Annotated[RotationalSpeed, at_least(1.0, "1 rad/s")] = Field(gt=0, le=400, description="synchronous speed n_s [rad/s]")
    rated_speed: Annotated[RotationalSpeed, at_least(1.0, "1 rad/s")] = Field(gt=0, le=400, description="rated speed n_n [rad/s]")
    starting_torque_ratio: Number = Field(gt=0, le=10, description="starting torque / rated torque")
    breakdown_torque_ratio: Number = Field(gt=1, le=10, description="pull-out (maximum) torque / rated torque")
    rotor_inertia: MomentOfInertia = Field(gt=0, le=1e3, description="rotor moment of inertia [kg·m²]")

    @model_validator(mode="after")
    def _slip(self) -> "Motor":
        if not self.rated_speed < self.synchronous_speed:
            raise ValueError("rated_speed must be below synchronous_speed (an induction motor has slip)")
        return self


class Drive(Section):
    """Motor, V-belt drive and gearbox between the motor and the crank shaft."""

    motor: Motor
    gearbox: str = Field(description="gearbox type designation")
    gearbox_ratio: Number = Field(gt=1, le=200, description="gearbox reduction ratio u_r")
    motor_sheave_diameter: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=3, description="motor (driving) sheave diameter d_1 [m]")
    gearbox_sheave_diameter: Annotated[Length, at_least(0.01, "10 mm")] = Field(gt=0, le=5, description="gearbox (driven) sheave diameter d_2 [m]")
    motor_sheave_inertia: MomentOfInertia = Field(
        default=0.0, ge=0, le=1e3, description="motor (driving) sheave, on the motor shaft; 0: not counted [kg·m²]"
    )
    gearbox_sheave_inertia: MomentOfInertia = Field(
        default=0.0, ge=0, le=1e4, description="gearbox (driven) sheave, on the gearbox input shaft; 0: not counted [kg·m²]"
    )
    gearbox_inertia: MomentOfInertia = Field(
        default=0.0, ge=0, le=1e4,
        description="gears and shafts of the gearbox referred to its input shaft; 0: not counted [kg·m²]",
    )

    @model_validator(mode="after")
    def _pumping_speed(self) -> "Drive":
        spm = self.rated_crank_speed * 30.0 / math.pi
        if not SPM_RANGE[0] <= spm <= SPM_RANGE[1]:
            raise ValueError(f"motor, sheaves and gearbox turn the crank at {spm:.4g} strokes/min at the motor's rated "
                             f"speed, outside {SPM_RANGE[0]:g} .. {SPM_RANGE[1]:g}: check the sheave diameters and the "
                             f"gearbox ratio")
        return self

    @property
    def belt_ratio(self) -> float:
        """V-belt reduction u_belt = d_2 / d_1 (:func:`~pumpjack_cli.core.dynamics.drive.belt_ratio`)."""
        return belt_ratio(self.motor_sheave_diameter, self.gearbox_sheave_diameter)

    @property
    def total_ratio(self) -> float:
        """Motor speed / crank speed (:func:`~pumpjack_cli.core.dynamics.drive.total_ratio`)."""
        return total_ratio(self.gearbox_ratio, self.belt_ratio)

    @property
    def rated_crank_speed(self) -> float:
        """Crank speed at the motor's rated speed [1/s] (:func:`~pumpjack_cli.core.dynamics.drive.rated_crank_speed`)."""
        return rated_crank_speed(self.motor.rated_speed, self.total_ratio)
