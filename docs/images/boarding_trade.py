#!/usr/bin/env python3
"""Draws docs/images/boarding_trade.svg: boarding against catastrophes in the paper's sea
as the path's clearance over the forecast ramp grows, with the 95 % upper bound of each
catastrophic rate.

Each point is `deckland campaign FILE --runs 3000 --seed 2026 --threads 2`, FILE
papers-sea.toml (the printed default with the filter ship) with the
`[control.flight_path]` keys named (docs/no-oracle-results.md, "The trade", gives the
rows). Standard library only:
python3 docs/images/boarding_trade.py > docs/images/boarding_trade.svg
"""
import math

RUNS = 3000
# (label, boardings, ramp strikes, hard landings) in 3000 approaches, seed 2026.
POINTS = [
    ("p_R 2 %", 241, 0, 2),
    ("p_R 2 %, m_R 3.5 m", 282, 0, 2),
    ("p_R 0.1 %, r 1.16 m", 342, 0, 4),
    ("p_R 2 %, m_R 3.9 m", 448, 0, 4),
    ("p_R 0.01 %, r 1.16 m (default)", 501, 0, 5),
    ("the default, cap m_max 4.5 m", 651, 0, 9),
    ("the default, cap m_max 5 m", 653, 0, 10),
]
W, H, LEFT, BOTTOM, TOP, RIGHT = 760, 420, 70, 50, 30, 210


def upper_bound(events, n, confidence=0.95):
    """One-sided Clopper–Pearson upper bound of a binomial rate, by bisection."""
    if events >= n:
        return 1.0

    def cdf(p):
        log_p, log_q = math.log(p), math.log1p(-p)
        total = 0.0
        for k in range(events + 1):
            log_term = (math.lgamma(n + 1) - math.lgamma(k + 1) - math.lgamma(n - k + 1)
                        + k * log_p + (n - k) * log_q)
            total += math.exp(log_term)
        return total

    low, high = 0.0, 1.0
    for _ in range(100):
        middle = 0.5 * (low + high)
        if cdf(middle) > 1.0 - confidence:
            low = middle
        else:
            high = middle
    return high


def x_of(boarding_pct):
    return LEFT + boarding_pct / 70.0 * (W - LEFT - RIGHT)


def y_of(rate_pct):
    return H - BOTTOM - rate_pct / 1.2 * (H - BOTTOM - TOP)


def main():
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
           'font-family="sans-serif" font-size="11">',
           f'<rect width="{W}" height="{H}" fill="white"/>']
    x0, x1, y0, y1 = LEFT, W - RIGHT, H - BOTTOM, TOP
    out.append(f'<line x1="{x0}" y1="{y0}" x2="{x1}" y2="{y0}" stroke="black"/>')
    out.append(f'<line x1="{x0}" y1="{y0}" x2="{x0}" y2="{y1}" stroke="black"/>')
    for boarding in range(0, 71, 10):
        x = x_of(boarding)
        out.append(f'<line x1="{x:.1f}" y1="{y0}" x2="{x:.1f}" y2="{y0 + 4}" stroke="black"/>')
        out.append(f'<text x="{x:.1f}" y="{y0 + 16}" text-anchor="middle">{boarding}</text>')
    for tenth in range(0, 13, 2):
        rate = tenth / 10.0
        y = y_of(rate)
        out.append(f'<line x1="{x0 - 4}" y1="{y:.1f}" x2="{x0}" y2="{y:.1f}" stroke="black"/>')
        out.append(f'<text x="{x0 - 8}" y="{y + 4:.1f}" text-anchor="end">{rate:.1f}</text>')
    out.append(f'<text x="{(x0 + x1) / 2}" y="{H - 12}" text-anchor="middle">'
               f'boarding (% of {RUNS} approaches)</text>')
    out.append(f'<text x="16" y="{(y0 + y1) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 16 {(y0 + y1) / 2})">rate (%), bar to the 95 % upper '
               'bound</text>')
    target = x_of(65.0)
    out.append(f'<line x1="{target:.1f}" y1="{y0}" x2="{target:.1f}" y2="{y1}" '
               'stroke="#888" stroke-dasharray="4 3"/>')
    out.append(f'<text x="{target + 4:.1f}" y="{y1 + 10}" fill="#555">65 % boarding</text>')
    hard_limit = y_of(0.1)
    out.append(f'<line x1="{x0}" y1="{hard_limit:.1f}" x2="{x1}" y2="{hard_limit:.1f}" '
               'stroke="#888" stroke-dasharray="4 3"/>')
    out.append(f'<text x="{x1 + 4}" y="{hard_limit + 4:.1f}" fill="#555">0.1 % hard landings</text>')
    for column, colour, label, dx in [(2, "#c00", "ramp strikes", -3), (3, "#e80", "hard landings", 3)]:
        previous = None
        for point in POINTS:
            boarding = 100.0 * point[1] / RUNS
            rate = 100.0 * point[column] / RUNS
            bound = 100.0 * upper_bound(point[column], RUNS)
            x, y = x_of(boarding) + dx, y_of(rate)
            out.append(f'<line x1="{x:.1f}" y1="{y:.1f}" x2="{x:.1f}" y2="{y_of(bound):.1f}" '
                       f'stroke="{colour}"/>')
            out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="4" fill="{colour}"/>')
            if previous:
                out.append(f'<line x1="{previous[0]:.1f}" y1="{previous[1]:.1f}" x2="{x:.1f}" '
                           f'y2="{y:.1f}" stroke="{colour}" stroke-opacity="0.5"/>')
            previous = (x, y)
            if column == 3:
                number = POINTS.index(point) + 1
                out.append(f'<text x="{x:.1f}" y="{y - 8:.1f}" text-anchor="middle" '
                           f'fill="#333">{number}</text>')
        out.append(f'<text x="{x1 + 4}" y="{y1 + 30 + 14 * column}" fill="{colour}">{label}</text>')
    for number, point in enumerate(POINTS, start=1):
        out.append(f'<text x="{x1 + 4}" y="{y1 + 90 + 14 * number}" fill="#333">'
                   f'{number}: {point[0]}</text>')
    out.append("</svg>")
    print("\n".join(out))


if __name__ == "__main__":
    main()
