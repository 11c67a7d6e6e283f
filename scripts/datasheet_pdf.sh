#!/bin/sh
# Prints the datasheet of a camopt result (RESULT_DIR/datasheet.html, written by cycloid_ltca and
# lcr_analysis with "ratings" or "stiffness"; docs/ratings.md) to a PDF with headless Chromium
# (Debian's package chromium; scripts/install_deps.sh installs it). The PDF goes beside the result
# folder (RESULT_DIR_datasheet.pdf), not into it: a result folder holds only what camopt wrote, so
# that the next `camopt run` may replace it. A PDF carries its creation time: unlike camopt's own
# files it is not byte-identical from run to run.
#   usage: scripts/datasheet_pdf.sh RESULT_DIR [OUT.pdf]
#   exit: 0 written (its path on stdout); 2 no datasheet.html; 3 no Chromium; 1 Chromium failed
set -eu
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: scripts/datasheet_pdf.sh RESULT_DIR [OUT.pdf]" >&2
  exit 2
fi
dir=${1%/}
html="$dir/datasheet.html"
if [ ! -f "$html" ]; then
  echo "datasheet_pdf: $html: no datasheet (a cycloid_ltca or lcr_analysis result with ratings or stiffness has one)" >&2
  exit 2
fi
out=${2:-${dir}_datasheet.pdf}
browser=
for name in chromium chromium-browser google-chrome; do
  if command -v "$name" >/dev/null 2>&1; then browser=$name; break; fi
done
if [ -z "$browser" ]; then
  echo "datasheet_pdf: no Chromium on PATH (Debian package chromium): open $html in a browser and print it" >&2
  exit 3
fi
profile=$(mktemp -d)
tmp="$out.part"
trap 'rm -rf "$profile" "$tmp"' EXIT
"$browser" --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions --user-data-dir="$profile" \
  --no-pdf-header-footer --print-to-pdf="$tmp" "file://$(realpath "$html")" >/dev/null 2>&1 || true
if [ ! -s "$tmp" ] || [ "$(head -c 4 "$tmp")" != "%PDF" ]; then
  echo "datasheet_pdf: $browser wrote no PDF of $html" >&2
  exit 1
fi
mv "$tmp" "$out"
echo "$out"
