"""The figures of docs/units.md: the four-bar of each kind of beam unit, drawn from the package's own mechanisms.

One SVG per kind (``unit-<kind>.svg`` beside this script): the unit at a working crank angle
(black) and at the bottom and top of its stroke (grey), with the centre bearing, the crank
shaft O, the crank pin, the equalizer bearing, the horsehead arc and the polished rod; the
API Spec 11E letters A, C, I, H−G, R, P; the direction of rotation and θ measured from 12
o'clock in it; and the kind's counterbalance: the resultant of the crank counterweights at
its offset τ, the beam counterweight, or the air cylinder and its pin on the beam.

Every position comes from the unit's mechanism (``geometry.mechanism().motion(θ)``: beam and
pitman angles; the crank pin is the equalizer bearing minus the pitman, and is checked against
the crank shaft plus the crank); the units are the bundled C-114D-133-54, M-912D-365-168 and
A-228D-246-86, and the reverse-mark and beam-balanced files that docs/units.md shows
(read from the page, so the figure and the page's file cannot differ).

The output is deterministic: a fixed hash salt for the SVG ids, no date, text kept as text
(``svg.fonttype = none``); ``tests/architecture/test_unit_figures.py`` checks that the
committed figures are what this script makes. Run it after changing the page's unit files,
the bundled units or the drawing::

    python docs/figures/make_unit_figures.py            # writes docs/figures/unit-*.svg
    python docs/figures/make_unit_figures.py OUTDIR     # elsewhere
"""

from __future__ import annotations

import math
import re
import sys
import tomllib
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
PAGE = REPO / "docs" / "units.md"

#: The kinds drawn, in the page's order: (kind, bundled unit name or a file the page shows).
UNITS = (
    ("conventional", "c-114d-133-54"),
    ("reverse-mark", "rm-640d-365-168.toml"),
    ("beam-balanced", "beam-balanced-example.toml"),
    ("mark-ii", "m-912d-365-168"),
    ("air-balanced", "a-228d-246-86"),
)
#: The working crank angle drawn in black [deg], and in radians.
THETA = 60.0
THETA_RAD = math.radians(THETA)

INK, GHOST, BALANCE, ANGLE = "#222222", "#b8b8b8", "#1f5fa8", "#c0392b"
#: Behind every label: the lines it crosses stay visible but do not cut the letters.
LABEL_BOX = {"boxstyle": "round,pad=0.12", "facecolor": "white", "edgecolor": "none", "alpha": 0.8}
#: A file the page shows: a TOML block whose first line is ``# NAME.toml``.
PAGE_FILE = re.compile(r"```toml\n# ([\w.-]+\.toml)\n(.*?)```", re.S)


def page_files(text: str) -> dict[str, str]:
    """The unit files a page shows, by name: each TOML block that starts with ``# NAME.toml``."""
    return {name: body for name, body in PAGE_FILE.findall(text)}


def load(source: str):
    """A unit by bundled name, or one of the files docs/units.md shows."""
    from pumpjack_cli.config import load_unit
    from pumpjack_cli.config.files import parse_unit

    if not source.endswith(".toml"):
        return load_unit(source)
    return parse_unit(tomllib.loads(page_files(PAGE.read_text(encoding="utf-8"))[source]), source)


class Drawing:
    """One unit's figure: the positions of its joints from its mechanism, and the drawing helpers."""

    def __init__(self, unit, ax) -> None:
        self.unit, self.ax = unit, ax
        self.geometry = unit.geometry
        self.mechanism = mech = unit.geometry.mechanism()
        g = self.geometry
        self.s = mech.rotation                                  # +1 clockwise, -1 counterclockwise
        self.side = math.copysign(1.0, mech.equalizer_arm)      # -1: class I, +1: class III
        self.R, self.A = g.crank_radius, mech.horsehead_arm
        self.O = np.array([self.side * g.horizontal_offset, -g.vertical_offset])
        self.dead = mech.dead_positions()
        self.base = self.O[1] - 1.5 * self.R

    # --- positions ------------------------------------------------------------------

    def direction(self, theta: float) -> np.ndarray:
        """The unit vector at crank angle theta [rad] from 12 o'clock in the direction of rotation."""
        return np.array([self.s * math.sin(theta), math.cos(theta)])

    def at(self, theta: float) -> dict:
        """Beam angle, equalizer bearing and crank pin at crank angle theta [rad], from the mechanism."""
        m = self.mechanism.motion(np.array([theta]))
        psi, chi = float(m.beam_angle[0]), float(m.pitman_angle[0])
        beam = np.array([math.cos(psi), math.sin(psi)])
        equalizer = self.mechanism.equalizer_arm * beam
        pin = equalizer - self.mechanism.pitman_length * np.array([math.cos(chi), math.sin(chi)])
        assert np.allclose(pin, self.O + self.R * self.direction(theta), atol=1e-9 * self.A), "pin off the crank"
        return {"psi": psi, "beam": beam, "equalizer": equalizer, "pin": pin}

    # --- drawing helpers ------------------------------------------------------------

    def line(self, a, b, color=INK, width=1.6, **kw) -> None:
        self.ax.plot([a[0], b[0]], [a[1], b[1]], color=color, lw=width, solid_capstyle="round", **kw)

    def text(self, where, label, **kw) -> None:
        kw.setdefault("fontsize", 8)
        kw.setdefault("ha", "center")
        kw.setdefault("va", "center")
        kw.setdefault("bbox", LABEL_BOX)
        kw.setdefault("zorder", 7)
        self.ax.text(where[0], where[1], label, **kw)

    def dimension(self, a, b, label, offset, color="#555555") -> None:
        """A dimension line between a and b, shifted by ``offset`` (a vector), its label at the middle."""
        a, b, offset = np.asarray(a), np.asarray(b), np.asarray(offset)
        self.ax.annotate("", xy=b + offset, xytext=a + offset,
                         arrowprops=dict(arrowstyle="<->", color=color, lw=0.7, shrinkA=0, shrinkB=0))
        for end in (a, b):
            self.line(end, end + 1.12 * offset, color=color, width=0.4, ls=":")
        normal = offset / max(np.linalg.norm(offset), 1e-12)
        self.text((a + b) / 2 + offset + 0.045 * self.A * normal, label, color=color, fontsize=9, style="italic")

    def arc(self, centre, radius, start, end, color, width=1.0, arrow=False) -> None:
        """An arc about ``centre`` from crank-convention angle ``start`` to ``end`` [rad], with an
        arrowhead at ``end`` if asked."""
        phi = np.linspace(start, end, 60)
        points = centre[:, None] + radius * np.array([self.s * np.sin(phi), np.cos(phi)])
        self.ax.plot(points[0], points[1], color=color, lw=width)
        if arrow:
            self.ax.annotate("", xy=points[:, -1], xytext=points[:, -4],
                             arrowprops=dict(arrowstyle="-|>", color=color, lw=width, mutation_scale=9))

    # --- the unit -------------------------------------------------------------------

    def frame(self) -> None:
        """Base, Samson post and gearbox, in grey."""
        span = np.array([min(-0.25 * self.A, self.O[0] - 1.5 * self.R), max(self.A, self.O[0] + 1.5 * self.R)])
        self.line((span[0], self.base), (span[1] + 0.1 * self.A, self.base), color=GHOST, width=1.2)
        post = 0.18 * self.geometry.vertical_offset
        for foot in (-post, post):
            self.line((0.0, 0.0), (foot, self.base), color=GHOST, width=1.2)
        box = 0.3 * self.R
        self.ax.add_patch(_rectangle((self.O[0] - box, self.base), 2 * box, self.O[1] - self.base, "#eeeeee"))

    def linkage(self, theta: float, color: str, width: float) -> dict:
        """Beam, horsehead, pitman and crank at crank angle theta [rad]."""
        p = self.at(theta)
        rear = -(self.geometry.rear_arm + 0.12 * self.A) if self.side < 0 else -0.12 * self.A
        self.line(rear * p["beam"], self.A * p["beam"], color=color, width=width * 1.8)
        self.line(p["pin"], p["equalizer"], color=color, width=width)
        self.line(self.O, p["pin"], color=color, width=width * 1.4)
        return p

    def horsehead(self, p) -> None:
        """The horsehead arc (radius A about the centre bearing) over the stroke, and the polished rod."""
        low, high = self.dead.beam_angle_bottom, self.dead.beam_angle_top
        margin = math.radians(3.0)
        phi = np.linspace(p["psi"] - high - margin, p["psi"] - low + margin, 60)
        self.ax.plot(self.A * np.cos(phi), self.A * np.sin(phi), color=INK, lw=3.2, solid_capstyle="butt")
        self.line((self.A, 0.0), (self.A, self.base), width=1.0)
        self.ax.add_patch(_rectangle((self.A - 0.05 * self.A, self.base), 0.1 * self.A, 0.06 * self.A, "#dddddd"))
        self.text((self.A + 0.03 * self.A, 0.5 * self.base), "polished rod", ha="left", rotation=90)
        self.text((1.05 * self.A, 0.1 * self.A), "horsehead", ha="left", fontsize=7.5)

    def crank_angle(self, theta: float, p) -> None:
        """12 o'clock, θ in the direction of rotation, the rotation arrow and the crank circle."""
        R, O = self.R, self.O
        self.line(O, O + 1.15 * R * self.direction(0.0), color=ANGLE, width=0.7, ls="--")
        self.arc(O, 0.42 * R, 0.0, theta, ANGLE, arrow=True)
        self.text(O + 0.58 * R * self.direction(theta / 2), "θ", color=ANGLE, fontsize=11)
        circle = np.linspace(0.0, 2 * math.pi, 200)
        self.ax.plot(O[0] + R * np.sin(circle), O[1] + R * np.cos(circle), color=GHOST, lw=0.6, ls=":")
        self.arc(O, 1.12 * R, math.radians(150.0), math.radians(210.0), ANGLE, width=1.1, arrow=True)
        self.text(O + 1.3 * R * self.direction(math.pi), "rotation", color=ANGLE, fontsize=7)

    def counterbalance(self, theta: float, p) -> None:
        """The kind's counterbalance: crank counterweights, a beam counterweight or an air cylinder."""
        from pumpjack_cli.core.beam.air_balanced import AirCylinder
        from pumpjack_cli.core.beam.beam_balanced import BeamCounterweight
        from pumpjack_cli.core.beam.counterbalance import Counterbalance

        balance, _ = self.unit.counterbalance_model()
        if isinstance(balance, Counterbalance):
            self._crank_counterweights(theta, balance)
        elif isinstance(balance, BeamCounterweight):
            self._beam_counterweight(p, balance)
        elif isinstance(balance, AirCylinder):
            self._air_cylinder(p, balance)
        else:
            raise TypeError(f"no drawing for {type(balance).__name__}")

    def _crank_counterweights(self, theta: float, balance) -> None:
        R, O, tau = self.R, self.O, balance.offset
        reference = theta + math.pi if balance.tail else theta   # the tail (class III) or the pin (class I)
        if balance.tail:
            self.line(O, O + 0.95 * R * self.direction(reference), width=1.6 * 1.4)
        resultant = reference + tau   # tau: the lead ahead of the pin or the tail, in the rotation
        where = O + 0.78 * R * self.direction(resultant)
        self.ax.plot(*where, "o", ms=11, color=BALANCE, zorder=5)
        self.ax.annotate("", xy=where - np.array([0, 0.45 * R]), xytext=where,
                         arrowprops=dict(arrowstyle="-|>", color=BALANCE, lw=1.1, mutation_scale=9), zorder=5)
        offset = f"{math.degrees(tau):+.0f}°".replace("-", "−") if abs(tau) > 1e-9 else "0"
        label = f"counterweights\nτ = {offset}"
        if balance.tail:   # beside the blocks: the rotation arrow is below them
            self.text(where + np.array([0.22 * R, -0.1 * R]), label, color=BALANCE, fontsize=7.5, ha="left")
        else:
            self.text(where - np.array([0, 0.72 * R]), label, color=BALANCE, fontsize=7.5)
        if abs(tau) > 1e-9:
            self.line(O, O + 0.95 * R * self.direction(resultant), color=BALANCE, width=0.7, ls="--")
            self.arc(O, 0.62 * R, reference, resultant, BALANCE, width=0.9)

    def _beam_counterweight(self, p, balance) -> None:
        where = balance.arm * p["beam"]
        size = 0.09 * self.A
        self.ax.add_patch(_rectangle(where - size / 2, size, size, BALANCE, zorder=5))
        self.text(where + np.array([0.06 * self.A, -0.17 * self.A]), "beam\ncounterweight", color=BALANCE,
                  fontsize=7.5, ha="left")

    def _air_cylinder(self, p, balance) -> None:
        pin = balance.lever * p["beam"]
        width = 2.0 * math.sqrt(balance.piston_area / math.pi)
        height = 0.45 * (pin[1] - self.base)
        self.ax.add_patch(_rectangle((pin[0] - width / 2, self.base), width, height, "#d6e4f5", zorder=1,
                                     edgecolor=BALANCE))
        self.line((pin[0], self.base + height), pin, color=BALANCE, width=1.6)
        self.ax.plot(*pin, "o", ms=4, color=BALANCE, zorder=5)
        side = 1.0 if pin[0] > self.O[0] else -1.0   # the label on the side away from the crank
        self.text((pin[0] + side * (width / 2 + 0.03 * self.A), self.base + 0.5 * height), "air cylinder",
                  color=BALANCE, fontsize=7.5, ha="left" if side > 0 else "right")
        self.dimension((0.0, 0.0), pin, "d", -0.11 * self.A * np.array([-p["beam"][1], p["beam"][0]]),
                       color=BALANCE)

    def letters(self, p) -> None:
        """A, C, R, P, I and H−G."""
        A, R, O, beam = self.A, self.R, self.O, p["beam"]
        normal = np.array([-beam[1], beam[0]])
        self.dimension((0.0, 0.0), A * beam, "A", 0.13 * A * normal)
        self.dimension((0.0, 0.0), p["equalizer"], "C", (0.07 if self.side < 0 else 0.24) * A * normal)
        crank = p["pin"] - O
        across = np.array([-crank[1], crank[0]]) / np.linalg.norm(crank)
        self.text(O + crank / 2 + 0.16 * R * across * -self.s, "R", style="italic", fontsize=9)
        pitman = p["equalizer"] - p["pin"]
        across = np.array([pitman[1], -pitman[0]]) / np.linalg.norm(pitman)
        across = across if across[0] > 0 else -across
        self.text(p["pin"] + 0.5 * pitman + 0.05 * A * across, "P", style="italic", fontsize=9)
        self.dimension((O[0], O[1]), (0.0, O[1]), "I", np.array([0.0, self.base - O[1] - 0.07 * A]))
        self.dimension((O[0], O[1]), (O[0], 0.0), "H−G", np.array([-1.45 * R, 0.0]))

    def joints(self, p) -> None:
        """The centre bearing, the crank shaft, the crank pin and the equalizer bearing, named."""
        A, R, O = self.A, self.R, self.O
        for point, size in (((0.0, 0.0), 7), (O, 7), (p["pin"], 5), (p["equalizer"], 5)):
            self.ax.plot(*point, "o", ms=size, color="white", mec=INK, mew=1.3, zorder=6)
        if self.side < 0:
            self.text((0.05 * A, -0.08 * A), "centre bearing", fontsize=7.5, ha="left")
            self.text(p["equalizer"] + np.array([-0.04 * A, -0.04 * A]), "equalizer\nbearing", fontsize=7.5,
                      ha="right")
        else:
            self.text((0.0, 0.08 * A), "centre bearing", fontsize=7.5)
            near = p["equalizer"][0] < 0.5 * A   # a short C: to the right, clear of the centre bearing's name
            self.text(p["equalizer"] + np.array([0.02 * A if near else -0.02 * A, 0.045 * A]), "equalizer bearing",
                      fontsize=7.5, ha="left" if near else "right")
        self.text(O + np.array([-0.22 * R, -0.2 * R]), "O", fontsize=9, fontweight="bold")
        pin = self.direction(THETA_RAD)
        self.text(p["pin"] + 0.25 * R * pin, "crank pin", fontsize=7.5, ha="left" if pin[0] > 0 else "right")



def _rectangle(corner, width, height, color, zorder=0, edgecolor="none"):
    from matplotlib.patches import Rectangle

    return Rectangle(tuple(corner), width, height, facecolor=color, edgecolor=edgecolor, lw=0.8, zorder=zorder)


def draw(unit, kind: str, path: Path) -> None:
    """One kind's figure, written to ``path`` (SVG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with matplotlib.rc_context():
        matplotlib.rcdefaults()       # the same figure whatever a matplotlibrc or an earlier plot has set
        matplotlib.rcParams.update({"svg.hashsalt": "pumpjack-units", "svg.fonttype": "none", "font.size": 8,
                                    "font.family": "DejaVu Sans", "path.simplify": False})
        fig, ax = plt.subplots(figsize=(6.4, 4.6))
        d = Drawing(unit, ax)
        d.frame()
        for theta, label in ((d.dead.crank_angle_bottom, "bottom"), (d.dead.crank_angle_top, "top")):
            ghost = d.linkage(theta, GHOST, 0.9)
            d.text(1.04 * d.A * ghost["beam"] + np.array([0.0, 0.03 * d.A]), label, color="#888888", fontsize=7,
                   ha="left")
        p = d.linkage(THETA_RAD, INK, 1.6)
        d.horsehead(p)
        d.crank_angle(THETA_RAD, p)
        d.counterbalance(THETA_RAD, p)
        d.letters(p)
        d.joints(p)
        rotation = "clockwise" if d.s > 0 else "counterclockwise"
        ax.set_title(f"{kind} ({unit.name}): class {d.mechanism.lever_class}, {rotation}, θ = {THETA:.0f}°",
                     fontsize=9)
        ax.set_aspect("equal")
        ax.axis("off")
        fig.tight_layout(pad=0.3)
        fig.savefig(path, format="svg", metadata={"Date": None})
        plt.close(fig)


def make(folder: Path) -> list[Path]:
    """Every kind's figure, written to ``folder`` as ``unit-<kind>.svg``; returns the paths."""
    written = []
    for kind, source in UNITS:
        unit = load(source)
        assert unit.geometry.unit_class == kind, (source, unit.geometry.unit_class)
        path = folder / f"unit-{kind}.svg"
        draw(unit, kind, path)
        written.append(path)
    return written


if __name__ == "__main__":
    sys.path.insert(0, str(REPO))     # this checkout's package, not an installed one
    for made in make(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(made, made.stat().st_size, "bytes")
