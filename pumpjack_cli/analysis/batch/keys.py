"""Content keys of a batch: what tells a card already in the store with the same analysis and options.

A stored row is keyed by (well, card digest, analysis, options hash); the digests are
SHA-256 of the files' bytes, so a changed card, unit file or rod-string file is analysed
again and an unchanged one is skipped, whatever its name or time stamp.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

from ...errors import ConfigError
from ...readers.manifest import Job
from ...readers.unit_files import unit_path
from .per_card import Options


def _sha256(path: str | Path) -> str:
    """SHA-256 of a file's bytes (hex), read in blocks of 1 MiB."""
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def card_digest(path: str) -> str:
    """The content hash of a card file, or a hash of its name when it cannot be read (the
    analysis then records the error)."""
    try:
        return _sha256(path)
    except OSError:
        return "unreadable:" + hashlib.sha256(path.encode()).hexdigest()


def unit_digest(spec: str) -> str:
    """The content hash of the file a unit spec names (a bundled name, resolved as
    :func:`pumpjack_cli.config.load_unit` resolves it, or a file), or the spec itself when
    it cannot be read (the analysis then records the error)."""
    try:
        return _sha256(unit_path(spec))
    except (ConfigError, OSError):
        return f"unreadable:{spec}"


def options_key(job: Job, analysis: str, options: Options, unit_digest: str) -> tuple[str, str]:
    """What makes a result, as JSON text (stored beside the result, so that a view can say
    which options differ), and its SHA-256 (the key): the analysis and its options, the unit
    (its file's content) and the row's overrides (a rod-string file by its content)."""
    rod_digest = _sha256(job.rod_string) if job.rod_string and os.path.isfile(job.rod_string) else job.rod_string
    text = json.dumps({"analysis": analysis, "options": options.for_analysis(analysis), "unit": unit_digest,
                       "spm": job.spm, "counterbalance_moment": job.counterbalance_moment, "rod_string": rod_digest},
                      sort_keys=True)
    return text, hashlib.sha256(text.encode()).hexdigest()
