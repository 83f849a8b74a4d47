#!/usr/bin/env python3
"""Hostile HTTP clients against `lightcone monitor` (tests/e2e/monitor_http.sh),
on raw sockets so that nothing is tidied up on the way.  Each check prints
one line "name: ..." and exits non-zero with the reason when the server
does not hold: every socket has a timeout, every loop a bound.

Usage: monitor_abuse.py PORT CHECK [ARG]
  multirange          an 8 KB Range of 1,000 ranges: refused small and fast
  gzip-post           a gzip body unpacking to 62 MiB, POSTed: refused, not unpacked
  chunked-post        a chunked body: refused before it is sent
  header-flood        10 MB of header lines: refused once the head outgrows its bound
  slow-clients N      N clients each sending a header line a second: a normal
                      request is answered meanwhile within 2 s, and each slow
                      client is cut off within 10 s
  trace-burst QUERY   8 pixel traces at once (QUERY: folder=..&shot=..&frame=..):
                      one is traced, the others answered 429 at once
  slow-readers PID PATH N MARK_AT MARK BOUND_MB
                      N clients ask for PATH (a large file), one at a time,
                      then read nothing (half of them a byte a second) for
                      4 s: the monitor's (PID) memory (VmRSS) grows by less
                      than BOUND_MB however large the file, a normal request
                      is answered meanwhile within 2 s, a range of the file
                      at MARK_AT is answered 206 with the bytes MARK, and each
                      slow client was answered 200
"""
import socket
import sys
import threading
import time
import zlib

HOST = "127.0.0.1"
port, check = int(sys.argv[1]), sys.argv[2]


def connect(timeout=10.0):
    s = socket.create_connection((HOST, port), timeout=timeout)
    s.settimeout(timeout)
    return s


def read_reply(s, limit=1 << 20):
    """The status code and the bytes read until the server closes or the
    head and Content-Length's body are in (at most `limit`)."""
    data = b""
    while len(data) < limit:
        try:
            chunk = s.recv(65536)
        except (ConnectionResetError, BrokenPipeError):
            break
        if not chunk:
            break
        data += chunk
        head, sep, body = data.partition(b"\r\n\r\n")
        if sep:
            length = [int(l.split(b":")[1]) for l in head.split(b"\r\n") if l.lower().startswith(b"content-length:")]
            if length and len(body) >= length[0]:
                break
    status = int(data.split(b" ")[1]) if data.startswith(b"HTTP/") else 0
    return status, data


def fail(message):
    print(f"{check}: FAIL {message}")
    sys.exit(1)


def get(path, timeout=5.0):
    s = connect(timeout)
    s.sendall(f"GET {path} HTTP/1.1\r\nHost: {HOST}\r\nConnection: close\r\n\r\n".encode())
    status, data = read_reply(s, 64 << 20)
    s.close()
    return status, data


if check == "multirange":
    ranges = "bytes=" + ",".join(["0-"] * 1000)
    start = time.monotonic()
    s = connect()
    s.sendall(f"GET / HTTP/1.1\r\nHost: {HOST}\r\nRange: {ranges}\r\nConnection: close\r\n\r\n".encode())
    status, data = read_reply(s, 16 << 20)
    took = time.monotonic() - start
    if status != 416 or len(data) > 4096 or took > 2:
        fail(f"HTTP {status}, {len(data)} bytes in {took:.1f} s (want 416, small, fast)")
    print(f"multirange: {status}, {len(data)} bytes in {took:.2f} s")

elif check == "gzip-post":
    # 62 MiB of zeros, deflated a MiB at a time: 63 KB on the wire, under
    # the 64 KB a body may have had before.
    z = zlib.compressobj(9, zlib.DEFLATED, 31)
    body = b"".join(z.compress(bytes(1 << 20)) for _ in range(62)) + z.flush()
    start = time.monotonic()
    s = connect()
    s.sendall((f"POST /api/folders HTTP/1.1\r\nHost: {HOST}\r\nContent-Encoding: gzip\r\n"
               f"Content-Type: application/octet-stream\r\nContent-Length: {len(body)}\r\n\r\n").encode())
    try:
        s.sendall(body)
    except (ConnectionResetError, BrokenPipeError):
        pass  # refused before the body was taken: as it should
    status, data = read_reply(s)
    took = time.monotonic() - start
    if status not in (405, 413, 415) or took > 3:
        fail(f"HTTP {status} in {took:.1f} s: {data[:200]!r}")
    print(f"gzip-post: {status} for {len(body)} bytes unpacking to 62 MiB, in {took:.2f} s")

elif check == "chunked-post":
    start = time.monotonic()
    s = connect()
    s.sendall(f"POST /api/folders HTTP/1.1\r\nHost: {HOST}\r\nTransfer-Encoding: chunked\r\n\r\n".encode())
    # The answer must come before any chunk is sent.
    status, data = read_reply(s)
    took = time.monotonic() - start
    if status not in (405, 413) or took > 3:
        fail(f"HTTP {status} in {took:.1f} s: {data[:200]!r}")
    print(f"chunked-post: {status} before a chunk was sent, in {took:.2f} s")

elif check == "header-flood":
    start = time.monotonic()
    s = connect()
    s.sendall(f"GET /api/folders HTTP/1.1\r\nHost: {HOST}\r\n".encode())
    line = ("X-Flood: " + "a" * 1000 + "\r\n").encode()
    sent = 0
    try:
        for _ in range(10000):  # 10 MB at most
            s.sendall(line)
            sent += len(line)
    except (ConnectionResetError, BrokenPipeError, socket.timeout):
        pass
    status, data = read_reply(s)
    took = time.monotonic() - start
    # Refused (413, 431), or cut off before all of it was taken.
    if not (status in (413, 431) or (status == 0 and sent < 10000 * len(line))) or took > 10:
        fail(f"HTTP {status} after {sent} bytes in {took:.1f} s")
    print(f"header-flood: HTTP {status or 'closed'} after {sent} bytes of header lines in {took:.2f} s")

elif check == "slow-clients":
    n = int(sys.argv[3])
    slow = []
    for _ in range(n):
        s = connect(timeout=1.0)
        s.sendall(f"GET /api/folders HTTP/1.1\r\nHost: {HOST}\r\n".encode())
        slow.append(s)
    cut = [None] * n
    start = time.monotonic()
    worst = 0.0
    for tick in range(20):  # a header line a second each, 20 s at most
        for k, s in enumerate(slow):
            if cut[k] is not None:
                continue
            try:
                s.sendall(f"X-Slow-{tick}: {k}\r\n".encode())
                s.settimeout(0.01)
                if s.recv(1) == b"":
                    cut[k] = time.monotonic() - start
            except socket.timeout:
                pass
            except (ConnectionResetError, BrokenPipeError):
                cut[k] = time.monotonic() - start
        t0 = time.monotonic()
        status, _ = get("/api/folders", timeout=5.0)
        took = time.monotonic() - t0
        worst = max(worst, took)
        if status != 200 or took > 2:
            fail(f"with {n} slow clients a normal request took {took:.1f} s: HTTP {status}")
        if all(c is not None for c in cut):
            break
        time.sleep(max(0.0, 1.0 - took))
    if any(c is None or c > 10 for c in cut):
        fail(f"slow clients not cut off within 10 s: {cut}")
    print(f"slow-clients: {n} cut off after {min(cut):.1f}-{max(cut):.1f} s; normal requests meanwhile took at most {worst:.2f} s")

elif check == "trace-burst":
    query = sys.argv[3]
    results = [None] * 8

    def ask(k):
        status, data = get(f"/api/trace?{query}&x={k}&y=1", timeout=60.0)
        results[k] = status

    threads = [threading.Thread(target=ask, args=(k,)) for k in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(90)
    if results.count(200) < 1 or results.count(429) < 1 or any(r not in (200, 429) for r in results):
        fail(f"statuses {results} (want one trace at a time: 200 and 429s)")
    print(f"trace-burst: {results.count(200)} traced, {results.count(429)} told 429")

elif check == "slow-readers":
    pid, path, n, mark_at, mark, bound_mb = sys.argv[3], sys.argv[4], int(sys.argv[5]), int(sys.argv[6]), sys.argv[7].encode(), int(sys.argv[8])

    def rss_kb():
        with open(f"/proc/{pid}/status") as f:
            return next(int(l.split()[1]) for l in f if l.startswith("VmRSS:"))

    base = rss_kb()
    most = 0

    def measure(when):
        # Fails at once past the bound: a server that copies the file for
        # each client must not be driven much further than that.
        global most
        grown = rss_kb() - base
        most = max(most, grown)
        if grown > bound_mb * 1024:
            fail(f"{when}: the monitor's memory grew by {grown // 1024} MB (bound {bound_mb} MB)")

    slow = []
    for k in range(n):
        s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        # A small receive window: the kernel takes little of the answer for
        # the client, the server keeps the rest to send.
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        s.settimeout(5.0)
        s.connect((HOST, port))
        s.sendall(f"GET {path} HTTP/1.1\r\nHost: {HOST}\r\n\r\n".encode())
        slow.append([s, b""])
        time.sleep(0.25)  # the server has read the request and begun its answer
        measure(f"{k + 1} slow readers")
    worst = 0.0
    for tick in range(4):
        for k, entry in enumerate(slow):
            if k % 2 == 0:
                entry[1] += entry[0].recv(1)
        t0 = time.monotonic()
        status, _ = get("/api/folders", timeout=5.0)
        s = connect()
        s.sendall(f"GET {path} HTTP/1.1\r\nHost: {HOST}\r\nRange: bytes={mark_at}-{mark_at + len(mark) - 1}\r\n"
                  f"Connection: close\r\n\r\n".encode())
        ranged, data = read_reply(s)
        s.close()
        took = time.monotonic() - t0
        worst = max(worst, took)
        if status != 200 or took > 2:
            fail(f"with {n} slow readers a normal request took {took:.1f} s: HTTP {status}")
        if ranged != 206 or not data.endswith(b"\r\n\r\n" + mark):
            fail(f"with {n} slow readers a range of the file: HTTP {ranged}, ending {data[-64:]!r}")
        measure(f"{n} slow readers, {tick + 1} s")
        time.sleep(max(0.0, 1.0 - took))
    for entry in slow:
        while len(entry[1]) < 12:
            chunk = entry[0].recv(12 - len(entry[1]))
            if not chunk:
                break
            entry[1] += chunk
        entry[0].close()
    heads = sorted(set(e[1][:12] for e in slow))
    if heads != [b"HTTP/1.1 200"]:
        fail(f"the slow readers were answered {heads}")
    print(f"slow-readers: {n} clients not reading a large file; the monitor grew by at most {most // 1024} MB "
          f"(bound {bound_mb}); normal requests and a range meanwhile took at most {worst:.2f} s")

else:
    fail("unknown check")
