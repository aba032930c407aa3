#!/usr/bin/env python3
"""verify stops within its limits: no Z3 context is made after the deadline, and none that ran out
of memory is freed (Z3 takes minutes to free one).

Usage: verify_limits.py HOLON WORKDIR LIBRARY

- 300 invariants with --timeout 2: every obligation after the deadline made a context and kept
  it, 13 MB each: 3.9 GB and 9 s for a 5 s budget (3,000 invariants: the machine ran out, no table).
- planner_intermediate on square:14x14 with --memory 300: the obligation ran out of memory in 1 s,
  and freeing its context took 54 s before the exit (square:20x20: minutes, deaf to signals).
- progress --reach with --obligation-timeout 2: the invariants it assumes were proved first, each
  with a budget of its own, and that time was in no row (the table said 2.9 s of a 5 s run).
"""
import os, re, resource, subprocess, sys, time

holon, work, lib = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
failures = []


def run(name, args, code, most_seconds, most_mib, expect):
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.monotonic()
    r = subprocess.run([holon] + args, capture_output=True, text=True, timeout=300)
    took = time.monotonic() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss >> 10  # of any child so far, MiB
    ok = r.returncode == code and took <= most_seconds and peak <= most_mib and expect in r.stdout
    print(f"{name}: exit {r.returncode}, {took:.1f} s (at most {most_seconds}), peak {peak} MiB (at most {most_mib})" + ("" if ok else f"  FAILED\n{r.stdout[-2000:]}{r.stderr[-2000:]}"))
    if not ok:
        failures.append(name)


many = os.path.join(work, "many.holon")
with open(many, "w") as f:
    f.write("system manyp\nlattice square2d\nstates M\nrule r: M@(0,0) _@(1,0) => _ M\n")
    for i in range(300):
        f.write(f"invariant p{i}: count(#) <= {i + 5}\n")
run("300 invariants, --timeout 2", ["verify", many, "--region", "square:3x3", "--timeout", "2"], 3, 8, 1000, "p299")
run("square:14x14 --memory 300", ["verify", os.path.join(lib, "planner_intermediate.holon"), "--region", "square:14x14", "--memory", "300", "--property", "progress"], 3, 10, 2000,
    "out of memory")
examples = os.path.join(lib, "..", "..", "examples", "verify")
start = time.monotonic()
r = subprocess.run([holon, "verify", os.path.join(lib, "planner_general2.holon"), "--region", "square:3x2", "--property", "progress", "--reach", "--from",
                    os.path.join(examples, "general_start.json"), "--input", "target=" + os.path.join(examples, "general_target.txt"), "--obligation-timeout", "2"],
                   capture_output=True, text=True, timeout=300)
took = time.monotonic() - start
shown = sum(int(ms) for ms in re.findall(r"^  \S+ +\S+ +(\d+) ms", r.stdout, re.M)) / 1000
ok = r.returncode in (0, 1, 3) and shown >= 0.8 * took
print(f"progress --reach, --obligation-timeout 2: exit {r.returncode}, {took:.1f} s, the table shows {shown:.1f} s (at least 80 %)" + ("" if ok else f"  FAILED\n{r.stdout[-2000:]}"))
if not ok:
    failures.append("reach time")
sys.exit(1 if failures else 0)
