#pragma once
// `holon check`: explore a system's reconfiguration graph on a bounded region and decide its
// properties with evidence.

#include "checker/Explorer.h"
#include "checker/Verdict.h"
#include "rules/Interpreter.h"

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace holon::checker {

struct CheckOptions {
    Limits limits;
    bool all = false;                           // every legal configuration instead of the reachable ones
    std::vector<rules::Configuration> initial;  // used when !all
    std::vector<std::uint32_t> inputs;          // per cell; with --all, the problem's inputs
    std::vector<std::string> properties;        // empty: all of them
    std::function<void(const ExploreStats&)> onProgress;
};

struct CheckReport {
    std::string system, region;
    ExploreStats stats;
    int components = -1;  // -1: not computed
    std::size_t bytesPerState = 0;
    std::vector<PropertyResult> properties;
    bool violated() const;
    /// Every property's verdict combined: a violation wins, then unknown.
    Verdict overall() const;
    nlohmann::json toJson() const;
};

/// The names `--property` accepts for a system: its declared properties and "deadlock".
std::vector<std::string> checkableProperties(const rules::System& system);

/// The engine and the explored graph, kept after a check for drawing and export.
struct Exploration {
    std::unique_ptr<rules::Engine> engine;
    std::unique_ptr<Explorer> explorer;
};

/// The engine of an exploration on `region`, within the memory bound: refused before it is built
/// (LimitError, exit 3) when its estimate (rules::Engine::bytesFor) is over limits.memoryBytes;
/// the bytes it holds are taken off limits.memoryBytes, which is then what the exploration has.
std::unique_ptr<rules::Engine> engineWithin(const rules::Model& model, const rules::Region& region, const std::vector<std::uint32_t>& inputs, Limits& limits);
/// The set-up of a check, shared with diff (checker/Diff.h): the engine on the region (engineWithin
/// `limits`), with the inputs of the first initial configuration (options.inputs with `all` or no
/// initial one).
std::unique_ptr<rules::Engine> checkEngine(const rules::Model& model, const rules::Region& region, const CheckOptions& options, Limits& limits);
/// An explorer of `engine` with `xo`, given the starts `options` says: every legal configuration,
/// or the initial configurations, each legal (else InputError).
std::unique_ptr<Explorer> startExplorer(const rules::Engine& engine, const CheckOptions& options, Explorer::Options xo);

/// Runs the exploration and every selected property. Every trace returned has been replayed
/// through the reference interpreter (its result's `confirmation`, witness["replayed"]): one that
/// does not replay is a bug in holon. Throws InputError for bad input (an unknown property, an
/// illegal initial configuration).
CheckReport check(const rules::Model& model, const rules::Region& region, const CheckOptions& options, Exploration* keep = nullptr);

}  // namespace holon::checker
