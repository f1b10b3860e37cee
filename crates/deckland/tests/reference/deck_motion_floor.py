"""Independent numbers for analysis/deck_floor/ (docs/deck-prediction.md).

The physics floor of a deck point's forecast: the covariance the shaping filters'
white noise builds up over a horizon h from a known state, integrated here as the
matrix ODE dS/dt = A S + S Aᵀ + B Bᵀ, S(0) = 0, by classical RK4 (the library takes
P∞ − e^{Ah} P∞ e^{Aᵀh} with a Lyapunov solution and a matrix exponential instead). The
noise intensities come from the RMS heave and pitch through the stationary covariance,
here the same ODE run to 400 s.

Then the best wave-off rule on the forecast deck velocity (a threshold), found by
bisection on a trapezoidal integral over a fine grid.

Run: python3 crates/deckland/tests/reference/deck_motion_floor.py (numpy only).
"""
import math

import numpy as np

D = [0.16, 0.4, 1.32, 2.08]
A = np.array([[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1], [-D[0], -D[1], -D[2], -D[3]]], float)
BBT = np.zeros((4, 4))
BBT[3, 3] = 1.0


def built_up_covariance(h, steps):
    s = np.zeros((4, 4))
    dt = h / steps
    rate = lambda s: A @ s + s @ A.T + BBT
    for _ in range(steps):
        k1 = rate(s)
        k2 = rate(s + dt / 2 * k1)
        k3 = rate(s + dt / 2 * k2)
        k4 = rate(s + dt * k3)
        s = s + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return s


P_INF = built_up_covariance(400.0, 400_000)


def floor(heave_rms, pitch_rms_deg, arm, h):
    q_h = heave_rms**2 / (1.21**2 * P_INF[0, 0])
    q_p = math.radians(pitch_rms_deg) ** 2 / (0.773**2 * P_INF[2, 2])
    s = built_up_covariance(h, 20_000) if h < 100 else P_INF
    height = q_h * 1.21**2 * s[0, 0] + q_p * (arm * 0.773) ** 2 * s[2, 2]
    velocity = q_h * 1.21**2 * s[1, 1] + q_p * (arm * 0.773) ** 2 * s[3, 3]
    return math.sqrt(height), math.sqrt(velocity)


def phi(x):
    return 0.5 * math.erfc(-x / math.sqrt(2))


def bound(s, u, margin, rate):
    sf = math.sqrt(s * s - u * u)
    f = np.linspace(-12 * sf, 12 * sf, 200_001)
    density = np.exp(-0.5 * (f / sf) ** 2) / (sf * math.sqrt(2 * math.pi))
    hard = np.array([phi((x - margin) / u) for x in f]) * density
    cumulative = np.concatenate([[0], np.cumsum((hard[1:] + hard[:-1]) / 2 * (f[1] - f[0]))])
    tau = np.interp(rate, cumulative, f)
    return 1 - phi(margin / s), tau, 1 - phi(tau / sf)


if __name__ == "__main__":
    for h in [0.5, 1.4, 2.5, 1e9]:
        for arm, name in [(81.0, "landing point"), (141.0, "ramp")]:
            height, velocity = floor(2.0, 1.5, arm, h)
            print(f"paper's sea, {name}, h = {h:g} s: height {height:.5f} m, velocity {velocity:.5f} m/s")
    s = floor(2.0, 1.5, 81.0, 1e9)[1]
    for h in [0.5, 2.5]:
        u = floor(2.0, 1.5, 81.0, h)[1]
        for margin in [3.8, 4.2, 4.6]:
            without, tau, fraction = bound(s, u, margin, 0.001)
            print(f"decision at {h} s, margin {margin} m/s: without {without:.6f}, "
                  f"threshold {tau:.4f} m/s, wave-offs {fraction:.5f}")
