#!/usr/bin/env bash
# ctest-labels: slow
# `lightcone monitor` (docs/monitor.md) on a real render: the API's counts
# follow the journal while the render is held mid-run, after it is
# interrupted and after it resumes (by the command the monitor gives to
# copy, run as given); a real headless browser (Debian's
# chromium) draws the page from it: the counts, a thumbnail per latest
# frame, a point of the cost chart per finished frame, the rank, node and
# wall time of each latest frame (the screenshot is kept as monitor.png); clicking a frame's pixel (Selenium) shows what
# `lightcone trace` says of it, with its path drawn (monitor_pixel.png);
# hostile requests get 4xx and nothing outside the folder; an MPI run's
# workers and what each holds, and one of them lost when it is killed,
# named as what ended the run, with the event log's last lines, and each
# of its frames' ranks, node and wall time (docs/monitor.md); the monitor stops on a kill.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

FALL="$SRC/shots/kerr_fall.lua"
SMALL=(--size 96x54 --supersample 1 --progress 0 --frames 0:179:20)  # 9 frames of 54 rows


expect_error monitor_missing "out: not a directory" -- "$LIGHTCONE" monitor out --port 0
mkdir -p out mpi_out
"$LIGHTCONE" monitor out mpi_out --port 0 2>monitor.log &
monitor=$!
# The monitor (and a held render) hold the test's output open: they must
# not outlive the script.
mpijob=""
trap 'kill "$monitor" ${mpijob:+"$mpijob"} 2>/dev/null || true' EXIT
for _ in $(seq 1 100); do grep -q "http://127.0.0.1:" monitor.log && break; sleep 0.05; done
URL=$(grep -o "http://127.0.0.1:[0-9]*" monitor.log) || { fail "the monitor did not start: $(cat monitor.log)"; e2e_end; exit 1; }
# A request that fails or times out (a loaded machine) gives an empty
# answer, which the checks that read it report, rather than stopping the
# script under `set -e` with nothing said.
api() { curl -s --max-time 30 "$URL$1" || echo "{}"; }
# A port in use is refused naming it; a bad port never reaches the network.
expect_error port_in_use "--port ${URL##*:}: cannot listen there" -- "$LIGHTCONE" monitor out --port "${URL##*:}"
expect_error port_range "--port" -- "$LIGHTCONE" monitor out --port 70000
field() { $PY -c "import json,sys; d=json.load(sys.stdin); print(eval(sys.argv[1]))" "$1"; }
[ "$(api /api/folders | field 'd["folders"][0]["shots"]')" = "[]" ] || fail "an empty folder lists shots: $(api /api/folders)"
[ "$(api /api/folders | field 'len(d["folders"])')" = 2 ] || fail "folders: $(api /api/folders)"

# A render held after 130 working sets: two frames stored, the third in flight.
LIGHTCONE_TEST_PAUSE_AFTER=130 "$LIGHTCONE" render "$FALL" --out out --threads 2 "${SMALL[@]}" 2>render.log &
render=$!
wait_for_pause render.log "$render" || true
sleep 2.5  # a progress line (every 2 s) says what is in flight
Q="folder=0&shot=kerr_fall"
status=$(api "/api/status?$Q")
journalled=$(grep -c '^frame=' out/kerr_fall.journal || true)
[ "$(field 'd["frames"]["done"]' <<<"$status")" = "$journalled" ] || fail "held: done is not the journal's $journalled: $status"
[ "$(field 'd["run"]["state"]' <<<"$status")" = running ] || fail "held: not running: $status"
[ "$(field 'd["frames"]["to_do"]' <<<"$status")" = $((9 - journalled)) ] || fail "held: to do: $status"
[ "$(field 'len(d["frames"]["in_flight"]) > 0' <<<"$status")" = True ] || fail "held: nothing in flight: $status"
[ "$(field 'd["run"]["eta_seconds"] is not None and d["run"]["frames_per_minute"] > 0' <<<"$status")" = True ] \
  || fail "held: no ETA in wall time: $status"
[ "$(field 'd["run"]["threads"]' <<<"$status")" = 2 ] || fail "held: threads: $status"
# The page, while the render is held: its counts are the journal's.
BROWSER=(chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars --window-size=1200,800
  --virtual-time-budget=6000)
timeout 60 "${BROWSER[@]}" --dump-dom "$URL/" >page_held.html 2>browser.log || fail "chromium (held): $(tail -3 browser.log)"
grep -q "data-count=\"done\">$journalled<" page_held.html || fail "held: the page does not show $journalled done: $(grep -o 'data-count="[a-z_]*">[^<]*<' page_held.html)"
grep -q "data-count=\"to_do\">$((9 - journalled))<" page_held.html || fail "held: the page's to do"
grep -q 'data-count="in_flight">0<' page_held.html && fail "held: the page shows nothing in flight"
grep -q 'class="state running"' page_held.html || fail "held: the page's run state"
grep -q "data-points=\"$journalled\"" page_held.html || fail "held: the cost chart has not $journalled points: $(grep -o 'data-points="[0-9]*"' page_held.html)"
[ "$(grep -o '<figure data-frame=' page_held.html | wc -l)" = "$journalled" ] || fail "held: the page shows $(grep -o '<figure data-frame=' page_held.html | wc -l) thumbnails for $journalled frames"

# Interrupted (SIGTERM, as a Ctrl-C: a background job of a script ignores SIGINT), then resumed.
kill -TERM "$render"
wait "$render" 2>/dev/null || true
status=$(api "/api/status?$Q")
[ "$(field 'd["run"]["state"]' <<<"$status")" = interrupted ] || fail "after Ctrl-C: $status"
# The frames left are still left (the same command resumes them).
left=$((9 - $(grep -c '^frame=' out/kerr_fall.journal || true)))
[ "$(field 'd["frames"]["to_do"]' <<<"$status")" = "$left" ] || fail "after Ctrl-C: to do is not $left: $status"
# The command the status gives to resume it is the render's own, in its
# folder; run as the page shows it (in a shell), it resumes.
resume=$(field 'd["run"]["resume"]' <<<"$status")
[ "$resume" = "cd $WORK && $LIGHTCONE render $FALL --out out --threads 2 ${SMALL[*]}" ] || fail "the resume command: $resume"
(cd / && bash -c "$resume") 2>resume.log || fail "resume: $(cat resume.log)"
grep -q "resuming: $((9 - left)) of 9 frames already finished" resume.log || fail "resume: $(cat resume.log)"
status=$(api "/api/status?$Q")
[ "$(field 'd["frames"]["done"]' <<<"$status")" = 9 ] || fail "resumed: done: $status"
[ "$(field 'd["run"]["state"]' <<<"$status")" = done ] || fail "resumed: state: $status"
[ "$(api "/api/frames?$Q" | field 'len(d["frames"])')" = 9 ] || fail "frames: $(api "/api/frames?$Q")"
# Each frame names who rendered it, on which node, and its wall time: a
# render without MPI is rank 0 (its threads) on this host.
HOST=$(hostname)
[ "$(api "/api/frames?$Q" | field 'all(f["ranks"] == [0] and f["nodes"] == ["'"$HOST"'"] and f["rank_count"] == 1 and f["wall_seconds"] > 0 for f in d["frames"])')" = True ] \
  || fail "the frames' rank, node and wall time: $(api "/api/frames?$Q")"
curl -s --max-time 10 -o frame.png "$URL/api/frame.png?$Q&frame=40"
cmp -s frame.png out/kerr_fall.0040.png || fail "the served frame 40 is not the file"

# Hostile requests: 4xx, and nothing from outside the folder.
echo "SECRET-TOKEN-42" >secret.txt
ln -sf "$WORK/secret.txt" out/kerr_fall.0999.png
for path in "/api/frame.png?$Q&frame=999" "/api/frame.png?folder=0&shot=..%2F..%2Fetc%2Fpasswd&frame=0" \
  "/api/status?folder=7&shot=kerr_fall" "/api/frames?$Q&count=100000000" "/api/frame.png?$Q&frame=-1" \
  "/../../etc/passwd" "/%2e%2e/%2e%2e/etc/passwd" "/api/status?folder=0&shot=%00"; do
  code=$(curl -s --path-as-is --max-time 10 -o body.txt -w "%{http_code}" "$URL$path")
  case "$code" in 4??) ;; *) fail "$path: HTTP $code, expected 4xx: $(cat body.txt)" ;; esac
  grep -q "SECRET-TOKEN-42\|root:" body.txt && fail "$path served a file outside the folder"
done
code=$(curl -s --max-time 10 -o /dev/null -w "%{http_code}" -X POST -d x=1 "$URL/api/folders")
case "$code" in 4??) ;; *) fail "POST: HTTP $code, expected 4xx" ;; esac
rm out/kerr_fall.0999.png

# The page in a real browser: after its first polls, the counts are the
# API's, one thumbnail for each of the latest frames, one chart point per
# finished frame.
timeout 60 "${BROWSER[@]}" --dump-dom "$URL/" >page.html 2>browser.log || fail "chromium: $(tail -3 browser.log)"
grep -q 'data-count="done">9<' page.html || fail "the page does not show 9 done: $(grep -o 'data-count="[a-z_]*">[^<]*<' page.html)"
grep -q 'data-count="to_do">0<' page.html || fail "the page's to do"
[ "$(grep -o '<figure data-frame=' page.html | wc -l)" = 8 ] || fail "the page shows $(grep -o '<figure data-frame=' page.html | wc -l) thumbnails, not the 8 latest"
grep -q 'data-points="9"' page.html || fail "the cost chart has not 9 points: $(grep -o 'data-points="[0-9]*"' page.html)"
grep -q 'class="state done"' page.html || fail "the page's run state"
# The table of the latest frames: the newest first, its rank, node and wall time.
grep -Eq "<tr data-frame=\"160\"><td>160</td><td class=\"rank\">0 \(local\)</td><td class=\"node\">$HOST</td><td class=\"wall\">[0-9]+\.[0-9] s</td>" page.html \
  || fail "the page's frame table: $(grep -o '<table class="frames">.*</table>' page.html | head -c 600)"
timeout 60 "${BROWSER[@]}" --screenshot="$WORK/monitor.png" "$URL/" >/dev/null 2>>browser.log || fail "chromium's screenshot: $(tail -3 browser.log)"
[ -s monitor.png ] || fail "no screenshot"

# The pixel inspector: its API answers what `lightcone trace` says of the
# pixel; in the browser, a click on a frame's pixel shows that pixel's
# trace and draws its path.
api "/api/trace?$Q&frame=40&x=40&y=30" >trace_api.json
"$LIGHTCONE" trace "$FALL" --frame 40 --pixel 40,30 --size 96x54 --json >trace_cli.json 2>/dev/null || fail "trace"
[ "$(field 'd["report"]' <trace_api.json)" = "$(field 'd' <trace_cli.json)" ] \
  || fail "the inspector's report is not trace's: $(cat trace_api.json) vs $(cat trace_cli.json)"
[ "$(field 'len(d["path"]) > 1' <trace_api.json)" = True ] || fail "the inspector drew no path: $(cat trace_api.json)"
timeout 120 "$PY" "$SRC/tests/tools/monitor_click.py" "$URL/" "$WORK/monitor_pixel.png" 0.40 0.55 >click.txt 2>click.err \
  || fail "clicking a pixel in the browser: $(tail -5 click.err)"
read -r frame pixel points <click.txt || true
grep -q "^pixel $pixel: hit " click.txt || fail "the page's trace report: $(cat click.txt)"
[ "${points:-0}" -gt 1 ] || fail "the page drew no path: $(cat click.txt)"
"$LIGHTCONE" trace "$FALL" --frame "$frame" --pixel "$pixel" --size 96x54 --json >clicked.json 2>/dev/null
grep -q "hit $(field 'd["hit"]' <clicked.json)" click.txt || fail "the page's hit is not trace's: $(cat click.txt) vs $(cat clicked.json)"

# A render under mpirun, each worker held after 60 working sets (two
# frames stored, the third in flight): the page lists its two workers with
# their node, threads and what each holds.  Then rank 2 is killed outright
# (SIGKILL, as the OOM killer would): mpirun ends the job, the master names
# the rank it lost, and the page shows it lost; the same command resumes
# and finishes, no frame rendered twice.
use_mpirun
MQ="folder=1&shot=kerr_fall"
MPI_ARGS=(--size 96x54 --supersample 1 --progress 0 --frames 0:100:20)  # 6 frames
LIGHTCONE_TEST_PAUSE_AFTER=60 mpi 3 "$LIGHTCONE" render "$FALL" --out mpi_out "${MPI_ARGS[@]}" 2>mpi.log &
mpijob=$!
for _ in $(seq 1 1200); do
  [ "$(grep -c 'test pause: pid' mpi.log || true)" -ge 2 ] && break
  kill -0 "$mpijob" 2>/dev/null || break
  sleep 0.05
done
sleep 2.5  # a progress line (every 2 s) says what each worker holds
status=$(api "/api/status?$MQ")
[ "$(field 'sorted((w["rank"], w["host"], w["state"]) for w in d["run"]["workers"])' <<<"$status")" = \
  "[(1, '$(hostname)', 'working'), (2, '$(hostname)', 'working')]" ] || fail "the MPI run's workers: $status"
[ "$(field 'all(w["sets"] > 0 and w["frames"] for w in d["run"]["workers"])' <<<"$status")" = True ] \
  || fail "the MPI workers hold nothing: $status"
[ "$(field 'd["run"]["ranks"], d["run"]["state"]' <<<"$status")" = "(3, 'running')" ] || fail "the MPI run: $status"
timeout 60 "${BROWSER[@]}" --dump-dom "$URL/" >page_mpi.html 2>>browser.log || fail "chromium (MPI run)"
[ "$(grep -o '<tr class="rank working"' page_mpi.html | wc -l)" = 2 ] \
  || fail "the page does not show two working ranks: $(grep -o '<tr class="rank[^>]*>' page_mpi.html)"
victim=$(sed -n 's/.*test pause: pid \([0-9]*\) (rank 2).*/\1/p' mpi.log)
if [ -n "$victim" ]; then
  kill -KILL "$victim"
else
  fail "no pid of rank 2 in: $(cat mpi.log)"
  kill -TERM "$mpijob"
fi
wait "$mpijob" && fail "mpirun succeeded with a rank killed: $(cat mpi.log)"
mpijob=""
# (Its words on stderr may not outrun mpirun's end of the job; the event
# log is written directly.)
grep -q " event=lost rank=2 host=$(hostname) " mpi_out/kerr_fall.events ||
  fail "the master did not log the lost rank: $(cat mpi_out/kerr_fall.events)"
status=$(api "/api/status?$MQ")
[ "$(field 'sorted((w["rank"], w["state"]) for w in d["run"]["workers"])' <<<"$status")" = "[(1, 'interrupted'), (2, 'lost')]" ] \
  || fail "after the kill: $status"
timeout 60 "${BROWSER[@]}" --dump-dom "$URL/" >page_lost.html 2>>browser.log || fail "chromium (lost rank)"
grep -q '<tr class="rank lost" data-rank="2"' page_lost.html || fail "the page does not show rank 2 lost: $(grep -o '<tr class="rank[^>]*>' page_lost.html)"
# The card names the rank that ended the run, and shows the event log's last lines.
grep -q "<div class=\"ended\">interrupted: rank 2 on $(hostname) stopped answering (lost)</div>" page_lost.html \
  || fail "the page does not name the rank that ended the run: $(grep -o '<div class="ended">[^<]*<' page_lost.html)"
grep -q '<pre data-lines="[1-9][0-9]*">' page_lost.html && grep -q " end status=interrupted stored=" page_lost.html \
  || fail "the page's event log: $(grep -o '<pre data-lines.*' page_lost.html | head -c 600)"
# The interrupted run's card offers the command that resumes it, launcher first.
grep -q "<code>cd $WORK &amp;&amp; mpirun -n 3 $LIGHTCONE render $FALL --out mpi_out ${MPI_ARGS[*]}</code>" page_lost.html \
  || fail "the page's resume command: $(grep -o '<div class="resume">.*</div>' page_lost.html | head -c 400)"
before=$(grep -c '^frame=' mpi_out/kerr_fall.journal || true)
[ "$before" -ge 1 ] && [ "$before" -lt 6 ] || fail "$before frames journalled when rank 2 was killed"
mpi 3 "$LIGHTCONE" render "$FALL" --out mpi_out "${MPI_ARGS[@]}" 2>mpi_resume.log || fail "the MPI resume: $(cat mpi_resume.log)"
grep -q "resuming: $before of 6 frames already finished" mpi_resume.log || fail "the MPI resume: $(cat mpi_resume.log)"
[ -z "$(grep -o '^frame=[0-9]*' mpi_out/kerr_fall.journal | sort | uniq -d)" ] || fail "a frame was rendered twice"
# Every frame of the MPI render, before the kill and after the resume, names
# the workers (ranks 1 and 2, never the master) whose sets made it, their
# node, and its wall time.
[ "$(api "/api/frames?$MQ" | field 'len(d["frames"]) == 6 and all(f["ranks"] and set(f["ranks"]) <= {1, 2} and f["nodes"] == ["'"$HOST"'"] * len(f["ranks"]) and f["rank_count"] == len(f["ranks"]) and f["wall_seconds"] > 0 for f in d["frames"])')" = True ] \
  || fail "the MPI frames' ranks, nodes and wall time: $(api "/api/frames?$MQ")"
status=$(api "/api/status?$MQ")
[ "$(field 'd["frames"]["done"], d["run"]["state"], sorted(w["state"] for w in d["run"]["workers"])' <<<"$status")" = \
  "(6, 'done', ['done', 'done'])" ] || fail "the resumed MPI run: $status"

# A kill (SIGTERM; a Ctrl-C alike) stops it.
kill -TERM "$monitor"
wait "$monitor" 2>/dev/null || true
grep -q "monitor: stopped by" monitor.log || fail "the monitor's stop: $(cat monitor.log)"
e2e_end
