#!/usr/bin/env python3
# Where a plan's transfers go (issue 28): reads a `holon plan --plan-out` file of a system with
# creators (planner_general1: a C is spent by `create`, made by `delete`, moved by `transfer`),
# follows every C from where it appears to where it is spent, and sorts each of its hops into
# toward or away: whether it brings the C nearer the cell that finally spends it. Distances are
# counted through the metamodules present at that moment and the target cells (every cell a C can
# still pass through or reach later), so a detour forced by cells not yet built counts as toward.
# Every away hop costs two transfers over a path that never turns back.
#
# Usage: transfer_waste.py PLAN.jsonl
# Prints the transfers, how many moved C's that were later spent, their toward and away hops, the
# sum over those C's of the distance from where each appeared to where it was spent (through the
# start and target cells), and the hops of C's never spent (surplus left resting).
import json
import sys
from collections import deque


def main(path):
    with open(path) as f:
        head = json.loads(f.readline())
        steps = [json.loads(line) for line in f if line.strip()]
    start = head['start']
    dimension = 3 if start['region'].startswith('cubic') else 2
    # The header's cells are region coordinates, the steps' the shapes': region = shape + offset.
    offset = start.get('offset', [0] * dimension)

    def shifted(at):
        return tuple(a - o for a, o in zip(at, offset))

    res = {shifted(c['at']): c['res'] for c in start['cells']}
    target = {shifted(t) for t in start.get('inputs', {}).get('target', [])}
    moves = [tuple(s * (k == d) for k in range(dimension)) for d in range(dimension) for s in (1, -1)]
    startCells = set(res)

    # First pass: every C's path, as (cell, step index) from where it appeared to where it is spent.
    at, paths, spentAt = {}, [], {}
    for cell, r in res.items():
        if r == 'C':
            at[cell] = len(paths)
            paths.append([(cell, -1)])
    transfers = 0
    now = dict(res)
    for index, step in enumerate(steps):
        cells = [tuple(c) for c in step['cells']]
        before = [now.get(c) for c in cells]
        if step['rule'] == 'transfer':
            transfers += 1
            giver, taker = cells if before[0] == 'C' else cells[::-1]
            token = at.pop(giver)
            at[taker] = token
            paths[token].append((taker, index))
            now[giver], now[taker] = 'D', 'C'
            continue
        for cell, after, was in zip(cells, step['after'], before):
            if not after:
                now.pop(cell, None)
                continue
            if was == 'C' and after['res'] != 'C':
                spentAt[at.pop(cell)] = cell
            if after['res'] == 'C' and was != 'C':
                at[cell] = len(paths)
                paths.append([(cell, index)])
            now[cell] = after['res']

    def distances(source, passable):
        seen, queue = {source: 0}, deque([source])
        while queue:
            x = queue.popleft()
            for m in moves:
                y = tuple(a + b for a, b in zip(x, m))
                if y in passable and y not in seen:
                    seen[y] = seen[x] + 1
                    queue.append(y)
        return seen

    # Second pass: replay occupancy; transfers do not change it, so one search per spending cell
    # serves every hop until the next creation or deletion.
    hops = sorted((index, path[k - 1][0], cell, spentAt[token]) for token, path in enumerate(paths) if token in spentAt
                  for k, (cell, index) in enumerate(path) if k > 0)
    occupied = set(res)
    cache = {}  # spending cell -> its distances through the cells passable now
    toward = away = 0
    h = 0
    for index, step in enumerate(steps):
        while h < len(hops) and hops[h][0] == index:
            _, a, b, site = hops[h]
            h += 1
            if site not in cache:
                cache[site] = distances(site, occupied | target)
            d = cache[site]
            if d.get(b, 1 << 30) > d.get(a, 1 << 30):
                away += 1
            else:
                toward += 1
        if step['rule'] != 'transfer':
            for cell, after in zip(step['cells'], step['after']):
                cell = tuple(cell)
                if bool(after) != (cell in occupied):
                    (occupied.add if after else occupied.discard)(cell)
                    cache.clear()
    whole = startCells | target
    direct = sum(distances(site, whole).get(paths[token][0][0], 0) for token, site in spentAt.items())
    resting = sum(len(path) - 1 for token, path in enumerate(paths) if token not in spentAt)
    print(f'transfers {transfers}')
    print(f'spent C\'s {len(spentAt)}: hops toward where each is spent {toward}, away {away}; '
          f'distance from where each appeared to where it was spent {direct}')
    print(f'C\'s never spent {len(paths) - len(spentAt)}: hops {resting}')
    if toward + away + resting != transfers:
        sys.exit('transfer_waste: the hops do not add up to the transfers; is this a planner_general1 plan?')


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit('usage: transfer_waste.py PLAN.jsonl')
    main(sys.argv[1])
