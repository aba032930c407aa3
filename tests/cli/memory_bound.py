#!/usr/bin/env python3
"""check, path and diff stay within --memory on a large region: the rule engine on the region
(about 1.3 KB a cell for planner_intermediate) and the workers' buffers (a slot per rule instance)
count against it. export --config checks its estimate before it parses the configuration.

Usage: memory_bound.py HOLON WORKDIR LIBRARY

Before, neither was counted: check on square:400x400 with --memory 300 peaked at 603 MB, and with
--memory 16 the same; on the largest region check takes (4,194,304 cells) that is about 15 GB.
"""
import os, signal, subprocess, sys, threading, time

holon, work, lib = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
start = os.path.join(work, "start.txt")
with open(start, "w") as f:
    f.write("FF\nFF\n")
rules = os.path.join(lib, "planner_intermediate.holon")
common = ["--from", start, "--input", "target=all"]
failures = []


def run(name, args, code, most_mib, expect, most_seconds=60, signal_after=None):
    start_time = time.monotonic()
    p = subprocess.Popen([holon] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if signal_after is not None:
        threading.Timer(signal_after, lambda: p.send_signal(signal.SIGTERM)).start()
    out = p.stdout.read()
    _, status, usage = os.wait4(p.pid, 0)
    took = time.monotonic() - start_time
    rc = os.waitstatus_to_exitcode(status)
    if rc < 0:
        rc = 128 - rc  # killed by the signal itself, as a shell reports it
    peak = usage.ru_maxrss >> 10  # MiB
    ok = rc == code and peak <= most_mib and expect in out and took <= most_seconds
    print(f"{name}: exit {rc}, peak {peak} MiB (at most {most_mib}), {took:.1f} s (at most {most_seconds})" + ("" if ok else f"  FAILED\n{out[-2000:]}"))
    if not ok:
        failures.append(name)


# The engine alone is over the bound: refused before it is built, naming the region.
run("check square:200x200 --memory 16", ["check", rules, "--region", "square:200x200", "--memory", "16"] + common, 3, 40,
    "the rule engine on region square:200x200")
# The region's own tables are over the bound: refused before they are built (199 MiB under --memory 16).
run("check square:2000x2000 --memory 16", ["check", rules, "--region", "square:2000x2000", "--memory", "16"] + common, 3, 40,
    "region square:2000x2000 (4000000 cells) needs about")
# The engine fits, the workers' buffers do not: a memory stop before the first expansion.
run("check square:400x400 --memory 300", ["check", rules, "--region", "square:400x400", "--memory", "300"] + common, 3, 330, "stopped by memory")
run("path square:400x400 --memory 300", ["path", rules, "--region", "square:400x400", "--memory", "300", "--goal"] + common, 3, 330, "stopped by memory")
run("diff square:300x300 --memory 300", ["diff", rules, rules, "--region", "square:300x300", "--memory", "300"] + common, 3, 330, "stopped by memory")
# Building the engine on a large region polls --timeout and signals: --timeout 1 on square:1000x1000
# took 11.8 s (65 s on 2048x2048), and a SIGTERM during the build of path ended as "stopped by
# memory", exit 3.
run("check square:1000x1000 --timeout 1", ["check", rules, "--region", "square:1000x1000", "--timeout", "1"] + common, 3, 2000,
    "--timeout ran out while building the rule engine", most_seconds=4)
run("path square:1000x1000, SIGTERM during the build", ["path", rules, "--region", "square:1000x1000", "--memory", "2000", "--goal"] + common, 143, 2100,
    "terminated (SIGTERM)", signal_after=0.8)
# export --config: the memory check came after the JSON was parsed (three times, whole, for the
# names in it): a 45 MB configuration peaked at 651 MB under --memory 16.
big = os.path.join(work, "big.json")
# Written by a child: a forked child's peak counts its parent's pages before exec, and the text
# built here would be counted against holon.
subprocess.run([sys.executable, "-c", """import sys
cells = [[x, y] for x in range(500) for y in range(500)]
with open(sys.argv[1], "w") as f:
    f.write('{"system":"planner_intermediate","region":"square:500x500","inputs":{"target":' + str(cells).replace(" ", "") + '},"cells":[' +
            ",".join('{"at":[%d,%d],"label":"F"}' % (x, y) for x, y in cells) + "]}")
""", big], check=True)
run("export --config (11 MB) --memory 16", ["export", "--config", big, "--memory", "16", "--visiblesim", os.path.join(work, "big.xml")], 3, 50,
    "reading --config " + big)
sys.exit(1 if failures else 0)
