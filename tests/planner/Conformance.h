#pragma once
// The back-end conformance harness (OMPL's one harness for every planner): a back-end runs under a
// planner::Recorder, and every rule instance it reports is replayed through the reference
// interpreter on a mirror of the ensemble it writes. A run conforms when each reported instance is
// enabled in the mirror (left side and guard; a legal step where the system has constraints),
// each instance changes exactly what the interpreter's rewrite changes, no cell changes without a
// reported instance (the ensemble before each instance, and at each checkpoint, equals the
// mirror), and every rule comes from a system the back-end claims to run, each of which fires.
// Big runs are sampled: `window` instances in a row are replayed out of every `period`, the mirror
// taken afresh from the ensemble at the start of each window.

#include "planner/Recorder.h"
#include "planner/Replay.h"

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace holon::test {

class Conformance {
public:
    Conformance(std::vector<std::string> claimed, std::int64_t period, std::int64_t window)
        : claimed_(std::move(claimed)), period_(period), window_(window), recorder_([this](const planner::Applied& a) { heard(a); }) {}

    /// Compares every mirror in step with the ensemble it follows; call while the back-end lives.
    void checkpoint() {
        for (auto& [key, m] : mirrors_)
            if (m.synced && fault_.empty()) compare(m, read(m), "at a checkpoint");
    }
    /// The first fault, or "" when the run conformed.
    std::string verdict() const {
        if (!fault_.empty()) return fault_;
        for (const std::string& s : claimed_)
            if (!fired_.count(s)) return "the back-end claims to run " + s + " but applied none of its rules";
        return "";
    }
    std::int64_t replayed() const { return replayed_; }

private:
    /// One ensemble: the region the interpreter sees it as, and the mirror the replay keeps.
    struct Mirror {
        const rules::Region* region = nullptr;
        std::unique_ptr<rules::Region> ownRegion;  // a compiled engine's board as a box region
        std::vector<std::int64_t> boardOf;         // region cell -> board index (compiled engines)
        const planner::BoxEngine::Value* cells = nullptr;
        const rules::Configuration* configuration = nullptr;
        std::vector<rules::CellValue> state;
        bool synced = false;
        std::int64_t heard = 0;
    };

    std::vector<rules::CellValue> read(const Mirror& m) const {
        if (m.configuration) return m.configuration->cells;
        std::vector<rules::CellValue> out(m.boardOf.size());
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = m.cells[m.boardOf[i]];
        return out;
    }

    void compare(const Mirror& m, const std::vector<rules::CellValue>& now, const std::string& when) {
        for (std::size_t i = 0; i < now.size(); ++i)
            if (now[i] != m.state[i]) {
                const rules::Vec p = m.region->cell(static_cast<int>(i));
                fault_ = "cell (" + std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(p.z) + ") holds state " +
                         std::to_string(now[i]) + " " + when + ", but the rule instances replayed give " + std::to_string(m.state[i]) +
                         ": a write no rule instance explains";
                return;
            }
    }

    void heard(const planner::Applied& a) {
        if (!fault_.empty()) return;
        const rules::Model& model = a.engine ? a.engine->tables().model() : a.interpreter->model();
        const std::string& system = model.system().name;
        fired_.insert(system);
        if (std::find(claimed_.begin(), claimed_.end(), system) == claimed_.end()) {
            fault_ = "a rule of " + system + " fired, a system the back-end does not claim to run";
            return;
        }
        const void* key = a.engine ? static_cast<const void*>(a.cells) : static_cast<const void*>(a.configuration);
        Mirror& m = mirrors_[key];
        if (!m.region) setUp(m, a);
        if (m.heard++ % period_ >= window_) {
            m.synced = false;
            return;
        }
        const std::vector<rules::CellValue> now = read(m);
        if (m.synced) compare(m, now, "before an instance of " + model.rules()[model.shapes()[a.engine ? a.shape : a.instance.shape].rule].name);
        if (!fault_.empty()) return;
        rules::Configuration config{now, a.configuration ? a.configuration->inputs : inputs(m, *a.engine)};
        const rules::Instance instance = a.engine ? rules::Instance{a.shape, a.engine->board().point(a.anchor) - a.engine->board().lower() -
                                                                                 model.shapes()[a.shape].offsets[0]}
                                                  : a.instance;
        const rules::Interpreter& in = interpreter(m, model);
        const std::string name = model.rules()[model.shapes()[instance.shape].rule].name;
        if (const planner::StepFault f = planner::replayStep(in, config, instance); f != planner::StepFault::None) {
            fault_ = system + ": rule " + name + " fired, but " + planner::describe(f);
            return;
        }
        m.state = std::move(config.cells);
        m.synced = true;
        ++replayed_;
    }

    void setUp(Mirror& m, const planner::Applied& a) {
        if (a.configuration) {
            m.region = &a.interpreter->region(), m.configuration = a.configuration;
            return;
        }
        const planner::Board& board = a.engine->board();
        m.ownRegion = std::make_unique<rules::Region>(rules::Region::box(board.lattice(), board.extent()));
        m.region = m.ownRegion.get(), m.cells = a.cells;
        for (int i = 0; i < m.region->size(); ++i) m.boardOf.push_back(board.index(m.region->cell(i) + board.lower()));
    }

    std::vector<std::uint32_t> inputs(const Mirror& m, const planner::BoxEngine& engine) {
        auto& in = inputs_[{&m, &engine}];
        if (in.empty())
            for (std::int64_t b : m.boardOf) {
                const std::uint8_t c = engine.combo(b);
                in.push_back(c == planner::BoxEngine::kOutside ? 0u : engine.tables().comboInputs(c));
            }
        return in;
    }

    const rules::Interpreter& interpreter(const Mirror& m, const rules::Model& model) {
        auto& in = interpreters_[{&m, &model}];
        if (!in) in = std::make_unique<rules::Interpreter>(model, *m.region);
        return *in;
    }

    std::vector<std::string> claimed_;
    std::int64_t period_, window_;
    std::map<const void*, Mirror> mirrors_;
    std::map<std::pair<const Mirror*, const planner::BoxEngine*>, std::vector<std::uint32_t>> inputs_;
    std::map<std::pair<const Mirror*, const rules::Model*>, std::unique_ptr<rules::Interpreter>> interpreters_;
    std::set<std::string> fired_;
    std::string fault_;
    std::int64_t replayed_ = 0;
    planner::Recorder recorder_;
};

}  // namespace holon::test
