"""Rod tables: API steel sucker rods, sinker bars, API grades; building a string from sections.

* Steel sucker rods, weight per foot WITH couplings and elastic constant E_r, as
  printed in API RP 11L, 4th ed., Table 4.1 (columns 3 and 4) [API11L]. E_r is the
  stretch per unit load per unit length, 1/(E A), in in/(lb ft); we keep the table's
  value exactly by giving each size the modulus E = 1/(E_r A) on the nominal area
  (30.6-30.8 Mpsi: the couplings stiffen the string a little). With the coupling-
  inclusive mass these give a = sqrt(E A / m) = 16 350 ft/s for every size, RP 11L's
  "about 16 300 ft/s"; bare steel would give about 17 000 ft/s (RP 11L, A10).
* Sinker bars: solid steel bars of 1-1/4 to 2 in, the sizes of API Spec 11B [API11B],
  mass = rho_steel pi d^2 / 4 (the threaded ends are neglected), E of steel.
* Grades: minimum tensile strength of API Spec 11B grades K and C (90 000 psi) and
  D (115 000 psi), as stated by PetroWiki [PetroWikiRods] from [API11B].
* Fibreglass rods (API Spec 11C) have no table here: their modulus and weight per
  length differ by maker and size, so a fibreglass section must state both.

Conversions are the exact NIST SP 811 factors [NIST811].
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ...errors import DownholeError
from ..constants import STEEL_DENSITY
from .string import STEEL_YOUNGS_MODULUS, RodString

_INCH = 0.0254
_FOOT = 0.3048
_POUND_MASS = 0.45359237
_POUND_FORCE = 4.4482216152605
_PSI = _POUND_FORCE / _INCH**2

#: Diameters within this distance of a table size are that size [m] (rods given to the
#: nearest millimetre, 16/19/22/25/29 mm, are the API inch sizes).
DIAMETER_TOLERANCE = 0.6e-3

#: API RP 11L Table 4.1 [API11L]: size, diameter [in], weight with couplings [lb/ft],
#: elastic constant E_r [1e-6 in/(lb ft)].
_API_RODS = (
    ("5/8 in", 0.625, 1.135, 1.270),
    ("3/4 in", 0.750, 1.634, 0.883),
    ("7/8 in", 0.875, 2.224, 0.649),
    ("1 in", 1.000, 2.904, 0.497),
    ("1-1/8 in", 1.125, 3.676, 0.393),
)

#: Sinker-bar sizes of API Spec 11B [API11B]: size, diameter [in].
_SINKER_BARS = (
    ("1-1/4 in", 1.250), ("1-3/8 in", 1.375), ("1-1/2 in", 1.500),
    ("1-5/8 in", 1.625), ("1-3/4 in", 1.750), ("2 in", 2.000),
)

#: Minimum tensile strength of the API Spec 11B grades [psi] [PetroWikiRods].
_GRADES_PSI = {"K": 90_000.0, "C": 90_000.0, "D": 115_000.0}

#: Section kinds understood by :func:`rod_string`.
KINDS = ("steel", "sinker", "fibreglass")


@dataclass(frozen=True)
class RodSize:
    """One table entry, SI.

    Parameters
    ----------
    name : str
        Nominal size, e.g. ``"7/8 in"``.
    diameter : float
        d [m].
    mass_per_length : float
        m [kg/m], with couplings for sucker rods.
    youngs_modulus : float
        E [Pa] on the nominal area pi d^2 / 4.
    """

    name: str
    diameter: float
    mass_per_length: float
    youngs_modulus: float

    @property
    def area(self) -> float:
        """A = pi d^2 / 4 [m^2]."""
        return float(np.pi * self.diameter**2 / 4.0)


def _api_rod(name: str, inches: float, pounds_per_foot: float, elastic_constant: float) -> RodSize:
    diameter = inches * _INCH
    axial_stiffness = 1.0 / (elastic_constant * 1e-6 * _INCH / (_POUND_FORCE * _FOOT))   # E A [N]
    return RodSize(name, diameter, pounds_per_foot * _POUND_MASS / _FOOT,
                   axial_stiffness / (np.pi * diameter**2 / 4.0))


def _sinker_bar(name: str, inches: float) -> RodSize:
    diameter = inches * _INCH
    return RodSize(name, diameter, STEEL_DENSITY * np.pi * diameter**2 / 4.0, STEEL_YOUNGS_MODULUS)


#: API steel sucker rods, smallest first [API11L].
STEEL_RODS = tuple(_api_rod(*row) for row in _API_RODS)
#: Sinker bars, smallest first [API11B].
SINKER_BARS = tuple(_sinker_bar(*row) for row in _SINKER_BARS)


def _lookup(table: tuple[RodSize, ...], diameter: float, what: str) -> RodSize:
    sizes = np.array([size.diameter for size in table])
    if np.isfinite(diameter):
        index = int(np.argmin(np.abs(sizes - diameter)))
        if abs(sizes[index] - diameter) <= DIAMETER_TOLERANCE:
            return table[index]
    listing = ", ".join(f"{size.name} ({size.diameter * 1e3:.3f} mm)" for size in table)
    raise DownholeError(f"no {what} of diameter {diameter * 1e3:.4g} mm; the table has {listing}")


def steel_rod(diameter: float) -> RodSize:
    """The API steel sucker rod of this diameter [API11L].

    Parameters
    ----------
    diameter : float
        d [m]; within :data:`DIAMETER_TOLERANCE` of a table size.

    Returns
    -------
    RodSize
        Mass per length with couplings [kg/m] and the modulus [Pa] that reproduces E_r.

    Raises
    ------
    DownholeError
        For a diameter not in the table; the message lists the table.

    Examples
    --------
    7/8 in: 2.224 lb/ft = 3.310 kg/m; E_r = 0.649e-6 in/(lb ft) gives E A = (12 in/ft) / E_r
    = 18.49e6 lbf = 82.2 MN.

    >>> rod = steel_rod(0.022)
    >>> rod.name, round(rod.mass_per_length, 3), round(rod.youngs_modulus * rod.area / 1e6, 1)
    ('7/8 in', 3.31, 82.2)

    References
    ----------
    [API11L] (Table 4.1), [NIST811].
    """
    return _lookup(STEEL_RODS, diameter, "API steel sucker rod")


def sinker_bar(diameter: float) -> RodSize:
    """The API sinker bar of this diameter, solid steel [API11B].

    Examples
    --------
    1-1/2 in: 7850 kg/m^3 pi (0.0381 m)^2 / 4 = 8.95 kg/m (6.01 lb/ft; [API11B]: 6.0 lb/ft).

    >>> round(sinker_bar(0.0381).mass_per_length, 2)
    8.95

    References
    ----------
    [API11B], [Shigley2011].
    """
    return _lookup(SINKER_BARS, diameter, "API sinker bar")


def mass_per_length(diameter: float, kind: str = "steel") -> float:
    """Mass per unit length of a table section [kg/m], couplings included for rods.

    Parameters
    ----------
    diameter : float
        d [m].
    kind : str
        ``"steel"`` (API sucker rod, [API11L]) or ``"sinker"`` (sinker bar, [API11B]).
    """
    if kind == "steel":
        return steel_rod(diameter).mass_per_length
    if kind == "sinker":
        return sinker_bar(diameter).mass_per_length
    raise DownholeError(f"no table of mass per length for rod kind {kind!r}; tables: 'steel', 'sinker'")


def tensile_strength(grade: str) -> float:
    """Minimum tensile strength of an API Spec 11B grade [Pa] [PetroWikiRods].

    >>> round(tensile_strength("D") / 1e6, 1)   # 115 000 psi
    792.9

    References
    ----------
    [PetroWikiRods], [API11B].
    """
    key = str(grade).strip().upper()
    if key not in _GRADES_PSI:
        raise DownholeError(f"unknown rod grade {grade!r}; known grades: {', '.join(_GRADES_PSI)}")
    return _GRADES_PSI[key] * _PSI


@dataclass(frozen=True)
class RodSection:
    """One taper as a user describes it; :func:`rod_string` fills in the table data.

    Parameters
    ----------
    diameter : float
        d [m].
    length : float
        L [m] (the caller turns fractions of the pump depth into lengths).
    kind : str
        ``"steel"`` (API sucker rod), ``"sinker"`` (sinker bar) or ``"fibreglass"``.
    grade : str, optional
        API grade (K, C, D) giving the tensile strength.
    youngs_modulus : float, optional
        E [Pa], overrides the table (required for fibreglass).
    mass_per_length : float, optional
        m [kg/m] with couplings, overrides the table (required for fibreglass).
    tensile_strength : float, optional
        Minimum tensile strength [Pa], instead of a grade.
    material_density : float, optional
        Density of the solid for buoyancy [kg/m^3]; default steel, or m / A for
        fibreglass (the body volume displaces the fluid).
    """

    diameter: float
    length: float
    kind: str = "steel"
    grade: str | None = None
    youngs_modulus: float | None = None
    mass_per_length: float | None = None
    tensile_strength: float | None = None
    material_density: float | None = None


def _section_data(section: RodSection, index: int) -> tuple[str, float, float, float, float, float]:
    where = f"rod section {index + 1}"
    if section.kind not in KINDS:
        raise DownholeError(f"{where}: unknown kind {section.kind!r}; kinds: {', '.join(KINDS)}")
    if not (np.isfinite(section.diameter) and section.diameter > 0):
        raise DownholeError(f"{where}: diameter must be finite and positive, got {section.diameter:g} m")
    area = float(np.pi * section.diameter**2 / 4.0)
    if section.kind == "fibreglass":
        if section.youngs_modulus is None or section.mass_per_length is None:
            raise DownholeError(f"{where}: a fibreglass section needs its Young's modulus and mass per length")
        if section.grade is not None:
            raise DownholeError(f"{where}: API steel grades do not apply to fibreglass; give tensile_strength")
        name = f"{section.diameter * 1e3:.4g} mm fibreglass"
        modulus, mass = section.youngs_modulus, section.mass_per_length
        density = mass / area if section.material_density is None else section.material_density
    else:
        size = steel_rod(section.diameter) if section.kind == "steel" else sinker_bar(section.diameter)
        name = size.name if section.kind == "steel" else f"{size.name} sinker bar"
        area = size.area
        modulus = size.youngs_modulus if section.youngs_modulus is None else section.youngs_modulus
        mass = size.mass_per_length if section.mass_per_length is None else section.mass_per_length
        density = STEEL_DENSITY if section.material_density is None else section.material_density
    if section.grade is not None and section.tensile_strength is not None:
        raise DownholeError(f"{where}: give a grade or a tensile strength, not both")
    strength = np.nan
    if section.grade is not None:
        strength = tensile_strength(section.grade)
        name = f"{name} {section.grade.strip().upper()}"
    elif section.tensile_strength is not None:
        strength = section.tensile_strength
    return name, area, modulus, mass, density, strength


def rod_string(sections: Sequence[RodSection]) -> RodString:
    """Build a :class:`RodString` from sections listed from the polished rod down.

    Parameters
    ----------
    sections : sequence of RodSection
        The tapers, top first.

    Returns
    -------
    RodString
        With nominal areas, table masses and moduli unless overridden, material
        densities for buoyancy and the grades' tensile strengths (NaN if not given).

    Raises
    ------
    DownholeError
        For an empty list, a size not in the tables, a fibreglass section without
        modulus or mass, an unknown grade, or non-positive values.

    Examples
    --------
    The 1530 m string of [SK8Rotation2013], 25/22/19 mm with 23/26/51 %:

    >>> s = rod_string([RodSection(0.025, 351.9), RodSection(0.022, 397.8), RodSection(0.019, 780.3)])
    >>> s.names, round(s.total_length, 1)
    (('1 in', '7/8 in', '3/4 in'), 1530.0)

    References
    ----------
    [API11L], [API11B], [PetroWikiRods].
    """
    if len(sections) == 0:
        raise DownholeError("a rod string needs at least one section")
    rows = [_section_data(section, index) for index, section in enumerate(sections)]
    names, area, modulus, mass, density, strength = zip(*rows)
    return RodString(length=np.array([section.length for section in sections]), area=np.array(area),
                     youngs_modulus=np.array(modulus), mass_per_length=np.array(mass),
                     material_density=np.array(density), tensile_strength=np.array(strength), names=names)
