#!/usr/bin/env python3
"""Draws docs/images/boarding_trade.svg: boarding against catastrophes (ramp strikes and
hard landings) for the variants of the risk-aware design tried in the paper's sea.

Each point is one `deckland campaign FILE --runs 400 --seed 101 --threads 2`, FILE the
printed default with the keys named changed (docs/no-oracle-results.md gives the rows).
Standard library only: python3 docs/images/boarding_trade.py > docs/images/boarding_trade.svg
"""

# (label, boarding %, ramp strikes, hard landings) in 400 approaches, seed 101.
POINTS = [
    ("fixed 2.5 m margin, 1.5 m wave-off limit", 65.0, 3, 2),
    ("p_R 0.1 %", 47.5, 0, 5),
    ("p_R 1 %", 62.5, 0, 2),
    ("p_R 2 %", 65.0, 0, 3),
    ("p_R 5 %", 66.0, 2, 2),
    ("p_R 1 %, m_R 2 m", 65.8, 0, 2),
    ("p_R 2 %, m_R 2 m (default)", 68.0, 0, 3),
    ("p_R 5 %, m_R 2 m", 69.5, 2, 3),
    ("wave-off at P(ramp) 1 %", 25.0, 0, 1),
    ("wave-off at P(hard) 5 %", 39.8, 3, 1),
    ("default, flare at 4 m/s", 56.2, 0, 1),
]
RUNS = 400
W, H, LEFT, BOTTOM, TOP, RIGHT = 720, 440, 70, 50, 20, 250


def x_of(catastrophes):
    return LEFT + (catastrophes / RUNS * 100.0) / 1.5 * (W - LEFT - RIGHT)


def y_of(boarding):
    return H - BOTTOM - (boarding - 20.0) / 55.0 * (H - BOTTOM - TOP)


out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
       'font-family="sans-serif" font-size="11">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
x0, x1, y0, y1 = LEFT, W - RIGHT, H - BOTTOM, TOP
out.append(f'<line x1="{x0}" y1="{y0}" x2="{x1}" y2="{y0}" stroke="black"/>')
out.append(f'<line x1="{x0}" y1="{y0}" x2="{x0}" y2="{y1}" stroke="black"/>')
for pct in [0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5]:
    x = x_of(pct / 100.0 * RUNS)
    out.append(f'<line x1="{x:.1f}" y1="{y0}" x2="{x:.1f}" y2="{y0 + 4}" stroke="black"/>')
    out.append(f'<text x="{x:.1f}" y="{y0 + 16}" text-anchor="middle">{pct:.2f}</text>')
for boarding in range(20, 76, 10):
    y = y_of(boarding)
    out.append(f'<line x1="{x0 - 4}" y1="{y:.1f}" x2="{x0}" y2="{y:.1f}" stroke="black"/>')
    out.append(f'<text x="{x0 - 8}" y="{y + 4:.1f}" text-anchor="end">{boarding}</text>')
out.append(f'<text x="{(x0 + x1) / 2}" y="{H - 12}" text-anchor="middle">'
           'ramp strikes + hard landings (% of 400 approaches)</text>')
out.append(f'<text x="16" y="{(y0 + y1) / 2}" text-anchor="middle" '
           f'transform="rotate(-90 16 {(y0 + y1) / 2})">boarding (%)</text>')
for label, boarding, strikes, hard in POINTS:
    x, y = x_of(strikes + hard), y_of(boarding)
    colour = "#c00" if strikes else "#06c"
    out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="4" fill="{colour}"/>')
    out.append(f'<text x="{x + 7:.1f}" y="{y + 4:.1f}">{label}</text>')
out.append(f'<text x="{x1 - 40}" y="{TOP + 12}" fill="#c00">red: with ramp strikes</text>')
out.append(f'<text x="{x1 - 40}" y="{TOP + 26}" fill="#06c">blue: none</text>')
out.append("</svg>")
print("\n".join(out))
