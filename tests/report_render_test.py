#!/usr/bin/env python3
"""report.html opens in headless Chromium: it renders and logs nothing on the console.

Usage: report_render_test.py CAMOPT_BINARY SOURCE_DIR WORK_DIR [SCREENSHOT_DIR] [--shard I/N]

With --shard I/N only the examples I, I + N, ... of the list below (ctest runs two shards, each in
its own WORK_DIR: a Chromium profile folder is not shared).

For each of the examples below (LCR analysis, LCR min-size, cycloid LTCA, LCR analysis with lives:
its life table and life.svg, a drive train's rigidity, a disc-cam sizing, a disc cam, the cycloid's
and the LCR's catalogue pages) and a small sweep (its report.html and Pareto plot) it runs camopt,
then checks report.html:
  * statically: self-contained (no src/href/url() other than data: and in-page #anchors, no
    <script>), every inline <svg> is well-formed XML, one inline plot per .svg file of the run;
  * in Chromium, one start per report (--headless --screenshot, with --enable-logging=stderr
    --v=0): the screenshot is not blank (enough non-white pixels, more than a handful of colours)
    and the log holds no console line. The page has no script, so any console message (an error,
    a warning, a blocked resource) means something is wrong; Chromium writes them to stderr as
    "INFO:CONSOLE:<line>] ...".
Exit 77 (ctest SKIP_RETURN_CODE) only when no Chromium is installed; scripts/install_deps.sh
installs Debian's chromium, so CI runs it. With SCREENSHOT_DIR, the screenshots are copied there
(docs/images/ is made that way). The catalogue examples' datasheet.html too: every number read back
from the rendered DOM against result.json, and printed to a PDF by scripts/datasheet_pdf.sh.
"""
import html as html_lib
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

EXAMPLES = [  # (example, screenshot name); "sweep:" a sweep written by sweep_file()
    ("lcr_ii", "report_lcr_analysis.png"),
    ("lcr_min_size", "report_lcr_min_size.png"),
    ("cycloid_ltca_nnm_lcm", "report_cycloid_ltca.png"),
    ("lcr_ii_life", "report_lcr_life.png"),
    ("sweep:crowning_vs_torque", "report_sweep.png"),
    ("rigidity_gearbox", "report_rigidity.png"),
    ("disc_cam_min_size", "report_disc_cam_min_size.png"),
    ("disc_cam_translating", "report_disc_cam.png"),
    ("cycloid_catalogue", "report_cycloid_catalogue.png"),
    ("lcr_catalogue", "report_lcr_catalogue.png"),
]

# Other pages of a run rendered the same way (page, screenshot name): the datasheet, whose every
# number is also read back from the rendered DOM against result.json (datasheet_checks).
PAGES = {
    "cycloid_catalogue": [("datasheet.html", "datasheet_cycloid.png")],
    "lcr_catalogue": [("datasheet.html", "datasheet_lcr.png")],
}

# What a kind's report is for, drawn (file of the run, text it must hold): the rigidity chain with
# each element's share and the advice, the backlash against its limit; the sized cam (the sized
# reducer) over its start; the pressure-angle limit lines on the disc cam's plot.
DRAWN = {
    "rigidity_gearbox": [("compliance_share.svg", "jaw coupling"), ("compliance_share.svg", "Advice: "),
                         ("backlash.svg", "backlash limit"), ("report.html", "<li>Advice: jaw coupling")],
    "disc_cam_min_size": [("profile.svg", "start design"), ("profile.svg", "sized cam")],
    "lcr_min_size": [("sized_assembly.svg", "start design: cam profile"), ("sized_assembly.svg", "sized: rollers")],
    "disc_cam_translating": [("angles.svg", "pressure angle limit"), ("angles.svg", "−pressure angle limit")],
}


def sweep_file(source, work):
    """A small sweep of the cycloid example (6 cases on a coarse grid) with a Pareto front."""
    import json
    path = os.path.join(work, "sweep_crowning_vs_torque.json")
    sweep = {
        "sweep": "crowning against torque",
        "base": os.path.join(os.path.abspath(source), "studies", "examples", "cycloid_ltca_nnm_lcm.json"),
        "set": {"/analysis": {"crank_angle_steps": 6, "grid": [12, 12]}},
        "vary": [{"path": "/crowning/coefficient_mm", "values": [0.002, 0.005, 0.01]},
                 {"path": "/load/torque_Nm", "values": [100, 300]}],
        "outputs": ["/max_contact_stress_MPa", "/lte_peak_to_peak_arcsec"],
        "pareto": {"minimize": ["/max_contact_stress_MPa"], "maximize": ["/lte_peak_to_peak_arcsec"]},
    }
    with open(path, "w", encoding="utf-8") as f:
        json.dump(sweep, f)
    return path
WINDOW = (1280, 2000)


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def top_level_svgs(html):
    """The outermost <svg>…</svg> elements of the page (a stacked plot nests one per panel)."""
    svgs, depth, start = [], 0, 0
    for m in re.finditer(r"<svg\b|</svg>", html):
        if m.group(0) == "</svg>":
            depth -= 1
            if depth == 0:
                svgs.append(html[start:m.end()])
        else:
            if depth == 0:
                start = m.start()
            depth += 1
    return svgs


def static_checks(html, out_dir):
    errors = []
    for m in re.finditer(r'\b(?:src|href)\s*=\s*"([^"]*)"', html):
        if not (m.group(1).startswith("data:") or m.group(1).startswith("#")):
            errors.append("external reference: " + m.group(0))
    for m in re.finditer(r"url\(([^)]*)\)", html):
        if not m.group(1).strip("'\" ").startswith("data:"):
            errors.append("external url(): " + m.group(0))
    if re.search(r"<script\b", html, re.I):
        errors.append("a <script> element")
    svgs = top_level_svgs(html)
    for k, svg in enumerate(svgs):
        try:
            ET.fromstring(svg)
        except ET.ParseError as e:
            errors.append("inline SVG %d is not well-formed XML: %s" % (k, e))
    files = sorted(f for f in os.listdir(out_dir) if f.endswith(".svg"))
    if len(svgs) != len(files):
        errors.append("%d inline plots for %d .svg files (%s)" % (len(svgs), len(files), ", ".join(files)))
    if not files:
        errors.append("no plot in the run")
    return errors


def render(chromium, html_path, png_path, profile_dir):
    cmd = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
           "--no-first-run", "--disable-extensions", "--user-data-dir=" + profile_dir,
           "--enable-logging=stderr", "--v=0", "--log-level=0",
           "--window-size=%d,%d" % WINDOW, "--screenshot=" + png_path, "file://" + html_path]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    return p.returncode, p.stdout + p.stderr


def dump_dom(chromium, html_path, profile_dir):
    cmd = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-extensions",
           "--user-data-dir=" + profile_dir, "--dump-dom", "file://" + html_path]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    return p.stdout


def datasheet_checks(dom, result):
    """Every cell with a data-source shows result.json's value at that pointer: a number to 6
    significant digits (with its unit after it), a text as it is."""
    errors, numbers = [], 0
    for m in re.finditer(r'data-source="([^"]+)">([^<]*)<', dom):
        pointer, shown = m.group(1), html_lib.unescape(m.group(2))
        value = result
        for part in pointer.strip("/").split("/"):
            if isinstance(value, list):
                value = value[int(part)] if part.isdigit() and int(part) < len(value) else None
            elif isinstance(value, dict):
                value = value.get(part)
            else:
                value = None
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            numbers += 1
            read = float(shown.split(" ")[0])
            if abs(read - value) > 5e-6 * abs(value) + 1e-12:
                errors.append("%s shows %r, result.json has %r" % (pointer, shown, value))
        elif isinstance(value, str):
            if shown != value:
                errors.append("%s shows %r, result.json has %r" % (pointer, shown, value))
    if numbers < 20:
        errors.append("only %d numbers on the datasheet" % numbers)
    print("  datasheet: %d numbers checked against result.json" % numbers)
    return errors


def pdf_checks(source, out, result):
    """scripts/datasheet_pdf.sh prints the datasheet to a PDF beside the result folder: a PDF whose
    text (pdftotext, Debian's poppler-utils, when installed) holds the rated torque as the page
    shows it and its JSON pointer."""
    pdf = out + "_datasheet.pdf"
    if os.path.exists(pdf):
        os.remove(pdf)
    run = subprocess.run([os.path.join(source, "scripts", "datasheet_pdf.sh"), out], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, timeout=120)
    if run.returncode != 0 or run.stdout.strip() != pdf:
        return ["datasheet_pdf.sh exit %d (%s): %s" % (run.returncode, run.stdout.strip(), run.stderr.strip())]
    with open(pdf, "rb") as f:
        if f.read(5) != b"%PDF-":
            return ["%s is not a PDF" % pdf]
    if not shutil.which("pdftotext"):
        print("  pdf: %s written (%d bytes; no pdftotext to read it back)" % (pdf, os.path.getsize(pdf)))
        return []
    text = subprocess.run(["pdftotext", pdf, "-"], stdout=subprocess.PIPE, text=True, timeout=60).stdout
    rated = "%.6g" % result["rated_torque_Nm"]
    errors = [] if rated in text and "/rated_torque_Nm" in text else [
        "the PDF's text lacks the rated torque %s or its pointer" % rated]
    print("  pdf: %d bytes, rated torque %s N m read back" % (os.path.getsize(pdf), rated))
    return errors


def pixel_checks(png_path):
    from PIL import Image  # Debian python3-pil
    im = Image.open(png_path).convert("RGB")
    if im.size != WINDOW:
        return ["screenshot is %dx%d, expected %dx%d" % (im.size + WINDOW)]
    small = im.resize((im.size[0] // 4, im.size[1] // 4))
    pixels = list(small.getdata())
    non_white = sum(1 for p in pixels if min(p) < 235)
    colours = len(set((r // 32, g // 32, b // 32) for r, g, b in pixels))
    share = non_white / len(pixels)
    print("  screenshot: %.1f%% non-white pixels, %d colour bins" % (100 * share, colours))
    errors = []
    if share < 0.03:
        errors.append("screenshot nearly blank (%.2f%% non-white)" % (100 * share))
    if colours < 8:
        errors.append("screenshot has only %d colour bins (plots not drawn?)" % colours)
    return errors


def main():
    args = sys.argv[1:]
    shard, shards = 0, 1
    if "--shard" in args:
        k = args.index("--shard")
        try:
            shard, shards = (int(v) for v in args[k + 1].split("/"))
        except (IndexError, ValueError):
            shard, shards = -1, 0
        if not 0 <= shard < shards:
            print("--shard I/N with 0 <= I < N")
            return 2
        del args[k:k + 2]
    if len(args) < 3:
        print(__doc__)
        return 2
    camopt, source, work = args[0], args[1], os.path.abspath(args[2])
    shots = args[3] if len(args) > 3 else None
    examples = EXAMPLES[shard::shards]
    chromium = find_chromium()
    if not chromium:
        print("SKIPPED: no chromium on PATH (Debian package chromium; scripts/install_deps.sh installs it)")
        return 77
    try:
        import PIL  # noqa: F401
    except ImportError:
        print("FAILED: %s has no PIL (Debian python3-pil; scripts/install_deps.sh installs it)" % sys.executable)
        return 1
    os.makedirs(work, exist_ok=True)
    failures = []
    for example, shot in examples:
        print(example)
        out = os.path.join(work, example)
        if example.startswith("sweep:"):
            out = os.path.join(work, example[6:])
            command = [camopt, "sweep", sweep_file(source, work), "--out", out, "--quiet", "--jobs", "1"]
        else:
            study = os.path.join(source, "studies", "examples", example + ".json")
            command = [camopt, "run", study, "--out", out, "--quiet"]
        run = subprocess.run(command, cwd=source,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600)
        if run.returncode != 0:
            failures.append("%s: camopt exit %d: %s" % (example, run.returncode, run.stderr.strip()))
            continue
        html_path = os.path.join(out, "report.html")
        with open(html_path, encoding="utf-8") as f:
            html = f.read()
        errors = static_checks(html, out)
        for name, text in DRAWN.get(example, []):
            path = os.path.join(out, name)
            if not os.path.exists(path):
                errors.append("no %s in the run" % name)
            elif text not in open(path, encoding="utf-8").read():
                errors.append("%s does not show %r" % (name, text))
        png = os.path.join(work, shot)
        if os.path.exists(png):
            os.remove(png)
        profile = os.path.join(work, "chromium-profile")
        shutil.rmtree(profile, ignore_errors=True)
        code, log = render(chromium, html_path, png, profile)
        console = [line for line in log.splitlines() if ":CONSOLE" in line]
        errors += ["console: " + line for line in console]
        if not os.path.exists(png):
            errors.append("chromium (exit %d) wrote no screenshot; its log:\n%s" % (code, log[-2000:]))
        else:
            errors += pixel_checks(png)
            if shots:
                os.makedirs(shots, exist_ok=True)
                shutil.copyfile(png, os.path.join(shots, shot))
        for page, page_shot in PAGES.get(example, []):
            page_path = os.path.join(out, page)
            if not os.path.exists(page_path):
                errors.append("no %s in the run" % page)
                continue
            with open(os.path.join(out, "result.json"), encoding="utf-8") as f:
                result = json.load(f)
            shutil.rmtree(profile, ignore_errors=True)
            errors += datasheet_checks(dump_dom(chromium, page_path, profile), result)
            errors += pdf_checks(source, out, result)
            page_png = os.path.join(work, page_shot)
            shutil.rmtree(profile, ignore_errors=True)
            code, log = render(chromium, page_path, page_png, profile)
            errors += ["%s console: %s" % (page, line) for line in log.splitlines() if ":CONSOLE" in line]
            if not os.path.exists(page_png):
                errors.append("chromium (exit %d) wrote no screenshot of %s" % (code, page))
            else:
                errors += pixel_checks(page_png)
                if shots:
                    shutil.copyfile(page_png, os.path.join(shots, page_shot))
        failures += ["%s: %s" % (example, e) for e in errors]
    for f in failures:
        print("FAILED: " + f)
    print("%d reports checked, %d problems" % (len(examples), len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
