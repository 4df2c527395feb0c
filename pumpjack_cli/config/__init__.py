"""Validated unit configs: the field types, one schema per machine kind, and the files.

* :mod:`.quantities`: field types (SI floats parsed from values with units);
* :mod:`.geometry_names`: GOST names and API 11E letters ([API11E]) of the geometry (pure Python);
* :mod:`.beam_unit`: the beam pumping unit (geometry, masses, drive, well, ...);
* :mod:`.slider_crank`: slider-crank machines (drill pumps; [InertiaUNB600A]);
* :mod:`.files`: the registry of kinds, validating and loading unit files (read by
  :mod:`pumpjack_cli.readers.unit_files`).

The names below are imported lazily, so that ``import pumpjack_cli.config`` costs
nothing until a schema is used.
"""

from __future__ import annotations

import importlib

_EXPORTS = {
    "load_unit": "files", "load_any_unit": "files", "read_unit_file": "files", "parse_unit": "files",
    "bundled_units": "files", "unit_listing": "files", "format_validation_error": "files", "error_message": "files",
    "UNIT_KINDS": "files",
    "UnitConfig": "beam_unit", "ConventionalGeometry": "conventional", "Masses": "masses", "Drive": "drive",
    "Motor": "drive", "Well": "well", "Deviations": "beam_unit", "PitmanSectionConfig": "beam_unit",
    "SliderCrankConfig": "slider_crank", "SteppedSlider": "slider_crank",
}


def __getattr__(name: str):
    if name not in _EXPORTS:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f".{_EXPORTS[name]}", __name__), name)
