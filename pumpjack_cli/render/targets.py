"""Where output goes: files written atomically (or in place for devices), and standard output.

Text goes through :class:`EncodedText`: a stream whose encoding cannot write a character
(standard output under ``PYTHONIOENCODING=ascii`` or a locale without UTF-8, a file name
that is not UTF-8) gets its plain-ASCII spelling (:data:`PLAIN`) or a backslash escape,
never an encoding error.
"""

from __future__ import annotations

import io
import os
import select
import stat
import sys
from contextlib import contextmanager
from functools import cache
from pathlib import Path

from ..errors import PumpjackError
from ..text_input import describe_os_error, input_kind

#: Plain-ASCII spellings of the non-ASCII characters of the results' titles, names, units and
#: meanings (``tests/render/test_targets.py`` checks that every one has its spelling); units
#: joined by ``*`` as the quantity parser reads them back (``N*m``, ``kg*m^2``).
PLAIN = {
    "°": "deg", "²": "^2", "³": "^3", "⁴": "^4", "ᵀ": "^T", "·": "*", "⋅": "*", "×": "x", "½": "1/2",
    "−": "-", "–": "-", "—": "--", "′": "'", "″": "''", "…": "...", "→": "->", "∫": "int ", "µ": "u",
    "α": "alpha", "δ": "delta", "Δ": "Delta", "ε": "epsilon", "θ": "theta", "λ": "lambda", "μ": "mu",
    "ν": "nu", "π": "pi", "τ": "tau", "φ": "phi", "Φ": "Phi", "χ": "chi", "ψ": "psi", "ω": "omega",
}


@cache
def _spellings(encoding: str) -> dict[int, str]:
    """The translation table of the characters of :data:`PLAIN` that ``encoding`` cannot encode
    (encoded ignoring errors, such a character is nothing)."""
    nothing = "".encode(encoding)
    return {ord(char): spelled for char, spelled in PLAIN.items() if char.encode(encoding, "ignore") == nothing}


def plain(text: str, encoding: str) -> str:
    """``text`` as ``encoding`` can write it: characters it cannot encode in their spelling of
    :data:`PLAIN`, any other as a backslash escape (``\\u0421``, ``\\udcff``)."""
    return text.translate(_spellings(encoding)).encode(encoding, "backslashreplace").decode(encoding)


class EncodedText:
    """A text stream that writes only what its encoding can encode: a text that it cannot
    (rare: the stream raised before writing any of it) is written again made :func:`plain`.

    A stream without a buffer below its text (``python -u``, ``PYTHONUNBUFFERED``) is written
    here, to the end: its text layer hands each text to the file in one write and drops what a
    short write leaves (a pipe whose reader has gone takes what fits and says so with a short
    count, not an error), so that a table cut off by ``| head`` would end the run as a success.
    Written to the end, the next write finds the closed pipe (BrokenPipeError, exit code 1).
    """

    def __init__(self, stream):
        self.stream = stream
        self.encoding = getattr(stream, "encoding", None) or "utf-8"
        raw = getattr(stream, "buffer", None)
        self.raw = raw if isinstance(raw, io.RawIOBase) else None

    def write(self, text: str) -> int:
        if self.raw is not None:
            try:
                data = text.encode(self.encoding)
            except UnicodeEncodeError:
                data = plain(text, self.encoding).encode(self.encoding)
            _write_all(self.raw, data)
            return len(text)
        try:
            return self.stream.write(text)
        except UnicodeEncodeError:
            return self.stream.write(plain(text, self.encoding))


def _write_all(raw, data: bytes) -> None:
    """Every byte of ``data`` to the unbuffered stream ``raw``, write after write (a stream that
    would block, ``None`` written, is waited for)."""
    view = memoryview(data)
    while view:
        written = raw.write(view)
        if written is None:
            select.select([], [raw], [])
            continue
        view = view[written:]


#: Output paths written in place, never replaced by a rename (devices, /dev/stdout, /proc/self/fd/N).
SPECIAL_FILES = ("/dev/", "/proc/")


class Target:
    """One output file, checked before anything is computed, written at the end.

    A regular file (or a new one) is written to a temporary file beside it and renamed
    onto it only when everything has been written; anything else (a device, a FIFO,
    ``/dev/stdout``) is written in place, never replaced.
    """

    def __init__(self, path: Path, option: str):
        self.path, self.option = path, option
        self.tmp: Path | None = None
        try:
            info = os.stat(path)
        except FileNotFoundError:
            info = None
        except OSError as exc:
            raise PumpjackError(f"{option} {path}: {describe_os_error(exc)}") from None
        if info is not None and stat.S_ISDIR(info.st_mode):
            raise PumpjackError(f"{option} {path}: is a directory")
        real = os.path.realpath(path)
        self.in_place = (info is not None and not stat.S_ISREG(info.st_mode)) or real.startswith(SPECIAL_FILES) \
            or str(path).startswith(SPECIAL_FILES)
        self.mode = stat.S_IMODE(info.st_mode) if info is not None and not self.in_place else None
        if self.in_place:
            if info is not None and not os.access(path, os.W_OK):
                raise PumpjackError(f"{option} {path}: not writable")
            return
        self.path = Path(real)  # through a symbolic link: replace the file it points to, keep the link
        directory = self.path.parent
        if not directory.is_dir():
            raise PumpjackError(f"{option} {path}: directory {path.parent} does not exist")
        if not os.access(directory, os.W_OK | os.X_OK):
            raise PumpjackError(f"{option} {path}: directory {path.parent} is not writable")

    def refuse_input(self) -> None:
        """Refuse a target that is one of the files the run has read (it would be replaced)."""
        kind = input_kind(self.path)
        if kind is not None:
            raise PumpjackError(f"{self.option} {self.path}: is the {kind} this run read; write the result elsewhere")

    @contextmanager
    def written(self, binary: bool = False):
        """A stream to write to (UTF-8 text, or bytes): the temporary file, or the target itself
        when written in place; a failure to open, write or close it names the target."""
        with _failures_named(f"{self.option} {self.path}"):
            if self.in_place:
                stream = open(self.path, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""}))
            else:
                import tempfile

                fd, name = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=self.path.suffix, dir=self.path.parent)
                self.tmp = Path(name)
                stream = os.fdopen(fd, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""}))
            with stream:
                yield stream if binary else EncodedText(stream)

    def commit(self) -> None:
        """Move the written temporary file onto the target, with the target's mode (or the usual one)."""
        if self.tmp is None:
            return
        if self.mode is None:
            umask = os.umask(0)
            os.umask(umask)
        with _failures_named(f"{self.option} {self.path}"):
            os.chmod(self.tmp, self.mode if self.mode is not None else 0o666 & ~umask)
            os.replace(self.tmp, self.path)
        self.tmp = None

    def discard(self) -> None:
        if self.tmp is not None:
            self.tmp.unlink(missing_ok=True)
            self.tmp = None


@contextmanager
def standard_output(note: str = ""):
    """Standard output as a stream to write to, flushed at the end; a failure to write names it
    (followed by ``note``) and drops what is still buffered."""
    with _failures_named("standard output", drop_stdout, note):
        yield EncodedText(sys.stdout)
        sys.stdout.flush()


@contextmanager
def _failures_named(where: str, cleanup=lambda: None, note: str = ""):
    """An OSError as one line naming where the output went, then ``note``, after ``cleanup`` (a
    closed pipe stays a BrokenPipeError: the run stops quietly)."""
    try:
        yield
    except BrokenPipeError:
        raise
    except OSError as exc:
        cleanup()
        raise PumpjackError(f"{where}: cannot write: {describe_os_error(exc)}{note}") from None


def drop_stdout() -> None:
    """Point standard output at /dev/null, so that the text still buffered for a pipe that
    closed (or a full disk) is not written again, and complained about, at exit."""
    if sys.stdout is None:
        return
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass
