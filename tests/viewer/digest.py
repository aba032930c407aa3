#!/usr/bin/env python3
"""The digest of a run's configuration at a step, computed from the input file alone (no holon code):
what holon's viewer page must show in #digest at #step=K (docs/viewer.md). Occupied cells, each as
"x,y,z FIELDS" (FIELDS: the state's fields as compact JSON, keys sorted), sorted and joined by
newlines; FNV-1a (32 bits) over that text; then the count of occupied cells.

usage: digest.py INPUT STEP      (STEP: a number, or "last")
prints: DIGEST COUNT, and the number of steps on a second line
"""
import json
import sys


def key(fields):
    return json.dumps(fields, sort_keys=True, separators=(",", ":"), ensure_ascii=False)


def point(p):
    if isinstance(p, dict):
        p = p["#tup"]
    return (p[0], p[1], p[2] if len(p) == 3 else 0)


def itf_steps(itf):
    for state in itf["states"]:
        yield {point(at): key(fields) for at, fields in state["cells"]["#map"]}


def lines_steps(first, rest):
    start = first["start"]
    offset = point(start.get("offset", [0, 0, 0]))
    now = {}
    for cell in start["cells"]:
        fields = {k: v for k, v in cell.items() if k != "at"}
        now[point(cell["at"])] = key(fields)
    yield dict(now)
    round_ = None
    for line in rest:
        if not line.strip():
            continue
        j = json.loads(line)
        if round_ is not None and j["round"] != round_:
            yield dict(now)
        round_ = j["round"]
        after = j.get("after") or [{} for _ in j["cells"]]
        for at, fields in zip(j["cells"], after):
            p = point(at)
            p = (p[0] + offset[0], p[1] + offset[1], p[2] + offset[2])
            if "fault" in j or not fields:
                now.pop(p, None)
            else:
                now[p] = key(fields)
    if round_ is not None:
        yield dict(now)


def configurations(path):
    with open(path, encoding="utf-8") as f:
        first = f.readline()
        try:
            head = json.loads(first)
            if isinstance(head, dict) and "states" not in head:
                return list(lines_steps(head, f))
        except json.JSONDecodeError:
            pass
        f.seek(0)
        return list(itf_steps(json.load(f)))


def digest(config):
    text = "\n".join(sorted("%d,%d,%d %s" % (p[0], p[1], p[2], k) for p, k in config.items()))
    h = 0x811C9DC5
    for ch in text:  # the page hashes UTF-16 code units: the same for holon's ASCII names
        h = ((h ^ ord(ch)) * 16777619) & 0xFFFFFFFF
    return "%08x %d" % (h, len(config))


if __name__ == "__main__":
    configs = configurations(sys.argv[1])
    k = len(configs) - 1 if sys.argv[2] == "last" else int(sys.argv[2])
    print(digest(configs[k]))
    print(len(configs))
