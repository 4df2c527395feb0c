"""The sucker-rod string: its sections and the damped wave equation along it."""
