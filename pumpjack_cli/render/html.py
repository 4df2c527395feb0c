"""A page of results as one self-contained HTML file: inline CSS, plots inline as SVG, no
network access, no external script (a few lines inline sort a sortable table).

Every number shown carries ``data-key`` (the command and the suffixed name its ``-f json``
summary uses, ``torque.peak_net_torque_n_m``) and ``data-value`` (the JSON value, full
precision), while the text shows it rounded for reading (:func:`~.display.display_number`);
``tests/commands/test_report_cli.py`` compares both with the commands' JSON.
"""

from __future__ import annotations

import dataclasses
import html
import io
import re

from ..names import suffixed
from ..quantities import output_unit
from ..page import Figure, Note, Page, Quantities, Section, SideBySide, Table, Values
from ..results import STORED, TEXT, Result, Scalar
from .display import display_number

STYLE = """
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,"DejaVu Sans",sans-serif;margin:1.5em auto;max-width:72em;
color:#1d2429;line-height:1.35;padding:0 1em}
h1{font-size:1.45em;margin:0 0 .1em}h2{font-size:1.15em;border-bottom:2px solid #2f6f8f;padding-bottom:.15em;
margin-top:1.6em}.subtitle{color:#55606a;margin:0 0 1em}
nav a{margin-right:.9em;font-size:.9em}
table{border-collapse:collapse;margin:.5em 0 1em;font-size:.92em}
th,td{border-bottom:1px solid #d5dce1;padding:.22em .7em;text-align:left;vertical-align:top}
th{background:#eef3f6}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
td.unit{color:#55606a;white-space:nowrap}td.meaning{color:#55606a;font-size:.9em}
.note{margin:.4em 0}.warning{background:#fff4e0;border-left:4px solid #d98a00;padding:.3em .6em}
.missing{color:#6b5300;font-style:italic}
figure{margin:.5em 0}.wide{overflow-x:auto}figure svg{max-width:100%;height:auto}
table.sortable th{cursor:pointer}table.sortable th:after{content:" \\2195";color:#9aa6ae}
@media print{nav{display:none}h2{break-after:avoid}figure{break-inside:avoid}}
"""

SORT_SCRIPT = """
document.querySelectorAll("table.sortable").forEach(function(table){
 table.querySelectorAll("th").forEach(function(th,i){th.addEventListener("click",function(){
  var body=table.tBodies[0],rows=Array.prototype.slice.call(body.rows),up=th.dataset.order!=="up";
  rows.sort(function(a,b){var x=a.cells[i],y=b.cells[i];
   var p=x.dataset.value!==undefined?parseFloat(x.dataset.value):NaN,q=y.dataset.value!==undefined?parseFloat(y.dataset.value):NaN;
   var c=(isNaN(p)||isNaN(q))?x.textContent.localeCompare(y.textContent):p-q;return up?c:-c;});
  rows.forEach(function(r){body.appendChild(r);});th.dataset.order=up?"up":"down";});});});
"""


def _e(text: object) -> str:
    return html.escape(str(text), quote=True)


def _number_cell(key: str | None, value: float, shown: str) -> str:
    keyed = f' data-key="{_e(key)}"' if key else ""
    return f'<td class="num"{keyed} data-value="{value!r}">{_e(shown)}</td>'


def _scalar_cells(source: str, s: Scalar, system: str) -> tuple[str, str]:
    """The value cell and the unit cell of a summary value (text values as they are)."""
    if isinstance(s.value, str):
        return f'<td data-key="{_e(source + "." + s.name)}">{_e(s.value)}</td>', '<td class="unit"></td>'
    unit = output_unit(s.quantity, system)
    value = float(unit.convert(float(s.value)))
    key = f"{source}.{suffixed(s.name, s.quantity, system)}"
    return _number_cell(key, value, display_number(value, s.quantity)), f'<td class="unit">{_e(unit.label)}</td>'


def _values(block: Values, system: str) -> str:
    rows = []
    for s in block.present():
        value, unit = _scalar_cells(block.source, s, system)
        rows.append(f'<tr><th scope="row">{_e(s.name.replace("_", " "))}</th>{value}{unit}'
                    f'<td class="meaning">{_e(s.description)}</td></tr>')
    return f'<table class="values">{"".join(rows)}</table>' if rows else ""


def _side_by_side(block: SideBySide, system: str) -> str:
    found = {s.name: s for s in block.result.summary}
    head = f'<tr><th></th><th colspan="2">{_e(block.columns[0])}</th><th colspan="2">{_e(block.columns[1])}</th></tr>'
    rows = []
    for label, first, second in block.rows:
        cells = []
        for name in (first, second):
            if name in found:
                cells += _scalar_cells(block.source, found[name], system)
            else:
                cells += ['<td class="num missing">not available</td>', '<td class="unit"></td>']
        rows.append(f'<tr><th scope="row">{_e(label)}</th>{"".join(cells)}</tr>')
    return f'<table class="duty">{head}{"".join(rows)}</table>'


def _quantities(block: Quantities, system: str) -> str:
    rows = []
    for label, value, quantity in block.rows:
        if quantity == TEXT or isinstance(value, str):
            rows.append(f'<tr><th scope="row">{_e(label)}</th><td colspan="2">{_e(value)}</td></tr>')
            continue
        unit = output_unit(quantity, system)
        shown = float(unit.convert(float(value)))
        rows.append(f'<tr><th scope="row">{_e(label)}</th>{_number_cell(None, shown, display_number(shown, quantity))}'
                    f'<td class="unit">{_e(unit.label)}</td></tr>')
    return f'<table class="inputs">{"".join(rows)}</table>'


def _table(block: Table, system: str) -> str:
    units = []
    for name, quantity in block.headers:
        label = "" if quantity in ("", TEXT, STORED) else output_unit(quantity, system).label
        units.append(f'{_e(name)}{" [" + _e(label) + "]" if label else ""}')
    head = "".join(f"<th>{u}</th>" for u in units)
    rows = []
    for r, row in enumerate(block.rows):
        cells = []
        for c, ((name, quantity), value) in enumerate(zip(block.headers, row)):
            if value is None:
                cells.append('<td class="missing">—</td>')
            elif isinstance(value, str) or quantity in ("", TEXT):
                text = _e(value)
                link = block.links[r] if c == 0 and r < len(block.links) else None
                cells.append(f'<td><a href="#{_e(link)}">{text}</a></td>' if link else f"<td>{text}</td>")
            else:
                shown = float(value) if quantity == STORED else float(output_unit(quantity, system).convert(float(value)))
                cells.append(_number_cell(None, shown, display_number(shown, quantity)))
        rows.append(f"<tr>{''.join(cells)}</tr>")
    kind = ' class="sortable"' if block.sortable else ""
    return f'<div class="wide"><table{kind}><thead><tr>{head}</tr></thead><tbody>{"".join(rows)}</tbody></table></div>'


def svg_figure(result: Result, system: str, salt: str) -> str:
    """The result's panels as an inline ``<svg>`` element: text kept as text, no date, ids salted
    per figure so that several figures on one page never share an id."""
    import matplotlib

    from .plot import figure

    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": salt}):
        buffer = io.StringIO()
        figure(result, system).savefig(buffer, format="svg", metadata={"Date": None, "Creator": None})
    text = buffer.getvalue()
    text = text[text.index("<svg"):]
    return re.sub(r"<metadata>.*?</metadata>", "", text, flags=re.S)


def _figure(block: Figure, system: str, salt: str) -> str:
    panels = tuple(p for p in block.result.panels if not block.panels or p.title in block.panels)
    if not panels:
        return ""
    shown = dataclasses.replace(block.result, panels=panels)
    return f'<figure role="img" aria-label="{_e(block.result.title)}">{svg_figure(shown, system, salt)}</figure>'


def _note(block: Note) -> str:
    return f'<p class="note {block.kind}">{_e(block.text)}</p>'


def _section(section: Section, system: str, number: int) -> str:
    parts = [f'<section id="{_e(section.anchor)}"><h2>{_e(section.title)}</h2>']
    for i, block in enumerate(section.blocks):
        if isinstance(block, Values):
            parts.append(_values(block, system))
        elif isinstance(block, SideBySide):
            parts.append(_side_by_side(block, system))
        elif isinstance(block, Quantities):
            parts.append(_quantities(block, system))
        elif isinstance(block, Table):
            parts.append(_table(block, system))
        elif isinstance(block, Figure):
            parts.append(_figure(block, system, f"pumpjack-{number}-{i}"))
        elif isinstance(block, Note):
            parts.append(_note(block))
        else:
            raise TypeError(f"a page cannot show {type(block).__name__}")
    parts.append("</section>")
    return "\n".join(parts)


def write_html(page: Page, system: str, stream) -> None:
    """The page as one HTML document (UTF-8, no external resource)."""
    sortable = any(isinstance(b, Table) and b.sortable for s in page.sections for b in s.blocks)
    nav = " ".join(f'<a href="#{_e(s.anchor)}">{_e(s.title)}</a>' for s in page.sections)
    units = "SI" if system == "si" else "oilfield"
    stream.write("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                 "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
                 f"<title>{_e(page.title)}</title><style>{STYLE}</style></head>\n<body>\n"
                 f"<header><h1>{_e(page.title)}</h1><p class=\"subtitle\">{_e(page.subtitle)}; {units} units</p>"
                 f"<nav>{nav}</nav></header>\n<main>\n")
    for number, section in enumerate(page.sections):
        stream.write(_section(section, system, number) + "\n")
    stream.write("</main>\n")
    if sortable:
        stream.write(f"<script>{SORT_SCRIPT}</script>\n")
    stream.write("</body></html>\n")
