#pragma once
// What the browser viewer shows, whatever it was read from: the cells of a lattice region, a table
// of cell states (each with its fields, colour and text), the inputs, the start configuration and
// the steps, each a list of cells that change and the cells its rule instances only looked at.
// Readers (Readers.h) fill it from an ITF trace, a plan, a hex run or a Roombots run; Page.h turns it
// into one self-contained HTML file.

#include "rules/Lattice.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace holon::viewer {

using rules::Vec;

struct Run {
    /// A cell state as the page shows it; state 0 is the empty cell.
    struct State {
        std::string key;     // the fields as compact JSON with sorted keys: {"label":"P"}
        std::string colour;  // its fill, as the SVG pictures fill it
        std::string text;    // the values written in the cell
    };
    struct Input {
        std::string name, colour;
        std::vector<int> cells;  // indices into cells
    };
    struct Step {
        std::string label;
        std::vector<std::pair<int, int>> changes;  // (cell, new state)
        std::vector<int> context;                  // cells a rule instance looked at but left alone
        std::vector<int> marked;                   // cells a violated property points at
    };
    std::string kind;  // "trace", "plan", "hex", "roombots"
    std::string title;
    std::vector<std::string> notes;  // lines shown under the title
    rules::LatticeKind lattice = rules::LatticeKind::Square2D;
    std::vector<Vec> cells;
    std::vector<State> states{{"", "#ffffff", ""}};
    /// What each fill colour means, in order: (colour, label).
    std::vector<std::pair<std::string, std::string>> legend;
    std::vector<Input> inputs;
    std::vector<int> start;     // state per cell
    std::vector<Step> steps;    // steps[0] is the start: no changes
    int violation = -1;         // the first step at which a property is violated; -1: none
    int sampled = 1;            // each step shown stands for this many steps of the run (1: every step)
    std::int64_t runSteps = 0;  // steps in the run, before sampling

    /// The index of a state with these fields (compact JSON, sorted keys), added when new.
    int state(const std::string& key, const std::string& colour, const std::string& text);
};

/// Limits past which the viewer samples or refuses (docs/viewer.md): a page shows at most kMaxCells
/// cells (more: LimitError) and kMaxChanges cell changes over all its steps; a run with more
/// changes is shown every g-th step, g as small as keeps the changes within the limit.
constexpr std::int64_t kMaxCells = 4'000'000;
constexpr std::int64_t kMaxChanges = 4'000'000;
/// The largest input file the viewer reads (a plan of 10^6 metamodules is about 250 MB).
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{2} << 30;
/// The memory a JSON value read whole takes per byte of its text, an upper bound (readRun).
constexpr std::uint64_t kBytesPerJsonByte = 40;

/// Merges runs of `g` consecutive steps into one (labels of the first and last, changes to their
/// net effect, context of all), g the smallest power of 2 that brings the changes within
/// `maxChanges`; records g in run.sampled and the run's own step count in run.runSteps.
void sample(Run& run, std::int64_t maxChanges = kMaxChanges);

/// The configuration after step k (0: the start).
std::vector<int> configurationAt(const Run& run, std::size_t k);

}  // namespace holon::viewer
