"""Content keys of a batch: what tells a card already in the store with the same analysis and options.

A stored row is keyed by (well, card digest, analysis, options hash); the digests are
SHA-256 of the files' bytes, so a changed card, unit file or rod-string file is analysed
again and an unchanged one is skipped, whatever its name or time stamp. The rows of a
file of several strokes have the stroke's number after the digest (``<sha256>#07``).
"""

from __future__ import annotations

import errno
import hashlib
import json
import os
import stat
from pathlib import Path

from ...errors import ConfigError
from ...readers.manifest import Job
from ...readers.catalogue import Catalogue, CatalogueRow
from ...readers.unit_files import read_table, unit_source
from .per_card import Options


def file_sha256(path: str | Path) -> str:
    """SHA-256 of a file's bytes (hex), read unbuffered in blocks of 64 KiB (a card in one; a
    larger block is allocated whole at each read, which costs more than hashing a card)."""
    digest = hashlib.sha256()
    # opened without blocking and refused unless a regular file: a FIFO would wait for a writer and
    # a device such as /dev/zero never ends (the card's reader then names what it is)
    with open(os.open(path, os.O_RDONLY | os.O_NONBLOCK), "rb", buffering=0) as handle:
        if not stat.S_ISREG(os.fstat(handle.fileno()).st_mode):
            raise OSError(errno.EINVAL, "not a regular file", str(path))
        while block := handle.read(1 << 16):
            digest.update(block)
    return digest.hexdigest()


def card_digest(path: str) -> str:
    """The content hash of a card file, or a hash of its name when it cannot be read (the
    analysis then records the error)."""
    try:
        return file_sha256(path)
    except OSError:
        return "unreadable:" + hashlib.sha256(path.encode()).hexdigest()


def unit_digest(spec: str, catalogue: Catalogue | None = None) -> str:
    """The content hash of what a unit spec names, resolved as :func:`pumpjack_cli.config.load_unit`
    resolves it: a file's bytes (a bundled unit or a path), or a catalogue row's table and
    published stroke (so that editing another row of the catalogue changes nothing); the
    spec itself when it cannot be read (the analysis then records the error)."""
    try:
        found = unit_source(spec, catalogue)
        if isinstance(found, CatalogueRow):
            return hashlib.sha256(json.dumps([found.table, found.stroke], sort_keys=True).encode()).hexdigest()
        digest = file_sha256(found)
    except (ConfigError, OSError):
        return f"unreadable:{spec}"
    survey = _survey_of(found)
    return digest if survey is None else f"{digest}+{survey}"


def _survey_of(path: Path) -> str | None:
    """The content hash of the survey file a unit file's ``[well]`` names (relative to the unit
    file), None without one (the unit's digest is then its file's alone, as before surveys)."""
    try:
        table = read_table(path)
    except ConfigError:
        return None
    well = table.get("well") if isinstance(table, dict) else None
    survey = well.get("survey") if isinstance(well, dict) else None
    if not isinstance(survey, str):
        return None
    file = Path(survey) if Path(survey).is_absolute() else path.parent / survey
    try:
        return file_sha256(file)
    except OSError:
        return f"unreadable:{file}"


def options_key(job: Job, analysis: str, options: Options, unit_digest: str,
                known: dict | None = None) -> tuple[str, str]:
    """What makes a result, as JSON text (stored beside the result, so that a view can say
    which options differ), and its SHA-256 (the key): the analysis and its options, the unit
    (its file's content) and the row's overrides (a rod-string file by its content).
    ``known`` keeps the keys made so far with the same ``options`` (a run's), by what they are
    made of: the cards of a well share one key, made (and its files read) once."""
    made_of = (analysis, unit_digest, job.spm, job.counterbalance_moment, job.rod_string, job.survey, job.runtime)
    if known is not None and made_of in known:
        return known[made_of]
    rod_digest = file_sha256(job.rod_string) if job.rod_string and os.path.isfile(job.rod_string) else job.rod_string
    made = {"analysis": analysis, "options": options.for_analysis(analysis), "unit": unit_digest,
            "spm": job.spm, "counterbalance_moment": job.counterbalance_moment, "rod_string": rod_digest}
    if job.survey is not None:  # absent without one, so that the stores written before surveys keep their keys
        made["survey"] = file_sha256(job.survey) if os.path.isfile(job.survey) else job.survey
    if job.runtime is not None and analysis == "downhole":  # a row without one keeps the hash stores had before
        made["runtime"] = job.runtime
    text = json.dumps(made, sort_keys=True)
    key = text, hashlib.sha256(text.encode()).hexdigest()
    if known is not None:
        known[made_of] = key
    return key


def with_files(done: set[tuple[str, str, str, str]]) -> set[tuple[str, str, str, str]]:
    """The store's keys, and for each stroke's row (digest ``<sha256>#<stroke>``) its file's key:
    a file of several strokes, stored in one transaction, is done when its strokes are."""
    return done | {(well, digest.partition("#")[0], analysis, options) for well, digest, analysis, options in done
                   if "#" in digest}
