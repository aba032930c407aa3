#pragma once
// What a metamodule can tell from its own cells about the resources the planner asks for (seed
// 000 §IV-B): whether a creation or deletion it takes part in waits for it to be heavier (it needs
// a C) or lighter (it needs a D). Shared by the allocators that route resources to those demands.
// Which resource is heavy or light, and which rules create or delete, is read off the compiled
// rule tables: nothing here names a rule of a particular system.

#include "planner/Problem.h"

#include <deque>
#include <vector>

namespace holon::planner {

class Execution;

class DemandProbe {
public:
    explicit DemandProbe(const Problem& problem);
    /// Whether cell i holds a resource and a motion instance it takes part in is disabled now but
    /// would be enabled with i one creator heavier (a C) or one destroyer lighter (a D); when i is
    /// the instance's anchor, also when one other cell of it had the other resource as well.
    bool needsHeavier(const Execution& ex, std::int64_t i) const;
    bool needsLighter(const Execution& ex, std::int64_t i) const;
    /// Whether a value's resource is the creator (C) or the full one (D); whether it is labelled F
    /// (final: it stays to the end).
    bool heavy(BoxEngine::Value v) const { return heavy_[v] != 0; }
    bool light(BoxEngine::Value v) const { return light_[v] != 0; }
    bool final(BoxEngine::Value v) const { return final_[v] != 0; }
    /// The state one creator heavier / one destroyer lighter than v (v when there is none): the
    /// states the demand questions put in a cell's place.
    BoxEngine::Value heavierOf(BoxEngine::Value v) const { return heavier_[v] ? heavier_[v] : v; }
    BoxEngine::Value lighterOf(BoxEngine::Value v) const { return lighter_[v] ? lighter_[v] : v; }
    /// Whether cell i, as it is, can take part in a transfer: only such a cell can pass a
    /// resource on, so only through it is a demand any nearer.
    bool carrier(const Execution& ex, std::int64_t i) const;

private:
    bool wouldEnable(const Execution& ex, std::int64_t i, BoxEngine::Value instead) const;
    std::vector<BoxEngine::Value> heavier_, lighter_;
    std::vector<char> heavy_, light_, final_;
    // Per input combination and state: the motion shapes and steps to their anchor from a pattern
    // cell whose test that state passes (most instances around a cell fail there, and the fields
    // ask this of every cell near a change).
    std::vector<std::vector<std::pair<int, std::int64_t>>> accepting_;
    std::vector<char> carrier_;  // per input combination and state: a transfer's pattern cell accepts it
    std::size_t alphabet_ = 0;
};

/// The cells whose demand (needsHeavier, needsLighter) a change of one cell can alter: the cells of
/// every motion instance that reads it and can tell its old state from its new one, or the states
/// one resource heavier or lighter than those (the demand questions put those in a partner's
/// place: DemandProbe::wouldEnable). A transfer changes only which resource a cell holds, and most
/// motions read resources at a few of their sites (general1's deletion guard reads only labels):
/// in 3D its stencil is 7 steps where the stencil of every change was 25 (the demand allocator on
/// the block at K = 16: 30.8 -> 24.2 s, docs/scale.md).
class DemandStencil {
public:
    DemandStencil(const Problem& problem, const DemandProbe& probe);
    /// Steps from a cell that changed from `was` to `now`; sorted, without repeats, 0 among them.
    const std::vector<std::int64_t>& steps(BoxEngine::Value was, BoxEngine::Value now) const {
        std::int32_t& at = index_[static_cast<std::size_t>(was) * alphabet_ + now];
        if (at < 0) at = build(was, now);
        return lists_[static_cast<std::size_t>(at)];
    }

private:
    std::int32_t build(BoxEngine::Value was, BoxEngine::Value now) const;
    const Problem* problem_;
    const DemandProbe* probe_;
    std::size_t alphabet_;
    // Built on first use per pair of states: most pairs never occur. A deque: references stay valid.
    mutable std::vector<std::int32_t> index_;
    mutable std::deque<std::vector<std::int64_t>> lists_;
};

}  // namespace holon::planner
