"""The options of a batch run and the analyses of one card, as the single commands run them.

The units are loaded once per worker process and the exact torque's responses once per
unit and grid (:func:`..torque._exact_basis`), so the per-card work is the card's own.
:func:`analyse_chunk` is what every executor runs (a local process or a Dask worker): jobs
in, plain data out.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from ...errors import PumpjackError, collected_warnings
from ...readers.manifest import Job
from ...readers.unit_files import read_table
from ...results import check_finite, converted_summary

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ...config.beam_unit import UnitConfig

#: Analyses a card can go through, in the order they run.
ANALYSES = ("torque", "downhole")
#: Crank positions of the per-angle table the batch does not keep (the summaries are
#: computed on their own fixed grid and do not depend on it).
STEPS = 4


@dataclass(frozen=True)
class Options:
    """Options that apply to every card: the analyses and their settings (damping: Gibbs'
    factor nu [-], None for the unit file's or the energy balance's)."""

    analyses: tuple[str, ...] = ANALYSES
    method: str = "api"
    balance: str = "equal-peaks"
    damping: float | None = None
    #: Units of card columns whose header names none ("si", "field"); None refuses them.
    card_units: str | None = None

    def for_analysis(self, analysis: str) -> dict:
        """The options that change an analysis' result (for the options hash; without
        --card-units the hash is that of a store written before the option existed)."""
        chosen = {"method": self.method, "balance": self.balance} if analysis == "torque" else {"damping": self.damping}
        return chosen if self.card_units is None else {**chosen, "card_units": self.card_units}


@dataclass(frozen=True)
class Outcome:
    """One analysis of one card: ``ok`` with the summary (SI, suffixed names) or ``error`` with the message."""

    analysis: str
    status: str
    error: str
    warnings: str
    summary: dict


_UNITS: dict = {}


def _unit(job: Job):
    """The unit of a job with its overrides, loaded once per process."""
    key = (job.unit, job.counterbalance_moment, job.rod_string)
    if key not in _UNITS:
        from ...config import load_unit

        unit = load_unit(job.unit)
        if job.counterbalance_moment is not None:
            unit = _with_moment(unit, job.counterbalance_moment)
        if job.rod_string is not None:
            unit = _with_rod_string(unit, job.rod_string)
        _UNITS[key] = unit
    return _UNITS[key]


def _with_moment(unit: UnitConfig, moment: float):
    """The unit whose API counterbalance moment is ``moment`` [N·m] (B and tau kept)."""
    balance, _ = unit.counterbalance_model()
    section = {"structural_unbalance": balance.structural_unbalance, "moment": moment, "phase": balance.offset}
    data = unit.model_dump(by_alias=True)
    data["counterbalance"] = section
    return type(unit).model_validate(data)


def _with_rod_string(unit: UnitConfig, path: str):
    """The unit whose ``[well].rod_string`` is the one in the file ``path``."""
    if unit.well is None:
        raise PumpjackError(f"unit {unit.name} has no [well] section for the rod string of {path}")
    table = read_table(Path(path))
    sections = table.get("rod_string") if isinstance(table, dict) else None
    if sections is None:
        raise PumpjackError(f"{path}: no rod_string list in the file")
    data = unit.model_dump(by_alias=True)
    data["well"]["rod_string"] = sections
    try:
        return type(unit).model_validate(data)
    except Exception as exc:  # a pydantic ValidationError, reported as the config reader does
        raise PumpjackError(f"{path}: rod_string: {str(exc).splitlines()[-1].strip()}") from None


class _CardOnce:
    """A card source read once for all the analyses of a card (duck-typed CardSource)."""

    def __init__(self, path: str, units: str | None):
        from ..card_runs import CardSource

        self.source = CardSource(Path(path), units)
        self.name = self.source.name
        self._reading = None

    def read(self, linkage):
        if self._reading is None:
            self._reading = self.source.read(linkage)
        return self._reading


def analyse(job: Job, options: Options) -> list[Outcome]:
    """Every analysis of one card, each as the single command runs it; never raises for a
    problem of the card or the unit."""
    from ..downhole import downhole
    from ..torque import torque

    card = _CardOnce(job.card, options.card_units)
    outcomes = []
    for analysis in options.analyses:
        with collected_warnings() as noted:
            try:
                unit = _unit(job)
                if analysis == "torque":
                    result = torque(unit, card, job.spm, STEPS, "auto", options.method, options.balance)
                else:
                    result = downhole(unit, card, job.spm, "auto", "gibbs", options.damping)
                check_finite(result)
                status, error, summary = "ok", "", converted_summary(result, "si")
            except PumpjackError as exc:
                status, error, summary = "error", " ".join(str(exc).split()), {}
            except MemoryError:
                status, error, summary = "error", "not enough memory for this card", {}
            except Exception as exc:  # noqa: BLE001 - a fault of this program on one card must not stop a field
                status, error, summary = "error", (f"internal error ({type(exc).__name__}: "
                                                   f"{' '.join(str(exc).split())}); please report it"), {}
        outcomes.append(Outcome(analysis, status, error, " | ".join(noted), summary))
    return outcomes


def analyse_chunk(chunk: list[tuple[int, dict]], options: dict) -> list[tuple[int, list[dict]]]:
    """The analyses of a chunk of jobs (index, job fields) as plain data, for a process pool
    or a Dask worker; floating-point warnings are not printed."""
    import warnings

    settings = Options(**{**options, "analyses": tuple(options["analyses"])})
    out = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        for index, fields in chunk:
            out.append((index, [asdict(o) for o in analyse(Job(**fields), settings)]))
    return out
