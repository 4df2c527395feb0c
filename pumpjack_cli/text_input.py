"""Reading the user's text files safely: one clear line for anything that is not a text file.

Every input file (unit files, dynamometer cards, batch manifests) goes through
:func:`read_text`: it refuses, before reading, what is not a regular file (a directory,
a FIFO that would block, a device such as ``/dev/zero`` that never ends) and what is
larger than the limit of its kind; it reads at most that many bytes; and it accepts
only UTF-8 text (a byte-order mark is dropped), naming UTF-16, binary data and other
encodings instead of misreading them. ``-`` reads standard input with the same limit.
"""

from __future__ import annotations

import errno
import os
import stat
import sys
from pathlib import Path
from typing import BinaryIO

from .errors import PumpjackError

#: What the operating system's errors mean to a user, by errno.
_OS_ERRORS = {
    errno.ENOENT: "no such file",
    errno.EACCES: "permission denied",
    errno.EPERM: "permission denied",
    errno.ENAMETOOLONG: "file name too long",
    errno.ENOTDIR: "a part of the path is not a directory",
    errno.ELOOP: "too many symbolic links",
    errno.EISDIR: "is a directory",
}


def describe_os_error(exc: OSError) -> str:
    """A few words for an OSError (the errno's meaning, else its strerror)."""
    return _OS_ERRORS.get(exc.errno, exc.strerror or str(exc))


def _kind_of(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def _decode(data: bytes, source: str, error: type[PumpjackError]) -> str:
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise error(f"{source}: is UTF-16 text; save it as UTF-8")
    if b"\x00" in data:
        raise error(f"{source}: is binary data (it contains NUL bytes), not a text file")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise error(
            f"{source}: line {line}: is not UTF-8 text (byte 0x{data[exc.start]:02x}); save it as UTF-8 "
            f"(for example from cp1251 or Latin-1)"
        ) from None


def _read_stream(stream: BinaryIO, limit: int, source: str, what: str, error: type[PumpjackError]) -> bytes:
    data = stream.read(limit + 1)
    if len(data) > limit:
        raise error(f"{source}: more than {limit:,} bytes; a {what} is at most {limit:,} bytes")
    return data


def read_text(path: Path | str, limit: int, what: str, error: type[PumpjackError] = PumpjackError,
              stdin: BinaryIO | None = None) -> str:
    """The UTF-8 text of a file (``"-"``: standard input) of at most ``limit`` bytes.

    ``what`` names the kind of file in messages ("unit file", "card"); problems raise
    ``error`` (a :class:`~pumpjack_cli.errors.PumpjackError`) with one line naming the
    file and the problem.
    """
    if str(path) == "-":
        stream = stdin if stdin is not None else sys.stdin.buffer
        return _decode(_read_stream(stream, limit, "<stdin>", what, error), "<stdin>", error)
    source = str(path)
    try:
        info = os.stat(path)
        if not stat.S_ISREG(info.st_mode):
            raise error(f"{source}: is {_kind_of(info.st_mode)}, not a {what}")
        if info.st_size > limit:
            raise error(f"{source}: is {info.st_size:,} bytes; a {what} is at most {limit:,} bytes")
        with open(path, "rb") as stream:
            data = _read_stream(stream, limit, source, what, error)
    except OSError as exc:
        raise error(f"{source}: cannot read: {describe_os_error(exc)}") from None
    except ValueError as exc:  # embedded NUL in the path
        raise error(f"{source!r}: not a valid path: {exc}") from None
    return _decode(data, source, error)
