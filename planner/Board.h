#pragma once
// A box of lattice cells stored as one flat array with a border of padding cells, so that every
// neighbour of a cell inside the box is a fixed index step away: the planner's storage for
// ensembles of millions of metamodules, a few bytes per cell.

#include "rules/Error.h"
#include "rules/Lattice.h"

#include <cstdint>
#include <vector>

namespace holon::planner {

using rules::Vec;

class Board {
public:
    /// The box [lower, lower + extent) of the lattice, padded by `pad` cells on every side
    /// (in the lattice's dimensions only).
    Board(const rules::Lattice& lattice, Vec lower, Vec extent, int pad) : lattice_(&lattice), lower_(lower), extent_(extent), pad_(pad) {
        const int dims = lattice.dimension();
        padded_ = {extent.x + 2 * pad, extent.y + 2 * pad, dims == 3 ? extent.z + 2 * pad : 1};
        const std::int64_t total = std::int64_t(padded_.x) * padded_.y * padded_.z;
        if (total > std::int64_t{1} << 31) throw InputError("the bounding box of start and target has " + std::to_string(total) + " cells; at most 2^31 fit");
        size_ = total;
        for (int d = 0; d < lattice.degree(); ++d) {
            const Vec v = lattice.direction(d);
            steps_.push_back(v.x + std::int64_t(padded_.x) * (v.y + std::int64_t(padded_.y) * v.z));
        }
    }
    const rules::Lattice& lattice() const { return *lattice_; }
    std::int64_t size() const { return size_; }
    Vec lower() const { return lower_; }
    Vec extent() const { return extent_; }
    std::int64_t step(int d) const { return steps_[d]; }
    std::int64_t offset(Vec v) const { return v.x + std::int64_t(padded_.x) * (v.y + std::int64_t(padded_.y) * v.z); }
    std::int64_t index(Vec v) const {
        const Vec r = v - lower_;
        const int zp = lattice_->dimension() == 3 ? pad_ : 0;
        return (r.x + pad_) + std::int64_t(padded_.x) * ((r.y + pad_) + std::int64_t(padded_.y) * (r.z + zp));
    }
    Vec point(std::int64_t i) const {
        const int zp = lattice_->dimension() == 3 ? pad_ : 0;
        return {static_cast<int>(i % padded_.x) - pad_ + lower_.x, static_cast<int>(i / padded_.x % padded_.y) - pad_ + lower_.y,
                static_cast<int>(i / (std::int64_t(padded_.x) * padded_.y)) - zp + lower_.z};
    }
    /// Calls f(index, point) for every cell inside the box.
    template <class F>
    void forEachInside(F&& f) const {
        const int depth = lattice_->dimension() == 3 ? extent_.z : 1;
        for (int z = 0; z < depth; ++z)
            for (int y = 0; y < extent_.y; ++y)
                for (int x = 0; x < extent_.x; ++x) {
                    const Vec p = lower_ + Vec{x, y, z};
                    f(index(p), p);
                }
    }

private:
    const rules::Lattice* lattice_;
    Vec lower_, extent_, padded_;
    int pad_;
    std::int64_t size_ = 0;
    std::vector<std::int64_t> steps_;
};

}  // namespace holon::planner
