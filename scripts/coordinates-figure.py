#!/usr/bin/env python3
"""Writes docs/coordinates.svg, the figure of docs/coordinates.md, from the lattice's own formulas
(docs/conventions.md, section 1), so that the figure and the code cannot disagree.

Top: a module at cell (2, 2, 1) and its 12 neighbours seen from the top, each labelled with the
connector that faces it at orientation 0, which is also the number of the world direction.
Bottom: a box of 4 x 1 x 4 seen from the side, in plain skew coordinates (it leans) and upright
(`generate box --upright`: each layer's x less floor(z/2)).

    scripts/coordinates-figure.py [OUT.svg]     (default docs/coordinates.svg)
"""
import html
import math
import sys

# The 12 neighbour offsets by direction.
OFFSETS = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 1), (-1, -1, 1), (0, -1, 1),
           (-1, 0, 0), (0, -1, 0), (0, 0, -1), (1, 0, -1), (1, 1, -1), (0, 1, -1)]


def world(cell):
    """The centre of a cell at spacing 1."""
    x, y, z = cell
    return (x + 0.5 + z / 2, y + 0.5 + z / 2, math.sqrt(2) / 2 * (z + 0.5))


class Svg:
    def __init__(self, width, height):
        self.width, self.height = width, height
        self.parts = []

    def circle(self, cx, cy, r, fill, stroke="#555", width=1.2, dash=None):
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        self.parts.append(f'<circle cx="{cx:.1f}" cy="{cy:.1f}" r="{r:.1f}" fill="{fill}" '
                          f'stroke="{stroke}" stroke-width="{width}"{extra}/>')

    def text(self, x, y, text, size=13, anchor="middle", weight="normal", fill="#222"):
        self.parts.append(f'<text x="{x:.1f}" y="{y:.1f}" font-size="{size}" '
                          f'text-anchor="{anchor}" font-weight="{weight}" fill="{fill}">'
                          f'{html.escape(text)}</text>')

    def line(self, x1, y1, x2, y2, stroke="#888", width=1.0, arrow=False):
        extra = ' marker-end="url(#arrow)"' if arrow else ""
        self.parts.append(f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" '
                          f'stroke="{stroke}" stroke-width="{width}"{extra}/>')

    def write(self, path):
        with open(path, "w") as out:
            out.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{self.width}" '
                      f'height="{self.height}" viewBox="0 0 {self.width} {self.height}" '
                      'font-family="DejaVu Sans, sans-serif">\n'
                      '<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" '
                      'markerWidth="7" markerHeight="7" orient="auto-start-reverse">'
                      '<path d="M0,0 L10,5 L0,10 z" fill="#444"/></marker></defs>\n'
                      '<rect width="100%" height="100%" fill="white"/>\n')
            out.write("\n".join(self.parts))
            out.write("\n</svg>\n")


SAME, ABOVE, BELOW = "#5b7bd5", "#f0a040", "#9a9a9a"


def top_view(svg, left, top):
    scale = 120
    centre = (2, 2, 1)
    cx, cy, _ = world(centre)

    def at(cell):
        wx, wy, _ = world(cell)
        return left + 210 + (wx - cx) * scale, top + 250 - (wy - cy) * scale

    svg.text(left + 210, top + 20, "Seen from the top, looking down -z", 16, weight="bold")
    svg.text(left + 210, top + 42, "the module at (2,2,1) and its neighbours, by connector", 12.5)
    px, py = at(centre)
    svg.circle(px, py, scale * 0.42, "#dfe6f6", "#2b4ba5", 2.5)
    svg.text(px, py - 4, "(2,2,1)", 14, weight="bold", fill="#2b4ba5")
    svg.text(px, py + 14, "orientation 0", 10.5, fill="#2b4ba5")
    places = {}
    for d, offset in enumerate(OFFSETS):
        cell = tuple(c + o for c, o in zip(centre, offset))
        places.setdefault(tuple(round(v, 3) for v in at(cell)), []).append((d, offset, cell))
    for (qx, qy), items in places.items():
        if len(items) == 1:
            d, offset, cell = items[0]
            svg.circle(qx, qy, scale * 0.36, "#eef2fb", SAME, 2)
            svg.text(qx, qy - 2, str(d), 22, weight="bold", fill=SAME)
            svg.text(qx, qy + 17, "({},{},{})".format(*offset), 10.5)
            continue
        # Seen from the top, a neighbour above and one below share a place.
        svg.circle(qx, qy, scale * 0.36, "#f4f4f4", BELOW, 2)
        svg.circle(qx, qy, scale * 0.30, "none", ABOVE, 2.5)
        for k, (d, offset, cell) in enumerate(sorted(items, key=lambda item: -item[1][2])):
            colour = ABOVE if offset[2] > 0 else BELOW
            svg.text(qx, qy - 6 + 20 * k, f"{d}  ({offset[0]},{offset[1]},{offset[2]})", 11.5,
                     weight="bold", fill=colour)
    ax, ay = left + 20, top + 520
    svg.line(ax, ay, ax + 55, ay, "#444", 1.5, True)
    svg.line(ax, ay, ax, ay - 55, "#444", 1.5, True)
    svg.text(ax + 65, ay + 4, "x", 13, "start")
    svg.text(ax, ay - 62, "y", 13)


def legend(svg, left, top):
    lines = [
        ("A cell is (x, y, z): z the layer, 0 on the ground.", "#222", "bold"),
        ("Each layer is a square grid along x and y.", "#222", "normal"),
        ("Odd layers sit half a cell off the even ones.", "#222", "normal"),
        ("", "#222", "normal"),
        ("Neighbours, by the connector that faces them:", "#222", "bold"),
        ("0, 1, 6, 7   in the same layer", SAME, "bold"),
        ("2, 3, 4, 5   in the layer above (z + 1)", ABOVE, "bold"),
        ("8, 9, 10, 11 in the layer below (z - 1)", BELOW, "bold"),
        ("Connector i faces connector (i + 6) mod 12 of", "#222", "normal"),
        ("its neighbour.", "#222", "normal"),
        ("", "#222", "normal"),
        ("At another orientation the module's own", "#222", "normal"),
        ("connector numbers turn; these numbers stay", "#222", "normal"),
        ("the world directions.", "#222", "normal"),
    ]
    for k, (text, colour, weight) in enumerate(lines):
        svg.text(left, top + 22 * k, text, 13, "start", weight, colour)


def side_view(svg, left, top):
    scale = 52
    svg.text(left + 430, top + 20, "Seen from the side (y fixed): a box of 4 x 1 x 4", 16,
             weight="bold")
    for title, note, origin_x, upright in (
            ("generate box --size 4,1,4", "x = 0..3 on every layer: it leans", left + 40, False),
            ("generate box --size 4,1,4 --upright", "x less floor(z/2) on layer z: it stands",
             left + 480, True)):
        ground = top + 300
        for z in range(4):
            for x in range(4):
                cell = (x - (z // 2 if upright else 0), 0, z)
                wx, _, wz = world(cell)
                px, py = origin_x + wx * scale, ground - wz * scale
                svg.circle(px, py, scale * 0.48, "#dfe6f6" if z % 2 else "#ececec", "#8899bb")
                svg.text(px, py + 4, f"{cell[0]},0,{cell[2]}", 10)
        svg.line(origin_x, ground + 2, origin_x + 330, ground + 2, "#444", 2.5)
        svg.text(origin_x + 165, ground + 24, title, 12.5, weight="bold")
        svg.text(origin_x + 165, ground + 42, note, 12, fill="#555")
    svg.line(left + 420, top + 280, left + 420, top + 200, "#444", 1.5, True)
    svg.text(left + 420, top + 190, "up: +z", 12)
    svg.text(left + 430, top + 372,
             "ground: z < 0 is solid. A layer is sqrt(2)/2 spacing above the one below; "
             "cell (x, y, z + 2) is straight above (x + 1, y + 1, z).", 12, fill="#333")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "docs/coordinates.svg"
    svg = Svg(900, 960)
    top_view(svg, 10, 10)
    legend(svg, 470, 120)
    side_view(svg, 10, 560)
    svg.write(out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
