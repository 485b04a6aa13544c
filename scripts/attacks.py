#!/usr/bin/env python3
"""Attacks on a real `softtune serve` process on 127.0.0.1, each bounded in time.

Before the attacks the server answers one request of every kind, a preview included, so it is measured as
a studio's server would be, not freshly started. During every attack a sampler reads the server's VmRSS
from /proc/PID/status (and, reported apart, that of its raster processes: preview frames are drawn in
child processes that hold Mesa) and a prober asks GET /api/v1/health on fresh connections; each attack
passes when the server's peak RSS stays under 100 MB (the crowded scenes, which run to their run-time
limit, 100 MB plus a request's 64 MiB peak budget), the probe p99 under 100 ms with no failed probe,
and afterwards health and a tune request answer normally. After them all and 5 s idle, the resident set
must be within twice the warm one plus what the caches hold (GET /metrics softtune_cache_bytes).
Usage: scripts/attacks.py path/to/softtune [--slowloris-seconds 20] [--json out.json] [--only NAME]
Only 127.0.0.1 is ever contacted. Exit status 1 when any attack fails.
"""
import argparse
import itertools
import gzip
import http.client
import json
import multiprocessing
import os
import socket
import subprocess
import sys
import threading
import time

HOST = "127.0.0.1"
RSS_LIMIT_KB = 100 * 1024
# A request may hold its budget's 64 MiB at its peak (server/app/budgets.h kPeakBytes): the crowded scenes,
# which run to their run-time limit, are held to the limit plus that.
RUN_PEAK_KB = 64 * 1024
RSS_LIMITS_KB = {"crowded_scenes": RSS_LIMIT_KB + RUN_PEAK_KB}
P99_LIMIT_MS = 100.0
TUNE_BODY = b'{"frequency_hz": 5, "damping_ratio": 0.5, "effective_mass": 1}'


def status_kb(pid, key):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith(key + ":"):
                return int(line.split()[1])
    return 0


def children(pid):
    """The live child processes of `pid` (its raster processes)."""
    pids = []
    for task in os.listdir(f"/proc/{pid}/task"):
        try:
            with open(f"/proc/{pid}/task/{task}/children") as f:
                pids += [int(c) for c in f.read().split()]
        except OSError:
            pass
    return pids


def children_rss_kb(pid):
    total = 0
    for child in children(pid):
        try:
            total += status_kb(child, "VmRSS")
        except OSError:
            pass  # exited between the listing and the read
    return total


def monitor(pid, port, stop, results):
    """Samples RSS every 20 ms and probes health every 25 ms on fresh connections until `stop` is set;
    runs in its own process so the attacking threads cannot delay the probes."""
    latencies, failures, peak, raster_peak = [], 0, 0, 0
    next_probe = time.monotonic()
    while not stop.is_set():
        peak = max(peak, status_kb(pid, "VmRSS"))
        raster_peak = max(raster_peak, children_rss_kb(pid))
        if time.monotonic() >= next_probe:
            t0 = time.perf_counter()
            try:
                c = http.client.HTTPConnection(HOST, port, timeout=2)
                c.request("GET", "/api/v1/health")
                r = c.getresponse()
                r.read()
                c.close()
                if r.status == 200:
                    latencies.append((time.perf_counter() - t0) * 1000)
                else:
                    failures += 1
            except OSError:
                failures += 1
            next_probe = time.monotonic() + 0.025
        time.sleep(0.005)
    results.put((peak, raster_peak, latencies, failures))


class Monitor:
    def __init__(self, pid, port):
        self.stop = multiprocessing.Event()
        self.results = multiprocessing.Queue()
        self.process = multiprocessing.Process(target=monitor, args=(pid, port, self.stop, self.results))

    def __enter__(self):
        self.process.start()
        time.sleep(0.1)
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.peak_rss_kb, self.raster_peak_rss_kb, self.latencies_ms, self.failures = self.results.get(timeout=30)
        self.process.join()

    def p99_ms(self):
        if not self.latencies_ms:
            return float("inf")
        s = sorted(self.latencies_ms)
        return s[min(len(s) - 1, int(0.99 * len(s)))]


def sustained(attack, seconds=3.0, workers=4):
    """Runs `attack` (one round, returns a dict with "ok") on `workers` threads again and again for
    `seconds`; the summary of the rounds."""
    rounds, bad, lock = [], [], threading.Lock()
    end = time.monotonic() + seconds

    def loop():
        while time.monotonic() < end:
            r = attack()
            with lock:
                rounds.append(r)
                if not r["ok"]:
                    bad.append(r)

    threads = [threading.Thread(target=loop) for _ in range(workers)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    out = {k: v for k, v in rounds[0].items() if k != "ok"}
    out.update({"rounds": len(rounds), "concurrent": workers, "bad_rounds": bad[:3], "ok": not bad})
    return out


# The server holds at most 128 connections per client address (server/http/limits.h
# kMaxConnectionsPerClient). The floods of many connections model many clients, so they come from 250
# loopback addresses (all of 127.0.0.0/8 is this machine); the health prober stays on 127.0.0.1, and the
# one_client attack uses an address of its own.
PER_CLIENT_LIMIT = 128
ONE_CLIENT_SOURCE = "127.0.0.252"


def attacker_source(i):
    """The loopback address the i-th connection of a flood comes from: 127.0.0.2 to 127.0.0.251."""
    return f"127.0.0.{2 + i % 250}"


_next_source = itertools.count()


def connect(port, timeout=5, source=None):
    # An attack's connection comes from an attacker's address, never the health prober's 127.0.0.1: one
    # address that sends 1 MiB heads 4000 times a second holds 128 connections the server is still draining,
    # and its next ones are refused 503 by the per-client limit -- which must not be the prober's.
    if source is None:
        source = attacker_source(next(_next_source))
    s = socket.create_connection((HOST, port), timeout=timeout, source_address=(source, 0))
    s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    return s


def read_status(s, deadline_s=5):
    """The status code of the answer on `s` (0 when the server closed without one)."""
    s.settimeout(deadline_s)
    data = b""
    try:
        while b"\r\n" not in data:
            chunk = s.recv(4096)
            if not chunk:
                break
            data += chunk
    except OSError:
        pass
    if data.startswith(b"HTTP/1.") and len(data) >= 12:
        return int(data[9:12])
    return 0


def send_until_refused(s, chunks, deadline):
    """Sends chunks until the server stops reading (closed or reset) or the deadline; bytes sent."""
    sent = 0
    s.settimeout(2)
    try:
        for chunk in chunks:
            if time.monotonic() > deadline:
                break
            s.sendall(chunk)
            sent += len(chunk)
    except OSError:
        pass
    return sent


def attack_chunked_100mb(port):
    s = connect(port)
    s.sendall(b"POST /api/v1/tune HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
              b"Transfer-Encoding: chunked\r\n\r\n")
    block = b"10000\r\n" + b"[" * 0x10000 + b"\r\n"
    sent = send_until_refused(s, (block for _ in range(100 * 16)), time.monotonic() + 10)
    status = read_status(s)
    s.close()
    return {"sent_bytes": sent, "status": status, "ok": status in (0, 400, 411, 413, 415, 501)}


BOMB = None


def attack_gzip_bomb(port):
    bomb = BOMB
    s = connect(port)
    s.sendall(b"POST /api/v1/tune HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
              b"Content-Encoding: gzip\r\nContent-Length: " + str(len(bomb)).encode() + b"\r\n\r\n")
    sent = send_until_refused(s, [bomb], time.monotonic() + 10)
    status = read_status(s)
    s.close()
    return {"compressed_bytes": len(bomb), "inflated_bytes": 200 << 20, "sent_bytes": sent, "status": status,
            "ok": status in (0, 400, 413, 415)}


def attack_declared_100mb(port):
    s = connect(port)
    s.sendall(b"POST /api/v1/tune HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
              b"Content-Length: 104857600\r\n\r\n")
    block = b" " * (1 << 20)
    sent = send_until_refused(s, (block for _ in range(100)), time.monotonic() + 15)
    status = read_status(s)
    s.close()
    return {"sent_bytes": sent, "status": status, "ok": status in (0, 413)}


def attack_huge_header_line(port, repeat=1):
    statuses = []
    for _ in range(repeat):
        s = connect(port)
        s.sendall(b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\nX-Big: ")
        send_until_refused(s, (b"a" * 65536 for _ in range(16)), time.monotonic() + 5)
        send_until_refused(s, [b"\r\n\r\n"], time.monotonic() + 1)
        statuses.append(read_status(s))
        s.close()
    return {"requests": repeat, "header_bytes": 1 << 20, "statuses": sorted(set(statuses)),
            "ok": all(st in (0, 400, 413, 431) for st in statuses)}


def attack_many_headers(port, repeat=1):
    statuses = []
    headers = b"".join(b"X-H%d: v\r\n" % i for i in range(10000))
    for _ in range(repeat):
        s = connect(port)
        send_until_refused(s, [b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\n" + headers + b"\r\n"],
                           time.monotonic() + 5)
        statuses.append(read_status(s))
        s.close()
    return {"requests": repeat, "headers": 10000, "statuses": sorted(set(statuses)),
            "ok": all(st in (0, 400, 431) for st in statuses)}


def attack_slowloris(port, seconds, connections=1000):
    """Up to `connections` connections at once, each trickling one header byte per second, for the whole
    `seconds`: the ones the server cuts off (408 at the request deadline) are reopened at once, so the
    pressure never drops. The health probes must not notice."""
    def open_one():
        s = connect(port, timeout=0.5, source=attacker_source(opened))
        s.sendall(b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\n")
        s.setblocking(False)
        return s

    socks, opened, refused, answers = [], 0, 0, {}
    start = time.monotonic()
    end = start + seconds
    closed_by_server = 0
    while time.monotonic() < end:
        # Top up to `connections`, spread over the first half for the first fill.
        target = connections if time.monotonic() > start + seconds / 2 else \
            int(connections * (time.monotonic() - start) / (seconds / 2)) + 1
        while len(socks) < target and time.monotonic() < end:
            try:
                socks.append(open_one())
                opened += 1
            except OSError:
                refused += 1
                break
        alive = []
        for s in socks:
            try:
                data = s.recv(4096)
                if data:
                    answers[data[9:12].decode(errors="replace")] = answers.get(data[9:12].decode(errors="replace"), 0) + 1
                closed_by_server += 1
                s.close()
                continue
            except BlockingIOError:
                pass
            except OSError:
                closed_by_server += 1
                s.close()
                continue
            try:
                s.sendall(b"X")
                alive.append(s)
            except OSError:
                closed_by_server += 1
                s.close()
        socks = alive
        time.sleep(0.2)
    held_at_end = len(socks)
    for s in socks:
        s.close()
    return {"connections_opened": opened, "held_at_end": held_at_end, "connect_failures": refused,
            "seconds": seconds, "closed_by_server": closed_by_server, "answers": answers, "ok": True}


TRAVERSALS = [
    "/../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2f..%2fetc%2fpasswd",
    "/%2e%2e%2f%2e%2e%2fetc%2fpasswd", "/index.html%00../../etc/passwd", "/%00", "/..%5c..%5cetc%5cpasswd",
    "/%252e%252e/%252e%252e/etc/passwd", "/....//....//etc/passwd", "/%c0%ae%c0%ae/%c0%ae%c0%ae/etc/passwd",
    "/api/v1/../../../etc/passwd", "/api/v1/presets/..%2f..%2fetc%2fpasswd", "/api/v1/presets/%2e%2e",
    "/api/v1/preview/..%2f..%2fetc%2fpasswd/0.png", "//etc/passwd", "/./././etc/passwd", "/%2e/%2e%2e/etc/passwd",
    "/web/../CMakeLists.txt", "/..%2fCMakeLists.txt", "/%2e%2e/CMakeLists.txt",
]


def attack_preview_flood(port, previews=16, frames=120):
    """Expensive requests at once: `previews` different previews asked for with "wait": true. Each
    waiter would hold one of the server's worker threads; past the waiter cap (2) they are answered at
    once with a progress URL and a wait_declined warning, so health and tune keep their threads."""
    answers, lock = [], threading.Lock()

    def one(i):
        body = {"response_frames": 10 + i, "oscillation": "some", "effective_mass": 1, "frames": frames,
                "size": "320x180"}
        c = http.client.HTTPConnection(HOST, port, timeout=120)
        c.request("POST", "/api/v1/preview", json.dumps(body).encode(), {"Content-Type": "application/json"})
        r = c.getresponse()
        data = json.loads(r.read() or b"null")
        c.close()
        with lock:
            answers.append((r.status, data))

    threads = [threading.Thread(target=one, args=(i,)) for i in range(previews)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    done = sum(1 for st, a in answers if st == 200 and a["status"] == "done")
    declined = [a for st, a in answers if st == 200 and a["status"] == "rendering"
                and any(w["code"] == "wait_declined" for w in a["warnings"])]
    # The declined renders go on: follow them to the end, so the probes run while the pool is busy.
    deadline, finished = time.monotonic() + 90, 0
    for a in declined:
        while time.monotonic() < deadline:
            c = http.client.HTTPConnection(HOST, port, timeout=10)
            c.request("GET", a["progress_url"])
            r = c.getresponse()
            status = json.loads(r.read())["status"]
            c.close()
            if status != "rendering":
                finished += status == "done"
                break
            time.sleep(0.1)
    return {"previews": previews, "frames_each": frames, "waited": done, "declined": len(declined),
            "declined_then_done": finished, "statuses": sorted({st for st, _ in answers}),
            "ok": done + len(declined) == previews and finished == len(declined)}


def attack_path_traversal(port, rounds=1):
    leaks, statuses = [], set()
    for _ in range(rounds):
        for path in TRAVERSALS:
            s = connect(port)
            s.sendall(b"GET " + path.encode() + b" HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
            s.settimeout(5)
            data = read_all(s)
            if b"root:" in data or b"cmake_minimum_required" in data:
                leaks.append(path)
            if data.startswith(b"HTTP/1."):
                statuses.add(int(data[9:12]))
    return {"paths": len(TRAVERSALS), "requests": rounds * len(TRAVERSALS), "statuses": sorted(statuses),
            "leaks": sorted(set(leaks)), "ok": not leaks and all(400 <= st < 500 for st in statuses)}


def read_all(s):
    """Everything `s` receives until the server closes it (or its timeout passes); closes it."""
    data = b""
    try:
        while True:
            chunk = s.recv(1 << 20)
            if not chunk:
                break
            data += chunk
    except OSError:
        pass
    s.close()
    return data


def fetch_raw(port, request, timeout=30, source=None):
    """Sends `request` on a fresh connection and reads the whole answer (the request asks to close)."""
    s = connect(port, timeout=timeout, source=source)
    s.sendall(request)
    data = read_all(s)
    head, _, body = data.partition(b"\r\n\r\n")
    status = int(head[9:12]) if head.startswith(b"HTTP/1.") else 0
    return status, head, body


def attack_multi_range(port, ranges=1000):
    """One GET of the OpenAPI document with a 3 KB Range header of `ranges` ranges (it had built a 229 MB
    answer in 15.8 s); then a single range. The answer must be the whole document, 200, never larger."""
    req = b"GET /api/v1/openapi.json HTTP/1.1\r\nHost: x\r\nConnection: close\r\n"
    _, _, whole = fetch_raw(port, req + b"\r\n")
    header = b"Range: bytes=0-" + b",0-" * (ranges - 1) + b"\r\n"
    t0 = time.perf_counter()
    status, head, body = fetch_raw(port, req + header + b"\r\n")
    seconds = time.perf_counter() - t0
    one_status, one_head, one_body = fetch_raw(port, req + b"Range: bytes=0-9\r\n\r\n")
    ratio = len(body) / max(1, len(whole))
    print(f"  multi_range: {ranges} ranges ({len(header)} header bytes): status {status}, answer {len(body)} bytes = "
          f"{ratio:.2f} x the document ({len(whole)} bytes), {seconds * 1000:.1f} ms; bytes=0-9: status {one_status}, "
          f"{len(one_body)} bytes", flush=True)
    return {"ranges": ranges, "header_bytes": len(header), "status": status, "answer_bytes": len(body),
            "document_bytes": len(whole), "answer_over_document": round(ratio, 3), "ms": round(seconds * 1000, 1),
            "single_range_status": one_status, "single_range_bytes": len(one_body),
            "ok": status == 200 and ratio <= 2 and one_status == 200 and one_body == whole
            and b"Content-Range" not in head + one_head}


def attack_slow_bodies(port, clients, seconds):
    """`clients` connections at once, each a complete POST head whose 400-byte body trickles at one byte
    a second; cut off ones are reopened at once. The body had held a worker for 10 s each: 10-20 such
    clients took health down. Now a body arriving waits in the gate and gets 408 after 1 s plus its length
    at 128 KiB/s."""
    head = (b"POST /api/v1/tune HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
            b"Content-Length: 400\r\n\r\n{")

    def open_one():
        s = connect(port, timeout=0.5, source=attacker_source(opened))
        s.sendall(head)
        s.setblocking(False)
        return s, time.monotonic()

    socks, opened, answers, held_for = [], 0, {}, []
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        while len(socks) < clients:
            try:
                socks.append(open_one())
                opened += 1
            except OSError:
                break
        alive = []
        for s, since in socks:
            try:
                data = s.recv(4096)
                if data:
                    code = data[9:12].decode(errors="replace")
                    answers[code] = answers.get(code, 0) + 1
                held_for.append(time.monotonic() - since)
                s.close()
                continue
            except BlockingIOError:
                pass
            except OSError:
                held_for.append(time.monotonic() - since)
                s.close()
                continue
            try:
                s.sendall(b" ")
                alive.append((s, since))
            except OSError:
                s.close()
        socks = alive
        time.sleep(1.0)
    for s, _ in socks:
        s.close()
    longest = max(held_for) if held_for else 0.0
    print(f"  slow_bodies x{clients}: {opened} connections, answers {answers}, longest held {longest:.1f} s", flush=True)
    return {"clients": clients, "seconds": seconds, "connections_opened": opened, "answers": answers,
            "longest_held_s": round(longest, 2), "ok": set(answers) <= {"408"} and longest < 5}


def attack_many_connections(port, connections=500, seconds=4.0):
    """`connections` clients at once, each asking again as soon as it is answered (a simulate of the vehicle,
    about 10 ms of work): the queue of complete requests overflows (503 for the attackers), and the health
    probes, on the reserved lane, must not notice (11-20 % of them had got 503)."""
    body = json.dumps({"preset": "vehicle"}).encode()
    req = (b"POST /api/v1/simulate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: "
           + str(len(body)).encode() + b"\r\nConnection: close\r\n\r\n" + body)
    counts, lock = {}, threading.Lock()
    end = time.monotonic() + seconds

    def client(source):
        while time.monotonic() < end:
            try:
                status, _, _ = fetch_raw(port, req, timeout=10, source=source)
            except OSError:
                status = 0
            with lock:
                counts[status] = counts.get(status, 0) + 1

    threads = [threading.Thread(target=client, args=(attacker_source(i),)) for i in range(connections)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    print(f"  health_500_connections: {connections} clients for {seconds} s, answers {dict(sorted(counts.items()))}",
          flush=True)
    return {"connections": connections, "answers": {str(k): v for k, v in sorted(counts.items())},
            "ok": set(counts) <= {200, 503, 0}}


def attack_one_client(port, connections=400, seconds=3.0):
    """`connections` connections from one address, each holding half a request head: the server holds
    PER_CLIENT_LIMIT of them and answers every other one 503 at once (it had let one client take all 1024
    places of the gate, pushing everyone else's connections out)."""
    socks, answers, connect_failures = [], {}, 0
    for _ in range(connections):
        try:
            s = connect(port, timeout=2, source=ONE_CLIENT_SOURCE)
            s.sendall(b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\n")
            socks.append(s)
        except OSError:
            connect_failures += 1
    time.sleep(seconds)
    held = 0
    for s in socks:
        s.setblocking(False)
        try:
            data = s.recv(4096)
            code = data[9:12].decode(errors="replace") if data else "closed"
            answers[code] = answers.get(code, 0) + 1
        except BlockingIOError:
            held += 1
        except OSError:
            answers["reset"] = answers.get("reset", 0) + 1
        s.close()
    print(f"  one_client x{connections}: {held} held (limit {PER_CLIENT_LIMIT}), answers {answers}, "
          f"connect failures {connect_failures}", flush=True)
    return {"connections": connections, "held": held, "answers": answers, "connect_failures": connect_failures,
            "ok": held == PER_CLIENT_LIMIT and answers == {"503": connections - PER_CLIENT_LIMIT}}


def cpu_seconds(pid):
    """User plus system CPU time of the process so far, s (/proc/PID/stat)."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def cpu_with_children(pid):
    """CPU time of the process and of its raster processes, live (their /proc/PID/stat) or reaped (the
    server's cutime and cstime), s: a preview's frames are drawn in those."""
    def stat(p):
        with open(f"/proc/{p}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()
    fields = stat(pid)
    total = sum(int(x) for x in fields[11:15])
    for child in children(pid):
        try:
            total += sum(int(x) for x in stat(child)[11:13])
        except OSError:
            pass  # exited between the listing and the read: now in the server's cutime
    return total / os.sysconf("SC_CLK_TCK")


def crowded_boxes(bodies=100, frames=2):
    """`bodies` unit boxes on one spot for `frames` frames: the largest modes request (100 bodies)."""
    return {"name": "crowded_boxes", "world": {"fps": 60, "duration_s": frames / 60, "gravity": [0, -10],
                                              "bounds": [-1000, -1000, 1000, 1000]},
            "bodies": [{"id": f"b{i}", "shape": {"type": "box", "width": 1, "height": 1}, "mass": 1,
                        "position": [0.001 * (i % 10), 0.001 * (i // 10)]} for i in range(bodies)]}


def crowded_scene(bodies=500, duration_s=40, velocity_iterations=8):
    """`bodies` circles all dropped on one spot: every pair in contact, the estimate's blind spot."""
    return {"name": "crowded", "world": {"fps": 60, "duration_s": duration_s, "gravity": [0, -10], "velocity_iterations": velocity_iterations,
                      "bounds": [-1000, -1000, 1000, 1000]},
            "bodies": [{"id": f"b{i}", "shape": {"type": "circle", "radius": 0.5}, "mass": 1,
                        "position": [0.001 * (i % 10), 0.001 * (i // 10)]} for i in range(bodies)]}


BUDGET_CPU_S = 2.0


def attack_crowded(pid, port):
    """Requests the estimate prices within the 2 s budget that would run for minutes (a simulate of 500
    overlapping circles over 3600 frames had run 409 s, and 349 s more after its client left): each must
    end, 200 or the documented 422, within 2x the budget of server CPU time."""
    cases = [
        ("simulate", "/api/v1/simulate", {"scene": crowded_scene()}),
        ("check", "/api/v1/check", {"scenes": [crowded_scene(duration_s=0.5, velocity_iterations=100)]}),
        ("preview", "/api/v1/preview", {"scene": crowded_scene(duration_s=20), "frames": 60, "size": "320x180"}),
        ("modes", "/api/v1/modes", crowded_boxes()),
        # Cheap to simulate, dear to draw: 600 full-HD frames (10.6 s before the frames had a limit).
        ("preview_full_hd", "/api/v1/preview", {"scene": crowded_scene(bodies=5, duration_s=10), "frames": 600,
                                                "size": "1920x1080"}),
    ]
    rows, ok = [], True
    for name, path, body in cases:
        c0, t0 = cpu_with_children(pid), time.perf_counter()
        try:
            status = post_json(port, path, body, timeout=120)
        except OSError:
            status = 0
        cpu, wall = cpu_with_children(pid) - c0, time.perf_counter() - t0
        passed = status in (200, 422) and cpu <= 2 * BUDGET_CPU_S + 0.5
        ok &= passed
        rows.append({"request": name, "status": status, "server_cpu_s": round(cpu, 2), "wall_s": round(wall, 2),
                     "passed": passed})
        print(f"  crowded {name}: status {status}, server CPU {cpu:.2f} s (bar {2 * BUDGET_CPU_S:.0f} s), wall {wall:.2f} s",
              flush=True)
    # A clip asked of a finished preview encodes on the request's thread (120 frames of 1280x720 as WebP, the
    # clip cap: 5.3 s for a busy scene before encoding had a limit). The frames first (their render has its
    # own limit), then the clip alone is measured.
    c = http.client.HTTPConnection(HOST, port, timeout=120)
    c.request("POST", "/api/v1/preview", json.dumps({"scene": crowded_scene(bodies=5, duration_s=2), "frames": 120,
                                                     "size": "1280x720"}).encode(), {"Content-Type": "application/json"})
    r = c.getresponse()
    preview = json.loads(r.read() or b"{}")
    c.close()
    clip_url = preview.get("animation", {}).get("webp")
    if clip_url:
        c0, t0 = cpu_with_children(pid), time.perf_counter()
        c = http.client.HTTPConnection(HOST, port, timeout=120)
        c.request("GET", clip_url)
        status = c.getresponse().status
        c.close()
        cpu, wall = cpu_with_children(pid) - c0, time.perf_counter() - t0
        passed = status in (200, 422) and cpu <= 2 * BUDGET_CPU_S + 0.5
    else:
        status, cpu, wall, passed = r.status, 0.0, 0.0, False
    ok &= passed
    rows.append({"request": "clip webp 120 x 1280x720", "status": status, "server_cpu_s": round(cpu, 2),
                 "wall_s": round(wall, 2), "passed": passed})
    print(f"  crowded clip webp: status {status}, server CPU {cpu:.2f} s (bar {2 * BUDGET_CPU_S:.0f} s), wall {wall:.2f} s",
          flush=True)
    # The client gives up after 1 s: the work must stop with it, not run on for minutes.
    c0 = cpu_seconds(pid)
    try:
        post_json(port, "/api/v1/simulate", {"scene": crowded_scene()}, timeout=1)
    except OSError:
        pass
    time.sleep(2.0)
    after = cpu_seconds(pid) - c0
    gone_ok = after < 1 + 2.0 + 0.5
    ok &= gone_ok
    print(f"  crowded simulate, client gone after 1 s: server CPU {after:.2f} s over the next 3 s", flush=True)
    rows.append({"request": "simulate, client gone at 1 s", "server_cpu_s": round(after, 2), "passed": gone_ok})
    return {"requests": rows, "ok": ok}


def cache_bytes(port):
    """Bytes the server's caches hold now, by cache (GET /metrics softtune_cache_bytes)."""
    c = http.client.HTTPConnection(HOST, port, timeout=10)
    c.request("GET", "/metrics")
    text = c.getresponse().read().decode()
    c.close()
    out = {}
    for line in text.splitlines():
        if line.startswith("softtune_cache_bytes{"):
            out[line.split('"')[1]] = int(line.rsplit(" ", 1)[1])
    return out


def serves_normally(port):
    c = http.client.HTTPConnection(HOST, port, timeout=5)
    c.request("GET", "/api/v1/health")
    health = c.getresponse().status
    c.close()
    c = http.client.HTTPConnection(HOST, port, timeout=10)
    c.request("POST", "/api/v1/tune", TUNE_BODY, {"Content-Type": "application/json"})
    r = c.getresponse()
    body = json.loads(r.read())
    c.close()
    return health == 200 and r.status == 200 and "soft" in json.dumps(body)


def post_json(port, path, body, timeout=60):
    c = http.client.HTTPConnection(HOST, port, timeout=timeout)
    c.request("POST", path, json.dumps(body).encode(), {"Content-Type": "application/json"})
    r = c.getresponse()
    r.read()
    c.close()
    return r.status


def warm_up(port):
    """One request of every kind, so the attacks meet a server that has done its work: tune, a Box2D
    scene, the accuracy report, and a preview (the render pool, its raster processes, cached PNGs)."""
    statuses = {
        "tune": post_json(port, "/api/v1/tune", json.loads(TUNE_BODY)),
        "simulate": post_json(port, "/api/v1/simulate", {"preset": "vehicle"}),
        "accuracy": post_json(port, "/api/v1/accuracy", json.loads(TUNE_BODY)),
        "preview": post_json(port, "/api/v1/preview", {"preset": "vehicle", "frames": 60}),
    }
    if any(st != 200 for st in statuses.values()):
        raise SystemExit(f"attacks: the warm-up requests failed: {statuses}")
    return statuses


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("softtune")
    ap.add_argument("--slowloris-seconds", type=float, default=20)
    ap.add_argument("--slowloris-connections", type=int, default=1000,
                    help="slow connections held at once (the server holds 1024 before closing the least useful)")
    ap.add_argument("--json")
    ap.add_argument("--server-log", help="write the server's request log (stderr) here")
    ap.add_argument("--only", action="append", default=[], help="run just this attack (repeatable)")
    args = ap.parse_args()

    presets = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "presets")
    server = subprocess.Popen([args.softtune, "serve", "--host", HOST, "--port", "0", "--presets", presets],
                              stdout=subprocess.PIPE,
                              stderr=open(args.server_log, "w") if args.server_log else subprocess.DEVNULL, text=True)
    try:
        line = server.stdout.readline()
        port = int(line.rsplit(":", 1)[1].split("/")[0])
        global BOMB
        BOMB = gzip.compress(b"0" * (200 << 20), 9)
        warm_up(port)
        warm_kb = status_kb(server.pid, "VmRSS")
        print(f"warm-up (tune, simulate, accuracy, a 60-frame preview): server RSS "
              f"{status_kb(server.pid, 'VmRSS') / 1024:.1f} MB, raster processes "
              f"{children_rss_kb(server.pid) / 1024:.1f} MB", flush=True)
        attacks = [
            ("chunked_100mb", lambda: sustained(lambda: attack_chunked_100mb(port))),
            ("declared_100mb", lambda: sustained(lambda: attack_declared_100mb(port))),
            ("gzip_bomb", lambda: sustained(lambda: attack_gzip_bomb(port))),
            ("header_line_1mb", lambda: sustained(lambda: attack_huge_header_line(port))),
            ("headers_10000", lambda: sustained(lambda: attack_many_headers(port))),
            ("path_traversal", lambda: sustained(lambda: attack_path_traversal(port))),
            ("slowloris", lambda: attack_slowloris(port, args.slowloris_seconds, args.slowloris_connections)),
            # More slow connections than the server holds (1024): it must close the oldest, not the newest.
            ("slowloris_flood", lambda: attack_slowloris(port, args.slowloris_seconds / 2, 3 * args.slowloris_connections)),
            ("preview_flood", lambda: attack_preview_flood(port)),
            ("multi_range", lambda: attack_multi_range(port)),
            ("slow_bodies_20", lambda: attack_slow_bodies(port, 20, 4)),
            ("slow_bodies_200", lambda: attack_slow_bodies(port, 200, 4)),
            ("health_500_connections", lambda: attack_many_connections(port)),
            ("one_client_400", lambda: attack_one_client(port)),
            ("crowded_scenes", lambda: attack_crowded(server.pid, port)),
        ]
        results, failed = {}, False
        for name, attack in attacks:
            if args.only and name not in args.only:
                continue
            t0 = time.monotonic()
            with Monitor(server.pid, port) as m:
                outcome = attack()
            outcome["seconds"] = round(time.monotonic() - t0, 2)
            outcome["peak_rss_mb"] = round(m.peak_rss_kb / 1024, 1)
            outcome["raster_processes_peak_rss_mb"] = round(m.raster_peak_rss_kb / 1024, 1)
            outcome["health_probes"] = len(m.latencies_ms)
            outcome["health_failures"] = m.failures
            outcome["health_p99_ms"] = round(m.p99_ms(), 2)
            outcome["serves_after"] = serves_normally(port)
            outcome["passed"] = (outcome["ok"] and m.peak_rss_kb < RSS_LIMITS_KB.get(name, RSS_LIMIT_KB) and m.failures == 0
                                 and m.p99_ms() < P99_LIMIT_MS and outcome["serves_after"])
            failed |= not outcome["passed"]
            results[name] = outcome
            verdict = "PASS" if outcome["passed"] else "FAIL"
            print(f"{name:16s} {verdict} " + json.dumps(outcome), flush=True)
        results["vm_hwm_mb"] = round(status_kb(server.pid, "VmHWM") / 1024, 1)
        print(f"server VmHWM (peak RSS over the whole run): {results['vm_hwm_mb']} MB")
        # Memory given back: after 5 s idle the resident set is within twice the warm one plus what the
        # caches are allowed to keep and now hold (a mixed hostile run had left 218 MB of a 21 MB warm server).
        time.sleep(5)
        post_json(port, "/api/v1/tune", json.loads(TUNE_BODY))  # the last request in flight trims
        idle_kb, caches = status_kb(server.pid, "VmRSS"), cache_bytes(port)
        bar_kb = 2 * warm_kb + sum(caches.values()) / 1024
        results["idle"] = {"warm_mb": round(warm_kb / 1024, 1), "idle_mb": round(idle_kb / 1024, 1),
                           "cache_mb": {k: round(v / 2 ** 20, 1) for k, v in caches.items()},
                           "bar_mb": round(bar_kb / 1024, 1), "passed": idle_kb <= bar_kb}
        failed |= idle_kb > bar_kb
        print(f"{'memory_after_idle':16s} {'PASS' if idle_kb <= bar_kb else 'FAIL'} " + json.dumps(results["idle"]),
              flush=True)
        if args.json:
            with open(args.json, "w") as f:
                json.dump(results, f, indent=2)
        return 1 if failed else 0
    finally:
        server.terminate()
        try:
            server.wait(10)
        except subprocess.TimeoutExpired:
            server.kill()


if __name__ == "__main__":
    sys.exit(main())
