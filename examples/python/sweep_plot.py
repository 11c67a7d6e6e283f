#!/usr/bin/env python3
"""A small sweep with camopt's Python module: the largest contact stress of the LCR II reducer
(studies/examples/lcr_ii.json) over the output torque, for three eccentricities, with the stress
limit drawn as a line. Writes the plot to the file given (default lcr_ii_sweep.png).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_plot.py sweep.png
"""
import argparse
import copy
import json
import pathlib

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import camopt

HERE = pathlib.Path(__file__).resolve().parent
BASE = json.loads((HERE.parents[1] / "studies" / "examples" / "lcr_ii.json").read_text())


def max_stress_MPa(eccentricity_mm, torque_Nm):
    study = copy.deepcopy(BASE)
    study["reducer"]["eccentricity_mm"] = eccentricity_mm
    study["load"]["output_torque_Nm"] = torque_Nm
    study["analysis"] = {"angle_steps": 360, "evaluate": ["stress"]}
    r = camopt.run(study)
    return max(r["input_cam"]["max_contact_stress_MPa"], r["output_cam"]["max_contact_stress_MPa"])


def main(out):
    torques = np.linspace(20, 120, 6)
    limit = BASE["limits"]["contact_stress_MPa"]
    fig, ax = plt.subplots(figsize=(6, 4))
    for e in (1.8, 2.0, 2.2):
        stress = [max_stress_MPa(e, t) for t in torques]
        ax.plot(torques, stress, marker="o", label=f"eccentricity {e} mm")
        print(f"e = {e} mm: " + ", ".join(f"{t:.0f} Nm → {s:.0f} MPa" for t, s in zip(torques, stress)))
    ax.axhline(limit, color="red", linestyle="--", label=f"limit {limit:.0f} MPa")
    ax.set_xlabel("output torque [N·m]")
    ax.set_ylabel("largest contact stress [MPa]")
    ax.set_title(f"LCR II, camopt {camopt.__version__}")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"plot written to {out}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("plot", nargs="?", default="lcr_ii_sweep.png", help="the plot file to write (default: %(default)s)")
    main(parser.parse_args().plot)
