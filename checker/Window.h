#pragma once
// The window of a proof for every region (issue 31): every rule shape placed with its first
// pattern cell at the lattice origin, and every lattice point within `margin` steps of a pattern
// cell, all of them free. Why one such window stands for every region is argued in
// proofs/README.md ("Proofs for every region").

#include "rules/Engine.h"

#include <string>
#include <vector>

namespace holon::checker {

/// How far an expression reads from the cell it is about: 1 when it (a rule's guard, a
/// quantifier's cell guard) counts or tests the cell's neighbours (`nbr`), else 0.
int readRadius(const rules::Expr& e);
/// How far the system's rules read beyond their pattern: the largest radius of their guards.
int ruleRadius(const rules::Model& model);

/// Why a conjunct of an invariant is not a condition on each cell and the neighbours it reads
/// (`all(T: G)`, `all(T)`, `no(T: G)`, `no(T)`), or why that condition could fail at a point
/// outside a region (holon's regions leave those empty, without inputs, and do not quantify over
/// them); empty when it is local.
std::string notLocal(const rules::Expr& conjunct, const rules::Engine& engine);

/// The same for a number (a ranking's component): a count whose cell guard reads neighbours and
/// whose predicate holds at an empty point without inputs could change outside a region, where the
/// region does not count; empty when there is none.
std::string notLocalNumber(const rules::Expr& number, const rules::Engine& engine);

class Window {
public:
    Window(const rules::Model& model, int margin);
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    const rules::Region& region() const { return region_; }
    /// Covers every input combination: the inputs are free like the states.
    const rules::Engine& engine() const { return engine_; }
    int margin() const { return margin_; }
    /// Per rule shape, the engine instance whose first pattern cell is the origin.
    const std::vector<int>& focus() const { return focus_; }
    /// The window cells within `radius` steps of instance `placed`'s pattern cells.
    std::vector<int> around(int placed, int radius) const;
    /// Every neighbour of the cell is in the window: a condition reading them can be stated there.
    bool interior(int cell) const;

private:
    rules::Region region_;
    rules::Engine engine_;
    int margin_;
    std::vector<int> focus_;
};

}  // namespace holon::checker
