#!/usr/bin/env bash
# The reports of the bundled scenes, checked by real tools (docs/report.md).
#   check_reports.sh xml    PENDULUM_G DATA_DIR OUT_DIR  every page and plot through xmllint
#   check_reports.sh render PENDULUM_G DATA_DIR OUT_DIR  every page rendered by headless Chromium to PNG
# Exits 77 (CTest: skipped) with a message when the tool is not installed.
set -euo pipefail
mode=$1 exe=$2 data=$3 out=$4
mkdir -p "$out"
out=$(realpath "$out") exe=$(realpath "$exe")

# The pages: a scene, a scene with a decay record, a series (it warns of a
# trial on stderr), a pivot scan and Kater's pendulum (both warn), a class
# (student_c fails, so batch exits 1 by design), each with the height of its
# whole page (px).
"$exe" report "$data/nelson_olsson_1986.json" -o "$out/report-nelson-olsson.html"
"$exe" report "$data/nelson_olsson_1986_decay.json" -o "$out/report-decay.html"
"$exe" report "$data/pendulum_lengths_series.json" -o "$out/report-series.html" 2>/dev/null
"$exe" report "$data/metre_stick_pivot_scan.json" -o "$out/report-pivot-scan.html" 2>/dev/null
"$exe" report "$data/kater_reversible_pendulum.json" -o "$out/report-kater.html" 2>/dev/null
(cd "$data" && "$exe" batch class --report "$out/report-class.html" >/dev/null) || [ $? -eq 1 ]
# A recording: the signal with its crossings, the amplitudes, the periods.
"$exe" report "$data/recordings/phyphox_gyroscope.csv" -o "$out/report-recording.html"
pages=(report-nelson-olsson:2880 report-decay:3870 report-series:5090 report-pivot-scan:7090 report-kater:4170
       report-class:6150 report-recording:3000)

case $mode in
  xml)
    if ! command -v xmllint >/dev/null; then
      echo "SKIPPED: xmllint is not installed (Debian: libxml2-utils; .ci/install-deps installs it)"
      exit 77
    fi
    for plot in corrections budget; do
      "$exe" report "$data/nelson_olsson_1986.json" --plot $plot -o "$out/nelson-olsson-$plot.svg"
    done
    "$exe" report "$data/nelson_olsson_1986_decay.json" --plot decay -o "$out/decay.svg"
    "$exe" report "$data/pendulum_lengths_series.json" --plot series -o "$out/series.svg" 2>/dev/null
    for plot in signal amplitude period-amplitude; do
      "$exe" report "$data/recordings/phyphox_gyroscope.csv" --plot $plot -o "$out/recording-$plot.svg"
    done
    "$exe" report "$data/metre_stick_pivot_scan.json" --plot pivot-scan -o "$out/pivot-scan.svg" 2>/dev/null
    "$exe" report "$data/kater_reversible_pendulum.json" --plot pivot-scan -o "$out/kater.svg" 2>/dev/null
    # The pages are written as well-formed XML too, so the same parser checks them.
    for f in "$out"/*.svg "$out"/*.html; do
      xmllint --noout "$f"
      echo "well-formed: $f"
    done
    ;;
  render)
    browser=$(command -v chromium || command -v chromium-browser || true)
    if [ -z "$browser" ]; then
      echo "SKIPPED: chromium is not installed (Debian: chromium; .ci/install-deps installs it)"
      exit 77
    fi
    profile=$(mktemp -d)
    trap 'rm -rf "$profile"' EXIT
    for entry in "${pages[@]}"; do
      name=${entry%%:*} height=${entry##*:}
      rm -f "$out/$name.png"
      # No name resolves, so that the page could load nothing even if it tried.
      "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --hide-scrollbars --user-data-dir="$profile" \
        --no-first-run --disable-background-networking --disable-component-update \
        --host-resolver-rules="MAP * ~NOTFOUND" --window-size=900,"$height" \
        --screenshot="$out/$name.png" "file://$out/$name.html" >/dev/null 2>&1
      # A PNG of the whole window: the signature, then the IHDR width and height.
      header=$(od -An -tx1 -N24 "$out/$name.png" | tr -d ' \n')
      expected=89504e470d0a1a0a0000000d49484452$(printf '%08x%08x' 900 "$height")
      if [ "$header" != "$expected" ]; then
        echo "$name: no 900x$height PNG from $browser (header $header)" >&2
        exit 1
      fi
      echo "rendered: $out/$name.png ($(stat -c %s "$out/$name.png") bytes)"
    done
    ;;
  *)
    echo "usage: $0 xml|render PENDULUM_G DATA_DIR OUT_DIR" >&2
    exit 2
    ;;
esac
