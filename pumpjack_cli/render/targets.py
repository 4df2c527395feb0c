"""Where output goes: files written atomically (or in place for devices), and standard output."""

from __future__ import annotations

import os
import stat
import sys
from pathlib import Path

from ..errors import PumpjackError
from ..text_input import describe_os_error, input_kind

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

    def open(self, binary: bool = False):
        """A stream to write to: the temporary file, or the target itself when written in place."""
        try:
            if self.in_place:
                return open(self.path, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""}))
            import tempfile

            fd, name = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=self.path.suffix, dir=self.path.parent)
            self.tmp = Path(name)
            return os.fdopen(fd, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""}))
        except OSError as exc:
            raise PumpjackError(f"{self.option} {self.path}: cannot write: {describe_os_error(exc)}") from None

    def commit(self) -> None:
        """Move the written temporary file onto the target, with the target's mode (or the usual one)."""
        if self.tmp is None:
            return
        if self.mode is None:
            umask = os.umask(0)
            os.umask(umask)
        os.chmod(self.tmp, self.mode if self.mode is not None else 0o666 & ~umask)
        os.replace(self.tmp, self.path)
        self.tmp = None

    def discard(self) -> None:
        if self.tmp is not None:
            self.tmp.unlink(missing_ok=True)
            self.tmp = None


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
