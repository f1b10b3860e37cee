"""Independent reference numbers for the deck-motion estimator (docs/model.md §3.1, §3.5,
§3.6), computed with scipy rather than the library's own code.

Run: python3 crates/deckland/tests/reference/deck_motion_kalman.py (numpy, scipy).

Prints
- the steady-state a-posteriori covariance diagonal of the heave and pitch Kalman
  filters (50 Hz, default sensing, paper's sea), from scipy's discrete algebraic Riccati
  solver: src/estimation/deck_motion/tests.rs pins its filter's converged covariance to them;
- the physics floor: the standard deviation of the landing point's height predicted T s
  ahead from the true filter state, sqrt(var heave + 81^2 var pitch) of the noise still to
  come, for the paper's sea and the moderate sea, and as touchdown scatter sigma /
  tan 3.5 deg (docs/model.md §3.6 quotes 5.3, 10.4, 14.5, 15.5 m at 0.5, 1, 2, 3 s);
- the same for the Kalman filter's prediction with the default 0.1-s latency, just after
  a measurement has arrived.
"""

import numpy as np
from scipy.linalg import expm, solve_continuous_lyapunov, solve_discrete_are

D = [0.16, 0.4, 1.32, 2.08]  # D(s) = s^4 + 2.08 s^3 + 1.32 s^2 + 0.4 s + 0.16
A = np.array([[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1], [-D[0], -D[1], -D[2], -D[3]]], float)
B = np.array([[0], [0], [0], [1.0]])
P_UNIT = solve_continuous_lyapunov(A, -B @ B.T)  # A P + P A^T + B B^T = 0
P_UNIT = 0.5 * (P_UNIT + P_UNIT.T)
HEAVE_GAIN, PITCH_GAIN = 1.21, 0.773
LEVER_ARM = 81.0
SAMPLE_S = 0.02
LATENCY_S = 0.1
SIGMAS = [0.05, 0.05, np.radians(0.02), np.radians(0.02)]


def intensities(heave_rms, pitch_rms_deg):
    return (heave_rms**2 / (HEAVE_GAIN**2 * P_UNIT[0, 0]),
            np.radians(pitch_rms_deg) ** 2 / (PITCH_GAIN**2 * P_UNIT[2, 2]))


def posterior(q, first, gain, sigmas):
    phi = expm(A * SAMPLE_S)
    qd = q * (P_UNIT - phi @ P_UNIT @ phi.T)
    qd = 0.5 * (qd + qd.T)
    h = np.zeros((2, 4))
    h[0, first], h[1, first + 1] = gain, gain
    r = np.diag(np.square(sigmas))
    prior = solve_discrete_are(phi.T, h.T, qd, r)
    s = h @ prior @ h.T + r
    return prior - prior @ h.T @ np.linalg.solve(s, h @ prior)


def prediction_sigma(qh, qp, lead, ph, pp):
    phi = expm(A * lead)
    rest = P_UNIT - phi @ P_UNIT @ phi.T
    heave = HEAVE_GAIN**2 * (phi @ ph @ phi.T + qh * rest)[0, 0]
    pitch = PITCH_GAIN**2 * (phi @ pp @ phi.T + qp * rest)[2, 2]
    return np.sqrt(heave + LEVER_ARM**2 * pitch)


qh, qp = intensities(2.0, 1.5)
ph = posterior(qh, 0, HEAVE_GAIN, SIGMAS[:2])
pp = posterior(qp, 2, PITCH_GAIN, SIGMAS[2:])
print("heave posterior diagonal", ", ".join(f"{v:.7e}" for v in np.diag(ph)))
print("pitch posterior diagonal", ", ".join(f"{v:.7e}" for v in np.diag(pp)))
tan = np.tan(np.radians(3.5))
for name, (heave, pitch) in [("paper", (2.0, 1.5)), ("moderate", (1.0, 0.75))]:
    qh, qp = intensities(heave, pitch)
    ph = posterior(qh, 0, HEAVE_GAIN, SIGMAS[:2])
    pp = posterior(qp, 2, PITCH_GAIN, SIGMAS[2:])
    zero = np.zeros((4, 4))
    for horizon in [0.5, 1.0, 2.0, 3.0, 5.0]:
        floor = prediction_sigma(qh, qp, horizon, zero, zero)
        kalman = prediction_sigma(qh, qp, horizon + LATENCY_S, ph, pp)
        print(f"{name} sea, {horizon} s: floor {floor:.4f} m ({floor / tan:.2f} m along the deck), "
              f"Kalman {kalman:.4f} m (ratio {kalman / floor:.3f})")
