"""The options of a batch run and the analyses of its cards, each card as the single commands
analyse it.

The units are loaded once per worker process and the exact torque's responses once per
unit and grid (:func:`..torque._exact_basis`). :func:`analyse_chunk` is what every executor
runs (a local process or a Dask worker): jobs in, plain data out. A task's cards are grouped
by unit (and speed option and runtime), and each group is placed on the crank, torqued and
balanced, and taken down the rods to its pump cards and their conditions as one array
computation (:func:`..card_runs.place_all`, :func:`..torque.torques`,
:func:`..downhole.downholes`), which the single commands run with one card: a stored
summary is the single command's, and one card's problem stays that card's error.

A file of several strokes (a continuous recording, a hex file of several blocks) is read
once and each stroke analysed as a card of its own: its outcomes carry the stroke's number,
which :func:`card_fields` folds into the stored card's name and key (``docs/batch.md``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from datetime import datetime, timedelta
from pathlib import Path
from typing import TYPE_CHECKING

from ...errors import CardError, PumpjackError, collected_warnings, warn
from ...readers.catalogue import read_catalogue
from ...readers.manifest import Job
from ...readers.unit_files import read_table
from ...results import check_finite, converted_summary

if TYPE_CHECKING:  # the schema is loaded by the caller; annotations only
    from ...config.beam_unit import UnitConfig

#: Analyses a card can go through, in the order they run.
ANALYSES = ("torque", "downhole")
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
    #: The cards' format (None: told from each file) and the points of a card block (None: 200).
    card_format: str | None = None
    card_points: int | None = None
    #: The operator's catalogue file whose units the manifest may name (DESIGNATION/HOLE), if any.
    catalogue: str | None = None

    def __post_init__(self):
        from ...readers.cards import check_options

        check_options(self.card_format, self.card_units, self.card_points)

    def for_analysis(self, analysis: str) -> dict:
        """The options that change an analysis' result (for the options hash; a card option
        not given leaves the hash that of a store written before the option existed)."""
        chosen = {"method": self.method, "balance": self.balance} if analysis == "torque" else {"damping": self.damping}
        cards = {"card_units": self.card_units, "card_format": self.card_format, "card_points": self.card_points}
        return {**chosen, **{name: value for name, value in cards.items() if value is not None}}


@dataclass(frozen=True)
class Outcome:
    """One analysis of one card: ``ok`` with the summary (SI, suffixed names) or ``error`` with
    the message; for a stroke of a file of several, its number (zero-padded to the count's
    width, so that the strokes sort in order) and its time stamp."""

    analysis: str
    status: str
    error: str
    warnings: str
    summary: dict
    stroke: str = ""
    timestamp: str = ""


def card_fields(job: Job, digest: str, outcome: dict) -> dict:
    """The stored card's name, key and time stamp of an outcome (:func:`analyse` as plain data):
    a stroke's number follows its file's path and digest after ``#``."""
    stroke = f"#{outcome['stroke']}" if outcome["stroke"] else ""
    return {"card": job.card + stroke, "card_sha256": digest + stroke, "timestamp": outcome["timestamp"]}


def stroke_time(base: str, start: object) -> str:
    """The time stamp of a stroke that starts ``start`` seconds into its recording (None: a card
    without time stamps): ``base`` (ISO 8601) plus ``start``, or ``base`` as it is."""
    try:
        when = datetime.fromisoformat(base)
    except ValueError:
        return base
    return base if start is None else (when + timedelta(seconds=float(start))).isoformat(timespec="milliseconds")


_UNITS: dict = {}
_CATALOGUES: dict = {}


def _catalogue(path: str | None):
    """The catalogue of a run, read once per process."""
    if path is not None and path not in _CATALOGUES:
        _CATALOGUES[path] = read_catalogue(Path(path))
    return None if path is None else _CATALOGUES[path]


def _unit(job: Job, catalogue: str | None) -> tuple[UnitConfig, tuple[str, ...]]:
    """The unit of a job with its overrides, loaded once per process, and the warnings of loading
    it (a catalogue unit's stroke), for every card that uses it."""
    key = (job.unit, job.counterbalance_moment, job.rod_string, job.survey, catalogue)
    if key not in _UNITS:
        from ...config import load_unit

        with collected_warnings() as noted:
            unit = load_unit(job.unit, _catalogue(catalogue))
            if job.counterbalance_moment is not None:
                unit = _with_moment(unit, job.counterbalance_moment)
            if job.rod_string is not None:
                unit = _with_rod_string(unit, job.rod_string)
            if job.survey is not None:
                from ..deviated import with_survey

                unit = with_survey(unit, Path(job.survey))
        _UNITS[key] = unit, tuple(noted)
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
    from pydantic import ValidationError

    from ...config.files import format_validation_error

    data = unit.model_dump(by_alias=True)
    data["well"]["rod_string"] = sections
    try:
        return type(unit).model_validate(data)
    except ValidationError as exc:   # named as the config reader names it, the rod string's key in the file
        raise PumpjackError(format_validation_error(str(path), exc, type(unit),
                                                    lambda loc: ".".join(map(str, loc[1:])))) from None


class _PlacedOnce:
    """A raw card placed and judged once for all the analyses of a card (duck-typed CardSource),
    its warnings given to each analysis that reads it; placed and judged with the other cards
    of its unit (:meth:`place_together`) or, when first read, alone."""

    def __init__(self, raw, name: str):
        self.raw, self.name = raw, name
        self._reading: tuple | CardError | None = None

    @staticmethod
    def place_together(cards: list[_PlacedOnce], unit, spm) -> None:
        """Place the cards of one unit in one array computation (:func:`..card_runs.place_all`),
        judge their loads so (:func:`..card_runs.judged`) and make their motion tables so
        (:func:`..card_runs.with_motion_tables`)."""
        from ..card_runs import judged, place_all, with_motion_tables

        placed = place_all([c.raw for c in cards], unit.geometry.mechanism())
        good = [k for k, found in enumerate(placed) if not isinstance(found, CardError)]
        for k, found in enumerate(placed):
            cards[k]._reading = found if isinstance(found, CardError) else None
        for k, verdict in zip(good, judged(unit, [placed[k] for k in good], spm) if good else []):
            cards[k]._reading = verdict if isinstance(verdict, CardError) else (placed[k], verdict)
        with_motion_tables([placed[k] for k in good])

    def read(self, unit, spm=None):
        from ..card_runs import noted, place

        if self._reading is None:
            with collected_warnings() as said:
                reading = noted(place(self.raw, unit.geometry.mechanism()), unit, spm)
            self._reading = reading, tuple(said)
        if isinstance(self._reading, CardError):
            raise self._reading
        for text in self._reading[1]:
            warn(text)
        return self._reading[0]


def _attempt(compute: Callable[[], object]) -> tuple[str, str, object]:
    """(status, error, value) of ``compute()``: never raises for a problem of the card or the unit."""
    try:
        return "ok", "", compute()
    except PumpjackError as exc:
        return "error", " ".join(str(exc).split()), None
    except MemoryError:
        return "error", "not enough memory for this card", None
    except Exception as exc:  # noqa: BLE001 - a fault of this program on one card must not stop a field
        return "error", f"internal error ({type(exc).__name__}: {' '.join(str(exc).split())}); please report it", None


def _analysed(analysis: str, unit, cards: list[_PlacedOnce], job: Job, options: Options) -> list:
    """One analysis of a unit's cards (:func:`..torque.torques`, :func:`..downhole.downholes`; the
    summary alone): each card's result or error with its warnings."""
    from ..downhole import Production, downholes
    from ..torque import torques

    if analysis == "torque":
        return torques(unit, cards, job.spm, None, "auto", options.method, options.balance)
    return downholes(unit, cards, job.spm, "auto", None, options.damping,  # Everitt-Jennings with drag if deviated
                     production=Production(runtime=job.runtime), tables=False)


def _summary(analysis: str, job: Job, card: _PlacedOnce, options: Options) -> dict:
    """One analysis of one card as the single command runs it: its summary (SI, suffixed names)."""
    from ..card_runs import alone

    unit, noted = _unit(job, options.catalogue)  # loaded once per process
    for text in noted:
        warn(text)
    return _checked(alone(_analysed(analysis, unit, [card], job, options)))


@dataclass
class _Stroke:
    """A card to analyse: its job, its stroke's label and time stamp, the card placed once, and
    the outcomes of its analyses as they are found."""

    job: Job
    label: str
    timestamp: str
    card: _PlacedOnce
    outcomes: dict = field(default_factory=dict)

    def outcome(self, analysis: str, status: str, error: str, noted: list[str], summary: dict | None) -> None:
        self.outcomes[analysis] = Outcome(analysis, status, error, " | ".join(noted), summary or {}, self.label,
                                          self.timestamp)


def _strokes(job: Job, options: Options) -> list[_Stroke] | list[Outcome]:
    """The cards of a job's file (each stroke of a file of several), or the outcomes of a file
    or unit that cannot be read."""
    from ..card_runs import CardSource

    source = CardSource(Path(job.card), options.card_units, None, options.card_format, options.card_points)
    status, error, raw = _attempt(lambda: (_unit(job, options.catalogue), source.raw())[1])  # the unit first
    if raw is None:
        return [Outcome(analysis, status, error, "", {}, "", job.timestamp) for analysis in options.analyses]
    base = job.timestamp or str(raw.metadata.get("timestamp", ""))
    strokes = raw.strokes or (raw,)
    width = len(str(len(strokes)))
    return [_Stroke(job, f"{number:0{width}d}" if raw.strokes else "",
                    stroke_time(base, stroke.metadata.get("start")) if raw.strokes else base,
                    _PlacedOnce(stroke, source.name))
            for number, stroke in enumerate(strokes, 1)]


def _one_by_one(analysis: str, strokes: list[_Stroke], options: Options) -> None:
    """An analysis of each card alone, as the single command runs it."""
    for stroke in strokes:
        with collected_warnings() as noted:
            status, error, summary = _attempt(lambda: _summary(analysis, stroke.job, stroke.card, options))
        stroke.outcome(analysis, status, error, noted, summary)


def _together(analysis: str, strokes: list[_Stroke], options: Options) -> None:
    """An analysis of the cards of one unit, speed option and runtime as one array computation
    (:func:`..torque.torques`, :func:`..downhole.downholes`: each card as the single command
    analyses it); if the group fails as a whole (the unit, or a fault of this program), each
    card alone."""
    job = strokes[0].job
    unit, loading = _unit(job, options.catalogue)

    def together():
        out = []
        for result, said in _analysed(analysis, unit, [s.card for s in strokes], job, options):
            status, error, summary = _attempt(lambda: _checked(result))
            out.append((status, error, [*loading, *said], summary))
        return out

    status, _, found = _attempt(together)
    if status != "ok":
        _one_by_one(analysis, strokes, options)
        return
    for stroke, (status, error, noted, summary) in zip(strokes, found):
        stroke.outcome(analysis, status, error, noted, summary)


def _checked(result) -> dict:
    """A result's summary (SI, suffixed names), or its error raised."""
    if isinstance(result, Exception):
        raise result
    check_finite(result)
    return converted_summary(result, "si")


def analyse_chunk(chunk: list[tuple[int, dict]], options: dict) -> list[tuple[int, list[dict]]]:
    """The analyses of a chunk of jobs (index, job fields) as plain data, for a process pool
    or a Dask worker, each card as the single commands analyse it, the cards of a unit (with
    one speed option and runtime) as one array computation (:func:`_together`). Floating-point
    warnings are not printed."""
    import warnings

    settings = Options(**{**options, "analyses": tuple(options["analyses"])})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        found = [(index, _strokes(Job(**fields), settings)) for index, fields in chunk]
        strokes = [s for _, items in found for s in items if isinstance(s, _Stroke)]
        groups: dict[tuple, list[_Stroke]] = {}
        for stroke in strokes:
            key = (id(_unit(stroke.job, settings.catalogue)[0]), stroke.job.spm, stroke.job.runtime)
            groups.setdefault(key, []).append(stroke)
        for members in groups.values():
            _attempt(lambda: _PlacedOnce.place_together([s.card for s in members],
                                                        _unit(members[0].job, settings.catalogue)[0],
                                                        members[0].job.spm))
        for analysis in settings.analyses:
            for members in groups.values():
                _together(analysis, members, settings)
    return [(index, [vars(item).copy() for item in items if isinstance(item, Outcome)]
             + [vars(s.outcomes[a]).copy() for s in items if isinstance(s, _Stroke) for a in settings.analyses])
            for index, items in found]
