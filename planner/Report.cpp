// Output of `holon plan`: the plan (JSON Lines), completion over time like seed 000 Fig. 8
// (creations and deletions done as a fraction of |T \ S| and |S \ T|), and snapshots like Fig. 5
// (U white, P black, F blue; a dot marks a creator resource C).

#include "planner/Report.h"

#include "planner/Diagnosis.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Svg.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace holon::planner {

namespace {

double fraction(std::int64_t done, std::int64_t total) { return total == 0 ? 1.0 : double(done) / double(total); }

}  // namespace

const std::vector<std::string>& Report::outDirFiles() {
    // violation.itf.json is the monitor's trace, which the CLI writes there.
    static const std::vector<std::string> names{"summary.json", "completion.csv", "snapshot-*.svg", "end.json", "violation.itf.json"};
    return names;
}

Report::Report(const Problem& problem, const Execution& execution, ReportOptions options)
    : problem_(&problem), execution_(&execution), options_(std::move(options)) {
    if (!options_.planOut.empty()) {
        plan_.emplace(rules::OutputFile(options_.planOutOption, options_.planOut).open());
        // The first line makes the plan self-contained: what it starts from, target included.
        const rules::System& system = problem.model->system();
        // The keys in the order the JSON library dumps them, the start streamed a cell at a time.
        std::ostream& out = plan_->stream();
        out << R"({"plan":"holon","source":)" << nlohmann::json(system.sourceName).dump() << R"(,"start":)";
        writeConfiguration(out, problem, execution.cells());
        out << R"(,"system":)" << nlohmann::json(system.name).dump() << "}\n";
    }
    if (!options_.outDir.empty()) {
        rules::prepareOutputDir(options_.outOption, options_.outDir, outDirFiles());
        rules::removeEarlierOutputs(options_.outDir, outDirFiles());
        csv_.emplace(rules::OutputFile(options_.outOption, options_.outDir + "/completion.csv").open());
        csv_->stream() << "round,steps,creations,deletions,transfers,creation_completion,deletion_completion,planner_enabled,planner_held\n";
        rules::OutputFile(options_.outOption, options_.outDir + "/snapshot-start.svg").write(drawBoard(*problem_, execution_->cells(), "start"));
    }
}

Report::~Report() = default;

void Report::fired(std::int64_t anchor, int shape, const BoxEngine::Value*) {
    if (plan_) plan_->stream() << planLine(*problem_->engine, lastRound_ + 1, anchor, shape, execution_->cells().data()).dump() << '\n';
}

void Report::lost(std::int64_t cell) {
    if (plan_)
        plan_->stream() << nlohmann::json{{"round", lastRound_}, {"fault", "lose"}, {"cells", {rules::pointJson(problem_->model->lattice(), problem_->board->point(cell))}}}.dump()
                        << '\n';
}

void Report::roundEnd(const RunStats& stats) {
    lastRound_ = stats.rounds;
    const double created = fraction(stats.creations, problem_->toCreate), deleted = fraction(stats.deletions, problem_->toDelete);
    if (csv_ && (stats.steps != lastStep_)) {
        const Execution::Waiting waiting = execution_->waiting();
        csv_->stream() << stats.rounds << ',' << stats.steps << ',' << stats.creations << ',' << stats.deletions << ',' << stats.transfers << ',' << created << ','
                       << deleted << ',' << waiting.enabled << ',' << waiting.held << '\n';
        lastStep_ = stats.steps;
    }
    const double done = fraction(stats.creations + stats.deletions, problem_->toCreate + problem_->toDelete);
    if (!options_.outDir.empty() && nextQuarter_ < 4 && done >= nextQuarter_ * 0.25) snapshot(std::to_string(25 * nextQuarter_++) + "pct");
    if (options_.progressBar && done - lastBar_ >= 0.01) {
        lastBar_ = done;
        const int width = 40, filled = static_cast<int>(done * width);
        std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << static_cast<int>(done * 100) << "% round "
                  << stats.rounds << std::flush;
    }
}

void Report::finish(const RunStats& stats, std::int64_t transferLowerBound) {
    if (options_.progressBar) std::cerr << "\r" << std::string(70, ' ') << "\r" << std::flush;
    if (plan_) attempt([&] { plan_->commit(); });
    if (options_.outDir.empty()) return;
    snapshot("end");
    attempt([&] { csv_->commit(); });
    if (!stats.complete)
        attempt([&] {
            rules::OutputFile(options_.outOption, options_.outDir + "/end.json").write([&](std::ostream& out) {
                writeConfiguration(out, *problem_, execution_->cells());
                out << '\n';
            });
        });
    nlohmann::json summary = runSummary(*problem_, *execution_, stats, transferLowerBound);
    summary.update(extra_);
    attempt([&] { rules::OutputFile(options_.outOption, options_.outDir + "/summary.json").write(summary.dump(2) + '\n'); });
}

nlohmann::json runSummary(const Problem& problem, const Execution& execution, const RunStats& stats, std::int64_t transferLowerBound) {
    const auto [short_, shortCount] = cellsShortOfGoal(execution, 20);
    nlohmann::json unfinished = nlohmann::json::array();
    std::optional<BoardConfiguration> board;
    if (!short_.empty()) board.emplace(problem, execution.cells());
    for (std::int64_t i : short_) {
        nlohmann::json cell = rules::stateFields(*problem.model, execution.cells()[i]);
        cell["at"] = rules::pointJson(problem.model->lattice(), problem.board->point(i));
        cell["waits_on"] = waitingOn(problem, *board, i);
        unfinished.push_back(cell);
    }
    return {{"metamodules", stats.metamodules}, {"creations", stats.creations}, {"deletions", stats.deletions}, {"transfers", stats.transfers}, {"transfer_lower_bound", transferLowerBound >= 0 ? nlohmann::json(transferLowerBound) : nlohmann::json()}, {"rounds", stats.rounds}, {"steps", stats.steps}, {"relabels", stats.relabels}, {"evaluations", stats.evaluations}, {"seconds", stats.seconds}, {"complete", stats.complete}, {"stopped", stopReasonName(stats.stopped)}, {"interrupted", stats.stopped == StopReason::Interrupted}, {"cells_short_of_goal", shortCount}, {"short_of_goal", unfinished}};
}

void Report::snapshot(const std::string& label) {
    attempt([&] { rules::OutputFile(options_.outOption, options_.outDir + "/snapshot-" + label + ".svg").write(drawBoard(*problem_, execution_->cells(), label)); });
}

void Report::attempt(const std::function<void()>& write) {
    try {
        write();
    } catch (const InputError& e) {
        errors_.push_back(e.what());
    }
}

namespace {

// The region is the board's bounding box: a board starting far from the origin was written on a
// region reaching back to it (4 metamodules at x = 10^6 on 4 million cells; at x = 5 * 10^8 a
// false "out of memory").
Vec shiftOf(const Board& board) {
    const Vec lower = board.lower();
    return {-lower.x, -lower.y, -lower.z};
}

rules::Region regionOf(const Board& board) {
    const Vec size = board.lower() + board.extent() + shiftOf(board);
    return rules::Region::box(board.lattice(), {size.x, size.y, board.lattice().dimension() == 3 ? size.z : 1});
}

}  // namespace

BoardConfiguration::BoardConfiguration(const Problem& problem, const std::vector<BoxEngine::Value>& cells)
    : shift_(shiftOf(*problem.board)), region_(regionOf(*problem.board)), interpreter_(*problem.model, region_), configuration_(interpreter_.empty()) {
    problem.board->forEachInside([&](std::int64_t i, Vec p) {
        const int at = region_.indexOf(p + shift_);
        configuration_.cells[at] = cells[i];
        const std::uint8_t combo = problem.engine->combo(i);
        if (combo != BoxEngine::kOutside) configuration_.inputs[at] = problem.tables->comboInputs(combo);
    });
}

nlohmann::json planLine(const BoxEngine& engine, std::int64_t round, std::int64_t anchor, int shape, const BoxEngine::Value* cells) {
    const rules::Model& model = engine.tables().model();
    nlohmann::json points = nlohmann::json::array(), after = nlohmann::json::array();
    for (std::int64_t s : engine.cellSteps(shape)) {
        points.push_back(rules::pointJson(engine.board().lattice(), engine.board().point(anchor + s)));
        after.push_back(rules::stateFields(model, cells[anchor + s]));
    }
    return {{"round", round}, {"rule", model.rules()[engine.ruleOf(shape)].name}, {"cells", points}, {"after", after}};
}

void writeConfiguration(std::ostream& out, const Problem& problem, const std::vector<BoxEngine::Value>& cells) {
    const BoardConfiguration board(problem, cells);
    rules::writeConfigJson(out, board.interpreter(), board.configuration(), board.shift() != Vec{} ? rules::pointJson(problem.board->lattice(), board.shift()) : nlohmann::json());
}

std::pair<std::vector<std::int64_t>, std::int64_t> cellsShortOfGoal(const Execution& execution, std::size_t limit) {
    std::vector<std::int64_t> some;
    std::int64_t count = 0;
    const auto& cells = execution.cells();
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (!execution.atGoal(static_cast<std::int64_t>(i), cells[i])) {
            ++count;
            if (some.size() < limit) some.push_back(static_cast<std::int64_t>(i));
        }
    return {some, count};
}

std::string drawBoard(const Problem& problem, const std::vector<BoxEngine::Value>& cells, const std::string& title) {
    const Board& board = *problem.board;
    const rules::Alphabet& alphabet = problem.model->alphabet();
    const PlannerSchema& schema = problem.schema;
    const bool is3d = board.lattice().dimension() == 3;
    const Vec ext = board.extent();
    // Every layer of a 3D board, in rows of at most 8 slices; as in the checker's pictures
    // (checker/Draw.h, rules/ConfigIo.h) x runs right and y down the page, so a shape drawn as
    // ASCII art appears as drawn. Large boards are sampled in x and y (never in z) to keep the
    // picture near 250,000 cells and 1200 pixels across.
    const int layers = is3d ? ext.z : 1, columns = std::min(layers, 8), rows = (layers + columns - 1) / columns;
    const double cellsShown = double(ext.x) * ext.y * layers;
    const int sample = std::max(1, static_cast<int>(std::ceil(std::sqrt(cellsShown / 250000.0))));
    const int w = (ext.x + sample - 1) / sample, h = (ext.y + sample - 1) / sample;
    const double px = std::clamp(1200.0 / (double(std::max(w, h)) * columns), 2.0, 24.0);
    const double gapX = is3d ? std::max(px * 2, 12.0) : 0, gapY = is3d ? 16 : 0;
    const double width = (w * px + gapX) * columns + 10, top = 25, legendTop = top + rows * (h * px + gapY) + 10;
    const rules::SvgAttrs font = {{"font-family", "sans-serif"}, {"font-size", 11}};
    rules::Svg svg;
    svg.text(5, 16, title + (sample > 1 ? " (every " + std::to_string(sample) + "th cell in x and y)" : std::string()), {{"font-family", "sans-serif"}, {"font-size", 13}});
    const int inTarget = problem.tables->comboIndex(1u << schema.target);
    constexpr const char *kU = "#ffffff", *kP = "#222222", *kF = "#3d6fb0", *kTarget = "#e8eef6", *kCreator = "#e07020";
    const rules::SvgAttr outline("stroke", "#888"), outlineWidth("stroke-width", px > 4 ? 0.5 : 0);
    for (int z = 0; z < layers; ++z) {
        const double ox = 5 + (z % columns) * (w * px + gapX), oy = top + (z / columns) * (h * px + gapY) + (is3d ? 12 : 0);
        if (is3d) svg.text(ox, oy - 3, "z=" + std::to_string(z + board.lower().z), {{"font-size", 10}, {"font-family", "sans-serif"}});
        for (int y = 0; y < ext.y; y += sample)
            for (int x = 0; x < ext.x; x += sample) {
                const std::int64_t i = board.index(board.lower() + Vec{x, y, z});
                const double cx = ox + (x / sample) * px, cy = oy + (y / sample) * px;
                const BoxEngine::Value v = cells[i];
                if (!v) {
                    if (problem.engine->combo(i) == inTarget) svg.rect(cx, cy, px, px, {{"fill", kTarget}});
                    continue;
                }
                const auto& f = alphabet.fields(v);
                const int label = f[schema.label];
                svg.rect(cx, cy, px, px, {{"fill", label == schema.final ? kF : label == schema.path ? kP
                                                                                                     : kU},
                                          outline,
                                          outlineWidth});
                if (schema.resource >= 0 && f[schema.resource] != schema.full && px >= 4) svg.circle(cx + px / 2, cy + px / 2, px / 4, {{"fill", kCreator}});
            }
    }
    // The legend: what each colour means, and the axes.
    const rules::Field& labels = problem.model->system().fields[static_cast<std::size_t>(schema.label)];
    const std::pair<const char*, std::string> keys[] = {{kU, labels.values[static_cast<std::size_t>(schema.unknown)] + " (undecided)"},
                                                        {kP, labels.values[static_cast<std::size_t>(schema.path)] + " (path: to be deleted)"},
                                                        {kF, labels.values[static_cast<std::size_t>(schema.final)] + " (final)"},
                                                        {kTarget, "empty target cell"}};
    double lx = 5;
    for (const auto& [fill, text] : keys) {
        svg.legend(lx, legendTop, text, {{"fill", fill}, outline, {"stroke-width", 0.5}});
        lx += 24 + 6.2 * static_cast<double>(text.size());
    }
    if (schema.resource >= 0) {
        svg.circle(lx + 7, legendTop + 7, 4, {{"fill", kCreator}});
        svg.text(lx + 18, legendTop + 11, "dot: creator resource", font);
    }
    svg.text(5, legendTop + 32, "x to the right, y down the page from (" + std::to_string(board.lower().x) + "," + std::to_string(board.lower().y) + ") at the top left" + (is3d ? "; one picture per layer z" : ""),
             font);
    return svg.document(std::max(width, 560.0), legendTop + 42);
}

}  // namespace holon::planner
