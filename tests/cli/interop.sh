#!/usr/bin/env bash
# Runs examples/interop/run.sh (the commands of docs/interop.md) into a scratch folder and reads what
# it wrote with readers of its own: Python's XML parser for the VisibleSim worlds (every module
# inside gridSize, each position once, the block problem's exact positions), a binvox decoder written
# from the format's description for the chair (the chair generator's 30 cells), and holon's own
# binvox and VisibleSim readers for round trips (the same bytes, the same world). Usage: interop.sh HOLON SOURCE_DIR
set -eu
holon=$1 src=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
HOLON=$holon OUT=$out bash "$src/examples/interop/run.sh"
"$holon" export --shape "$out/chair.binvox" --binvox "$out/chair_again.binvox" >/dev/null
cmp "$out/chair.binvox" "$out/chair_again.binvox"
# The block problem's world read back by holon (start and target) and written again: the same world,
# but for the first two comments, which name the shapes it was made from.
"$holon" export --shape "$out/blocks.xml" --target "$out/blocks.xml#target" --margin 1 --visiblesim "$out/blocks_again.xml" >/dev/null
diff <(tail -n +4 "$out/blocks.xml") <(tail -n +4 "$out/blocks_again.xml")
python3 - "$out" <<'PY'
import sys, xml.etree.ElementTree as ET
out = sys.argv[1]

def world(name):
    root = ET.parse(f"{out}/{name}").getroot()
    assert root.tag == "world", name
    grid = tuple(int(v) for v in root.get("gridSize").split(","))
    def cells(path):
        found = {}
        for e in root.iterfind(path):
            p = tuple(int(v) for v in e.get("position").split(","))
            assert all(0 <= p[k] < grid[k] for k in range(3)), (name, p, grid)
            assert p not in found, (name, "twice", p)
            found[p] = tuple(int(v) for v in e.get("color").split(","))
        return found
    return grid, root.find("blockList").get("blockSize"), cells("blockList/block"), cells("targetList/target[@format='grid']/cell")

# 1. box:6x3x2 -> box:3x3x4 at scale 2 is 12x6x4 -> 6x6x8 cells from (0,0,0); a margin of 1.
grid, size, blocks, targets = world("blocks.xml")
assert size == "10,10,10" and grid == (14, 8, 10), grid
assert set(blocks) == {(x + 1, y + 1, z + 1) for x in range(12) for y in range(6) for z in range(4)}
assert set(targets) == {(x + 1, y + 1, z + 1) for x in range(6) for y in range(6) for z in range(8)}
# 2. the counterexample's state 2: nine modules on square:4x3, a 2D world one layer thick.
grid, size, blocks, targets = world("counterexample.xml")
assert len(blocks) == 9 and grid[2] == 1 and not targets
# 3. hexanodes, one layer, 78 modules in three colours (the states M, C, H).
grid, size, blocks, targets = world("hex.xml")
assert size == "50,50,12.5" and grid[2] == 1 and len(blocks) == 78 and len(set(blocks.values())) == 3

# 4. the chair, decoded from the binvox description: header lines, then (value, count) pairs,
#    index = x*d*d + z*d + y.
data = open(f"{out}/chair.binvox", "rb").read()
header_end = data.index(b"data\n") + 5
header = data[:header_end].decode().split("\n")
assert header[0] == "#binvox 1"
d = int(header[1].split()[1])
voxels = []
for k in range(header_end, len(data), 2):
    voxels += [data[k]] * data[k + 1]
assert len(voxels) == d ** 3
filled = {(i // (d * d), i % d, i // d % d) for i, v in enumerate(voxels) if v}
n = 3
chair = {(x, y, z) for x in range(n) for y in range(n) for z in range(2 * n + 1)
         if (z < n and x in (0, n - 1) and y in (0, n - 1)) or z == n or (z > n and y == n - 1)}
assert filled == chair, sorted(filled ^ chair)
print("interop: the worlds and the binvox file read back as written")
PY
