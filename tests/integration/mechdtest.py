"""mechdtest.py — what the integration tests share (Python 3 stdlib only):
check() and its tally, summary() printing the "N passed, M failed" line CTest
reads, start_mechd() starting `mechd --port 0` and reading its port,
wait_for() polling a condition, and metric_value() reading one sample of the
Prometheus text that /metrics serves."""
import os
import re
import select
import subprocess
import sys
import time

_tally = {"passed": 0, "failed": 0}


def check(name, cond, info=""):
    """Count and print one check; returns cond as a bool."""
    if cond:
        _tally["passed"] += 1
        print("ok   %s" % name)
    else:
        _tally["failed"] += 1
        print("FAIL %s %s" % (name, info))
    sys.stdout.flush()
    return bool(cond)


def summary():
    """Print the closing line; return the exit status (1 if any check failed)."""
    print("%d passed, %d failed" % (_tally["passed"], _tally["failed"]))
    return 1 if _tally["failed"] else 0


def start_mechd(binary, args=(), stderr=None, timeout=20):
    """Start `binary --port 0 ARGS` with the MECHD_* environment cleared and
    return (proc, port) once it prints its listening line; raise RuntimeError
    (after killing it) if that line does not come within `timeout` s."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
    proc = subprocess.Popen([binary, "--port", "0"] + list(args), stdout=subprocess.PIPE,
                            stderr=stderr, env=env)
    fd = proc.stdout.fileno()
    buf = b""
    end = time.monotonic() + timeout
    while not buf.endswith(b"\n") and time.monotonic() < end:
        if not select.select([fd], [], [], max(0.0, end - time.monotonic()))[0]:
            break
        c = os.read(fd, 1)
        if not c:
            break
        buf += c
    m = re.fullmatch(rb"mechd listening on http://127\.0\.0\.1:(\d+)\n", buf)
    if not m:
        proc.kill()
        raise RuntimeError("mechd did not start: %r" % buf)
    return proc, int(m.group(1))


def stop_mechd(proc):
    """SIGTERM proc and return its exit status; SIGKILL it if it has not
    exited within 20 s."""
    proc.terminate()
    try:
        return proc.wait(20)
    except subprocess.TimeoutExpired:
        proc.kill()
        return proc.wait(20)


def wait_for(pred, timeout, period=0.02):
    """Poll pred() every `period` s until it is true (return True) or `timeout`
    s have passed (return False)."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if pred():
            return True
        time.sleep(period)
    return False


def metric_value(text, name):
    """The value of the unlabelled sample `name` in Prometheus text (str or
    bytes), as a float; None if absent."""
    if isinstance(text, bytes):
        text = text.decode("utf-8", "replace")
    m = re.search(r"(?m)^" + re.escape(name) + r" (\S+)$", text)
    return float(m.group(1)) if m else None
