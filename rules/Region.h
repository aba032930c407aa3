#pragma once
// Bounded regions of a lattice: the finite sets of cells that configurations live on.

#include "rules/Lattice.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace holon::rules {

class Region {
public:
    /// Parses "square:WxH", "cubic:WxHxD" or "hex:rR"; throws InputError naming the fix. `admit`,
    /// if given, is called with the number of cells before the region is built (a memory check).
    static Region parse(std::string_view spec, std::size_t maxCells = 1u << 26, const std::function<void(std::uint64_t cells)>& admit = {});
    /// What a region holds per cell, at most: its cell, its place in the box index and its
    /// neighbours (a few bytes more on a hexagon, whose box index covers its bounding box).
    static constexpr std::uint64_t kBytesPerCell = 64;
    static Region box(const Lattice& lattice, Vec size);
    static Region hexagon(int radius);
    /// Any finite set of lattice points (distinct, at least one), named `spec` in messages: the
    /// windows of proofs for every region (checker/Window.h).
    static Region of(const Lattice& lattice, std::string spec, std::vector<Vec> cells);
    /// The region and every lattice point within `margin` neighbour steps of it; the region's cells
    /// keep their indices (0..size()-1), the added ones follow.
    /// The region with every cell within `margin` lattice steps of it added; nothing (and no more
    /// work than that) once it would exceed `maxCells` cells.
    std::optional<Region> grown(int margin, std::size_t maxCells) const;
    Region grown(int margin) const;

    const Lattice& lattice() const { return *lattice_; }
    const std::string& spec() const { return spec_; }
    int size() const { return static_cast<int>(cells_.size()); }
    Vec cell(int i) const { return cells_[i]; }
    const std::vector<Vec>& cells() const { return cells_; }
    /// Index of a lattice point, or -1 when it lies outside the region.
    int indexOf(Vec v) const;
    bool contains(Vec v) const { return indexOf(v) >= 0; }
    /// Neighbour of cell i in direction d, or -1 outside the region.
    int neighbour(int i, int d) const { return neighbours_[static_cast<std::size_t>(i) * lattice_->degree() + d]; }
    /// The smallest box containing the region: lower corner and extent.
    Vec lower() const { return lower_; }
    Vec extent() const { return extent_; }

private:
    Region(const Lattice& lattice, std::string spec, std::vector<Vec> cells);
    const Lattice* lattice_;
    std::string spec_;
    std::vector<Vec> cells_;
    Vec lower_, extent_;
    std::vector<std::int32_t> boxIndex_;  // over the bounding box; -1 where not in the region
    std::vector<std::int32_t> neighbours_;
};

}  // namespace holon::rules
