"""Pumping-unit designations: API Spec 11E and GOST 5866-76, parsed into SI ratings.

Pure Python (no numpy, no pydantic): ``pumpjack units`` and config validation may call
it at no start-up cost.

API Spec 11E ([API11E]; [Guo2007] p. 12/163; [PetroWikiUnits]), e.g. ``C-228D-213-86``:

* first field, the unit type: C conventional (crank-balanced, class I lever), M Mark II,
  A air-balanced, B beam-balanced ([Guo2007]: "B is for beam counterbalance units"); a
  maker's own letters (Lufkin's RM for reverse-mark units, [LufkinRM]) are declared by the
  unit kind that models them and passed in as ``types``;
* second field, the gear-reducer (gearbox) peak torque rating in thousands of lbf·in,
  followed by D for a double-reduction reducer ([Guo2007]); no other letter is defined
  in the sources read, so a field without a letter has ``reduction = None`` (not
  stated) and any other letter is rejected. A letter P in front of the number appears
  in [Guo2007] Table 12.1 (``C-P57D-76-54``); its meaning is not stated there, so it is
  kept in ``reducer_code`` and not interpreted;
* third field, the structure (polished-rod load) rating in hundreds of lbf;
* fourth field, the maximum stroke in inches.

GOST 5866-76 ([GOST5866]), e.g. ``SK8-3,5-4000`` = ``СК8-3,5-4000``: ``SK x - y - z`` with
x the largest permissible load on the polished rod in tonne-force (tf), y the largest
stroke in metres and z the largest torque on the gearbox output shaft in kgf·m. The
standard's nominal SI labels round g to 10 m/s² (8 tf "= 80 kN", 4000 kgf·m "= 40 kN·m");
this module converts exactly (1 tf = 9806.65 N, 1 kgf·m = 9.80665 N·m), so SK8 is
78 453.2 N and 39 226.6 N·m. A number in front of SK (the 7 of ``7SK12-2,5-5600``, the
unit of [Spatial7SK12]) is kept as ``series``: the sources reachable for this project
do not say what it means (it is not part of the GOST 5866-76 ratings), so it is not
interpreted. Latin or Cyrillic letters, either case, and a decimal comma or point are
accepted; dashes may be -, – or —.

Conversions: lbf = 4.4482216152605 N, in = 0.0254 m ([NIST811]), kgf = g_n·1 kg with
g_n = 9.80665 m/s² ([BIPM2019]).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass

from ..errors import DesignationError
from .constants import STANDARD_GRAVITY

#: Pound-force [N] and inch [m], exact by definition ([NIST811], Appendix B).
POUND_FORCE = 4.4482216152605
INCH = 0.0254

API = "API Spec 11E"
GOST = "GOST 5866-76"

#: API Spec 11E unit-type letters ([Guo2007] p. 12/163) and the kinds they name (the ``[geometry] class``
#: of a unit file). A maker's own letters (RM, Lufkin's reverse-mark) are declared by the kind that
#: models them (:data:`pumpjack_cli.config.unit_classes.UNIT_CLASSES`), which passes its letters here.
API_TYPES = {"C": "conventional", "M": "mark-ii", "A": "air-balanced", "B": "beam-balanced"}

_DASH = r"\s*[-\u2013\u2014]+\s*"
_NUMBER = r"[0-9]+(?:[.,][0-9]+)?"
_API = re.compile(
    rf"^(?P<cls>[A-Z]{{1,2}}){_DASH}(?P<reducer>(?P<prefix>P?)(?P<torque>{_NUMBER})(?P<letter>[A-Z]?))"
    rf"{_DASH}(?P<structure>{_NUMBER}){_DASH}(?P<stroke>{_NUMBER})$",
    re.IGNORECASE,
)
_GOST = re.compile(
    rf"^(?P<series>[0-9]+)?\s*[S\u0421][K\u041a]\s*(?P<load>{_NUMBER}){_DASH}(?P<stroke>{_NUMBER}){_DASH}"
    rf"(?P<torque>{_NUMBER})$",
    re.IGNORECASE,
)

EXPECTED = (
    "expected an API Spec 11E designation such as C-228D-213-86 (type C, M, A or B - reducer rating "
    "in 1000 lbf·in, D for double reduction - structure rating in 100 lbf - maximum stroke in in) or a "
    "GOST 5866-76 one such as SK8-3,5-4000 (SK or СК, load in tf - maximum stroke in m - gearbox torque "
    "in kgf·m)"
)


@dataclass(frozen=True)
class Ratings:
    """A unit's ratings: gearbox (reducer) peak torque [N·m], structure (polished-rod load) [N]
    and maximum stroke [m]; None where unknown."""

    gearbox_torque: float | None
    structure_load: float | None
    max_stroke: float | None


@dataclass(frozen=True)
class Designation:
    """Ratings read from a unit designation, SI.

    ``gearbox_torque`` [N·m]: peak torque rating of the gear reducer (output shaft);
    ``structure_load`` [N]: largest polished-rod load of the structure;
    ``max_stroke`` [m]: largest polished-rod stroke; ``family``: ``API Spec 11E`` or
    ``GOST 5866-76``; ``unit_class``: the kind the type letters name (conventional, mark-ii,
    air-balanced, beam-balanced, or a maker's kind such as reverse-mark; GOST 5866-76 SK
    units are rear-mounted class I units, reported as conventional); ``reduction``: ``double`` when the API reducer field ends in D, None
    when not stated; ``reducer_code``: the API reducer field as printed; ``series``: the
    number before SK of a GOST designation (meaning unknown, see the module notes).
    """

    text: str
    family: str
    unit_class: str
    gearbox_torque: float
    structure_load: float
    max_stroke: float
    reduction: str | None = None
    reducer_code: str | None = None
    series: int | None = None


def _positive(text: str, value: str, quantity: str) -> float:
    number = float(value.replace(",", "."))
    if not number > 0:
        raise DesignationError(f"unit designation {text!r}: the {quantity} is {value}; it must be positive")
    return number


def _api(text: str, match: re.Match, types: Mapping[str, str]) -> Designation:
    letter = match["cls"].upper()
    if letter not in types:
        raise DesignationError(f"unit designation {text!r}: unknown API unit type {match['cls']!r} "
                               f"(types: {', '.join(types)}); {EXPECTED}")
    reduction_letter = match["letter"].upper()
    if reduction_letter not in ("", "D"):
        raise DesignationError(
            f"unit designation {text!r}: unknown reducer letter {match['letter']!r} after the torque rating "
            f"(D = double reduction); {EXPECTED}"
        )
    if "," in match.group(0):
        raise DesignationError(f"unit designation {text!r}: API designations use a decimal point, not a comma")
    return Designation(
        text=text,
        family=API,
        unit_class=types[letter],
        gearbox_torque=_positive(text, match["torque"], "reducer rating") * 1e3 * POUND_FORCE * INCH,
        structure_load=_positive(text, match["structure"], "structure rating") * 100.0 * POUND_FORCE,
        max_stroke=_positive(text, match["stroke"], "maximum stroke") * INCH,
        reduction="double" if reduction_letter == "D" else None,
        reducer_code=match["reducer"].upper(),
    )


def _gost(text: str, match: re.Match) -> Designation:
    if not match["torque"].isdigit():
        raise DesignationError(
            f"unit designation {text!r}: the gearbox torque {match['torque']!r} kgf·m must be a whole number "
            f"(GOST 5866-76 torques are; a comma there may be a thousands separator)"
        )
    return Designation(
        text=text,
        family=GOST,
        unit_class="conventional",
        gearbox_torque=_positive(text, match["torque"], "gearbox torque") * STANDARD_GRAVITY,
        structure_load=_positive(text, match["load"], "polished-rod load") * 1e3 * STANDARD_GRAVITY,
        max_stroke=_positive(text, match["stroke"], "maximum stroke"),
        series=int(match["series"]) if match["series"] else None,
    )


def parse_designation(text: str, types: Mapping[str, str] = API_TYPES) -> Designation:
    """The ratings of an API Spec 11E or GOST 5866-76 unit designation, in SI.

    Parameters
    ----------
    text : str
        The designation, e.g. ``C-228D-213-86``, ``M-912D-427-192``, ``SK8-3,5-4000``,
        ``7СК12-2,5-5600``.
    types : mapping of str to str
        The unit-type letters of an API designation (upper case) and the kind each names;
        API 11E's own by default, the unit kinds' (:mod:`pumpjack_cli.config.unit_classes`)
        when a unit file is read.

    Returns
    -------
    Designation
        Gearbox torque rating [N·m], structure load rating [N], maximum stroke [m],
        unit class, reduction and family.

    Raises
    ------
    DesignationError
        The text matches neither form; the message names it and both expected forms.

    References
    ----------
    [API11E]; [Guo2007] p. 12/163; [PetroWikiUnits]; [GOST5866]; [NIST811].

    Examples
    --------
    228 000 lbf·in x 0.1129848 N·m/(lbf·in) = 25 760.5 N·m; 21 300 lbf = 94 747.1 N;
    86 in = 2.1844 m (hand arithmetic with the [NIST811] factors):

    >>> api = parse_designation("C-228D-213-86")
    >>> api.unit_class, api.reduction, round(api.gearbox_torque, 1), round(api.structure_load, 1), api.max_stroke
    ('conventional', 'double', 25760.5, 94747.1, 2.1844)

    8 tf = 8000 x 9.80665 N = 78 453.2 N; 4000 kgf·m = 39 226.6 N·m:

    >>> gost = parse_designation("СК8-3,5-4000")
    >>> round(gost.structure_load, 1), gost.max_stroke, round(gost.gearbox_torque, 1), gost.family
    (78453.2, 3.5, 39226.6, 'GOST 5866-76')
    """
    if not isinstance(text, str):
        raise DesignationError(f"unit designation {text!r} is not text; {EXPECTED}")
    stripped = text.strip()
    match = _API.match(stripped)
    if match:
        return _api(stripped, match, types)
    match = _GOST.match(stripped)
    if match:
        return _gost(stripped, match)
    raise DesignationError(f"unknown unit designation {stripped!r}: {EXPECTED}")
