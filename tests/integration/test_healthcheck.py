#!/usr/bin/python3
"""test_healthcheck.py — `mechd healthcheck`, the container HEALTHCHECK without
curl: exit 0 against a running mechd (by --port and by MECHD_PORT),
1 when nothing listens, when the answer is not 200 (a fake server answering
503) and when the server never answers (a silent listener, --timeout-ms), 2
for a usage error. Timing is never asserted, only that a silent server does not
hang it (the subprocess timeout is 30 s, the healthcheck's 300 ms).

Usage: /usr/bin/python3 test_healthcheck.py PATH/TO/mechd
Prints "N passed, M failed"; exits 1 on failure.
"""
import os
import socket
import subprocess
import sys
import threading

from mechdtest import check, start_mechd, stop_mechd, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_healthcheck.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
ENV = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}


def hc(*args, env=None):
    p = subprocess.run([MECHD, "healthcheck"] + list(args), capture_output=True, text=True,
                       timeout=30, env=env or ENV)
    return p.returncode, p.stderr


def fake_server(reply):
    """A listener on 127.0.0.1 that answers every connection with reply (None: says
    nothing and keeps the connection open); returns (port, stop)."""
    ls = socket.socket()
    ls.bind(("127.0.0.1", 0))
    ls.listen(4)
    ls.settimeout(0.2)
    held, done = [], threading.Event()

    def run():
        while not done.is_set():
            try:
                c, _ = ls.accept()
            except socket.timeout:
                continue
            if reply is None:
                held.append(c)
                continue
            try:
                c.recv(1024)
                c.sendall(reply)
            finally:
                c.close()

    t = threading.Thread(target=run, daemon=True)
    t.start()

    def stop():
        done.set()
        t.join(5)
        for c in held:
            c.close()
        ls.close()
    return ls.getsockname()[1], stop


proc, port = start_mechd(MECHD)
try:
    rc, err = hc("--port", str(port))
    check("healthy mechd by --port: exit 0", rc == 0, err)
    rc, err = hc(env=dict(ENV, MECHD_PORT=str(port)))
    check("healthy mechd by MECHD_PORT: exit 0", rc == 0, err)
finally:
    stop_mechd(proc)

rc, err = hc("--port", str(port))
check("nothing listening: exit 1, and says why", rc == 1 and "refused" in err.lower(), err)

fport, stop = fake_server(b"HTTP/1.1 503 Service Unavailable\r\nContent-Length: 0\r\n\r\n")
try:
    rc, err = hc("--port", str(fport))
    check("an answer that is not 200: exit 1, quoting the status line",
          rc == 1 and "503" in err, err)
finally:
    stop()

fport, stop = fake_server(b"HTTP/1.0 200 OK\r\nContent-Length: 2\r\n\r\nok")
try:
    rc, err = hc("--port", str(fport))
    check("a 200 from anything at that port: exit 0", rc == 0, err)
finally:
    stop()

fport, stop = fake_server(None)
try:
    rc, err = hc("--port", str(fport), "--timeout-ms", "300")
    check("a server that never answers: exit 1 after --timeout-ms", rc == 1 and "timeout" in err, err)
finally:
    stop()

for bad in (["--port", "0"], ["--port", "x"], ["--timeout-ms", "0"], ["--host", "localhost"],
            ["--what"]):
    rc, err = hc(*bad)
    check("usage error %r: exit 2" % " ".join(bad), rc == 2 and err, err)
rc, err = hc(env=dict(ENV, MECHD_PORT="99999"))
check("MECHD_PORT that is not a port: exit 2", rc == 2, err)

sys.exit(summary())
