#!/usr/bin/env python3
"""Hand check of a cycloid_ltca datasheet (docs/validation.md, "The paper's drive at 350 N·m: datasheet").

Reads hysteresis.csv and result.json of a cycloid_ltca run with "stiffness" and recomputes the
catalogue numbers from the curve (stiffness: (T_r/2)/(θ(T_r) − θ(T_r/2)) in each direction; lost
motion θ(+3%) − θ(−3%); backlash θ(0+) − θ(0−)), then two independent first-order estimates:

  * output pins: Palmgren line contact (δ = K_P (Q/E*)^0.9 L^−0.8, Palmgren 1959) on the pins of the
    linearised geometry, δ_j = R_w w sin φ_j − c (sine law, Blagojević et al. 2011), Σ Q_j R_w sin φ_j = T;
  * ring pins: the same law on the rigid-body arms l_i = n2 e sin α_i (normals through the pitch
    point at n1 e from the ring centre), δ_i = l_i β, modifications ignored (NNM's 1.6–8 µm gaps
    would soften it), Σ F_i l_i = T.

    python3 scripts/cycloid_datasheet_check.py OUT_DIR STUDY.json
"""
import csv
import json
import math
import os
import sys


def bisect(f, lo, hi, target):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


def main(out_dir, study_path):
    study = json.load(open(study_path))
    result = json.load(open(os.path.join(out_dir, "result.json")))
    rows = list(csv.DictReader(open(os.path.join(out_dir, "hysteresis.csv"))))
    load = [r for r in rows if r["branch_loading_0_unloading_1"] == "0"]
    t = [float(r["output_torque_Nm"]) for r in load]
    th = [float(r["output_angle_arcmin"]) for r in load]
    tr = study["stiffness"]["rated_torque_Nm"]

    def at(torque, zero_side=0):
        hits = [k for k, x in enumerate(t) if abs(x - torque) < 1e-9 * tr]
        return th[hits[zero_side]] if torque == 0 else th[hits[0]]

    k_pos = 0.5 * tr / (at(tr) - at(0.5 * tr))
    k_neg = 0.5 * tr / (at(-0.5 * tr) - at(-tr))
    lost = at(0.03 * tr) - at(-0.03 * tr)
    backlash = at(0, 1) - at(0, 0)  # loading branch: 0− first, then 0+
    print(f"stiffness from the csv   {0.5 * (k_pos + k_neg):.6f} N·m/arcmin (+ {k_pos:.6f}, − {k_neg:.6f}); "
          f"result.json {result['torsional_stiffness_Nm_per_arcmin']:.6f}")
    print(f"lost motion from the csv {lost:.9f}′; result.json {result['lost_motion_arcmin']:.9f}′")
    print(f"backlash from the csv    {backlash:.9f}′; result.json {result['backlash_arcmin']:.9f}′")
    unload = [r for r in rows if r["branch_loading_0_unloading_1"] == "1"]
    width = max(abs(float(a["output_angle_arcmin"]) - float(b["output_angle_arcmin"]))
                for a, b in zip(load, reversed(unload)))
    print(f"hysteresis width (loading vs unloading at the same torque) {width:.3g}′")

    # Independent first-order estimates.
    d, om = study["drive"], study["output_mechanism"]
    mat = study["material"]
    e_star = mat["youngs_modulus_GPa"] * 1e3 / (2 * (1 - mat["poisson_ratio"] ** 2))
    e_ref = 207e3 / (2 * (1 - 0.3 ** 2))
    length = d["face_width_mm"]
    kp = 3.84e-5 * e_ref ** 0.9

    def force(delta):  # Palmgren's force at approach delta [mm]
        return 0.0 if delta <= 0 else e_star * (delta * length ** 0.8 / kp) ** (10 / 9)

    arcmin = 180 / math.pi * 60
    rw, zw, e = om["pin_circle_radius_mm"], om["pins"], d["eccentricity_mm"]
    c = om["hole_radius_mm"] - om["pin_radius_mm"] - e
    s = [math.sin(2 * math.pi * j / zw) for j in range(zw)]  # crank 0: pin 0 on the eccentricity

    def pins_moment(w):
        return sum(force(rw * w * sj - c) * rw * sj for sj in s if sj > 0)

    w = lambda torque: bisect(pins_moment, 0.0, 0.1, torque * 1e3)
    k_pins = 0.5 * tr / ((w(tr) - w(0.5 * tr)) * arcmin)
    n1, n2, a = d["rollers"], d["teeth"], d["roller_position_radius_mm"]
    arms = []
    for i in range(n1):
        ci = (a * math.cos(2 * math.pi * i / n1), a * math.sin(2 * math.pi * i / n1))
        p = (n1 * e, 0.0)  # pitch point, crank 0
        dx, dy = ci[0] - p[0], ci[1] - p[1]
        n = math.hypot(dx, dy)
        arm = n2 * e * dy / n  # n2 e (u × d), u = x̂ at crank 0; > 0 on the loaded flank
        if arm > 0.02 * n2 * e:
            arms.append(arm)

    def ring_moment(beta):
        return sum(force(li * beta) * li for li in arms)

    beta = lambda torque: bisect(ring_moment, 0.0, 0.1, torque * 1e3)
    k_ring = 0.5 * tr / ((beta(tr) - beta(0.5 * tr)) * arcmin)
    k_series = 1 / (1 / k_pins + 1 / k_ring)
    # Backlash at crank 0: 2 β0 + 2 c/R_w. β0 = min_i g_i/l_i to first order in the modification: the
    # tooth's normal clearance g_i = −Δa (u·N) + Δρ at roller i (X(t) = a u(t) − e u(n1 t), N its
    # outward normal at t_i = 2πi/n1), over the arm l_i = X × N of the normal about the disc centre.
    mod = study.get("modification", {})
    da, dr = mod.get("delta_position_um", 0) * 1e-3, mod.get("delta_radius_um", 0) * 1e-3
    beta0 = math.inf
    for i in range(n1):
        ti = 2 * math.pi * i / n1
        x = (a * math.cos(ti) - e * math.cos(n1 * ti), a * math.sin(ti) - e * math.sin(n1 * ti))
        xp = (-a * math.sin(ti) + e * n1 * math.sin(n1 * ti), a * math.cos(ti) - e * n1 * math.cos(n1 * ti))
        nn = (xp[1] / math.hypot(*xp), -xp[0] / math.hypot(*xp))
        arm = x[0] * nn[1] - x[1] * nn[0]
        if arm > 0.02 * n2 * e:
            beta0 = min(beta0, (-da * (math.cos(ti) * nn[0] + math.sin(ti) * nn[1]) + dr) / arm)
    print(f"backlash, first order: 2 x {beta0 * arcmin * 60:.3f}″ + 2 c/R_w = {2 * (beta0 + c / rw) * arcmin:.6f}′")
    share = result["stiffness"]
    print(f"output pins, first-order Palmgren: {k_pins:.1f} N·m/arcmin (ours: "
          f"{result['torsional_stiffness_Nm_per_arcmin'] / share['output_pins_share']:.1f} from the share)")
    print(f"ring pins, rigid-body arms + Palmgren, no modification: {k_ring:.1f} N·m/arcmin on {len(arms)} pairs "
          f"(ours: {result['torsional_stiffness_Nm_per_arcmin'] / share['ring_pins_share']:.1f})")
    print(f"in series: {k_series:.1f} N·m/arcmin")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
