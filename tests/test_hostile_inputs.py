"""Hostile inputs for every command: a right answer, or exit code 2 and one line naming the culprit.

Generated cases, one class at a time: files that are not unit files, unit files with
a broken structure, every numeric field of a unit set to extreme values, quantities
written wrongly, bad options, output targets that will fail, and standard output
closed, full, cut or unable to encode the text. Each case checks the exit code, a single ``pumpjack: error:`` line
on stderr that names the file, field or option, no traceback, empty stdout, and that a
pre-existing output file is left untouched. (Card files have their own module,
``tests/readers/cards/test_card_hostile.py``.)
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from helpers import REPO_ROOT, SK8_CARD, SK8_TOML, one_line_error

UNB = REPO_ROOT / "configs" / "unb-600a.toml"

#: Every beam-unit command, as a function of the unit argument (small grids and, for
#: `dynamics`, a loose periodicity tolerance: these tests check how bad input is refused,
#: not the accuracy of the solution, which the commands' own tests check).
COMMANDS = {
    "kinematics": lambda unit: ["kinematics", unit, "--steps", "8"],
    "reactions": lambda unit: ["reactions", unit, "--card", SK8_CARD, "--steps", "8"],
    "compare-redundancy": lambda unit: ["compare-redundancy", unit, "--card", SK8_CARD, "--steps", "8",
                                        "--crank-phase", "0.1 deg"],
    "dynamics": lambda unit: ["dynamics", unit, "--steps", "8", "--rtol", "1e-6"],
    "inertia-error": lambda unit: ["inertia-error", unit, "--steps", "8"],
    "torque": lambda unit: ["torque", unit, "--card", SK8_CARD, "--steps", "8"],
    "downhole": lambda unit: ["downhole", unit, "--card", SK8_CARD, "--samples", "32"],
    "predict": lambda unit: ["predict", unit, "--samples", "64", "--damping", "0.1"],
}


# --- files that are not unit files ------------------------------------------------------

def _fifo(tmp: Path) -> Path:
    path = tmp / "unit.toml"
    os.mkfifo(path)
    return path


def _sparse(tmp: Path) -> Path:
    path = tmp / "huge.toml"
    with open(path, "wb") as f:
        f.truncate(2 << 20)
    return path


def _write(name: str, content: bytes):
    def make(tmp: Path) -> Path:
        path = tmp / name
        path.write_bytes(content)
        return path
    return make


SK8_TEXT = SK8_TOML.read_text(encoding="utf-8")
FILES = {
    "directory": (lambda tmp: tmp, "is a directory"),
    "fifo": (_fifo, "is a FIFO"),
    "dev-zero": (lambda tmp: Path("/dev/zero"), "is a device"),
    "too-large": (_sparse, "a unit file is at most"),
    "missing": (lambda tmp: tmp / "nothing.toml", "no such file"),
    "name-too-long": (lambda tmp: tmp / ("u" * 300 + ".toml"), "file name too long"),
    "binary": (_write("b.toml", bytes(range(256))), "NUL"),
    "cp1251": (_write("c.toml", SK8_TEXT.replace("SK8-3,5-4000", "СК8").encode("cp1251")), "not UTF-8"),
    "utf16": (_write("w.toml", SK8_TEXT.encode("utf-16")), "UTF-16"),
    "empty": (_write("e.toml", b""), "Field required"),
    "top-level-list": (_write("l.json", b"[1, 2]"), "expected a table"),
    "kind-list": (_write("k.json", b'{"kind": ["beam-pump"]}'), "kind: must be text"),
    "kind-unknown": (_write("k.toml", b'kind = "mark-iv"\n'), "unknown machine kind"),
    "json-duplicate": (_write("d.json", b'{"name": "a", "name": "b"}'), "key 'name' is given twice"),
    "yaml-duplicate": (_write("d.yaml", b"name: a\nname: b\n"), "key 'name' is given twice"),
    "yaml-alias": (_write("a.yaml", b"a: &x [1, 2]\nb: *x\n"), "aliases"),
    "json-deep": (_write("deep.json", b"[" * 100000 + b"]" * 100000), "not valid JSON: nested too deep"),
    "toml-deep": (_write("deep.toml", b"a = " + b"[" * 5000 + b"]" * 5000 + b"\n"), "not valid TOML"),
    "yaml-deep": (_write("deep.yaml", b"[" * 5000 + b"]" * 5000), "not valid YAML"),
    "json-nested-9": (_write("n.json", b'{"a": ' * 9 + b"1" + b"}" * 9), "nested 9 levels deep"),
    "bad-toml": (_write("t.toml", b"name = \n"), "not valid TOML"),
    "unknown-suffix": (_write("u.ini", SK8_TEXT.encode()), "unknown file type"),
}


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("case", FILES)
def test_files_that_are_not_unit_files(run_cli, tmp_path, command, case):
    make, fragment = FILES[case]
    path = make(tmp_path)
    code, out, err = run_cli(*COMMANDS[command](path), "-f", "csv")
    one_line_error(code, out, err, fragment)


# --- every numeric field at extreme values -----------------------------------------------

def _numeric_fields(data, prefix=()):
    for key, value in data.items():
        if isinstance(value, dict):
            yield from _numeric_fields(value, prefix + (key,))
        elif isinstance(value, (int, float, str)) and not isinstance(value, bool) and key not in (
                "name", "description", "model", "gearbox", "rotation", "kind", "phase"):
            if isinstance(value, str) and not value[:1].isdigit():
                continue
            yield prefix + (key,), value


def _replace(text: str, path: tuple[str, ...], new: str) -> str:
    """The TOML text with the field at ``path`` set to ``new`` (the field's own line)."""
    section = "[" + ".".join(path[:-1]) + "]" if len(path) > 1 else None
    lines = text.splitlines()
    start = lines.index(section) + 1 if section else 0
    for i in range(start, len(lines)):
        if lines[i].split("=")[0].strip() == path[-1]:
            lines[i] = f"{path[-1]} = {new}"
            return "\n".join(lines) + "\n"
    raise KeyError(path)


FIELDS = [path for path, _ in _numeric_fields(tomllib.loads(SK8_TEXT))]
EXTREMES = {"tiny": "1e-320", "negative": "-1e-3", "huge": "1e300", "zero": "0"}


def _commands_for(path: tuple[str, ...]) -> list[str]:
    if path[0] == "geometry":
        return ["kinematics", "reactions"]
    if path[0] == "masses":
        return ["reactions", "dynamics", "torque"]
    if path[0] == "pitman_section":
        return ["compare-redundancy"]
    if path[0] == "well":
        return ["dynamics", "downhole", "predict"]
    return ["dynamics"]


#: Field names as the schema spells them (the SK8 file uses the GOST names).
CANONICAL = {"k1": "front_arm", "k": "rear_arm", "r": "crank_radius", "l": "pitman", "l1": "horizontal_offset",
             "l2": "vertical_offset"}
#: Traces of a value that went on into the computation instead of being refused.
NON_FINITE = ("not finite", "inf ", "nan", "e-3", "e+3")


@pytest.mark.parametrize("value", EXTREMES)
@pytest.mark.parametrize("path", FIELDS, ids=".".join)
def test_extreme_field_values_are_refused_by_name(run_cli, tmp_path, path, value):
    """Either a finite result, or one line that names the field, or (for a value that
    is legal but physically impossible to run with, e.g. no counterweights at all) a
    verdict about the machine that shows no non-finite or absurd number."""
    unit = tmp_path / "unit.toml"
    unit.write_text(_replace(SK8_TEXT, path, EXTREMES[value]), encoding="utf-8")
    field = CANONICAL.get(path[-1], path[-1])
    for command in _commands_for(path):
        code, out, err = run_cli(*COMMANDS[command](unit), "-f", "json")
        if code == 0:
            assert err == "" or err.startswith("pumpjack: warning"), err
            assert "NaN" not in out and "Infinity" not in out
            continue
        one_line_error(code, out, err)
        if f"{'.'.join(path[:-1])}.{field}" not in err:
            assert not any(trace in err.lower() for trace in NON_FINITE), err


# --- quantities written wrongly ----------------------------------------------------------

QUANTITIES = {
    "space-inside-unit": ('k1 = "3500 mm"', 'k1 = "3.5 m m"', "unknown unit 'm m'"),
    "decimal-comma": ('k1 = "3500 mm"', 'k1 = "3,5 m"', "decimal comma"),
    "wrong-dimension": ('k1 = "3500 mm"', 'k1 = "3500 kg"', "is a mass, not a length"),
    "overflow": ('k1 = "3500 mm"', 'k1 = "1e999 m"', "not a finite number"),
    "infinite": ('k1 = "3500 mm"', "k1 = inf", "not a finite number"),
    "not-a-number": ('k1 = "3500 mm"', "k1 = nan", "not a finite number"),
    "boolean": ('k1 = "3500 mm"', "k1 = true", "boolean"),
    "unknown-unit": ('k1 = "3500 mm"', 'k1 = "3500 furlongs"', "unknown unit"),
    "count-as-text": ("count = 8", 'count = "8"', "count"),
    "fraction-over-100": ('fraction = "51 %"', 'fraction = "151 %"', "fraction"),
}


@pytest.mark.parametrize("case", QUANTITIES)
def test_quantities_written_wrongly(run_cli, tmp_path, case):
    old, new, fragment = QUANTITIES[case]
    assert old in SK8_TEXT
    unit = tmp_path / "unit.toml"
    unit.write_text(SK8_TEXT.replace(old, new, 1), encoding="utf-8")
    code, out, err = run_cli("dynamics" if "fraction" in old else "reactions", unit, "--card", SK8_CARD,
                             *(() if "fraction" in old else ("--steps", "8")), "-f", "csv") \
        if "fraction" not in old else run_cli("dynamics", unit, "--steps", "8", "-f", "csv")
    one_line_error(code, out, err, str(unit), fragment)


# --- options ------------------------------------------------------------------------------

OPTIONS = [
    (["inertia-error", "unb-600a", "--mass", "1e30 kg"], "--mass must be at most 100000 kg (as a unit file's mass)"),
    (["downhole", "sk8-3.5-4000", "--card", "samples/sk8-3.5-4000-deviated-card.csv", "--survey",
      "samples/j-well-survey.csv", "--guide-limit", "1e-9 lbf"], "--guide-limit 1e-9 lbf: must lie between 10 and"),
    (["predict", "sk8-3.5-4000", "--gas-exponent", "nan"], "'--gas-exponent': nan is not a finite number"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-pin-stiffness", "1e-9 N*m/rad"],
     "--crank-pin-stiffness"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-phase", "0.1"], "--crank-phase: '0.1' has no unit"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--pitman-length", "2"], "--pitman-length: '2' has no unit"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-phase", "inf deg"], "--crank-phase"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-phase", "15 deg"], "--crank-phase"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-pin-stiffness", "3e6"],
     "--crank-pin-stiffness: '3e6' has no unit"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-pin-stiffness", "-3e6 N*m/rad"],
     "--crank-pin-stiffness"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--equalizer-pin-clearance", "1 mm"],
     "is a length, not an angle"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--equalizer-pin-clearance", "10 deg"],
     "--equalizer-pin-clearance"),
    (["compare-redundancy", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-phase-mode", "keyway"], "--crank-phase-mode"),
    (["reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--counterweight-radius", "0.9"], "--counterweight-radius: '0.9' has no unit"),
    (["reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--counterweight-radius", "nan m"], "--counterweight-radius"),
    (["reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--counterweight-count", "17"], "--counterweight-count"),
    (["reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--spm", "6"], "disagrees with the time stamps"),
    (["reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-motion", "dynamic", "--spm", "10.9"], "--spm"),
    (["reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--crank-motion", "sideways"], "--crank-motion"),
    (["reactions", "sk8-3.5-4000", "--card", SK8_CARD, "--card-columns", "position=Pos"], "--card-columns"),
    (["reactions", "sk8-3.5-4000"], "--card"),
    (["inertia-error", "unb-600a", "--mass", "3000"], "--mass: '3000' has no unit"),
    (["inertia-error", "unb-600a", "--mass", "inf kg"], "--mass"),
    (["inertia-error", "unb-600a", "--mass", "3000 m"], "--mass: '3000 m' is a length, not a mass"),
    (["inertia-error", "unb-600a", "--rpm", "0"], "--rpm"),
    (["kinematics", "sk8-3.5-4000", "--spm", "0"], "--spm"),
    (["kinematics", "sk8-3.5-4000", "--spm", "nan"], "--spm"),
    (["kinematics", "sk8-3.5-4000", "--steps", "2"], "--steps"),
    (["kinematics", "sk8-3.5-4000", "--steps", "many"], "--steps"),
    (["kinematics", "sk8-3.5-4000", "--spm", "\u0665"], "--spm: '\\u0665': write numbers with the digits 0-9"),
    (["kinematics", "sk8-3.5-4000", "--spm=\uff15"], "--spm: '\\uff15': write numbers with the digits 0-9"),
    (["kinematics", "sk8-3.5-4000", "--steps", "\u0663\u0666"], "--steps: '\\u0663\\u0666'"),
    (["kinematics", "sk8-3.5-4000", "-f", "csv", "--format", "xml"], "--format"),
    (["kinematics", "sk8-3.5-4000", "--units", "imperial"], "--units"),
    (["kinematics", "no-such-unit"], "unknown unit 'no-such-unit'"),
    (["kinematics", "unb-600a"], "not a beam pumping unit"),
    (["dynamics", "sk8-3.5-4000", "--rtol", "1"], "--rtol"),
    (["dynamics", "sk8-3.5-4000", "--card", "-"], "<stdin>"),
    (["downhole", "sk8-3.5-4000", "--card", SK8_CARD, "--damping", "-0.1"], "--damping"),
    (["downhole", "sk8-3.5-4000", "--card", SK8_CARD, "--damping", "nan"], "--damping"),
    (["downhole", "sk8-3.5-4000", "--card", SK8_CARD, "--method", "fourier"], "--method"),
    (["downhole", "sk8-3.5-4000", "--card", SK8_CARD, "--samples", "4"], "--samples"),
    (["downhole", "sk8-3.5-4000", "--card", SK8_CARD, "--service-factor", "2"], "--service-factor"),
    (["downhole", "sk8-3.5-4000", "--card", SK8_CARD, "--spm", "6"], "disagrees with the time stamps"),
    (["downhole", "unb-600a", "--card", SK8_CARD], "not a beam pumping unit"),
    (["no-such-command"], "No such command"),
    (["kinematics", "sk8-3.5-4000", "--no-such-option"], "--no-such-option"),
]


@pytest.mark.parametrize("argv,fragment", OPTIONS, ids=lambda x: " ".join(map(str, x[:3])) if isinstance(x, list) else x)
def test_bad_options(run_cli, argv, fragment):
    code, out, err = run_cli(*argv)
    one_line_error(code, out, err, fragment)


# --- output targets -----------------------------------------------------------------------

TARGETS = {
    "output-missing-dir": (["-o", "missing/out.csv"], "--output missing/out.csv: directory missing does not exist"),
    "output-is-dir": (["-o", "."], "is a directory"),
    "plot-missing-dir": (["-o", "pre.csv", "--plot", "missing/p.png"], "--plot missing/p.png"),
    "plot-bad-suffix": (["-o", "pre.csv", "--plot", "p.gif"], "use a file ending in .png"),
    "plot-is-output": (["-o", "same.png", "--plot", "same.png"], "name the same file"),
    "plot-missing-dir-stdout": (["--plot", "missing/p.png"], "--plot missing/p.png"),
}


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("case", TARGETS)
def test_output_targets_checked_before_anything_is_written(run_cli, tmp_path, monkeypatch, command, case):
    monkeypatch.chdir(tmp_path)
    pre = tmp_path / "pre.csv"
    pre.write_text("precious\n")
    argv, fragment = TARGETS[case]
    unit = str(UNB) if command == "inertia-error" else str(SK8_TOML)
    code, out, err = run_cli(*COMMANDS[command](unit), *argv)
    one_line_error(code, out, err, fragment)
    assert pre.read_text() == "precious\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pre.csv"]


def test_output_onto_a_device_is_written_in_place(run_cli):
    code, out, err = run_cli("kinematics", "sk8-3.5-4000", "--steps", "8", "-o", "/dev/null")
    assert (code, out, err) == (0, "", "")
    assert Path("/dev/null").is_char_device()


def test_output_through_a_symbolic_link_keeps_the_link(run_cli, tmp_path):
    target = tmp_path / "real.csv"
    target.write_text("old\n")
    link = tmp_path / "link.csv"
    link.symlink_to(target)
    code, _, err = run_cli("kinematics", "sk8-3.5-4000", "--steps", "8", "-o", link)
    assert (code, err) == (0, "")
    assert link.is_symlink() and target.read_text().startswith("crank_angle_deg,")


# --- standard output closed, full, or cut -------------------------------------------------

def _script_path() -> str:
    script = Path(sys.executable).parent / "pumpjack"
    if not script.is_file():
        pytest.skip("the pumpjack console script is not installed")
    return str(script)


def _script(argv, **kwargs):
    return subprocess.run([_script_path(), *map(str, argv)], cwd=REPO_ROOT, timeout=120, **kwargs)


def _full_device() -> str:
    """The device that is always full (Linux), or a skip where there is none."""
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full on this system")
    return "/dev/full"


@pytest.mark.parametrize("fmt", ["csv", "json", "table"])
def test_full_stdout_is_one_line(fmt):
    with open(_full_device(), "w") as full:
        done = _script(["kinematics", "sk8-3.5-4000", "--steps", "2000", "-f", fmt], stdout=full, stderr=subprocess.PIPE)
    err = done.stderr.decode()
    assert done.returncode == 2 and err == "pumpjack: error: standard output: cannot write: no space left on device\n", err


def test_an_output_file_on_a_full_device_is_named(run_script):
    """A few lines fit the buffer: the device refuses them when the file is closed."""
    done = run_script("kinematics", "sk8-3.5-4000", "--steps", "8", "-o", _full_device())
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr == "pumpjack: error: --output /dev/full: cannot write: no space left on device\n"


def test_a_plot_on_a_full_device_is_named(run_cli, tmp_path):
    plot = tmp_path / "curves.png"
    plot.symlink_to(_full_device())
    code, out, err = run_cli("kinematics", "sk8-3.5-4000", "--steps", "8", "-f", "csv", "--plot", plot)
    one_line_error(code, out, err, f"--plot {plot}: cannot write: no space left on device")


@pytest.mark.parametrize("fmt", ["csv", "json", "table"])
def test_closed_stdout_is_one_line(fmt):
    script = _script_path()
    done = subprocess.run(f"{script} kinematics sk8-3.5-4000 --steps 20 -f {fmt} >&-", shell=True,
                          capture_output=False, stderr=subprocess.PIPE, cwd=REPO_ROOT, timeout=120)
    err = done.stderr.decode()
    assert done.returncode == 2 and err == "pumpjack: error: standard output is closed: give --output FILE\n", err


@pytest.mark.parametrize("fmt", ["csv", "json", "table"])
def test_broken_pipe_is_quiet(fmt):
    """The reader takes 10 bytes and closes the pipe: exit code 1, nothing on stderr. 4000 rows
    are at least 320 kB in every format, five times a pipe's 64 KiB buffer (Linux's default,
    pipe(7)): the writer is still writing when the pipe closes. Unbuffered (``PYTHONUNBUFFERED``),
    where Python's text layer took the pipe's short write of a whole table for a success and the
    run ended with exit code 0, its output cut off (render/targets.py, EncodedText)."""
    process = subprocess.Popen([_script_path(), "kinematics", "sk8-3.5-4000", "--steps", "4000", "-f", fmt],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=REPO_ROOT,
                               env={**os.environ, "PYTHONUNBUFFERED": "1"})
    process.stdout.read(10)
    process.stdout.close()
    err = process.stderr.read()
    assert process.wait(timeout=120) == 1 and err == b""


def test_an_unbuffered_non_blocking_pipe_gets_every_row(run_cli):
    """A pipe set non-blocking by whoever made it (the flag is shared with the child): an
    unbuffered standard output that would block is waited for, not dropped; all 320 kB of the
    table arrive, as the command prints them in-process."""
    read_end, write_end = os.pipe()
    os.set_blocking(write_end, False)
    argv = ["kinematics", "sk8-3.5-4000", "--steps", "4000", "-f", "csv"]
    process = subprocess.Popen([_script_path(), *argv], stdout=write_end, stderr=subprocess.PIPE, cwd=REPO_ROOT,
                               env={**os.environ, "PYTHONUNBUFFERED": "1"})
    os.close(write_end)
    with open(read_end, "rb") as pipe:
        received = pipe.read()
    assert process.wait(timeout=120) == 0 and process.stderr.read() == b""
    assert received.decode() == run_cli(*argv)[1]


# --- a standard output that cannot encode the text, a file name that is not UTF-8 -----------

#: An ASCII standard output: by Python's variable, or by a locale without UTF-8 (Python's
#: UTF-8 mode, which the C locale would turn on, off).
ASCII_BY_VARIABLE = {"PYTHONIOENCODING": "ascii"}
ASCII_BY_LOCALE = {"PYTHONIOENCODING": None, "LC_ALL": "C", "PYTHONUTF8": "0", "PYTHONCOERCECLOCALE": "0"}
KINEMATICS_FIELD = ("kinematics", "sk8-3.5-4000", "--steps", "8", "--units", "field")


@pytest.mark.parametrize("environment", [ASCII_BY_VARIABLE, ASCII_BY_LOCALE], ids=["variable", "locale"])
def test_an_ascii_stdout_gets_a_plain_ascii_table(run_script, environment):
    done = run_script(*KINEMATICS_FIELD, "-f", "table", environment=environment)
    assert (done.returncode, done.stderr) == (0, "")
    assert done.stdout.isascii()
    assert "pumping speed, 60 omega1 / 2pi" in done.stdout and "[ft/s^2]" in done.stdout


def test_an_ascii_stdout_gets_plain_ascii_csv(run_script):
    """The summary's units and meanings are the CSV's non-ASCII text."""
    done = run_script(*KINEMATICS_FIELD, "-f", "csv", "--what", "summary", environment=ASCII_BY_VARIABLE)
    assert (done.returncode, done.stderr) == (0, "")
    assert done.stdout.isascii()
    rows = {row["name"]: row for row in csv.DictReader(io.StringIO(done.stdout))}
    assert rows["max_acceleration_ft_s2"]["unit"] == "ft/s^2"


def test_an_ascii_stdout_gets_json_with_escapes(run_script, run_json):
    done = run_script(*KINEMATICS_FIELD, "-f", "json", environment=ASCII_BY_VARIABLE)
    assert (done.returncode, done.stderr) == (0, "")
    assert done.stdout.isascii()
    assert json.loads(done.stdout) == run_json(*KINEMATICS_FIELD)


def test_a_card_name_that_is_not_utf8_is_escaped_in_an_output_file(run_cli, tmp_path):
    """The card's name is in the title; the output file is UTF-8, so its byte 0xff is written as an escape."""
    card = tmp_path / os.fsdecode(b"\xff-card.csv")
    try:
        card.write_bytes(SK8_CARD.read_bytes())
    except (OSError, UnicodeError):
        pytest.skip("the file system takes only UTF-8 file names")
    table = tmp_path / "out.txt"
    code, out, err = run_cli("torque", "sk8-3.5-4000", "--card", card, "--steps", "8", "-o", table)
    assert (code, out, err) == (0, "", "")
    assert "card \\udcff-card.csv," in table.read_text(encoding="utf-8").splitlines()[0]


def test_an_unknown_mplbackend_is_left_aside_for_a_plot_file(run_script, tmp_path):
    """The plot goes to a file: drawn by its file backend, whatever backend the environment names."""
    plot = tmp_path / "curves.png"
    done = run_script("kinematics", "sk8-3.5-4000", "--steps", "12", "-f", "csv", "--plot", plot,
                      environment={"MPLBACKEND": "no-such-backend"})
    assert (done.returncode, done.stderr) == (0, "")
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"  # PNG signature (PNG spec, section 5.2)


def test_no_floating_point_warning_reaches_stderr(run_cli, tmp_path):
    unit = tmp_path / "unit.toml"
    unit.write_text(SK8_TEXT.replace('r = "1010 mm"', 'r = "1 mm"'), encoding="utf-8")
    code, out, err = run_cli("kinematics", unit, "--steps", "8", "-f", "csv")
    assert "RuntimeWarning" not in err and (code == 0 or err.count("\n") == 1)
    assert not any(math.isnan(float(v)) for v in out.splitlines()[1].split(",")) if code == 0 else True


def _reversed_card(tmp_path: Path) -> Path:
    """The SK8 sample card with its rows in reverse time order (read with one warning)."""
    lines = [line for line in SK8_CARD.read_text(encoding="utf-8").splitlines() if not line.startswith("#")]
    card = tmp_path / "reversed.csv"
    card.write_text("\n".join([lines[0], *lines[:0:-1]]) + "\n", encoding="utf-8")
    return card


def test_warnings_follow_a_successful_run(run_cli, tmp_path):
    """A reader's warning reaches stderr when the run succeeds, after nothing else."""
    card = _reversed_card(tmp_path)
    code, out, err = run_cli("torque", "sk8-3.5-4000", "--card", card, "-f", "csv")
    assert code == 0 and out
    assert err == f"pumpjack: warning: {card}: rows listed in reverse time order; read in time order\n"


def test_a_failed_run_prints_only_its_error(run_cli, tmp_path):
    """The same card's warning is noted before --spm is found to contradict its time
    stamps; the failure is still one line on stderr."""
    card = _reversed_card(tmp_path)
    code, out, err = run_cli("torque", "sk8-3.5-4000", "--card", card, "--spm", "5", "-f", "csv")
    one_line_error(code, out, err, f"--spm 5 disagrees with the time stamps of {card}")


@pytest.mark.parametrize("option", ["-o", "--plot"])
def test_an_output_onto_an_input_is_refused_and_the_input_kept(run_cli, tmp_path, option):
    """-o or --plot naming the card or the unit file the run reads (directly or through a
    symbolic link) would replace that input: refused, the file left as it was."""
    card, unit = tmp_path / "card.csv", tmp_path / "unit.toml"
    card.write_bytes(SK8_CARD.read_bytes())
    unit.write_bytes(SK8_TOML.read_bytes())
    (tmp_path / "link.csv").symlink_to(card)
    for target, kind in ((card, "card file"), (tmp_path / "link.csv", "card file"), (unit, "unit file")):
        named = target.with_suffix(".png") if option == "--plot" else target
        if option == "--plot":
            named.symlink_to(target)
        code, out, err = run_cli("torque", unit, "--card", card, option, named, "-f", "csv")
        one_line_error(code, out, err, f"is the {kind} this run read")
        assert card.read_bytes() == SK8_CARD.read_bytes() and unit.read_bytes() == SK8_TOML.read_bytes()
        if option == "--plot":
            named.unlink()
    assert sorted(path.name for path in tmp_path.iterdir()) == ["card.csv", "link.csv", "unit.toml"]


def test_export_onto_its_own_store_is_refused(run_cli, tmp_path):
    card = tmp_path / "card.csv"
    card.write_bytes(SK8_CARD.read_bytes())
    manifest = tmp_path / "field.csv"
    manifest.write_text(f"well,unit,card\nw1,sk8-3.5-4000,{card}\n", encoding="utf-8")
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", "run", manifest, "--store", store, "--workers", "1")[0] == 0
    before = store.read_bytes()
    code, out, err = run_cli("batch", "export", "--store", store, "-o", store)
    one_line_error(code, out, err, "is the results store this run read")
    assert store.read_bytes() == before


def test_warnings_outside_the_cli_go_to_stderr_at_once(capsys):
    """Used as a library (no collector), a warning is written to stderr when it arises;
    inside collected_warnings it is kept by the innermost collector only."""
    from pumpjack_cli.errors import collected_warnings, warn

    import threading

    warn("first   one")
    assert capsys.readouterr().err == "pumpjack: warning: first one\n"
    with collected_warnings() as outer:
        with collected_warnings() as empty:
            pass
        warn("a")
        with collected_warnings() as inner:
            warn("b")
        warn("c")
        elsewhere = []
        thread = threading.Thread(target=lambda: elsewhere.append(_collect_in_a_thread()))
        thread.start()
        thread.join()
    assert (outer, empty, inner, elsewhere, capsys.readouterr().err) == (["a", "c"], [], ["b"], [["t"]], "")


def _collect_in_a_thread() -> list[str]:
    from pumpjack_cli.errors import collected_warnings, warn

    with collected_warnings() as noted:
        warn("t")
    return noted
