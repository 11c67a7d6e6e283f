#!/usr/bin/env python3
"""cycloid_ltca's estimated errors against crank-converged values (docs/validation.md).

For the paper's drive at 150 / 350 / 450 N·m and the four crowning forms of
studies/examples/cycloid_ltca_nnm_*.json (their own settings: 32 angles per mesh period, reported at
the refined 64, 40 x 40 grid), runs the example and the same drive on the same grid at 1024 angles
per mesh period, and prints one Markdown row per case and output: reported, estimated error
(crank part + grid part), converged, actual error.

    python3 scripts/cycloid_error_table.py build/camopt > table.md
"""
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIELDS = [("max_contact_stress_MPa", "peak stress [MPa]", 1024),
          ("lte_peak_to_peak_arcsec", "LTE p-p [″]", 1024),
          ("gear_ratio_peak_to_peak", "GR p-p", 1024)]


def run(camopt, study, out):
    path = out + ".json"
    with open(path, "w") as f:
        json.dump(study, f)
    subprocess.run([camopt, "run", path, "--out", out, "--quiet"], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "result.json")) as f:
        return json.load(f)


def main():
    camopt = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "camopt")
    tmp = tempfile.mkdtemp(prefix="cycloid-error-table-")
    print("| torque [N·m] | crowning | output | reported (64/period) | estimated error (crank + grid) "
          "| converged (angles/period) | actual error | estimate >= actual |")
    print("|---|---|---|---|---|---|---|---|")
    for torque in (150, 350, 450):
        for form in ("none", "fcm", "pcm", "lcm"):
            with open(os.path.join(ROOT, "studies", "examples", "cycloid_ltca_nnm_%s.json" % form)) as f:
                study = json.load(f)
            study["load"]["torque_Nm"] = torque
            tag = "%s_%d" % (form, torque)
            own = run(camopt, study, os.path.join(tmp, tag))
            converged = {}
            for per_period in sorted({p for _, _, p in FIELDS}):
                ref = json.loads(json.dumps(study))
                ref["analysis"]["crank_angles_per_mesh_period"] = per_period
                ref["analysis"]["estimate_error"] = False
                converged[per_period] = run(camopt, ref, os.path.join(tmp, "%s_%d" % (tag, per_period)))
            src = own["estimated_error_sources"]
            for key, label, per_period in FIELDS:
                value, truth = own[key], converged[per_period][key]
                est = own["estimated_error"][key]
                crank, grid = src["crank_angles"]["error"][key], src["grid"]["error"][key]
                actual = abs(value - truth)
                print("| %d | %s | %s | %.5g | %.3g (%.3g + %.3g) | %.5g (%d) | %.3g | %s |" %
                      (torque, form, label, value, est, crank, grid, truth, per_period, actual,
                       "yes" if est >= actual else "**no**"))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
