// The goal structures and seeding recipes of seed 001 §V. The paper shows its cube and chair only in
// pictures; the voxel models here are choices that keep what the text says: a non-dense cube of four
// metamodules, a chair of six whose seeds 0-3 are the legs and 4-5 the back, metamodules starting
// about 20 Manhattan steps from the goal in a straight posture.
//
// Recipe file format (one run):
//   # comment
//   seed GROUP x,y,z x,y,z x,y,z x,y,z     the four cells, foot first (z = 0)
//   voxel x,y,z ...                        or the structure's cells, split into seeds (Voxels.cpp)
//   start x,y                              one per seed

#include "planner/roombots/Structures.h"

#include "planner/Random.h"
#include "rules/Error.h"
#include "rules/OutputFile.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <set>
#include <sstream>

namespace holon::planner::roombots {
namespace {

Seed leg(Cell foot, Cell inward, int group) {
    return Seed{{foot, foot + Cell{0, 0, 1}, foot + Cell{0, 0, 2}, foot + Cell{0, 0, 2} + inward}, group};
}
Seed post(Cell foot, int group) {
    return Seed{{foot, foot + Cell{0, 0, 1}, foot + Cell{0, 0, 2}, foot + Cell{0, 0, 3}}, group};
}

// The four legs in circular order; each L's top turns along the cube's top edge, so the legs' tops
// close the 3 x 3 ring at height 2.
std::array<Seed, 4> legs() {
    return {leg({0, 0, 0}, {1, 0, 0}, 0), leg({2, 0, 0}, {0, 1, 0}, 1), leg({2, 2, 0}, {-1, 0, 0}, 2), leg({0, 2, 0}, {0, -1, 0}, 3)};
}

std::vector<Cell> column(int x, int count, int y0) {
    std::vector<Cell> starts;
    for (int i = 0; i < count; ++i) starts.push_back({x, y0 + 3 * i, 0});
    return starts;
}

/// Each start moved by `min`..`max` fields (Manhattan) in a random direction, redrawn while it would
/// stand within one field of another metamodule.
std::vector<Cell> shifted(std::vector<Cell> starts, int min, int max, Random& random) {
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const Cell home = starts[i];
        for (int attempt = 0; attempt < 100; ++attempt) {
            const int length = min + static_cast<int>(random.below(max - min + 1));
            const int dx = static_cast<int>(random.below(length + 1)), dy = length - dx;
            starts[i] = home + Cell{random.below(2) ? dx : -dx, random.below(2) ? dy : -dy, 0};
            bool crowded = false;
            for (std::size_t k = 0; k < starts.size(); ++k)
                crowded |= k != i && std::abs(starts[k].x - starts[i].x) <= 1 && std::abs(starts[k].y - starts[i].y) <= 1;
            if (!crowded) break;
            starts[i] = home;
        }
    }
    return starts;
}

constexpr int kFloorReach = 500;  // the floor holon simulates is the box around seeds and starts
bool far(const Cell& c) { return std::abs(c.x) > kFloorReach || std::abs(c.y) > kFloorReach; }

Cell parseCell(const std::string& text, const std::string& where) {
    Cell c;
    char comma1 = 0, comma2 = 0;
    std::istringstream in(text);
    bool read = false;
    if (std::count(text.begin(), text.end(), ',') == 1) read = in >> c.x >> comma1 >> c.y && comma1 == ',' && in.peek() == EOF;
    else read = in >> c.x >> comma1 >> c.y >> comma2 >> c.z && comma1 == ',' && comma2 == ',' && in.peek() == EOF;
    if (!read) throw InputError(where + ": '" + text + "' is not a cell; write x,y,z (or x,y for a start)");
    // Bounded here, so that no later difference or absolute value of coordinates can overflow.
    for (int v : {c.x, c.y, c.z})
        if (v < -kFloorReach || v > kFloorReach) throw InputError(where + ": '" + text + "' lies more than " + std::to_string(kFloorReach) + " fields from the origin; move it closer");
    return c;
}

/// Checks the seeds alone and returns the cells they fill.
std::set<Cell> validateSeeds(const Recipe& recipe, const std::string& where) {
    if (recipe.seeds.empty()) throw InputError(where + ": no seeds; add lines `seed GROUP x,y,z x,y,z x,y,z x,y,z`");
    if (recipe.seeds.size() > 100) throw InputError(where + ": " + std::to_string(recipe.seeds.size()) + " seeds; holon roombots takes at most 100");
    for (const Seed& seed : recipe.seeds)
        if (far(seed.cells[0])) throw InputError(where + ": a seed lies more than 500 fields from the origin; move the structure closer");
    std::set<Cell> used;
    for (std::size_t i = 0; i < recipe.seeds.size(); ++i) {
        const auto& cells = recipe.seeds[i].cells;
        const std::string seed = where + ": seed " + std::to_string(i);
        if (cells[0].z != 0) throw InputError(seed + " must stand with its foot on the floor (z = 0)");
        for (int k = 0; k < 4; ++k) {
            if (cells[k].z < 0) throw InputError(seed + " goes below the floor");
            if (!used.insert(cells[k]).second) throw InputError(seed + " overlaps another seed at a cell");
            if (k > 0) {
                const Cell d = cells[k] - cells[k - 1];
                if (std::abs(d.x) + std::abs(d.y) + std::abs(d.z) != 1)
                    throw InputError(seed + ": cells " + std::to_string(k - 1) + " and " + std::to_string(k) + " are not face neighbours");
            }
        }
    }
    return used;
}

void validate(const Setting& s, const std::string& where) {
    const std::set<Cell> used = validateSeeds(s.recipe, where);
    if (s.starts.size() != s.recipe.seeds.size())
        throw InputError(where + ": " + std::to_string(s.recipe.seeds.size()) + " seeds but " + std::to_string(s.starts.size()) +
                         " starts; give one `start x,y` per seed");
    for (const Cell& start : s.starts) {
        if (far(start)) throw InputError(where + ": a start lies more than 500 fields from the origin; move it closer");
        if (used.count(start)) throw InputError(where + ": a start stands inside the structure");
    }
}

Setting parseFile(const std::string& path, const Budget& budget) {
    rules::OutputClaims::reading("the structure", path);
    const std::string text = rules::readTextFile(path);
    std::istringstream lines(text);
    std::string line;
    Setting s;
    s.recipe.name = path;
    std::vector<Cell> voxels;
    for (int number = 1; std::getline(lines, line); ++number) {
        const std::string where = path + ":" + std::to_string(number);
        std::istringstream in(line.substr(0, line.find('#')));
        std::string word;
        if (!(in >> word)) continue;
        if (word == "seed") {
            Seed seed;
            std::string cell;
            if (!(in >> seed.group) || seed.group < 0) throw InputError(where + ": `seed` needs a group number (0 or more) first");
            for (Cell& c : seed.cells) {
                if (!(in >> cell)) throw InputError(where + ": a seed lists four cells, foot first");
                c = parseCell(cell, where);
            }
            // What follows the four cells was dropped without a word (a fifth cell, a typo).
            if (in >> cell) throw InputError(where + ": '" + cell + "' after the seed's four cells; a seed is `seed GROUP x,y,z x,y,z x,y,z x,y,z`");
            s.recipe.seeds.push_back(seed);
        } else if (word == "voxel") {
            std::string cell;
            while (in >> cell) voxels.push_back(parseCell(cell, where));
        } else if (word == "start") {
            std::string cell;
            if (!(in >> cell)) throw InputError(where + ": `start` needs a cell x,y");
            // A start stands on the floor: x,y only (a z was set to 0 without a word), and nothing after.
            if (std::count(cell.begin(), cell.end(), ',') != 1) throw InputError(where + ": '" + cell + "': a start is a floor cell x,y, with no z");
            Cell c = parseCell(cell, where);
            if (in >> cell) throw InputError(where + ": '" + cell + "' after the start's cell; a start is `start x,y`");
            s.starts.push_back(c);
        } else {
            throw InputError(where + ": unknown line '" + word + "'; use `seed`, `voxel` or `start`");
        }
    }
    if (!voxels.empty()) {
        if (!s.recipe.seeds.empty()) throw InputError(path + ": give either `seed` lines or `voxel` lines, not both");
        s.recipe.seeds = seedsFromVoxels(voxels, path, budget);
    }
    return s;
}

Setting loadFile(const std::string& path, const Budget& budget) {
    Setting s = parseFile(path, budget);
    validate(s, path);
    return s;
}

}  // namespace

std::vector<Setting> loadScenario(const std::string& name, std::uint64_t seed, int runs, const Budget& budget) {
    Random random(seed);
    const auto l = legs();
    std::vector<Setting> settings;
    if (name == "cube") {
        // The paper's cube recipe is not given; the legs one after another around the ring.
        const Recipe recipe{"circular", {l[0], l[1], l[2], l[3]}};
        for (int run = 0; run < (runs > 0 ? runs : 3); ++run) settings.push_back({recipe, shifted(column(19, 4, -3), 1, 2, random)});
        return settings;
    }
    if (name == "chair") {
        const Seed backLeft = post({0, 3, 0}, 4), backRight = post({2, 3, 0}, 5);
        auto order = [&](const std::string& n, std::array<int, 4> legOrder, bool samePriority) {
            Recipe r{n, {}};
            for (int k = 0; k < 4; ++k) {
                Seed s = l[legOrder[k]];
                s.group = samePriority ? 0 : k;
                r.seeds.push_back(s);
            }
            r.seeds.push_back(backLeft), r.seeds.push_back(backRight);
            return r;
        };
        const auto starts = column(19, 6, -6);
        const std::array<Recipe, 4> recipes{order("circular", {0, 1, 2, 3}, false), order("cross-wise", {0, 2, 1, 3}, false),
                                            order("equal priority", {0, 1, 2, 3}, true), order("cross-wise shifted", {0, 2, 1, 3}, false)};
        for (int run = 0; run < (runs > 0 ? runs : 4); ++run)
            settings.push_back({recipes[run % 4], run % 4 == 3 ? shifted(starts, 0, 2, random) : starts});
        return settings;
    }
    const Setting file = loadFile(name, budget);
    for (int run = 0; run < (runs > 0 ? runs : 1); ++run)  // later runs from starts shifted by up to two fields
        settings.push_back({file.recipe, run == 0 ? file.starts : shifted(file.starts, 0, 2, random)});
    return settings;
}

Recipe loadRecipe(const std::string& path, const Recipe& structure, const Budget& budget) {
    const Setting s = parseFile(path, budget);  // its starts, if any, are not used
    validateSeeds(s.recipe, path);
    std::set<std::array<Cell, 4>> mine, theirs;
    for (const Seed& seed : s.recipe.seeds) mine.insert(seed.cells);
    for (const Seed& seed : structure.seeds) theirs.insert(seed.cells);
    if (mine != theirs)
        throw InputError(path + ": the recipe's seeds are not the structure's; a recipe orders the same " +
                         std::to_string(structure.seeds.size()) + " seeds (cells, foot first)");
    return s.recipe;
}

}  // namespace holon::planner::roombots
