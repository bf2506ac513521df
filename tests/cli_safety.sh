#!/bin/sh
# File- and process-level safety of pendulum-g (issue 22, docs/robustness.md,
# "Files"): one case per run, as ctest calls it:
#   cli_safety.sh PENDULUM_G FAULT_INJECTION_SO DATA_DIR CASE [sanitized]
# Each case builds its own files in a fresh temporary folder from the
# bundled scene and recordings (data/, made by tests/tools/make_*), runs the
# command, and checks the exit status, the message and what is on disk.
set -u
G=$1 SHIM=$2 DATA=$3 CASE=$4 SANITIZED=${5:-}
T=$(mktemp -d /tmp/pendulum-g-safety-XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# expect STATUS GREP-PATTERN COMMAND...: the status and a line of stderr.
expect() {
  want=$1 pattern=$2
  shift 2
  "$@" >out 2>err
  got=$?
  [ "$got" = "$want" ] || fail "$*: exit $got, expected $want; stderr: $(cat err)"
  grep -q -- "$pattern" err || fail "$*: stderr lacks '$pattern': $(cat err)"
}
cp "$DATA/nelson_olsson_1986.json" x.json
cp "$DATA/recordings/phyphox_pendulum_raw.tsv" rec.tsv
sed 's/phyphox_pendulum_raw.tsv/rec.tsv/g' "$DATA/recordings/phyphox_pendulum_raw_from_file.json" > scene.json

case $CASE in
output_over_input)
  cp x.json x.before
  expect 2 "the output x.json is the input x.json" "$G" report x.json -o x.json
  cmp -s x.json x.before || fail "report x.json -o x.json changed x.json"
  ln -s x.json link.json
  ln x.json hard.json
  expect 2 "the output link.json is the input x.json (the same file, through a link)" "$G" report x.json -o link.json
  expect 2 "the output x.json is the input hard.json" "$G" report hard.json -o x.json
  # The scene on standard input, redirected from the output's file.
  expect 2 "the output x.json is the input standard input" sh -c "'$G' report - -o x.json < x.json"
  expect 2 "the output link.json is the input standard input" sh -c "'$G' batch - --report link.json < x.json"
  cmp -s x.json x.before || fail "an output over standard input's file changed x.json"
  cp rec.tsv rec.before
  expect 2 "the output rec.tsv is the input rec.tsv" "$G" report rec.tsv -o rec.tsv
  # A scene's recording as the output: found once the scene names it, before
  # anything is written.
  expect 2 "the output rec.tsv is the input rec.tsv" "$G" report scene.json -o rec.tsv
  cmp -s rec.tsv rec.before || fail "report scene.json -o rec.tsv changed the recording"
  mkdir class && cp x.json class/a.json && cp x.json class/b.json
  cp class/a.json a.before
  expect 2 "the output class/a.json is the input class/a.json" "$G" batch class --report class/a.json
  cmp -s class/a.json a.before || fail "batch class --report class/a.json changed a.json"
  [ ! -s out ] || fail "batch printed results before refusing its report: $(cat out)"
  mkdir rclass && cp rec.tsv rclass/rec.tsv && cp scene.json rclass/scene.json
  expect 2 "the output rclass/rec.tsv is the input rclass/rec.tsv" "$G" batch rclass --report rclass/rec.tsv
  cmp -s rclass/rec.tsv rec.before || fail "batch --report over a recording changed it"
  [ ! -s out ] || fail "batch reduced scenes before refusing a report over a recording: $(cat out)"
  # A scene's table of settings, found before anything is read.
  cp "$DATA/pendulum_lengths_table.csv" "$DATA/pendulum_lengths_table_scene.json" .
  cp pendulum_lengths_table.csv table.before
  expect 2 "the output pendulum_lengths_table.csv is the input pendulum_lengths_table.csv" \
    "$G" report pendulum_lengths_table_scene.json -o pendulum_lengths_table.csv
  expect 2 "the output pendulum_lengths_table.csv is the input pendulum_lengths_table.csv" \
    "$G" batch pendulum_lengths_table_scene.json --report pendulum_lengths_table.csv
  [ ! -s out ] || fail "batch reduced the table's scene before refusing its report: $(cat out)"
  cmp -s pendulum_lengths_table.csv table.before || fail "a report over a scene's table changed it"
  echo class/a.json > list.txt
  expect 2 "the output list.txt is the input list.txt" "$G" batch --list list.txt --report list.txt
  ;;
truncated_in_batch)
  # Three scenes, each with its own copy of the recording; the second is cut
  # to half while it is read.
  mkdir class
  for s in a b c; do
    cp rec.tsv class/$s.tsv
    sed "s/rec.tsv/$s.tsv/g" scene.json > class/$s.json
  done
  LD_PRELOAD=$SHIM PENDULUM_TEST_TRUNCATE=b.tsv ASAN_OPTIONS=verify_asan_link_order=0 \
    "$G" batch --jobs 1 class/a.json class/b.json class/c.json >out 2>err
  got=$?
  [ "$got" = 1 ] || fail "batch with a recording truncated while read: exit $got, expected 1: $(cat err)"
  [ "$(grep -c '"ok":true' out)" = 2 ] || fail "expected two results: $(cat out)"
  grep '"input":"class/b.json"' out | grep -q 'b.tsv: the file changed while it was read' ||
    fail "no clear failure for b.json: $(cat out)"
  grep -q '"class":true' out || fail "no class line: $(cat out)"
  [ "$(wc -c < class/b.tsv)" -lt "$(wc -c < rec.tsv)" ] || fail "the shim did not truncate b.tsv"
  ;;
write_errors)
  expect 5 "output: cannot write standard output: No space left on device" sh -c "'$G' reduce x.json > /dev/full"
  expect 5 "output: cannot write standard output: Bad file descriptor" sh -c "'$G' reduce x.json >&-"
  expect 5 "output: cannot write standard output: No space left on device" sh -c "'$G' batch x.json > /dev/full"
  expect 5 "output: cannot write /dev/full: No space left on device" "$G" report x.json -o /dev/full
  # A full disk, as a file-size limit makes it (EFBIG; SIGXFSZ ignored, so
  # that the write fails instead of killing the process): the old report
  # stays whole, no temporary file is left, and a shell's file says so too.
  echo earlier > report.html
  expect 5 "output: cannot write report.html: File too large" \
    sh -c "trap '' XFSZ; ulimit -f 8; exec '$G' report x.json -o report.html"
  [ "$(cat report.html)" = earlier ] || fail "a failed report replaced the earlier one"
  expect 5 "output: cannot write standard output: File too large" \
    sh -c "trap '' XFSZ; ulimit -f 8; exec '$G' report x.json > shell.html"
  [ -z "$(ls | grep 'report.html.')" ] || fail "a temporary file was left: $(ls)"
  ;;
interrupted_report)
  # SIGTERM and SIGINT while the report is written (at its fsync): the
  # process ends by that signal and leaves no temporary file.
  for sig in 15 2; do
    LD_PRELOAD=$SHIM PENDULUM_TEST_SIGNAL_ON_FSYNC=$sig ASAN_OPTIONS=verify_asan_link_order=0 \
      "$G" batch x.json --report class.html >out 2>err
    got=$?
    [ "$got" = $((128 + sig)) ] || fail "signal $sig during the report: exit $got, expected $((128 + sig))"
    [ "$(ls | grep -c 'class.html')" = 0 ] || fail "signal $sig left a file: $(ls)"
  done
  # An ignored signal (nohup's SIGHUP, a background job's SIGINT) stays
  # ignored: the report is written whole, exit 0.
  for sig in 1 2 15; do
    sh -c "trap '' $sig; LD_PRELOAD='$SHIM' PENDULUM_TEST_SIGNAL_ON_FSYNC=$sig ASAN_OPTIONS=verify_asan_link_order=0 \
      exec '$G' batch x.json --report ignored.html" >out 2>err
    got=$?
    [ "$got" = 0 ] || fail "signal $sig, ignored, during the report: exit $got, expected 0: $(cat err)"
    grep -q '</html>' ignored.html 2>/dev/null || fail "signal $sig, ignored: no whole report"
    rm -f ignored.html
  done
  # A report written over keeps its mode; a new one gets the umask's.
  echo earlier > private.html && chmod 600 private.html
  "$G" report x.json -o private.html || fail "report -o private.html"
  [ "$(stat -c %a private.html)" = 600 ] || fail "the 0600 report became $(stat -c %a private.html)"
  (umask 022 && "$G" report x.json -o new.html) || fail "report -o new.html"
  [ "$(stat -c %a new.html)" = 644 ] || fail "a new report is $(stat -c %a new.html), expected 644 under umask 022"
  ;;
fifo_by_name)
  mkfifo pipe.json
  expect 1 "pipe.json: not a regular file (a named pipe" timeout 10 "$G" reduce pipe.json
  expect 1 "pipe.json: not a regular file (a named pipe" timeout 10 "$G" report pipe.json
  expect 1 "pipe.json: not a regular file (a named pipe" timeout 10 "$G" fit-decay pipe.json
  # batch: the pipe's line says why, the good scene's result is there.
  printf 'x.json\npipe.json\n' > list.txt
  for args in "x.json pipe.json" "--list list.txt"; do
    timeout 10 "$G" batch $args >out 2>err
    got=$?
    [ "$got" = 1 ] || fail "batch $args: exit $got, expected 1"
    grep '"input":"pipe.json"' out | grep -q 'not a regular file (a named pipe' || fail "batch $args: $(cat out)"
    grep -q '"input":"x.json","ok":true' out || fail "batch $args lost the good scene: $(cat out)"
  done
  expect 1 "pipe.json: not a regular file (a named pipe" timeout 10 "$G" batch --list pipe.json
  expect 1 "/dev/zero: not a regular file (a device)" timeout 10 "$G" reduce /dev/zero
  ;;
read_limits)
  # 1 GiB on standard input: refused once 1 MiB (kSceneInput) + 1 byte is
  # read, within bounded memory (the address space capped at 1 GiB, less
  # than the input) and quickly. AddressSanitizer reserves terabytes of
  # address space for its shadow at start, so there the cap is left out and
  # only the message, the status and the time are checked.
  limit="got more than 1048576 bytes; expected at most 1048576 in a scene file, a list or standard input (--max-bytes raises the limit)"
  cap="ulimit -v 1048576;"
  [ "$SANITIZED" = sanitized ] && cap=""
  start=$(date +%s)
  expect 1 "stdin: $limit" sh -c "head -c 1073741824 /dev/zero | ($cap exec '$G' batch -)"
  expect 1 "stdin: $limit" sh -c "head -c 1073741824 /dev/zero | ($cap exec '$G' reduce -)"
  [ $(($(date +%s) - start)) -lt 20 ] || fail "1 GiB on stdin took $(($(date +%s) - start)) s to refuse"
  truncate -s 1G big.txt
  expect 1 "big.txt: $limit" "$G" batch --list big.txt
  expect 1 "big.txt: $limit" "$G" reduce big.txt
  expect 1 "stdin: cannot read standard input: Bad file descriptor" sh -c "'$G' batch - <&-"
  expect 1 "stdin: cannot read standard input: Bad file descriptor" sh -c "'$G' reduce - <&-"
  # A table's rows and a line's cells are counted as they are read: past
  # the limit, refused at its line within the same capped address space
  # (before, 10^5 lengths took 5.4 GB and '1,' 5*10^6 times 2.2 GB). The
  # rows are a pendulum's (T = 2 pi sqrt(L/9.81 m/s^2)), so that only their
  # number is refused.
  awk 'BEGIN { print "L (m),T (s)"; for (i = 0; i <= 10000; i++) { l = 0.5 + i * 1e-5;
       printf "%.5f,%.6f\n", l, 2 * 3.141592653589793 * sqrt(l / 9.81) } }' > rows.csv
  rows="rows.csv:10002:1: got more than 10000 rows; expected at most 10000 in a table (--max-rows raises the limit)"
  expect 1 "$rows" sh -c "$cap exec '$G' import --table rows.csv"
  printf '{"amplitude": "not recorded", "observations": {"table": "rows.csv"}}' > rows.json
  expect 1 "observations.table: $rows" sh -c "$cap exec '$G' reduce rows.json"
  "$G" import --table rows.csv --max-rows 10001 > out 2> err || fail "--max-rows 10001 did not raise the limit: $(cat err)"
  # A value below an input's default lowers none (docs/robustness.md, "Limits").
  "$G" import rec.tsv --max-rows 99 --max-bytes 1000 > out 2> err || fail "--max-rows 99 lowered a limit: $(cat err)"
  head -c 5000000 /dev/zero | tr '\0' 1 | sed 's/1/1,/g' > cells.csv
  expect 1 "cells.csv:1:513: got more than 256 columns; expected at most 256 in a table (--max-columns raises the limit)" \
    sh -c "$cap exec '$G' import --table cells.csv"
  expect 1 "cells.csv:1:2049: got more than 1024 columns; expected at most 1024 in a recording (--max-columns raises" \
    sh -c "$cap exec '$G' import cells.csv"
  # A scene over 1 MiB, taken once --max-bytes raises the limit: its text, not its recordings'.
  { head -c 1100000 /dev/zero | tr '\0' ' '; cat x.json; } > long.json
  expect 1 "long.json: got more than 1048576 bytes" "$G" reduce long.json
  "$G" reduce long.json --max-bytes 2000000 > out 2> err || fail "--max-bytes 2000000 did not raise a scene's limit: $(cat err)"
  expect 2 "expected a whole number in decimal digits" "$G" import rec.tsv --max-rows 0x10
  ;;
recording_outside)
  mkdir class
  cp rec.tsv outside.tsv
  ln -s ../outside.tsv class/link.tsv
  for name in ../outside.tsv "$T/outside.tsv" /etc/passwd /proc/self/environ link.tsv; do
    sed "s#rec.tsv#$name#g" scene.json > class/s.json
    expect 1 "timing.recording: got \"$name\"; expected a file in the scene's folder or below" "$G" reduce class/s.json
    grep -q "root:" err && fail "a message quoted /etc/passwd: $(cat err)"
    "$G" batch class/s.json >out 2>err
    grep -q "\"ok\":false.*timing.recording: got .*; expected a file in the scene's folder or below" out ||
      fail "batch with $name: $(cat out)"
    expect 1 "expected a file in the scene's folder or below" "$G" report class/s.json -o r.html
    expect 1 "expected a file in the scene's folder or below" "$G" fit-decay class/s.json
  done
  sed "s#rec.tsv#../outside.tsv#g" scene.json > class/s.json
  "$G" reduce --allow-outside class/s.json >out 2>err || fail "reduce --allow-outside: $(cat err)"
  "$G" batch --allow-outside class/s.json >out 2>err || fail "batch --allow-outside: $(cat err)"
  mkdir class/sub && cp rec.tsv class/sub/rec.tsv
  sed "s#rec.tsv#sub/../sub/rec.tsv#g" scene.json > class/s.json
  "$G" reduce class/s.json >out 2>err || fail "a recording below the scene's folder was refused: $(cat err)"
  ;;
names)
  # A newline, an escape sequence and bytes that are not UTF-8 in file names.
  mkdir class
  cp x.json "class/new
line.json"
  cp x.json "$(printf 'class/\033[2Jx.json')"
  cp x.json "$(printf 'class/\377.json')"
  cp x.json "$(printf 'class/\376.json')"
  ln -s nowhere.json class/dangling.json
  "$G" batch class >out 2>err
  grep -q '"input":"class/new\\\\x0aline.json"' out || fail "a newline in a name: $(cat out)"
  grep -q '"input":"class/\\\\x1b\[2Jx.json"' out || fail "an escape in a name: $(cat out)"
  grep -q '"input":"class/\\\\xff.json"' out && grep -q '"input":"class/\\\\xfe.json"' out ||
    fail "names not UTF-8 are not distinct: $(cat out)"
  grep -q "$(printf '\033')" out err && fail "an escape reached the terminal"
  grep -q "skipped class/dangling.json: a symbolic link to nothing (nowhere.json)" err ||
    fail "the dangling link's note: $(cat err)"
  expect 1 "^pendulum-g: error: class/\\\\xff-missing.json: cannot open the file" "$G" reduce "$(printf 'class/\377-missing.json')"
  # A recording's header quoted in a message: control bytes escaped. A header
  # that is not UTF-8 is read as Latin-1 (docs/recordings.md, Columns), so
  # its bytes arrive as the characters they are there (\377 is ÿ, \316 Î).
  printf 'Time (s),\377\376 \033[2J \316\270 (rad)\n1,2\n2,3\n3,4\n' > bad.csv
  expect 1 'unrecognised header "Time (s)", "'"$(printf '\303\277\303\276')"' \\x1b\[2J '"$(printf '\303\216\302\270')"' (rad)"' "$G" import bad.csv
  printf 'Time (s),\033[2J \316\270 (rad)\n1,2\n2,3\n3,4\n' > bad.csv
  expect 1 'unrecognised header "Time (s)", "\\x1b\[2J '"$(printf '\316\270')"' (rad)"' "$G" import bad.csv
  # A header cell of 5000 bytes is quoted cut, each cell on its own (40 bytes).
  { printf 'Time (s),'; head -c 5000 /dev/zero | tr '\0' x; printf ' (rad),%s\n1,2,3\n2,3,4\n3,4,5\n' "$(printf '\033')w"; } > long.csv
  expect 1 'unrecognised header "Time (s)", "x\{37\}\.\.\.", "\\x1bw"; expected' "$G" import long.csv
  [ "$(wc -c < err)" -lt 1000 ] || fail "a long header made a message of $(wc -c < err) bytes"
  # An infinite cell: named where it is, not an "excursion is inf" later.
  printf 'time,angle\n0,0.1\n0.1,inf\n0.2,0.1\n' > inf.csv
  expect 1 'inf.csv:3:5: got "inf" in column "angle"; expected a finite number' "$G" import inf.csv
  grep -q 'nan' err && fail "the infinite cell's message says nan: $(cat err)"
  ;;
terminal_text)
  # Text from outside in a table and in option errors (issue 42, item 3):
  # escaped, and an option's value cut, so that it cannot clear the screen
  # or set the window's title.
  esc=$(printf '\033')
  mkdir class
  cp x.json "$(printf 'class/a\033[2J\033]0;pwned\007.json')"
  "$G" batch class --format table >out 2>err
  grep -q "$esc" out err && fail "batch --format table printed an escape: $(cat out)"
  grep -q 'class/a\\x1b\[2J\\x1b\]0;pwned\\x07.json  ok' out || fail "batch --format table's name: $(cat out)"
  cp rec.tsv "$(printf 'r\033[2J.tsv')"
  "$G" import "$(printf 'r\033[2J.tsv')" --format table >out 2>err
  grep -q "$esc" out err && fail "import --format table printed an escape: $(cat out)"
  grep -q '^recording *r\\x1b\[2J.tsv' out || fail "import --format table's name: $(cat out)"
  # A table's header cell, with an escape in it.
  sed "1s/\$/,$esc[2Jnote/; 2,\$s/\$/,1/" "$DATA/pendulum_lengths_table.csv" > hdr.csv
  "$G" import hdr.csv --format table >out 2>err
  grep -q "$esc" out err && fail "import --format table printed a header's escape: $(cat out) $(cat err)"
  grep -q '"\\x1b\[2Jnote"' out || fail "import --format table's header cell: $(cat out) $(cat err)"
  # Option errors: the value escaped, cut, and no bound of 309 digits.
  expect 2 'bob-width-m' "$G" import rec.tsv --bob-width-m "$(printf '\033[2J')"
  grep -q "$esc" err && fail "an option error printed an escape: $(cat err)"
  expect 2 'bob-width-m' "$G" import rec.tsv --bob-width-m "$(head -c 100000 /dev/zero | tr '\0' 7)"
  [ "$(wc -c < err)" -lt 400 ] || fail "a 100 KB option value made an error of $(wc -c < err) bytes"
  expect 2 '^--bob-width-m: got 0 m; expected a bob.s width across the beam from 1 mm to 1 km$' \
    "$G" import rec.tsv --bob-width-m 0
  grep -q '[0-9]\{20\}' err && fail "an option error printed a long number: $(cat err)"
  expect 2 '^--length-m: got 1e+300 m; expected a laboratory pendulum, 1 mm to 1 km long$' \
    "$G" import rec.tsv --length-m 1e300
  expect 2 '^--negligible-fraction: got NaN; expected' "$G" reduce x.json --negligible-fraction nan
  expect 2 'got "\\x1b\[2J:5"' "$G" import rec.tsv --range "$(printf '\033[2J:5')"
  grep -q "$esc" err && fail "--range's error printed an escape: $(cat err)"
  expect 2 "takes one scene; for several, run: pendulum-g batch x.json a\\\\x1b\\[2J.json" "$G" reduce x.json "$(printf 'a\033[2J.json')"
  grep -q "$esc" err && fail "reduce's extra scenes printed an escape: $(cat err)"
  # A number is decimal: strtod read 0x10 as 16, and no lab writes it so.
  expect 2 '^--range: got "0x1:20"; expected START:END' "$G" import rec.tsv --range 0x1:20
  expect 2 '^--length-m: got "0x10"; expected a decimal number' "$G" import rec.tsv --length-m 0x10
  expect 1 'got the column "frame:0x1fps"; expected frame numbers with their frame rate' \
    "$G" import "$DATA/recordings/tracker_headerless_xy.txt" --columns frame:0x1fps,x:px,y:px
  # Counts too: CLI11 read --jobs 0x2 as 2, --draws 0x100 as 256, --seed 0x10 as 16.
  expect 2 '^--jobs: got "0x2"; expected a whole number in decimal digits' "$G" batch x.json --jobs 0x2
  expect 2 '^--draws: got "0x100"; expected a whole number in decimal digits' \
    "$G" reduce x.json --uncertainty monte-carlo --draws 0x100
  expect 2 '^--seed: got "0x10"; expected a whole number in decimal digits' \
    "$G" reduce x.json --uncertainty monte-carlo --seed 0x10
  expect 2 '^--draws: got "1e3"; expected a whole number in decimal digits' \
    "$G" reduce x.json --uncertainty monte-carlo --draws 1e3
  ;;
csv_cells)
  # Names and titles in a CSV cell never start a formula (issue 42, item
  # 12): a ' before a leading =, +, - or @ (a spreadsheet shows it as text).
  mkdir class && cd class || exit 1
  sed 's/"title": "[^"]*"/"title": "=HYPERLINK(\\"http:\/\/x\\")"/' ../x.json > =1.json
  cp ../x.json +1.json && cp ../x.json -- -1.json && cp ../x.json @1.json
  "$G" batch --format csv -- =1.json +1.json -1.json @1.json >../out 2>../err
  cd .. || exit 1
  for name in =1.json +1.json -1.json @1.json; do
    grep -q "^'$name,true," out || fail "the name $name in CSV: $(cat out)"
  done
  grep -q ",\"'=HYPERLINK(\"\"http://x\"\")\"," out || fail "the title in CSV: $(cat out)"
  grep -q '^[=+@-]' out && fail "a cell starts a formula: $(cat out)"
  grep -q ',-\?[0-9]' out || fail "the numbers lost: $(cat out)"
  ;;
*)
  fail "no case $CASE"
  ;;
esac
[ "$failures" = 0 ] && echo "$CASE: passed"
[ "$failures" = 0 ]
