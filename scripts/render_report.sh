#!/usr/bin/env bash
# Looks at a report the way a reader does: renders REPORT.html in headless Chromium to a PNG of the
# whole page (and a PDF, as printed), so a broken plot, a clipped legend or an over-tall table is
# seen, not only parsed. The tests check that the page is well-formed XML; this is the eye check.
#   scripts/render_report.sh out/report/report.html [OUT_DIR]   (OUT_DIR defaults to the report's)
# Needs Debian's chromium (apt-get install chromium); the page itself needs nothing but itself.
set -euo pipefail
if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 REPORT.html [OUT_DIR]" >&2
  exit 2
fi
report="$(realpath "$1")"
out_dir="${2:-$(dirname "$report")}"
if [[ ! -f "$report" ]]; then
  echo "$0: $1: no such file" >&2
  exit 2
fi
if ! command -v chromium >/dev/null; then
  echo "$0: chromium is not installed (apt-get install chromium)" >&2
  exit 2
fi
mkdir -p "$out_dir"
# A window taller than any report; the PNG's blank bottom is the only cost. --no-sandbox: CI and
# these machines run as root, where Chromium's sandbox refuses to start.
chromium_flags=(--headless --no-sandbox --disable-gpu --hide-scrollbars)
chromium "${chromium_flags[@]}" --window-size=1280,16000 \
  --screenshot="$out_dir/report.png" "file://$report" 2>/dev/null
chromium "${chromium_flags[@]}" --no-pdf-header-footer \
  --print-to-pdf="$out_dir/report.pdf" "file://$report" 2>/dev/null
echo "$out_dir/report.png"
echo "$out_dir/report.pdf"
