#pragma once
// Where the field allocators let destroyers be spent: deletions start at the deepest P
// metamodules first, so the region to delete shrinks from its far side and keeps its exits wide
// (docs/scale.md, "The trunk bottleneck"). The rules are unchanged: holding an enabled deletion
// back is a choice among enabled instances, as an allocator's choice of transfers is.

#include "planner/Problem.h"

#include <cstdint>
#include <vector>

namespace holon::planner {

class Execution;

class DeletionOrder {
public:
    explicit DeletionOrder(const Problem& problem);
    /// Once per round: every P metamodule whose cell or a neighbour's values changed takes its
    /// depth from its parent's and what lies behind it from its deeper neighbours (one hop per
    /// round). Returns whether a value changed.
    bool update(const Execution& ex);
    /// False when the instance starts a deletion (a P metamodule holding a full resource gives
    /// mass up) and the metamodule knows of a deeper P metamodule behind it.
    bool releases(const Execution& ex, std::int64_t anchor, int shape) const;
    /// A P metamodule's depth in the planner's forest as it knows it (1 below an F), 0 elsewhere.
    std::uint32_t depth(std::int64_t cell) const { return depth_[cell]; }
    /// The deepest P metamodule it knows of behind it (reached through ever deeper neighbours).
    std::uint32_t behind(std::int64_t cell) const { return behind_[cell]; }

private:
    struct Values {
        std::uint32_t depth = 0, behind = 0;
    };
    Values derive(const std::vector<BoxEngine::Value>& cells, std::int64_t i) const;
    const Problem* problem_;
    std::vector<char> path_, full_;  // per state: labelled P; holding a full resource (D)
    std::vector<std::int64_t> up_;   // per state: the board step to its parent, 0 without one
    std::vector<char> starts_;       // per shape: a motion that can start a deletion
    std::vector<std::int64_t> around_;
    std::vector<std::uint32_t> depth_, behind_;
    std::vector<BoxEngine::Value> seen_;  // the cells as of the previous update
    std::vector<char> mark_;
    std::vector<std::int64_t> dirty_;
    std::vector<std::pair<std::int64_t, Values>> updates_;
};

}  // namespace holon::planner
