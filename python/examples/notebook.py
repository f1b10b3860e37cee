# %% [markdown]
# # deckland from Python: trim, linearise, fly, step, campaign
#
# A notebook in script form: each `# %%` starts a cell (Jupyter, VS Code and
# `jupytext --to notebook` read it as such), and `python notebook.py` runs it whole.
# It needs `pip install ./python[all]` (pandas, matplotlib, python-control), and runs
# with fewer: without matplotlib it draws nothing, without python-control it skips the
# state-space cell.

# %%
import importlib.util
import os

import numpy as np

import deckland

HAVE = {name: importlib.util.find_spec(name) is not None for name in ("pandas", "matplotlib", "control")}
print("deckland", deckland.__version__, "| optional:", HAVE)

# %% [markdown]
# ## Trim: steady flight on the glide slope
# The approach speed of the paper's Table 3 (69.1 m/s), descending on a 3.5° glide
# slope, landing configuration. Angles in degrees, thrust in N for both engines.

# %%
trim = deckland.trim(speed_mps=69.1, gamma_deg=-3.5, configuration="landing")
print(trim)

# %% [markdown]
# ## Linearise, into python-control
# `A`, `B` are numpy arrays; `C` (identity) and `D` (zeros) make every state an output.

# %%
lin = deckland.linearize(speed_mps=69.1, gamma_deg=-3.5)
print("states", lin.state_names, lin.state_units)
print("inputs", lin.input_names, lin.input_units)
print("A =\n", np.array2string(lin.a, precision=4))
for mode in lin.modes:
    print(f"  {mode['name']:<13} ω_n = {mode['natural_frequency_rad_s']:.3f} rad/s, ζ = {mode['damping_ratio']:.3f}")

if HAVE["control"]:
    import control

    plant = control.ss(lin.a, lin.b, lin.c, lin.d, states=lin.state_names, inputs=lin.input_names, outputs=lin.state_names)
    # Pitch angle per elevator: the transfer function the pitch law is designed on.
    theta_per_elevator = control.ss2tf(plant[lin.state_names.index("pitch_angle"), lin.input_names.index("elevator")])
    print("θ/δe =", theta_per_elevator)
    print("poles", np.round(control.poles(plant), 4))

# %% [markdown]
# ## Fly one approach
# The default scenario: adverse conditions (wind, air wake, turbulence, sensor noise,
# deck motion), O-PD pitch control. The same numbers as `deckland land --seed 1`.

# %%
scenario = deckland.Scenario.default()
flight = deckland.fly(scenario, seed=1)
print(flight)
print(flight.touchdown)
series = flight.time_series  # a pandas DataFrame (a dict of numpy arrays without pandas)
print(list(series.keys())[:8], "…", len(series["time_s"]), "samples")

# %% [markdown]
# ## Plot it (if matplotlib is there)

# %%
if HAVE["matplotlib"]:
    import matplotlib.pyplot as plt

    time = series["time_s"]
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    axes[0].plot(time, series["glide_path_height_m"], label="glide path")
    axes[0].plot(time, series["hook_height_m"], label="hook")
    axes[0].plot(time, series["landing_point_height_m"], label="landing point")
    axes[0].set_ylabel("height (m)")
    axes[0].legend()
    axes[1].plot(time, series["glide_path_error_m"])
    axes[1].set_ylabel("glide-path error (m)")
    axes[2].plot(time, series["theta_command_deg"], label="θ command")
    axes[2].plot(time, series["theta_deg"], label="θ")
    axes[2].set_ylabel("pitch (deg)")
    axes[2].set_xlabel("time (s)")
    axes[2].legend()
    fig.suptitle(f"Approach, seed 1: {flight.outcome}" + (f", wire {flight.wire}" if flight.wire else ""))
    fig.savefig("approach.png", dpi=80)  # in Jupyter the figure also shows inline
    print("wrote approach.png")

# %% [markdown]
# ## Change the scenario by dotted path
# A heavier sea (sea state 6 of the carrier in a seaway); a bad value raises `ValueError`
# naming the key, as the CLI does.

# %%
heavy = scenario.copy()
heavy["environment.seaway.significant_wave_height_m"] = 5.0
heavy["environment.seaway.peak_period_s"] = 12.4
print(deckland.fly(heavy, seed=1))
try:
    heavy["environment.seaway.significant_wave_height_m"] = -1.0
except ValueError as error:
    print("ValueError:", error)

# %% [markdown]
# ## Step it: your own commands, your own pitch law
# `Approach.step(None)` lets the built-in cascade fly one 20-ms interval;
# `{"pitch_command_rad": …}` replaces guidance and the sink-rate loop. Here a Python
# pitch law (a discrete PD, called once per interval) flies the whole approach.

# %%
def pitch_pd(inputs, kp=2.0, kd=0.8):
    error = inputs["theta_ref_rad"] - inputs["theta_measured_rad"]
    return inputs["elevator_trim_rad"] - kp * error + kd * inputs["pitch_rate_radps"]


approach = deckland.Approach(scenario, seed=1, pitch_law=pitch_pd)
observation = approach.reset()
while not observation["done"]:
    observation = approach.step()
summary = approach.summary
print(f"Python PD pitch law ({len(approach.events)} events): {summary['outcome']}, "
      f"glide-path error RMS {summary['glide_path_error_rms_m']} m")

# %% [markdown]
# ## A campaign, into pandas
# 40 approaches of the carrier in sea state 6, under O-PD and PID on the same seeds
# (`deckland campaign scenarios/sea-state-6.toml --runs 40 --compare`).

# %%
here = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
scenario_file = os.path.join(here, "..", "..", "scenarios", "sea-state-6.toml")
campaign_scenario = deckland.Scenario.from_file(scenario_file) if os.path.exists(scenario_file) else heavy
result = deckland.campaign(campaign_scenario, runs=40, seed=7, compare=True)
print(result)
runs = result.runs
if HAVE["pandas"]:
    print(runs.groupby(["controller", "outcome"]).size().unstack(fill_value=0))
    print(runs.groupby("controller")[["touchdown_distance_m", "touchdown_sink_rate_mps"]].describe().T.round(2))
for statistics in result.statistics:
    boarding = statistics["boarding"]
    print(f"{statistics['controller']}: boarding {boarding['rate']:.0%} "
          f"[{boarding['ci95_low']:.0%}, {boarding['ci95_high']:.0%}]")
