#!/usr/bin/python3
"""Geometry files checked by independent readers.

Runs camopt on every example of the kinds that write cam geometry (lcr_analysis, cycloid_ltca,
disc_cam) and checks each file with tools that share no code with camopt:
  - DXF: opened and audited with ezdxf (nothing to fix), units declared as mm, the cam profile an
    LWPOLYLINE with arcs; its distance from the profile computed here from the papers' formulas
    (LCR cams, cycloid disc, cycloidal disc cams) sampled densely, or from the model's profile points
    in series.csv (every disc cam), at most the study's tolerance.
  - STL: binary unless asked otherwise; free edges counted here on the raw triangles, and by admesh.
  - Parts (result.json "parts"): each part's DXF audited; a cycloid disc's HOLES circles against the
    output mechanism's count, circle and hole radius (to 1e-6 mm), its BORE, its PROFILE against the
    formula's profile turned by its phase -2 pi (k - 1) / (N n2), its volume from the DXF's own
    arcs and circles (shoelace and circular segments) against result.json's, its STL closed; bom.csv's
    masses are volume x density and its total their sum.
Usage: geometry_files_test.py CAMOPT_BINARY EXAMPLES_DIR
"""
import concurrent.futures
import csv
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile

try:
    import ezdxf
    import ezdxf.math
    import numpy as np
except ImportError as err:  # the install script installs them; the test installs nothing
    print(f"missing Python module ({err}): run scripts/install_deps.sh (python3-ezdxf, python3-numpy)")
    sys.exit(1)

DENSE = 20000  # exact-profile points per curve
FAILURES = []


def check(ok, what):
    if not ok:
        FAILURES.append(what)
        print("FAIL:", what)


# ---- the profiles, written here from the papers' formulas (docs/papers.md) ----------------------

def lcr_profile(side, ecc, n=DENSE):
    """LCR cam profile: pitch curve X = R u(psi) - e u(k psi), k = n/(n - m), offset by the roller
    radius toward the cam (left of the counter-clockwise tangent)."""
    R = side["turret_radius_mm"]
    k = side["rollers"] / (side["rollers"] - side["lobes"])
    rr = side["roller_diameter_mm"] / 2
    psi = np.linspace(0, 2 * np.pi, n, endpoint=False)
    x = R * np.cos(psi) - ecc * np.cos(k * psi)
    y = R * np.sin(psi) - ecc * np.sin(k * psi)
    tx = -R * np.sin(psi) + ecc * k * np.sin(k * psi)
    ty = R * np.cos(psi) - ecc * k * np.cos(k * psi)
    norm = np.hypot(tx, ty)
    return np.column_stack([x - rr * ty / norm, y + rr * tx / norm])


def cycloid_profile(drive, modification, n=DENSE):
    """Cycloid disc: roller-centre curve X = a' u(t) - e u(n1 t), offset by rho' toward the disc
    (a' = a + da, rho' = rho + drho)."""
    a = drive["roller_position_radius_mm"] + modification.get("delta_position_um", 0) * 1e-3
    rho = drive["roller_radius_mm"] + modification.get("delta_radius_um", 0) * 1e-3
    e, n1 = drive["eccentricity_mm"], drive["rollers"]
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    x = a * np.cos(t) - e * np.cos(n1 * t)
    y = a * np.sin(t) - e * np.sin(n1 * t)
    tx = -a * np.sin(t) + e * n1 * np.sin(n1 * t)
    ty = a * np.cos(t) - e * n1 * np.cos(n1 * t)
    norm = np.hypot(tx, ty)
    # outward normal = right of the counter-clockwise tangent: (ty, -tx)
    return np.column_stack([x - rho * ty / norm, y + rho * tx / norm])


def disc_cam_profile(study, n=DENSE):
    """Translating roller follower with cycloidal rises and dwells only (else None):
    C = L u + e J u, L = sqrt((rb + rf)^2 - e^2) + S, contact A = C - rf n,
    n along L u - (S' - e) J u."""
    f = study["follower"]
    if f["type"] != "translating_roller":
        return None
    segs = []
    for m in study["motion"]:
        if m["law"] not in ("cycloidal", "dwell"):
            return None
        segs.append((m["law"], m.get("rise_mm", 0.0), math.radians(m["cam_angle_deg"])))
    rb, rf, e = study["base_circle_radius_mm"], f["roller_radius_mm"], f.get("offset_mm", 0.0)
    th = np.linspace(0, 2 * np.pi, n, endpoint=False)
    s = np.zeros(n)
    ds = np.zeros(n)
    start, level = 0.0, 0.0
    for law, h, beta in segs:
        inside = (th >= start) & (th < start + beta)
        x = (th[inside] - start) / beta
        if law == "cycloidal":
            s[inside] = level + h * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
            ds[inside] = h / beta * (1 - np.cos(2 * np.pi * x))
            level += h
        else:
            s[inside] = level
        start += beta
    L = math.sqrt((rb + rf) ** 2 - e * e) + s
    u = np.column_stack([np.cos(th), np.sin(th)])
    ju = np.column_stack([-np.sin(th), np.cos(th)])
    c = L[:, None] * u + e * ju
    nv = L[:, None] * u - (ds - e)[:, None] * ju
    nv /= np.linalg.norm(nv, axis=1)[:, None]
    return c - rf * nv


# ---- distances from points to a DXF polyline of arcs ---------------------------------------------

def polyline_arcs(entity):
    pts = entity.get_points("xyb")
    n = len(pts)
    arcs = []
    for i in range(n if entity.closed else n - 1):
        x0, y0, b = pts[i]
        x1, y1, _ = pts[(i + 1) % n]
        arcs.append(((x0, y0), (x1, y1), b))
    return arcs


def distances_to_arcs(points, arcs):
    best = np.full(len(points), np.inf)
    px, py = points[:, 0], points[:, 1]
    for (x0, y0), (x1, y1), b in arcs:
        if abs(b) < 1e-12:
            dx, dy = x1 - x0, y1 - y0
            s = np.clip(((px - x0) * dx + (py - y0) * dy) / (dx * dx + dy * dy), 0, 1)
            d = np.hypot(px - x0 - s * dx, py - y0 - s * dy)
        else:
            centre, a0, a1, r = ezdxf.math.bulge_to_arc((x0, y0), (x1, y1), b)
            # ezdxf gives the arc counter-clockwise from a0 to a1
            ang = np.arctan2(py - centre.y, px - centre.x)
            sweep = (a1 - a0) % (2 * np.pi)
            inside = ((ang - a0) % (2 * np.pi)) <= sweep
            d_arc = np.abs(np.hypot(px - centre.x, py - centre.y) - r)
            d_end = np.minimum(np.hypot(px - x0, py - y0), np.hypot(px - x1, py - y1))
            d = np.where(inside, d_arc, d_end)
        best = np.minimum(best, d)
    return best


# ---- STL ----------------------------------------------------------------------------------------

def stl_triangles(path):
    data = open(path, "rb").read()
    if data[:5] == b"solid":
        return None  # ASCII
    n = struct.unpack_from("<I", data, 80)[0]
    assert len(data) == 84 + 50 * n, "binary STL size does not match its triangle count"
    tris = []
    for i in range(n):
        v = struct.unpack_from("<12f", data, 84 + 50 * i)
        tris.append((v[3:6], v[6:9], v[9:12]))
    return tris


def free_edges(tris):
    directed = {}
    for t in tris:
        for k in range(3):
            e = (t[k], t[(k + 1) % 3])
            directed[e] = directed.get(e, 0) + 1
    free = wrong = 0
    for (a, b), count in directed.items():
        back = directed.get((b, a), 0)
        if back == 0:
            free += 1
        elif count != 1 or back != 1:
            wrong += 1
    return free, wrong


def admesh_disconnected(path):
    # admesh echoes the 80-byte header as a C string: the header has no NUL inside its 80 bytes
    # (the format needs none), so the echo runs on into whatever memory follows, which need not be
    # UTF-8. Only the counts below are read.
    out = subprocess.run(["admesh", path], capture_output=True).stdout.decode("utf-8", errors="replace")
    total = None
    for line in out.splitlines():
        if line.startswith("Total disconnected facets"):
            total = int(line.split(":")[1].split()[0])
    return total


def bulge_polyline_area(arcs):
    """Signed area of a closed polyline with bulges: the chords' polygon plus each arc's segment."""
    area = 0.0
    for (x0, y0), (x1, y1), b in arcs:
        area += 0.5 * (x0 * y1 - x1 * y0)
        if abs(b) > 1e-15:
            theta = 4 * math.atan(abs(b))
            c = math.hypot(x1 - x0, y1 - y0)
            r = c / (2 * math.sin(theta / 2))
            area += math.copysign(r * r * (theta - math.sin(theta)) / 2, b)
    return area


def bulge_polyline_length(arcs):
    length = 0.0
    for (x0, y0), (x1, y1), b in arcs:
        c = math.hypot(x1 - x0, y1 - y0)
        if abs(b) > 1e-15:
            theta = 4 * math.atan(abs(b))
            length += c / (2 * math.sin(theta / 2)) * theta
        else:
            length += c
    return length


def check_parts(name, study, result, out):
    parts = result.get("parts", {}).get("parts")
    if not parts:
        return
    tol_mm = study.get("geometry_files", {}).get("dxf_tolerance_um", 1.0) * 1e-3 if isinstance(
        study.get("geometry_files"), dict) else 1e-3
    discs = study.get("discs", 1)
    om = study.get("output_mechanism", {})
    holes_expected = "hole_radius_mm" in om and "pins" in om
    density = result["parts"]["density_kg_m3"]
    for part, info in parts.items():
        doc = ezdxf.readfile(os.path.join(out, info["dxf"]))
        auditor = doc.audit()
        check(len(auditor.errors) == 0 and len(auditor.fixes) == 0, f"{name}/{info['dxf']}: ezdxf audit")
        msp = doc.modelspace()
        profile = [e for e in msp if e.dxftype() == "LWPOLYLINE" and e.dxf.layer == "PROFILE"]
        check(len(profile) == 1 and profile[0].closed, f"{name}/{info['dxf']}: one closed PROFILE")
        if not profile:
            continue
        arcs = polyline_arcs(profile[0])
        circles = [(e.dxf.center.x, e.dxf.center.y, e.dxf.radius, e.dxf.layer) for e in msp if e.dxftype() == "CIRCLE"]
        holes = [c for c in circles if c[3] == "HOLES"]
        bores = [c for c in circles if c[3] == "BORE"]
        area = bulge_polyline_area(arcs) - sum(math.pi * c[2] ** 2 for c in holes + bores)
        volume = area * info["thickness_mm"]
        bound = bulge_polyline_length(arcs) * tol_mm * info["thickness_mm"] + 1e-9 * volume
        print(f"{name} {part}: volume from the DXF {volume:.6f} mm3, result.json {info['volume_mm3']:.6f} "
              f"(bound {bound:.3g}), {len(holes)} holes")
        check(abs(volume - info["volume_mm3"]) <= bound, f"{name}/{part}: DXF volume {volume} vs {info['volume_mm3']}")
        check(abs(info["mass_kg"] - info["volume_mm3"] * density * 1e-9) <= 1e-12 * info["mass_kg"],
              f"{name}/{part}: mass is not volume x density")
        if part.startswith("disc_"):
            k = int(part[5:])
            drive = study["drive"]
            gamma = -2 * math.pi * (k - 1) / (discs * drive["teeth"])
            if holes_expected:
                z, rw, rh = om["pins"], om["pin_circle_radius_mm"], om["hole_radius_mm"]
                check(len(holes) == z, f"{name}/{part}: {len(holes)} holes, {z} expected")
                for j in range(z):
                    want = (rw * math.cos(2 * math.pi * j / z), rw * math.sin(2 * math.pi * j / z))
                    d = min((math.hypot(h[0] - want[0], h[1] - want[1]) for h in holes), default=math.inf)
                    check(d <= 1e-6, f"{name}/{part}: no hole within 1e-6 mm of {want} (nearest {d})")
                for h in holes:
                    check(abs(h[2] - rh) <= 1e-6, f"{name}/{part}: hole radius {h[2]} vs {rh}")
            if "bore_diameter_mm" in drive:
                check(len(bores) == 1 and abs(bores[0][2] - drive["bore_diameter_mm"] / 2) <= 1e-6
                      and math.hypot(bores[0][0], bores[0][1]) <= 1e-9, f"{name}/{part}: bore")
            ref = cycloid_profile(drive, study.get("modification", {}))
            c, s_ = math.cos(gamma), math.sin(gamma)
            turned = np.column_stack([c * ref[:, 0] - s_ * ref[:, 1], s_ * ref[:, 0] + c * ref[:, 1]])
            d = distances_to_arcs(turned, arcs).max()
            print(f"{name} {part}: PROFILE vs the formula turned {math.degrees(gamma):.6f} deg: max {d * 1e3:.4f} um")
            check(d <= tol_mm + 1e-9, f"{name}/{part}: profile {d * 1e3:.4f} um from the formula at its phase")
        tris = stl_triangles(os.path.join(out, info["stl"]))
        if tris is not None:
            free, wrong = free_edges(tris)
            check(free == 0 and wrong == 0, f"{name}/{info['stl']}: {free} free, {wrong} misoriented edges")
    with open(os.path.join(out, "bom.csv")) as f:
        rows = list(csv.DictReader(f))
    total = 0.0
    for r in rows:
        if r["part"] == "total":
            check(abs(float(r["total_mass_kg"]) - total) <= 1e-8 * max(total, 1e-9), f"{name}: bom total")
            continue
        info = parts.get(r["part"])
        check(info is not None, f"{name}: bom row {r['part']} is no part")
        if info is None:
            continue
        check(int(r["count"]) == info["count"], f"{name}: bom count of {r['part']}")
        m = float(r["mass_kg"])
        check(abs(m - float(r["volume_mm3"]) * density * 1e-9) <= 1e-8 * m, f"{name}: bom mass of {r['part']}")
        total += int(r["count"]) * m
    check(len(rows) == len(parts) + 1, f"{name}: bom rows {len(rows)} for {len(parts)} parts")


# ---- per example --------------------------------------------------------------------------------

def run_example(camopt, path, tmp):
    out = os.path.join(tmp, os.path.basename(path))
    return subprocess.run([camopt, "run", path, "--quiet", "--out", out], capture_output=True, text=True)


def check_example(camopt, path, tmp, run):
    study = json.load(open(path))
    kind = study.get("study") if isinstance(study, dict) else None
    if kind not in ("lcr_analysis", "cycloid_ltca", "disc_cam"):
        return
    name = os.path.basename(path)
    out = os.path.join(tmp, name)
    check(run.returncode == 0, f"{name}: camopt exit {run.returncode}: {run.stderr.strip()}")
    if run.returncode != 0:
        return
    result = json.load(open(os.path.join(out, "result.json")))
    check_parts(name, study, result, out)
    files = result.get("geometry_files", {})
    evaluate = study.get("analysis", {}).get("evaluate")
    profile_asked = evaluate is None or kind != "lcr_analysis" or "profile" in evaluate
    check((len(files) > 0) == profile_asked, f"{name}: geometry_files {'missing' if profile_asked else 'unasked'}")
    for part, info in files.items():
        tol_mm = info["dxf_tolerance_um"] * 1e-3
        dxf_path = os.path.join(out, info["dxf"])
        doc = ezdxf.readfile(dxf_path)
        auditor = doc.audit()
        check(len(auditor.errors) == 0 and len(auditor.fixes) == 0,
              f"{name}/{info['dxf']}: ezdxf audit: {len(auditor.errors)} errors, {len(auditor.fixes)} fixes")
        check(doc.header.get("$INSUNITS") == 4, f"{name}/{info['dxf']}: $INSUNITS is not 4 (mm)")
        check(doc.header.get("$MEASUREMENT") == 1, f"{name}/{info['dxf']}: $MEASUREMENT is not 1 (metric)")
        msp = doc.modelspace()
        layers = {e.dxf.layer for e in msp}
        check(set(info["dxf_layers"]) == layers, f"{name}/{info['dxf']}: layers {sorted(layers)}")
        profiles = [e for e in msp if e.dxftype() == "LWPOLYLINE" and e.dxf.layer == "CAM_PROFILE"]
        check(len(profiles) == 1 and profiles[0].closed, f"{name}/{info['dxf']}: one closed CAM_PROFILE")
        if not profiles:
            continue
        arcs = polyline_arcs(profiles[0])
        check(sum(1 for a in arcs if abs(a[2]) > 0) > len(arcs) // 2, f"{name}/{info['dxf']}: profile has no arcs")
        # Bolt circle and keyway as declared (lcr_analysis cams, disc cam): the holes where the study
        # puts them, the keyed bore's area in closed form, the solid's volume from the DXF's own curves.
        if kind == "lcr_analysis":
            spec = study["reducer"]["input" if part == "input_cam" else "output"]
        elif kind == "disc_cam":
            spec = study
        else:
            spec = {}
        holes = [(e.dxf.center.x, e.dxf.center.y, e.dxf.radius) for e in msp if e.dxftype() == "CIRCLE" and e.dxf.layer == "HOLES"]
        if "bolt_circle" in spec:
            b = spec["bolt_circle"]
            check(len(holes) == b["holes"], f"{name}/{part}: {len(holes)} holes, {b['holes']} declared")
            for j in range(b["holes"]):
                a = math.radians(b.get("angle_deg", 0)) + 2 * math.pi * j / b["holes"]
                want = (b["circle_diameter_mm"] / 2 * math.cos(a), b["circle_diameter_mm"] / 2 * math.sin(a))
                d = min((math.hypot(h[0] - want[0], h[1] - want[1]) for h in holes), default=math.inf)
                check(d <= 1e-6, f"{name}/{part}: no hole within 1e-6 mm of {want}")
            for h in holes:
                check(abs(h[2] - b["hole_diameter_mm"] / 2) <= 1e-6, f"{name}/{part}: hole radius {h[2]}")
        else:
            check(not holes, f"{name}/{part}: holes not declared")
        if "bore_diameter_mm" in spec and "solid_volume_mm3" in info:
            bore_e = [e for e in msp if e.dxf.layer == "BORE"]
            rb = spec["bore_diameter_mm"] / 2
            if "keyway" in spec:
                k = spec["keyway"]
                check(len(bore_e) == 1 and bore_e[0].dxftype() == "LWPOLYLINE", f"{name}/{part}: keyed bore polyline")
                hw = k["width_mm"] / 2
                x0 = math.sqrt(rb * rb - hw * hw)
                theta = 2 * math.asin(hw / rb)
                keyed = math.pi * rb * rb + k["width_mm"] * (rb + k["depth_mm"] - x0) - rb * rb * (theta - math.sin(theta)) / 2
                bore_area = abs(bulge_polyline_area(polyline_arcs(bore_e[0]))) if bore_e else math.inf
                print(f"{name} {part}: keyed bore area from the DXF {bore_area:.9f} mm2, closed form {keyed:.9f}")
                check(abs(bore_area - keyed) <= 1e-9 * keyed, f"{name}/{part}: keyed bore area {bore_area} vs {keyed}")
                # the slot along its declared direction: its bottom's midpoint at rb + depth
                a = math.radians(k.get("angle_deg", 0))
                pts = bore_e[0].get_points("xy")
                bottom = max(p[0] * math.cos(a) + p[1] * math.sin(a) for p in pts)
                check(abs(bottom - (rb + k["depth_mm"])) <= 1e-9, f"{name}/{part}: keyway bottom at {bottom}")
            else:
                keyed = math.pi * rb * rb
            vol = (abs(bulge_polyline_area(arcs)) - keyed - sum(math.pi * h[2] ** 2 for h in holes)) * info["thickness_mm"]
            bound = bulge_polyline_length(arcs) * tol_mm * info["thickness_mm"]
            print(f"{name} {part}: solid volume from the DXF {vol:.6f} mm3, result.json {info['solid_volume_mm3']:.6f}")
            check(abs(vol - info["solid_volume_mm3"]) <= bound, f"{name}/{part}: solid volume {vol} vs {info['solid_volume_mm3']}")
        cutter = [e for e in msp if e.dxf.layer == "CUTTER_PATH"]
        pitch = [e for e in msp if e.dxf.layer == "PITCH_CURVE"]
        check(not (cutter and "cutter_path" in info), f"{name}: cutter path written and noted as omitted")
        check(len(cutter) <= 1 and len(pitch) <= 1, f"{name}: one cutter path and one pitch curve at most")
        # The profile from the formulas above, densely, and the model's points where written.
        refs = []
        if kind == "lcr_analysis":
            side = study["reducer"]["input" if part == "input_cam" else "output"]
            refs.append(("formula", lcr_profile(side, study["reducer"]["eccentricity_mm"])))
        elif kind == "cycloid_ltca":
            refs.append(("formula", cycloid_profile(study["drive"], study.get("modification", {}))))
        else:
            dense = disc_cam_profile(study)
            if dense is not None:
                refs.append(("formula", dense))
            with open(os.path.join(out, "series.csv")) as f:
                rows = list(csv.DictReader(f))
            refs.append(("series.csv", np.array([[float(r["contact_x_mm"]), float(r["contact_y_mm"])] for r in rows])))
        for label, pts in refs:
            d = distances_to_arcs(pts, arcs).max()
            print(f"{name} {part}: DXF profile vs {label} ({len(pts)} points): max {d * 1e3:.4f} um "
                  f"(tolerance {tol_mm * 1e3:g} um; camopt reports {info['dxf_max_deviation_um']:.4f} um)")
            # 1e-9 mm: the DXF's 12 significant digits
            check(d <= tol_mm + 1e-9, f"{name}/{info['dxf']}: {d * 1e3:.4f} um from the {label} profile")
        # STL: closed and consistently oriented.
        if "stl" in info:
            stl_path = os.path.join(out, info["stl"])
            tris = stl_triangles(stl_path)
            check((tris is None) == (info["stl_format"] == "ascii"), f"{name}/{info['stl']}: format")
            if tris is not None:
                free, wrong = free_edges(tris)
                print(f"{name} {part}: STL {len(tris)} triangles, {free} free edges, {wrong} misoriented, "
                      f"{os.path.getsize(stl_path)} bytes")
                check(free == 0 and wrong == 0, f"{name}/{info['stl']}: {free} free, {wrong} misoriented edges")
            if shutil.which("admesh"):
                n = admesh_disconnected(stl_path)
                check(n == 0, f"{name}/{info['stl']}: admesh finds {n} facets with free edges")


def main():
    camopt, examples = sys.argv[1], sys.argv[2]
    paths = []
    for f in sorted(os.listdir(examples)):
        if f.endswith(".json"):
            study = json.load(open(os.path.join(examples, f)))
            if isinstance(study, dict) and study.get("study") in ("lcr_analysis", "cycloid_ltca", "disc_cam"):
                paths.append(os.path.join(examples, f))
    with tempfile.TemporaryDirectory(prefix="camopt-geometry-") as tmp:
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            runs = list(pool.map(lambda p: run_example(camopt, p, tmp), paths))
        for path, run in zip(paths, runs):
            check_example(camopt, path, tmp, run)
    if FAILURES:
        print(f"{len(FAILURES)} failures")
        return 1
    print("all geometry files pass")
    return 0


if __name__ == "__main__":
    sys.exit(main())
