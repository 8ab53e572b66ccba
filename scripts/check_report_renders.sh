#!/usr/bin/env bash
# Renders an HTML report in headless Chromium (Debian's `chromium`; `apt-get install
# chromium`) and checks that the screenshot exists and is not blank.
#
#   scripts/check_report_renders.sh REPORT.html OUT.png
#
# Exit status: 0 rendered; 1 missing, failed or blank; 77 chromium or python3 (which reads
# the PNG, standard library only) is not installed, so nothing was checked. CHROMIUM names
# another browser binary.
set -euo pipefail
if [[ $# -ne 2 ]]; then
  echo "usage: $0 REPORT.html OUT.png" >&2
  exit 2
fi
report="$1"
png="$2"
chromium="${CHROMIUM:-chromium}"
if ! command -v "$chromium" >/dev/null; then
  echo "$chromium is not installed (apt-get install chromium): render check skipped"
  exit 77
fi
if ! command -v python3 >/dev/null; then
  echo "python3 is not installed: render check skipped"
  exit 77
fi
if [[ ! -f "$report" ]]; then
  echo "$report: no such file" >&2
  exit 1
fi

profile="$(mktemp -d)"
log="$(mktemp)"
trap 'rm -rf "$profile" "$log"' EXIT
rm -f "$png"
# No network, no sync, no first-run UI: the page must render from the file alone.
if ! timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --screenshot="$(realpath -m "$png")" --window-size=1280,2400 \
  "file://$(realpath "$report")" >"$log" 2>&1; then
  echo "$chromium failed on $report:" >&2
  cat "$log" >&2
  exit 1
fi
if [[ ! -s "$png" ]]; then
  echo "$chromium wrote no screenshot $png:" >&2
  cat "$log" >&2
  exit 1
fi

# Blank: (almost) one colour. A rendered report has text, tables and figures in many colours.
python3 - "$png" <<'PY'
import struct, sys, zlib

path = sys.argv[1]
data = open(path, "rb").read()
if data[:8] != b"\x89PNG\r\n\x1a\n":
    sys.exit(f"{path}: not a PNG")
chunks, at = {}, 8
idat = b""
while at < len(data):
    length, kind = struct.unpack(">I4s", data[at:at + 8])
    body = data[at + 8:at + 8 + length]
    if kind == b"IHDR":
        width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
    elif kind == b"IDAT":
        idat += body
    at += 12 + length
channels = {2: 3, 6: 4, 0: 1, 4: 2}.get(colour)
if depth != 8 or channels is None or interlace != 0:
    sys.exit(f"{path}: unexpected PNG format (depth {depth}, colour type {colour})")
raw = zlib.decompress(idat)
stride = width * channels
previous = bytearray(stride)
counts = {}
for y in range(height):
    start = y * (stride + 1)
    kind = raw[start]
    row = bytearray(raw[start + 1:start + 1 + stride])
    for x in range(stride):
        left = row[x - channels] if x >= channels else 0
        up = previous[x]
        upper_left = previous[x - channels] if x >= channels else 0
        if kind == 1:
            row[x] = (row[x] + left) & 255
        elif kind == 2:
            row[x] = (row[x] + up) & 255
        elif kind == 3:
            row[x] = (row[x] + (left + up) // 2) & 255
        elif kind == 4:
            p = left + up - upper_left
            pa, pb, pc = abs(p - left), abs(p - up), abs(p - upper_left)
            predictor = left if pa <= pb and pa <= pc else up if pb <= pc else upper_left
            row[x] = (row[x] + predictor) & 255
    previous = row
    for x in range(0, stride, channels * 4):  # every 4th pixel is plenty
        pixel = bytes(row[x:x + channels])
        counts[pixel] = counts.get(pixel, 0) + 1
total = sum(counts.values())
background = max(counts.values())
ink = 1.0 - background / total
print(f"{path}: {width}x{height}, {len(counts)} colours, {100 * ink:.1f} % not background")
if len(counts) < 16 or ink < 0.02:
    sys.exit(f"{path}: the page looks blank")
PY
