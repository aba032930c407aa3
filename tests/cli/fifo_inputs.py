#!/usr/bin/env python3
"""Inputs read from a FIFO (or a pipe): each is read once, and --timeout holds while holon waits.

Usage: fifo_inputs.py HOLON WORKDIR SOURCE_DIR

A writer that has already gone is not waited for again: check --from and export --config read a
configuration a second time (for the system it names, a picture's shortfall), plan --rules for the
certificate's hash, hex --from opened a picture to see that it exists, and each then waited for ever.
A FIFO nothing writes kept check and plan waiting past --timeout for ever. Writers here give up
after 30 s, so a holon that never opens the FIFO fails the test instead of hanging it.
"""
import os, subprocess, sys, threading, time

holon, work, src = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
fifo = os.path.join(work, "f")
failures = []


def feed(text, delay=0.0):
    """Writes `text` into the FIFO once a reader opens it (within 30 s), after `delay` seconds."""
    def run():
        time.sleep(delay)
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            try:
                fd = os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)
            except OSError:  # no reader yet
                time.sleep(0.02)
                continue
            os.set_blocking(fd, True)
            try:
                os.write(fd, text.encode())
            finally:
                os.close(fd)
            return
    t = threading.Thread(target=run, daemon=True)
    t.start()
    return t


def run(name, args, codes, text=None, delay=0.0, expect=""):
    if os.path.exists(fifo):
        os.remove(fifo)
    os.mkfifo(fifo)
    writer = feed(text, delay) if text is not None else None
    start = time.monotonic()
    try:
        r = subprocess.run([holon] + args, capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        print(f"{name}: FAILED, still waiting after 60 s")
        failures.append(name)
        return
    took = time.monotonic() - start
    if writer:
        writer.join(timeout=35)
    ok = r.returncode in codes and expect in r.stdout + r.stderr
    print(f"{name}: exit {r.returncode} after {took:.1f} s" + ("" if ok else f"  FAILED (want {codes}, '{expect}')\n{r.stdout}{r.stderr}"))
    if not ok:
        failures.append(name)


read = lambda p: open(os.path.join(src, p)).read()
rules = os.path.join(src, "rules/library/planner_intermediate.holon")
start, target = read("examples/check/planner_start.txt"), os.path.join(src, "examples/check/planner_target.txt")
subprocess.run([holon, "plan", "--from", "box:4x4", "--to", "box:2x8", "--out", os.path.join(work, "out"), "--quiet", "--max-rounds", "3"], capture_output=True)
end = open(os.path.join(work, "out", "end.json")).read()

# Read once.
run("check --from FIFO", ["check", rules, "--region", "square:4x3", "--from", fifo, "--input", "target=" + target, "--timeout", "20"], {0}, start)
run("export --config FIFO", ["export", "--config", fifo, "--visiblesim", os.path.join(work, "w.xml")], {0}, end)
run("plan --rules FIFO", ["plan", "--rules", fifo, "--from", "box:4x4", "--to", "box:2x8", "--timeout", "20"], {0}, read("rules/library/planner_intermediate.holon"))
run("hex --from FIFO", ["hex", "--from", fifo, "--to", "circle", "--size", "12", "--timeout", "20"], {0, 1}, "\n".join(["...######..."] * 12) + "\n")
# A writer that comes late is waited for, within --timeout.
run("plan --from FIFO, late writer", ["plan", "--from", fifo, "--to", "box:2x2", "--timeout", "20"], {0}, "##\n##\n", delay=1.0)
# Nothing writes: --timeout ends the wait.
run("check FIFO rules, no writer", ["check", fifo, "--region", "square:3x3", "--timeout", "1"], {3}, expect="timeout ran out while holon waited for")
run("plan --from FIFO, no writer", ["plan", "--from", fifo, "--to", "box:2x2", "--timeout", "1"], {3})
# replay streams its plan: a FIFO with no writer waited for ever, and a late writer is read whole.
subprocess.run([holon, "plan", "--from", "box:3x2", "--to", "box:2x3", "--plan-out", os.path.join(work, "plan.jsonl"), "--quiet"], capture_output=True)
plan = open(os.path.join(work, "plan.jsonl")).read()
run("replay FIFO, no writer", ["replay", rules, fifo, "--timeout", "1"], {3}, expect="timeout ran out while holon waited for")
run("replay FIFO, late writer", ["replay", rules, fifo, "--timeout", "20"], {0}, plan, delay=1.0, expect="all 9 steps legal")
sys.exit(1 if failures else 0)
