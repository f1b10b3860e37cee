#!/usr/bin/env python3
"""Draws docs/images/seaway_spectra.svg: the carrier's heave, pitch and roll spectra over the
encounter frequency in sea states 3-6 (docs/model.md section 12), the response spectrum
|H|^2 S the fit aims at (solid), the fitted one-section filter's spectrum (dashed) and, for
heave and pitch, a Welch periodogram of the simulated ship (dots).

Reads the CSV of the example `seaway_spectra` on stdin (columns sea_state, motion,
omega_e_radps, target, fit and, optionally, simulated) and writes the SVG on stdout; it
runs nothing itself. Standard library only:

cargo run --release -p deckland --example seaway_spectra \
    | python3 docs/images/seaway_spectra.py > docs/images/seaway_spectra.svg

The figure is 85 mm wide (one journal column) in points (1 user unit = 1 pt), fonts 8 pt and
up. The y axes are logarithmic: the sea states' spectra differ by three to four orders of
magnitude. Values at or below zero, and below the axis, are drawn under it and clipped.
"""
import csv
import math
import sys

MOTIONS = [  # (name in the CSV, panel label with units)
    ("heave", "heave (m²·s/rad)"),
    ("pitch", "pitch (deg²·s/rad)"),
    ("roll", "roll (deg²·s/rad)"),
]
# Sea state -> colour (Okabe-Ito, distinguishable in colour-blind vision and in grey).
COLOURS = {3: "#56B4E9", 4: "#009E73", 5: "#E69F00", 6: "#000000"}
X_MIN, X_MAX = 0.0, 2.0
DECADES_BELOW_SMALLEST_PEAK = 3

WIDTH_PT = 85.0 / 25.4 * 72.0  # 85 mm
LEFT, RIGHT = 44.0, 8.0
LEGEND_TOP, LEGEND_HEIGHT = 4.0, 34.0
PANEL_HEIGHT, PANEL_GAP = 94.0, 10.0
BOTTOM = 29.0
FONT = 8.0
SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def read(stream):
    """data[motion][sea_state] = list of (omega_e, target, fit, simulated or None)."""
    data = {}
    for row in csv.DictReader(stream):
        simulated = row.get("simulated") or ""
        point = (float(row["omega_e_radps"]), float(row["target"]), float(row["fit"]),
                 float(simulated) if simulated.strip() else None)
        data.setdefault(row["motion"], {}).setdefault(int(row["sea_state"]), []).append(point)
    return data


def decade_range(curves):
    """(lowest, highest) decade: the largest value's decade above it, three decades below
    the smallest sea state's peak."""
    peaks = [max(max(p[1], p[2]) for p in points) for points in curves.values()]
    top = math.ceil(math.log10(max(peaks)))
    bottom = math.floor(math.log10(min(peaks))) - DECADES_BELOW_SMALLEST_PEAK
    return bottom, top


def main():
    data = read(sys.stdin)
    x0, x1 = LEFT, WIDTH_PT - RIGHT
    height = LEGEND_TOP + LEGEND_HEIGHT + 3 * PANEL_HEIGHT + 2 * PANEL_GAP + BOTTOM

    def x_of(omega):
        return x0 + (omega - X_MIN) / (X_MAX - X_MIN) * (x1 - x0)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="85mm" '
           f'height="{height * 25.4 / 72:.1f}mm" viewBox="0 0 {WIDTH_PT:.1f} {height:.1f}" '
           f'font-family="Helvetica, Arial, sans-serif" font-size="{FONT}">',
           f'<rect width="{WIDTH_PT:.1f}" height="{height:.1f}" fill="white"/>']

    # Legend: the sea states' colours, then the three line styles.
    y = LEGEND_TOP + 10
    out.append(f'<text x="12" y="{y + 3}">sea state</text>')
    for i, (state, colour) in enumerate(COLOURS.items()):
        lx = 12 + 44 + 44 * i
        out.append(f'<line x1="{lx}" y1="{y}" x2="{lx + 16}" y2="{y}" stroke="{colour}" '
                   'stroke-width="1.6"/>')
        out.append(f'<text x="{lx + 19}" y="{y + 3}">{state}</text>')
    y += 14
    simulated = any(p[3] is not None for curves in data.values()
                    for points in curves.values() for p in points)
    styles = [("target |H|²S", ""), ("fitted filter", "4 2")]
    if simulated:
        styles.append(("simulated", None))
    lx = 12.0
    for label, dash in styles:
        if dash is None:
            for k in range(3):
                out.append(f'<circle cx="{lx + 2 + 6 * k}" cy="{y}" r="1.2" fill="#555"/>')
        else:
            extra = f' stroke-dasharray="{dash}"' if dash else ""
            out.append(f'<line x1="{lx}" y1="{y}" x2="{lx + 16}" y2="{y}" stroke="#555" '
                       f'stroke-width="1.2"{extra}/>')
        out.append(f'<text x="{lx + 19}" y="{y + 3}">{label}</text>')
        lx += 19 + 4.4 * len(label) + 4

    for index, (motion, label) in enumerate(MOTIONS):
        curves = data.get(motion, {})
        if not curves:
            continue
        top_pt = LEGEND_TOP + LEGEND_HEIGHT + index * (PANEL_HEIGHT + PANEL_GAP)
        bottom_pt = top_pt + PANEL_HEIGHT
        low, high = decade_range(curves)

        def y_of(value, low=low, high=high, top_pt=top_pt, bottom_pt=bottom_pt):
            exponent = math.log10(value) if value > 0 else low - 1
            exponent = max(exponent, low - 1)
            return bottom_pt - (exponent - low) / (high - low) * (bottom_pt - top_pt)

        clip = f"clip-{motion}"
        out.append(f'<clipPath id="{clip}"><rect x="{x0}" y="{top_pt}" width="{x1 - x0:.1f}" '
                   f'height="{PANEL_HEIGHT}"/></clipPath>')
        # Decade grid and labels.
        step = 1 if high - low <= 8 else 2
        for decade in range(low, high + 1):
            gy = y_of(10.0 ** decade)
            if decade not in (low, high):
                out.append(f'<line x1="{x0}" y1="{gy:.1f}" x2="{x1:.1f}" y2="{gy:.1f}" '
                           'stroke="#ddd" stroke-width="0.5"/>')
            out.append(f'<line x1="{x0 - 3}" y1="{gy:.1f}" x2="{x0}" y2="{gy:.1f}" '
                       'stroke="black" stroke-width="0.6"/>')
            if (decade - low) % step == 0:
                text = "1" if decade == 0 else "10" + str(decade).translate(SUPERSCRIPT)
                out.append(f'<text x="{x0 - 5}" y="{gy + 2.8:.1f}" text-anchor="end">'
                           f'{text}</text>')
        for tenth in range(0, 21, 5):
            omega = tenth / 10
            tx = x_of(omega)
            out.append(f'<line x1="{tx:.1f}" y1="{bottom_pt}" x2="{tx:.1f}" '
                       f'y2="{bottom_pt + 3}" stroke="black" stroke-width="0.6"/>')
            if index == len(MOTIONS) - 1:
                out.append(f'<text x="{tx:.1f}" y="{bottom_pt + 12}" text-anchor="middle">'
                           f'{omega:g}</text>')
        out.append(f'<rect x="{x0}" y="{top_pt}" width="{x1 - x0:.1f}" height="{PANEL_HEIGHT}" '
                   'fill="none" stroke="black" stroke-width="0.6"/>')
        middle = (top_pt + bottom_pt) / 2
        out.append(f'<text x="10" y="{middle:.1f}" text-anchor="middle" '
                   f'transform="rotate(-90 10 {middle:.1f})">{label}</text>')

        for state in sorted(curves):
            points = curves[state]
            colour = COLOURS.get(state, "#888")
            for column, extra in [(1, ""), (2, ' stroke-dasharray="4 2"')]:
                path = " ".join(f"{x_of(p[0]):.2f},{y_of(p[column]):.2f}" for p in points)
                out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" '
                           f'stroke-width="1.1"{extra} clip-path="url(#{clip})"/>')
            for k, p in enumerate(points):
                if p[3] is not None and k % 4 == 2:
                    out.append(f'<circle cx="{x_of(p[0]):.2f}" cy="{y_of(p[3]):.2f}" r="1.2" '
                               f'fill="{colour}" clip-path="url(#{clip})"/>')
    out.append(f'<text x="{(x0 + x1) / 2:.1f}" y="{height - 6:.1f}" text-anchor="middle">'
               'encounter frequency ω<tspan dy="2">e</tspan><tspan dy="-2"> (rad/s)</tspan>'
               '</text>')
    out.append("</svg>")
    print("\n".join(out))


if __name__ == "__main__":
    main()
