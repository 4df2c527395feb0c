"""`pumpjack report` as a new user runs it, and `pumpjack batch report`.

The unit is written here as a production engineer writes one from its API letters: the
C-228D-213-86 of [UnitDatabase2018] (A 111, C 96.05, I 96, K 151.34, P 114 in, R = 37 in,
B = 450 lb), with the counterbalance effect a crew measured, and the well of its sample card.
One command must give every item of the page, and every number on the page must be the
number the single commands print with ``-f json`` (its ``data-value``, exactly; its text,
that value rounded for reading).
"""

from __future__ import annotations

import json
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from pumpjack_cli.analysis.report import SECTIONS
from pumpjack_cli.names import written_names
from pumpjack_cli.render.display import display_number

from helpers import sample_card

CARD = sample_card("c-228d-213-86")
UNIT = """\
name = "C-228D-213-86 well 7"
designation = "C-228D-213-86"

[geometry]      # [UnitDatabase2018], longest of the four crank holes
A = "111 in"
C = "96.05 in"
I = "96 in"
K = "151.34 in"
P = "114 in"
R = "37 in"
rotation = "clockwise"

[counterbalance]
structural_unbalance = "450 lbf"
counterbalance_effect = "12577 lbf"    # as measured, cranks horizontal

[well]
pump_depth = "5000 ft"
plunger_diameter = "1.5 in"
rod_string = [{ diameter = "0.875 in", fraction = "40 %", grade = "D" },
              { diameter = "0.75 in", fraction = "60 %", grade = "D" }]
fluid_density = "950 kg/m3"
pump_submergence = "500 ft"
"""
OPTIONS = ("--units", "field", "--electricity-price", "0.12", "--drive-efficiency", "0.9")


class _Page(HTMLParser):
    """Sections (id -> heading), numbers (data-key -> (data-value, text)), external references, scripts."""

    def __init__(self):
        super().__init__()
        self.sections, self.numbers, self.external, self.scripts, self.ids, self.links = {}, {}, [], [], set(), []
        self._section = self._heading = self._cell = None
        self._text = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "section":
            self._section = a.get("id")
        if tag == "h2":
            self._heading, self._text = self._section, []
        if tag == "td" and "data-key" in a:
            self._cell, self._text = a, []
        if tag == "script":
            self.scripts.append(a)
        for name in ("src", "href", "xlink:href"):
            value = a.get(name, "")
            if value.startswith(("http:", "https:", "//")) or (name == "src" and value):
                self.external.append(value)
            if name == "href" and value.startswith("#"):
                self.links.append(value[1:])
        if tag == "link":
            self.external.append(str(a))

    def handle_data(self, data):
        self._text.append(data)

    def handle_endtag(self, tag):
        if tag == "h2" and self._heading is not None:
            self.sections[self._heading] = "".join(self._text)
            self._heading = None
        if tag == "td" and self._cell is not None:
            self.numbers[self._cell["data-key"]] = (self._cell.get("data-value"), "".join(self._text))
            self._cell = None


@pytest.fixture(scope="module")
def well(tmp_path_factory, run_json):
    """The page of the new user's unit, and the JSON of `torque` and `downhole` with the same options."""
    from pumpjack_cli.cli import main
    import contextlib
    import io

    folder = tmp_path_factory.mktemp("report")
    unit = folder / "c-228d-well-7.toml"
    unit.write_text(UNIT, encoding="utf-8")
    page = folder / "well.html"
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()) as err:
        code = main(["report", str(unit), "--card", str(CARD), *OPTIONS, "-o", str(page)])
    assert code == 0, err.getvalue()
    parsed = _Page()
    parsed.feed(page.read_text(encoding="utf-8"))
    documents = {"torque": run_json("torque", unit, "--card", CARD, *OPTIONS),
                 "downhole": run_json("downhole", unit, "--card", CARD, "--units", "field")}
    return page, parsed, documents, err.getvalue()


def test_one_command_gives_every_section_in_order(well):
    page, parsed, _, _ = well
    assert list(parsed.sections.items()) == list(SECTIONS)
    text = page.read_text(encoding="utf-8")
    for words in ("NEMA motor size that covers it", "cyclic load factor", "motor energy a day", "energy cost a day",
                  "recommended counterbalance", "upstroke peak torque", "taper 1 goodman loading",
                  "pump condition", "travelling valve closing", "pump displacement", "fluid level depth", "card file SHA-256", "stroke loading 102."):
        assert words in text, words
    assert text.count("<svg") == 3   # the cards, the torque, the Goodman diagram


def test_every_number_is_the_commands_json(well):
    """data-value equals the command's JSON value exactly; the text is that value rounded for reading."""
    _, parsed, documents, _ = well
    assert len(parsed.numbers) >= 50
    for key, (value, text) in parsed.numbers.items():
        command, name = key.split(".", 1)
        expected = documents[command]["summary"][name]
        if isinstance(expected, str):
            assert text == expected, key
            continue
        assert float(value) == expected, key
        quantity = written_names()[name][1]
        assert text == display_number(expected, quantity), key
    # the duty at both counterbalances and the NEMA size are on the page
    for name in ("max_rod_load_lbf", "min_rod_load_lbf", "rms_net_torque_lbf_in", "recommended_rms_net_torque_lbf_in",
                 "cyclic_load_factor", "recommended_cyclic_load_factor", "nema_motor_size_hp",
                 "recommended_nema_motor_size_hp", "motor_energy_kwh_d", "energy_cost_per_day",
                 "gearbox_loading_percent", "recommended_counterbalance_moment_lbf_in"):
        assert f"torque.{name}" in parsed.numbers, name


def test_the_page_is_self_contained(well):
    page, parsed, _, _ = well
    assert parsed.external == [] and parsed.scripts == []   # no sortable table: no script at all
    assert set(parsed.links) <= parsed.ids
    text = page.read_text(encoding="utf-8")
    assert "<img" not in text and "@import" not in text and not re.search(r"url\((?!#)", text)


def test_the_warnings_are_on_the_page_and_on_stderr(well):
    page, _, _, err = well
    assert "stroke loading" in err
    assert 'class="note warning"' in page.read_text(encoding="utf-8")


def test_provenance_holds_the_input_hashes(well):
    import hashlib

    text = well[0].read_text(encoding="utf-8")
    assert hashlib.sha256(CARD.read_bytes()).hexdigest() in text
    assert "pumpjack 0." in text and "electricity price 0.12 per kWh" in text and "drive efficiency 0.9" in text
    # every option said in words: none printed as Python's None
    assert "downhole method the default (gibbs; everitt-jennings in a deviated well)" in text and "None" not in text


def test_a_unit_without_a_well_gets_the_torque_sections(run_cli, tmp_path):
    page = tmp_path / "c80.html"
    code, out, err = run_cli("report", "c-80d-133-48", "--card", sample_card("c-80d-133-48"), "-o", page)
    assert code == 0, err
    parsed = _Page()
    parsed.feed(page.read_text(encoding="utf-8"))
    assert list(parsed.sections) == [anchor for anchor, _ in SECTIONS]


@pytest.mark.parametrize(("argv", "message"), [
    (("--card", "-"), "needs a card file"),
    (("--card", str(CARD), "-o", "well.txt"), "use a file ending in .html"),
    (("--card", str(CARD), "--electricity-price", "-2"), "--electricity-price"),
])
def test_bad_input_is_one_line(run_cli, tmp_path, monkeypatch, argv, message):
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli("report", "c-114d-133-54", *argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and message in err, err
    assert list(tmp_path.iterdir()) == []


def test_a_failed_report_leaves_no_file(run_cli, tmp_path):
    page = tmp_path / "well.html"
    code, _, err = run_cli("report", "c-114d-133-54", "--card", sample_card("sk8-3.5-4000"), "-o", page)
    assert code == 2 and not page.exists() and list(tmp_path.iterdir()) == [], err


def test_the_field_report(run_cli, tmp_path):
    manifest = tmp_path / "m.csv"
    rows = [("w1", "c-114d-133-54", sample_card("c-114d-133-54"), "2026-01-01"),
            ("w1", "c-114d-133-54", sample_card("c-114d-133-54"), "2026-01-02"),
            ("w2", "c-80d-133-48", sample_card("c-80d-133-48"), "2026-01-01")]
    manifest.write_text("well,unit,card,timestamp\n" + "".join(",".join(map(str, r)) + "\n" for r in rows))
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", manifest, "--store", store, "--workers", "1")[0] == 0
    page = tmp_path / "field.html"
    code, _, err = run_cli("batch", "report", "--store", store, "-o", page)
    assert code == 0, err
    text = page.read_text(encoding="utf-8")
    parsed = _Page()
    parsed.feed(text)
    assert {"field", "well-w1", "well-w2"} <= parsed.ids and set(parsed.links) <= parsed.ids
    assert [s for s in parsed.scripts if s] == [] and parsed.external == []
    assert text.count('class="sortable"') == 3 and "<script>" in text
    code, out, _ = run_cli("batch", "export", "--store", store, "--analysis", "torque", "--well", "w2", "-f", "json")
    loading = json.loads(out)["series"]["gearbox_loading_percent"][0]
    assert f'data-value="{loading!r}"' in text
    code, out, _ = run_cli("batch", "export", "--store", store, "--analysis", "downhole", "--well", "w2", "-f", "json")
    assert json.loads(out)["series"]["pump_condition"][0] in text   # the latest card's label


# --- in a real browser: headless Chromium renders the page -------------------------------------------------


def _chromium() -> str:
    import shutil

    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        found = shutil.which(name)
        if found:
            return found
    pytest.skip("headless Chromium not found: the browser tests need the Debian package chromium "
                "(apt-get install chromium; .ci/run installs it when it can)")


def _browse(folder: Path, page: Path, *action: str) -> tuple[str, list[str]]:
    """Run headless Chromium on a page, offline, its profile and home in ``folder``: stdout and the
    page's console messages (Chromium logs them to stderr as CONSOLE lines)."""
    import os
    import subprocess

    env = dict(os.environ, HOME=str(folder))
    done = subprocess.run([_chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                           "--disable-extensions", "--disable-crash-reporter", "--disable-breakpad",
                           f"--user-data-dir={folder / 'profile'}", "--host-resolver-rules=MAP * ~NOTFOUND",
                           "--enable-logging=stderr", "--v=0", *action, page.as_uri()],
                          capture_output=True, text=True, timeout=120, env=env, cwd=folder)
    console = [line for line in done.stderr.splitlines() if ":CONSOLE" in line]
    return done.stdout, console


@pytest.fixture(scope="module")
def browser_folder(tmp_path_factory):
    return tmp_path_factory.mktemp("chromium")


def test_chromium_renders_the_page_to_png_without_console_errors(well, browser_folder):
    page = well[0]
    shot = browser_folder / "well.png"
    _, console = _browse(browser_folder, page, "--hide-scrollbars", "--window-size=1200,3000", f"--screenshot={shot}")
    assert console == []
    data = shot.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and int.from_bytes(data[16:20], "big") == 1200 and len(data) > 50_000


def test_the_rendered_dom_holds_the_sections_and_the_numbers(well, browser_folder):
    page, parsed, documents, _ = well
    dom, console = _browse(browser_folder, page, "--dump-dom")
    assert console == []
    text = " ".join(re.sub(r"<[^>]+>", " ", dom).split())
    for _, heading in SECTIONS:
        assert heading in text
    s = documents["torque"]["summary"]
    for name in ("peak_net_torque_lbf_in", "recommended_peak_net_torque_lbf_in", "cyclic_load_factor",
                 "nema_motor_size_hp", "max_rod_load_lbf", "motor_energy_kwh_d"):
        shown = display_number(s[name], written_names()[name][1])
        assert f'data-value="{s[name]!r}">{shown}<' in dom, name
    assert dom.count("<svg") == 3


def test_chromium_sorts_the_field_table(run_cli, tmp_path, browser_folder):
    """The inline sort script in a real browser: two clicks on the well heading put w2 first."""
    manifest = tmp_path / "m.csv"
    manifest.write_text("well,unit,card,timestamp\n" + "".join(
        f"{w},c-80d-133-48,{sample_card('c-80d-133-48')},2026-01-0{i}\n" for i, w in enumerate(("w1", "w2"), 1)))
    store = tmp_path / "r.sqlite"
    assert run_cli("batch", manifest, "--store", store, "--workers", "1", "--analyses", "torque")[0] == 0
    page = tmp_path / "field.html"
    assert run_cli("batch", "report", "--store", store, "-o", page)[0] == 0
    clicked = tmp_path / "clicked.html"
    clicked.write_text(page.read_text(encoding="utf-8").replace(
        "</body>", '<script>var h=document.querySelector("table.sortable th");h.click();h.click();</script></body>'),
        encoding="utf-8")
    dom, console = _browse(browser_folder, clicked, "--dump-dom")
    assert console == []
    body = dom[dom.index("<tbody>"):dom.index("</tbody>")]
    assert body.index("w2") < body.index("w1")
