#!/usr/bin/env python3
"""Outputs that are not regular files, and a file-size limit.

Usage: output_specials.py HOLON WORKDIR

- A FIFO no process reads: the open waited for ever, past --timeout, and a signal read as
  "cannot open" (exit 2). Now --timeout ends the wait (exit 3), and a reader that comes is served.
- A pipe whose reader stalls: a blocked write retried for ever, deaf to SIGTERM. Now exit 143.
- ulimit -f: SIGXFSZ killed holon mid-write (exit 153, FILE.tmp-XXXXXX left). Now the failed write
  is reported (exit 2, "File too large") and no temporary is left.
"""
import glob, os, resource, signal, subprocess, sys, threading, time

holon, work = sys.argv[1:3]
os.makedirs(work, exist_ok=True)
failures = []


def report(name, ok, detail):
    print(f"{name}: {detail}" + ("" if ok else "  FAILED"))
    if not ok:
        failures.append(name)


plan = [holon, "plan", "--from", "box:10x10", "--to", "box:5x20", "--quiet"]
fifo = os.path.join(work, "out.fifo")
if os.path.exists(fifo):
    os.remove(fifo)
os.mkfifo(fifo)

start = time.monotonic()
r = subprocess.run(plan + ["--plan-out", fifo, "--timeout", "1"], capture_output=True, text=True, timeout=60)
took = time.monotonic() - start
report("FIFO with no reader, --timeout 1", r.returncode == 3 and took < 5 and "waited for a reader" in r.stderr, f"exit {r.returncode} after {took:.1f} s: {r.stderr.strip()}")

lines = []
def read_later():
    time.sleep(0.5)
    with open(fifo) as f:
        lines.extend(f.readlines())
reader = threading.Thread(target=read_later, daemon=True)
reader.start()
r = subprocess.run(plan + ["--plan-out", fifo, "--timeout", "20"], capture_output=True, text=True, timeout=60)
reader.join(timeout=20)
report("FIFO whose reader comes late", r.returncode == 0 and len(lines) == 200, f"exit {r.returncode}, {len(lines)} lines read (200)")

# A reader that never reads: the pipe fills, the write blocks, SIGTERM must end it.
read_end, write_end = os.pipe()
p = subprocess.Popen([holon, "plan", "--from", "box:300x300", "--to", "box:150x600", "--quiet", "--plan-out", "/dev/stdout"], stdout=write_end, stderr=subprocess.PIPE)
os.close(write_end)
time.sleep(2)
sent = time.monotonic()
p.send_signal(signal.SIGTERM)
try:
    p.wait(timeout=10)
    report("a write blocked on a stalled pipe, SIGTERM", p.returncode == 143, f"exit {p.returncode} {time.monotonic() - sent:.1f} s after the signal")
except subprocess.TimeoutExpired:
    p.kill()
    p.wait()
    report("a write blocked on a stalled pipe, SIGTERM", False, "still running 10 s after the signal")
os.close(read_end)

out = os.path.join(work, "big.jsonl")
r = subprocess.run([holon, "plan", "--from", "box:200x200", "--to", "box:100x400", "--quiet", "--plan-out", out], capture_output=True, text=True, timeout=120,
                   preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 20, resource.RLIM_INFINITY)))
left = glob.glob(out + "*")
report("ulimit -f 1 MiB", r.returncode == 2 and "File too large" in r.stderr and not left, f"exit {r.returncode}: {r.stderr.strip()}; files left: {left}")
sys.exit(1 if failures else 0)
