#!/usr/bin/env bash
# The reports of the bundled scenes, checked by real tools (docs/report.md).
#   check_reports.sh xml    PENDULUM_G DATA_DIR OUT_DIR  every page and plot through xmllint
#   check_reports.sh render PENDULUM_G DATA_DIR OUT_DIR  every page rendered by headless Chromium to PNG
#   check_reports.sh layout PENDULUM_G DATA_DIR OUT_DIR  every page laid out by headless Chromium: nothing
#                                                        runs off (page, plot or frame), each page within its
#                                                        screenshot's height
# A fifth argument, the make_fresh_class program, adds the fresh class of
# issue 21 (tests/tools/make_fresh_class.cpp): its class page, and in xml
# mode every scene's page and plots.
# Exits 77 (CTest: skipped) with a message when the tool is not installed.
set -euo pipefail
mode=$1 exe=$2 data=$3 out=$4 fresh=${5:-}
here=$(dirname "$(realpath "$0")")
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
pages=(report-nelson-olsson:3040 report-decay:4010 report-series:4180 report-pivot-scan:4900 report-kater:4360
       report-class:6900 report-recording:3000)
# Long file paths (a scene and a class in a deep folder) must wrap, not run off.
deep="$out/long/a-folder-named-by-a-student-who-likes-long-names/lab_report_pendulum_group_7_final_version_2"
mkdir -p "$deep"
cp "$data/nelson_olsson_1986.json" "$deep/nelson_olsson_1986_measured_by_group_7_on_tuesday_afternoon.json"
"$exe" report "$deep/nelson_olsson_1986_measured_by_group_7_on_tuesday_afternoon.json" -o "$out/long-path.html"
"$exe" batch "$deep" --report "$out/long-path-class.html" >/dev/null
extra=(long-path long-path-class)
if [ -n "$fresh" ]; then
  rm -rf "$out/fresh" && mkdir -p "$out/fresh"
  "$fresh" "$out/fresh"
  # Four of its scenes are refused by design: batch exits 1.
  (cd "$out" && "$exe" batch fresh --report "$out/report-fresh-class.html" >/dev/null) || [ $? -eq 1 ]
  extra+=(report-fresh-class)
fi

# Sets browser and a fresh profile (removed at exit), or skips (77) without Chromium.
open_browser() {
  browser=$(command -v chromium || command -v chromium-browser || true)
  if [ -z "$browser" ]; then
    echo "SKIPPED: chromium is not installed (Debian: chromium; .ci/install-deps installs it)"
    exit 77
  fi
  profile=$(mktemp -d)
  trap 'rm -rf "$profile"' EXIT
}

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
    if [ -n "$fresh" ]; then
      # Every scene the fresh class reduces: its page and each of its plots.
      for scene in "$out"/fresh/*.json; do
        name=$(basename "$scene" .json)
        "$exe" report "$scene" -o "$out/fresh-$name.html" 2>/dev/null || continue
        for plot in corrections budget decay series; do
          "$exe" report "$scene" --plot $plot -o "$out/fresh-$name-$plot.svg" 2>/dev/null || true
        done
      done
    fi
    # The pages are written as well-formed XML too, so the same parser checks
    # them; an id twice in one file is invalid in both.
    for f in "$out"/*.svg "$out"/*.html; do
      xmllint --noout "$f"
      twice=$(grep -o ' id="[^"]*"' "$f" | sort | uniq -d | head -3)
      if [ -n "$twice" ]; then
        echo "$f: an id used twice:$twice" >&2
        exit 1
      fi
      echo "well-formed: $f"
    done
    ;;
  render)
    open_browser
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
  layout)
    open_browser
    failed=0
    # The screenshots' pages with their window heights, then the others (no height).
    for entry in "${pages[@]}" "${extra[@]}"; do
      name=${entry%%:*} height=${entry#*:}
      [ "$height" = "$entry" ] && height=
      copy="$out/$name.measure.html"
      { sed '/^<\/body>$/,$d' "$out/$name.html"; echo '<script>'; cat "$here/measure_page.js"; echo '</script>'
        echo '</body>'; echo '</html>'; } >"$copy"
      measured=$("$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --user-data-dir="$profile" \
        --no-first-run --disable-background-networking --disable-component-update \
        --host-resolver-rules="MAP * ~NOTFOUND" --window-size=900,1000 --dump-dom "file://$copy" 2>/dev/null |
        sed -n '/<pre id="measured">/,/<\/pre>/p' | sed 's/<[^>]*>//g')
      read -r _ width page_height <<<"$(grep '^size ' <<<"$measured")"
      if [ -z "${page_height:-}" ]; then
        echo "$name: no measurement from $browser" >&2
        exit 1
      fi
      problems=$(grep -E '^(off|svg) ' <<<"$measured" || true)
      if [ "$width" -gt 900 ]; then problems+=$'\n'"the page is $width px wide in a 900 px window"; fi
      # The screenshot holds the whole page, with at most 300 px to spare.
      if [ -n "$height" ] && { [ "$page_height" -gt "$height" ] || [ "$page_height" -lt $((height - 300)) ]; }; then
        problems+=$'\n'"the page is $page_height px tall; its screenshot's window is $height px: set pages=() to fit"
      fi
      if [ -n "$problems" ]; then
        echo "$name:$problems" | sed '2,$s/^/  /' >&2
        failed=1
      else
        echo "laid out: $name ($width x $page_height px, nothing runs off)"
      fi
    done
    exit $failed
    ;;
  *)
    echo "usage: $0 xml|render|layout PENDULUM_G DATA_DIR OUT_DIR [MAKE_FRESH_CLASS]" >&2
    exit 2
    ;;
esac
