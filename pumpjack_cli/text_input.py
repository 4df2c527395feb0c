"""Reading the user's text files safely: one clear line for anything that is not a text file.

Every input file (unit files, dynamometer cards, batch manifests) goes through
:func:`read_text`: it opens without blocking, refuses what is not a regular file (a
directory, a FIFO, a device such as ``/dev/zero`` that never ends) and what is larger
than the limit of its kind, reads at most that many bytes, and accepts only UTF-8 text
(a byte-order mark is dropped, line ends become LF), naming UTF-16, binary data and
other encodings instead of misreading them. ``-`` reads standard input with the same
limit, and refuses a terminal (it would wait for typing). A file that may be binary (a
card's float block) is read the same way by :func:`read_bytes`, and decoded by its reader.
"""

from __future__ import annotations

import errno
import os
import stat
import sys
from pathlib import Path
from typing import IO

from .errors import PumpjackError

STDIN = "-"
STDIN_NAME = "<stdin>"

#: What the operating system's errors mean to a user, by errno.
_OS_ERRORS = {
    errno.ENOENT: "no such file",
    errno.EACCES: "permission denied",
    errno.EPERM: "permission denied",
    errno.ENAMETOOLONG: "file name too long",
    errno.ENOTDIR: "a part of the path is not a directory",
    errno.ELOOP: "too many symbolic links",
    errno.EISDIR: "is a directory",
    errno.ENOSPC: "no space left on device",
    errno.EROFS: "read-only file system",
}
_FILE_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISCHR, "a device"),
               (stat.S_ISBLK, "a device"), (stat.S_ISSOCK, "a socket"))


def file_kind(mode: int) -> str | None:
    """What a file that is not a regular file is ("a directory", "a device"), from its
    ``st_mode``; None for a regular file."""
    if stat.S_ISREG(mode):
        return None
    return next((name for test, name in _FILE_KINDS if test(mode)), "not a regular file")


def describe_os_error(exc: OSError) -> str:
    """A few words for an OSError (the errno's meaning, else its strerror)."""
    return _OS_ERRORS.get(exc.errno, exc.strerror or str(exc))


def display_name(path: Path | str) -> str:
    """A file's name for a one-line message (non-printable characters escaped)."""
    name = STDIN_NAME if str(path) == STDIN else str(path)
    return name if name.isprintable() else ascii(name)[1:-1]


def _line_of(data: bytes, offset: int) -> int:
    return data[:offset].count(b"\n") + 1


def decode_text(data: bytes | str, source: str, error: type[PumpjackError]) -> str:
    """UTF-8 text with LF line ends and no byte-order mark; anything else raises ``error``."""
    if isinstance(data, bytes):
        if data.startswith((b"\xff\xfe", b"\xfe\xff")):
            raise error(f"{source}: is UTF-16 or UTF-32 text (byte-order mark); save it as UTF-8")
        nul = data.find(b"\0")
        if nul >= 0:
            line = data[:nul].replace(b"\r\n", b"\n").replace(b"\r", b"\n").count(b"\n") + 1
            raise error(f"{source}: line {line}: a NUL character: binary data, not text")
        try:
            data = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise error(f"{source}: line {_line_of(data, exc.start)}: byte 0x{data[exc.start]:02x} is not UTF-8; "
                        f"save the file as UTF-8 text (for example from cp1251 or Latin-1)") from None
    text = data.removeprefix("\ufeff")
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    nul = text.find("\0")
    if nul >= 0:
        raise error(f"{source}: line {text.count(chr(10), 0, nul) + 1}: a NUL character: binary data, not text")
    return text


#: The files this process has read, by (device, inode), with what each is ("card file"):
#: an output onto one of them is refused, so that no run replaces its own input.
_INPUTS: dict[tuple[int, int], str] = {}


def note_input(info: os.stat_result, what: str) -> None:
    """Remember a file (its ``os.stat`` result) as an input of this run."""
    _INPUTS[(info.st_dev, info.st_ino)] = what


def forget_inputs() -> None:
    """Start a new run: no file has been read yet."""
    _INPUTS.clear()


def input_kind(path: Path | str) -> str | None:
    """What input of this run the file at ``path`` is ("unit file", "card file"), if any."""
    try:
        info = os.stat(path)
    except (OSError, ValueError):
        return None
    return _INPUTS.get((info.st_dev, info.st_ino))


def _read_up_to(fd: int, size: int) -> bytes:
    """At most ``size`` bytes from the file descriptor ``fd``, fewer only at the end of the file
    (without a file object, whose set-up costs as many system calls again as the read)."""
    chunks = []
    while size > 0:
        chunk = os.read(fd, size)
        if not chunk:
            break
        chunks.append(chunk)
        size -= len(chunk)
    return b"".join(chunks)


def _read_file(path: Path | str, limit: int, what: str, source: str, error: type[PumpjackError]) -> bytes:
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise error(f"{source}: cannot read: {describe_os_error(exc)}") from None
    except ValueError:
        raise error(f"{source}: cannot read: the name holds a NUL character") from None
    try:
        info = os.fstat(fd)
        kind = file_kind(info.st_mode)
        if kind is not None:
            raise error(f"{source}: is {kind}, not a {what}")
        if info.st_size > limit:
            raise error(f"{source}: is {info.st_size:,} bytes; a {what} is at most {limit:,} bytes")
        note_input(info, what)
        data = _read_up_to(fd, info.st_size + 1)  # not limit + 1: that allocates the limit, 10 MB for a card
        return data if len(data) <= info.st_size else data + _read_up_to(fd, limit + 1 - len(data))
    except OSError as exc:
        raise error(f"{source}: cannot read: {describe_os_error(exc)}") from None
    finally:
        os.close(fd)


def read_bytes(path: Path | str, limit: int, what: str, error: type[PumpjackError] = PumpjackError,
               stream: IO | None = None) -> bytes | str:
    """The content of a file (``"-"``: ``stream``, by default standard input) of at most ``limit``
    bytes, as read: bytes, or text from a text stream. For a file that may be binary (a card
    block); :func:`read_text` for text.

    ``what`` names the kind of file in messages ("unit file", "card file"); problems
    raise ``error`` (a :class:`~pumpjack_cli.errors.PumpjackError`) with one line naming
    the file and the problem.
    """
    source = display_name(path)
    if str(path) == STDIN:
        stream = sys.stdin if stream is None else stream
        if stream is None:
            raise error(f"{source}: standard input is closed")
        if stream.isatty():
            raise error(f"{source}: is a terminal; pipe or redirect a {what} into it")
        try:
            data = getattr(stream, "buffer", stream).read(limit + 1)
        except OSError as exc:
            raise error(f"{source}: cannot read: {describe_os_error(exc)}") from None
    else:
        data = _read_file(path, limit, what, source, error)
    if len(data) > limit:
        raise error(f"{source}: more than {limit:,} bytes; a {what} is at most {limit:,} bytes")
    return data


def read_text(path: Path | str, limit: int, what: str, error: type[PumpjackError] = PumpjackError,
              stream: IO | None = None) -> str:
    """The text of a file (``"-"``: ``stream``) of at most ``limit`` bytes (:func:`read_bytes`),
    UTF-8 only (:func:`decode_text`)."""
    return decode_text(read_bytes(path, limit, what, error, stream), display_name(path), error)


def digit_limit(exc: ValueError) -> str | None:
    """What a ValueError of Python's limit on the digits of an integer it converts means to a user
    (a parser of TOML, JSON or YAML raises it, not its own error), or None for any other."""
    if "digits" not in str(exc):
        return None
    return f"an integer of more than {sys.get_int_max_str_digits()} digits"
