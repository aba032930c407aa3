// Output of `holon plan`: the plan (JSON Lines), completion over time like seed 000 Fig. 8
// (creations and deletions done as a fraction of |T \ S| and |S \ T|), and snapshots like Fig. 5
// (U white, P black, F blue; a dot marks a creator resource C).

#include "planner/Report.h"

#include "planner/Diagnosis.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>

namespace holon::planner {

namespace {

double fraction(std::int64_t done, std::int64_t total) { return total == 0 ? 1.0 : double(done) / double(total); }

}  // namespace

Report::Report(const Problem& problem, const Execution& execution, ReportOptions options)
    : problem_(&problem), execution_(&execution), options_(std::move(options)) {
    if (!options_.planOut.empty()) {
        plan_.emplace(rules::OutputFile(options_.planOutOption, options_.planOut).open());
        // The first line makes the plan self-contained: what it starts from, target included.
        const rules::System& system = problem.model->system();
        plan_->stream() << nlohmann::json{{"plan", "holon"}, {"system", system.name}, {"source", system.sourceName},
                                          {"start", configurationJson(problem, execution.cells())}}
                               .dump()
                        << '\n';
    }
    if (!options_.outDir.empty()) {
        rules::prepareOutputDir(options_.outOption, options_.outDir);
        csv_.emplace(rules::OutputFile(options_.outOption, options_.outDir + "/completion.csv").open());
        csv_->stream() << "round,steps,creations,deletions,transfers,creation_completion,deletion_completion\n";
        rules::OutputFile(options_.outOption, options_.outDir + "/snapshot-start.svg").write(drawBoard(*problem_, execution_->cells(), "start"));
    }
}

Report::~Report() = default;

void Report::fired(std::int64_t anchor, int shape, const BoxEngine::Value*) {
    if (!plan_) return;
    const rules::Model& model = *problem_->model;
    const BoxEngine& engine = *problem_->engine;
    nlohmann::json cells = nlohmann::json::array(), states = nlohmann::json::array();
    for (std::int64_t s : engine.cellSteps(shape)) {
        cells.push_back(rules::pointJson(model.lattice(), problem_->board->point(anchor + s)));
        states.push_back(rules::stateFields(model, execution_->cells()[anchor + s]));
    }
    plan_->stream() << nlohmann::json{{"round", lastRound_ + 1}, {"rule", model.rules()[engine.ruleOf(shape)].name}, {"cells", cells}, {"after", states}}.dump() << '\n';
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
        csv_->stream() << stats.rounds << ',' << stats.steps << ',' << stats.creations << ',' << stats.deletions << ',' << stats.transfers << ',' << created << ','
              << deleted << '\n';
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
    if (!stats.complete) attempt([&] { rules::OutputFile(options_.outOption, options_.outDir + "/end.json").write(configurationJson(*problem_, execution_->cells()).dump() + '\n'); });
    const auto [short_, shortCount] = cellsShortOfGoal(*execution_, 20);
    nlohmann::json unfinished = nlohmann::json::array();
    std::optional<BoardConfiguration> board;
    if (!short_.empty()) board.emplace(*problem_, execution_->cells());
    for (std::int64_t i : short_) {
        nlohmann::json cell = rules::stateFields(*problem_->model, execution_->cells()[i]);
        cell["at"] = rules::pointJson(problem_->model->lattice(), problem_->board->point(i));
        cell["waits_on"] = waitingOn(*problem_, *board, i);
        unfinished.push_back(cell);
    }
    nlohmann::json summary = {{"metamodules", stats.metamodules}, {"creations", stats.creations}, {"deletions", stats.deletions},
                              {"transfers", stats.transfers}, {"transfer_lower_bound", transferLowerBound >= 0 ? nlohmann::json(transferLowerBound) : nlohmann::json()},
                              {"rounds", stats.rounds}, {"steps", stats.steps}, {"seconds", stats.seconds}, {"complete", stats.complete},
                              {"stopped", stats.stopped}, {"interrupted", stats.stopped == "interrupted"},
                              {"cells_short_of_goal", shortCount}, {"short_of_goal", unfinished}};
    summary.update(extra_);
    attempt([&] { rules::OutputFile(options_.outOption, options_.outDir + "/summary.json").write(summary.dump(2) + '\n'); });
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

Vec shiftOf(const Board& board) {
    const Vec lower = board.lower();
    return {std::max(0, -lower.x), std::max(0, -lower.y), std::max(0, -lower.z)};
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

nlohmann::json configurationJson(const Problem& problem, const std::vector<BoxEngine::Value>& cells) {
    const BoardConfiguration board(problem, cells);
    nlohmann::json j = rules::configToJson(board.interpreter(), board.configuration());
    if (board.shift() != Vec{}) j["offset"] = rules::pointJson(problem.board->lattice(), board.shift());
    return j;
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
    const int slices = is3d ? std::min(ext.z, 12) : 1;
    // Large boards are sampled: at most ~600 cells across per slice.
    const int sample = std::max(1, std::max(ext.x, ext.y) * slices / 600 + 1);
    const double px = std::clamp(600.0 / (double(std::max(ext.x, ext.y)) / sample * slices), 2.0, 24.0);
    const int w = (ext.x + sample - 1) / sample, h = (ext.y + sample - 1) / sample;
    const double gap = is3d ? px * 2 : 0;
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << (w * px + gap) * slices + 10 << "\" height=\"" << h * px + 30 << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"5\" y=\"16\" font-family=\"sans-serif\" font-size=\"13\">" << title
        << "</text>\n";
    const int inTarget = problem.tables->comboIndex(1u << schema.target);
    for (int s = 0; s < slices; ++s) {
        const int z = is3d ? s * ext.z / slices : 0;
        const double ox = 5 + s * (w * px + gap), oy = 25;
        for (int y = 0; y < ext.y; y += sample)
            for (int x = 0; x < ext.x; x += sample) {
                const std::int64_t i = board.index(board.lower() + Vec{x, y, z});
                const double cx = ox + (x / sample) * px, cy = oy + (h - 1 - y / sample) * px;
                const bool target = problem.engine->combo(i) == inTarget;
                const BoxEngine::Value v = cells[i];
                if (!v) {
                    if (target) svg << "<rect x=\"" << cx << "\" y=\"" << cy << "\" width=\"" << px << "\" height=\"" << px << "\" fill=\"#e8eef6\"/>\n";
                    continue;
                }
                const auto& f = alphabet.fields(v);
                const int label = f[schema.label];
                const char* fill = label == schema.final ? "#3d6fb0" : label == schema.path ? "#222222" : "#ffffff";
                svg << "<rect x=\"" << cx << "\" y=\"" << cy << "\" width=\"" << px << "\" height=\"" << px << "\" fill=\"" << fill
                    << "\" stroke=\"#888\" stroke-width=\"" << (px > 4 ? 0.5 : 0) << "\"/>\n";
                if (schema.resource >= 0 && f[schema.resource] != schema.full && px >= 4)
                    svg << "<circle cx=\"" << cx + px / 2 << "\" cy=\"" << cy + px / 2 << "\" r=\"" << px / 4 << "\" fill=\"#e07020\"/>\n";
            }
        if (is3d) svg << "<text x=\"" << ox << "\" y=\"" << oy + h * px + 0 << "\" font-size=\"10\" font-family=\"sans-serif\">z=" << z + board.lower().z << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace holon::planner
