#!/usr/bin/env bash
# `lightcone monitor`'s HTTP layer and the folders it will not read
# (docs/monitor.md, "Safe by default"), over real sockets on 127.0.0.1:
# hostile clients (tests/tools/monitor_abuse.py: a thousand ranges, a
# gzip bomb and a chunked body POSTed, a header flood, slow clients
# trickling header lines, a burst of pixel traces) are refused small and
# fast while normal requests are answered, clients that never read a large
# file cost the monitor no memory, one byte range is answered 206 with its
# Content-Range (curl), of the page and of a frame sent from its file, and
# the monitor's memory stays bounded; journals that are links, FIFOs or someone else's are refused
# without a word of them and hold nothing; in a real browser one shot
# that cannot be shown says so on its card while the others are shown, and
# a 12,000-frame film's cost chart has all its points; a render started
# under a parent folder being watched is listed as it appears.
source "$(dirname "$0")/lib.sh"
e2e_begin "$@"

FALL="$SRC/shots/kerr_fall.lua"
tiny_fall_render out
# Beside the render: someone else's file named as a journal, a journal that
# is a FIFO (with a log, so the shot is listed), and links out of the folder.
echo "root:x:0:0:SECRET-ROOT-LINE" >passwd
cp passwd out/foreign.journal
mkfifo out/fifo.journal
cp out/kerr_fall.events out/fifo.events
ln -s "$WORK/passwd" out/leak.journal
ln -s "$WORK/passwd" out/count.events
# A film of 12,000 frames: the render's frame line copied with each
# frame's number and cost.
"$PY" "$SRC/tests/tools/journal_frames.py" out/kerr_fall.journal 0 12000 >out/long.journal

start_monitor out
PORT=${URL##*:}
# Its memory as it starts (mostly its libraries' pages), to measure what
# the clients below add.
base=$(awk '/^VmRSS:/ {print $2}' "/proc/$MONITOR/status")
abuse() { timeout 60 "$PY" "$SRC/tests/tools/monitor_abuse.py" "$PORT" "$@" || fail "$1: $(tail -1 abuse.txt)"; }
code() { curl -s --max-time 5 -o body.txt -w "%{http_code}" "$URL$1"; }

# Links are not shots; a foreign journal is refused unquoted; the FIFO
# answers at once, ten requests at a time, and holds nothing.
shots=$(curl -s --max-time 5 "$URL/api/folders")
grep -q '"shots": \["fifo", "foreign", "kerr_fall", "long"\]' <<<"$shots" || fail "the shots listed: $shots"
[ "$(code "/api/status?folder=0&shot=leak")" = 404 ] || fail "a linked journal: $(cat body.txt)"
[ "$(code "/api/status?folder=0&shot=count")" = 404 ] || fail "a linked event log: $(cat body.txt)"
[ "$(code "/api/status?folder=0&shot=foreign")" = 422 ] || fail "a foreign journal: $(cat body.txt)"
grep -q "SECRET" body.txt && fail "a foreign journal was quoted: $(cat body.txt)"
start=$(date +%s%N)
for k in $(seq 1 10); do curl -s --max-time 5 -o "fifo$k.txt" -w "%{http_code}\n" "$URL/api/status?folder=0&shot=fifo" >"fifo$k.code" & done
wait $(jobs -p | grep -v "^$MONITOR$") 2>/dev/null || true
took=$((($(date +%s%N) - start) / 1000000))
[ "$(cat fifo*.code | sort -u)" = 403 ] || fail "a FIFO journal: $(cat fifo*.code | tr '\n' ' ') $(cat fifo1.txt)"
[ "$took" -lt 3000 ] || fail "ten requests of a FIFO journal took $took ms"
[ "$(code /api/folders)" = 200 ] || fail "after the FIFO: the monitor does not answer"

# The HTTP layer.
: >abuse.txt
for check in multirange gzip-post chunked-post header-flood; do abuse "$check" >>abuse.txt; done
abuse slow-clients 12 >>abuse.txt
abuse trace-burst "folder=0&shot=kerr_fall&frame=0" >>abuse.txt
# Eight clients asking for a 256 MiB preview and reading nothing (or a byte
# a second): the file is sent from disk as they read, not held in memory
# for each (the monitor grows by less than 48 MB; copying it did by 256 MB
# a client).  Sparse: no disk used, but for a mark at 200 MiB that a range
# of it must answer.
mkdir -p out/preview
truncate -s 256M out/preview/long.0000.png
printf 'lightcone-mark-at-200MiB' | dd of=out/preview/long.0000.png bs=1 seek=$((200 << 20)) conv=notrunc status=none
abuse slow-readers "$MONITOR" "/api/frame.png?folder=0&shot=long&frame=0&preview=1" 8 $((200 << 20)) \
  lightcone-mark-at-200MiB 48 >>abuse.txt
rm out/preview/long.0000.png
cat abuse.txt
[ "$(code /)" = 200 ] || fail "the page after the abuse"
# HEAD is answered as GET without a body; other methods are refused.
[ "$(curl -s --max-time 5 -I -o /dev/null -w "%{http_code}" "$URL/api/folders")" = 200 ] || fail "HEAD"
[ "$(curl -s --max-time 5 -X DELETE -o /dev/null -w "%{http_code}" "$URL/api/folders")" = 405 ] || fail "DELETE"
# One range: 206 with that part; past the end: 416 with the size; several: 416.
curl -s --max-time 5 -D head.txt -H "Range: bytes=0-14" -o part.txt "$URL/"
grep -q "^HTTP/1.1 206" head.txt || fail "one range: $(head -1 head.txt)"
whole=$(curl -s --max-time 5 "$URL/" | wc -c)
grep -qi "^Content-Range: bytes 0-14/$whole" head.txt || fail "one range's Content-Range: $(grep -i content-range head.txt)"
[ "$(cat part.txt)" = "$(curl -s --max-time 5 "$URL/" | head -c 15)" ] || fail "one range's part: $(cat part.txt)"
[ "$(curl -s --max-time 5 -H "Range: bytes=-5" "$URL/" | wc -c)" = 5 ] || fail "the last 5 bytes"
curl -s --max-time 5 -D head.txt -H "Range: bytes=$whole-" -o /dev/null "$URL/"
grep -q "^HTTP/1.1 416" head.txt && grep -qi "^Content-Range: bytes \*/$whole" head.txt \
  || fail "a range past the end: $(head -1 head.txt) $(grep -i content-range head.txt)"
[ "$(curl -s --max-time 5 -H "Range: bytes=0-1,4-5" -o /dev/null -w "%{http_code}" "$URL/")" = 416 ] || fail "two ranges"
[ "$(curl -s --max-time 5 -H "Range: bytes=x-" -o /dev/null -w "%{http_code}" "$URL/")" = 200 ] || fail "a bad range"
# A frame, sent from its file: whole, and one range of it, as on disk.
FRAME="$URL/api/frame.png?folder=0&shot=kerr_fall&frame=0"
curl -s --max-time 5 -o frame.png "$FRAME"
cmp -s frame.png out/kerr_fall.0000.png || fail "the frame as served differs from its file"
png_size=$(stat -c %s out/kerr_fall.0000.png)
curl -s --max-time 5 -D head.txt -H "Range: bytes=10-29" -o part.bin "$FRAME"
grep -q "^HTTP/1.1 206" head.txt && grep -qi "^Content-Range: bytes 10-29/$png_size" head.txt \
  || fail "a range of the frame: $(head -1 head.txt) $(grep -i content-range head.txt)"
cmp -s part.bin <(tail -c +11 out/kerr_fall.0000.png | head -c 20) || fail "a range of the frame: other bytes"
[ "$(curl -s --max-time 5 -H "Range: bytes=-7" "$FRAME" | cmp -s - <(tail -c 7 out/kerr_fall.0000.png) && echo same)" = same ] \
  || fail "the frame's last 7 bytes"
# All of it in bounded memory (the gzip bomb alone unpacks to 62 MiB, the
# ranges asked for 1,000 copies of the page).
hwm=$(awk '/^VmHWM:/ {print $2}' "/proc/$MONITOR/status")
echo "monitor: VmRSS $base kB as it started, VmHWM $hwm kB after the clients"
[ $((${hwm:-999999} - ${base:-0})) -lt 32768 ] || fail "the monitor's memory grew from $base to $hwm kB"

# The page: the shot that cannot be shown says why on its card; the
# others are shown (not "cannot reach the monitor").
BROWSER=(chromium --headless=new --no-sandbox --disable-gpu --window-size=1200,800 --virtual-time-budget=6000)
timeout 60 "${BROWSER[@]}" --dump-dom "$URL/" >page.html 2>browser.log || fail "chromium: $(tail -3 browser.log)"
grep -q "id=\"note\">cannot reach" page.html && fail "one shot's error blanked the page"
grep -q 'data-count="done">1<' page.html || fail "the good shot's card: $(grep -o 'data-count="done">[^<]*<' page.html)"
grep -q 'cannot show this shot: foreign.journal is not a lightcone journal' page.html \
  || fail "the foreign shot's card: $(grep -o 'class="card-error">[^<]*<' page.html)"
grep -q "SECRET" page.html && fail "the page quotes a foreign file"
# The long film's cost chart has all its 12,000 points (not 10,000).
grep -q 'data-points="12000"' page.html || fail "the long film's chart: $(grep -o 'data-points="[0-9]*"' page.html | tr '\n' ' ')"

# A parent folder: a render that starts under it after the monitor is
# listed at the next poll; a link to a render folder is not followed.
mkdir -p films
ln -s "$WORK/out" films/leak
"$LIGHTCONE" monitor films --port 0 2>parent.log &
parent=$!
for _ in $(seq 1 100); do grep -q "http://127.0.0.1:" parent.log && break; sleep 0.05; done
PURL=$(grep -o "http://127.0.0.1:[0-9]*" parent.log) || fail "the parent's monitor did not start: $(cat parent.log)"
[ "$(curl -s --max-time 5 "$PURL/api/folders" | grep -o '"path"' | wc -l)" = 1 ] || fail "an empty parent: $(curl -s "$PURL/api/folders")"
"$LIGHTCONE" render "$FALL" --out films/take1 --size 32x18 --supersample 1 --progress 0 --frames 0:0 2>render2.log \
  || fail "render: $(cat render2.log)"
folders=$(curl -s --max-time 5 "$PURL/api/folders")
grep -q "{\"id\": 1, \"path\": \"$(cd films && pwd -P)/take1\", \"shots\": \[\"kerr_fall\"\]}" <<<"$folders" \
  || fail "the render under the parent: $folders"
grep -q "leak" <<<"$folders" && fail "a link under the parent was followed: $folders"
[ "$(curl -s --max-time 5 -o /dev/null -w "%{http_code}" "$PURL/api/status?folder=1&shot=kerr_fall")" = 200 ] || fail "its status"
kill -TERM "$parent"
wait "$parent" 2>/dev/null || true

# A kill (SIGTERM, as Ctrl-C) stops it at once.
kill -TERM "$MONITOR"
for _ in $(seq 1 40); do kill -0 "$MONITOR" 2>/dev/null || break; sleep 0.05; done
kill -0 "$MONITOR" 2>/dev/null && fail "the monitor did not stop within 2 s of SIGTERM"
wait "$MONITOR" 2>/dev/null || true
e2e_end
