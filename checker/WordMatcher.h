#pragma once
// Matching every rule instance of a small region at once, with word operations: on a region of at
// most 64 cells a set of cells is one 64-bit word, so the anchors where a shape's left side holds
// are the intersection, over its pattern cells, of the cells that accept their state shifted back
// to the anchor (the bitboard move generation of chess programs). The explorer's successor
// generator uses it; rules::Engine's cell-by-cell matcher serves larger regions and alphabets.

#include "rules/Engine.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace holon::checker {

using rules::CellValue;

class WordMatcher {
public:
    /// Usable when the region has at most 64 cells and the alphabet at most 64 states.
    static bool fits(int regionSize, int alphabet) { return regionSize <= 64 && alphabet <= 64; }
    /// Every instance of `engine`, not yet finished: the caller may add tests (addWordTest,
    /// require) before finish().
    explicit WordMatcher(const rules::Engine& engine);
    /// A test whose word the caller supplies at match time (forEachMatch's `extra`); returns
    /// its index among the extra words.
    int addWordTest() { return extraTests_++; }
    /// Instances of `shape` match only where pattern cell k lies in extra word `test`.
    void require(int shape, int k, int test) { filters_.push_back({shape, k, test}); }
    /// Lays the instances out for matching; call once, after the last require.
    void finish();

    /// f(placed) for every instance whose left side, guard and required tests hold, given the
    /// cells in each state as words (`occupied[v]`) and the words of the tests added by
    /// addWordTest (`extra`); `cells` is read only by guards.
    template <class F>
    void forEachMatch(const std::uint64_t* occupied, const std::uint64_t* extra, const CellValue* cells, F&& f) const {
        forEachShape(occupied, extra, [&](int s, std::uint64_t anchors) {
            const bool guarded = engine_->tables().shape(s).hasGuard;
            for (; anchors; anchors &= anchors - 1) {
                const std::int32_t p = engine_->instanceAt(std::countr_zero(anchors), s);
                if (!guarded || engine_->guardHolds(cells, p)) f(p);
            }
        });
    }

private:
    /// Calls f(shape, anchors) for every shape, `anchors` holding the first cells of its instances
    /// whose left side and required tests hold (guards are not tested).
    template <class F>
    void forEachShape(const std::uint64_t* occupied, const std::uint64_t* extra, F&& f) const {
        // Loops with fixed trip counts and shifts without branches: the branch predictor learns
        // them, where an early exit on the data mispredicts (measured: a third of the explorer's
        // mispredictions came from here).
        constexpr std::size_t kOnStack = 64;
        std::uint64_t onStack[kOnStack];
        thread_local std::vector<std::uint64_t> onHeap;
        std::uint64_t* accepted = onStack;
        const std::size_t all = tests_.size() + extraTests_;
        if (all > kOnStack) onHeap.resize(all), accepted = onHeap.data();
        for (std::size_t t = 0; t < tests_.size(); ++t) {
            const std::uint64_t* byState = &testCells_[t * alphabet_];
            std::uint64_t a = 0;
            for (int v = 0; v < alphabet_; ++v) a |= occupied[v] & byState[v];
            accepted[t] = a;
        }
        for (int e = 0; e < extraTests_; ++e) accepted[tests_.size() + e] = extra[e];
        // Every shape's anchors first, then f for the shapes that have any: a branch per shape
        // on whether it matched mispredicts about half the time, a walk over the mask of those
        // that did only at its end.
        std::uint64_t anchorsOf[kOnStack];
        for (std::size_t first = 0; first < shapes_.size(); first += kOnStack) {
            const std::size_t count = std::min(kOnStack, shapes_.size() - first);
            std::uint64_t matched = 0;
            for (std::size_t s = 0; s < count; ++s) {
                const Shape& shape = shapes_[first + s];
                std::uint64_t anchors = shape.anchors;
                for (int i = shape.first; i < shape.last; ++i) {
                    const Step& st = steps_[i];
                    anchors &= ((accepted[st.test] >> st.right) << st.left) | st.others;
                }
                anchorsOf[s] = anchors;
                matched |= static_cast<std::uint64_t>(anchors != 0) << s;
            }
            for (; matched; matched &= matched - 1) {
                const int s = std::countr_zero(matched);
                f(static_cast<int>(first) + s, anchorsOf[s]);
            }
        }
    }

    /// Registers one instance: shape `shape` with its pattern cells at region indices `cells`
    /// (the first is its anchor).
    void addInstance(int shape, const std::int32_t* cells, int size);

    /// One test of a shape's matching: the anchors whose pattern cell k sits delta = right - left
    /// indices away from them (one of the two is 0) keep only those where that cell passes
    /// test k; the other anchors (`others`) are left alone. A pattern cell's groups of anchors
    /// partition the shape's anchors, so a shape is a run of steps, each one AND.
    struct Step {
        std::uint64_t others;
        int test;
        std::uint8_t right, left;
    };
    struct Shape {
        std::uint64_t anchors = 0;  // first cells of the shape's instances
        int first = 0, last = 0;    // its steps in steps_
    };

    const rules::Engine* engine_;
    int regionSize_, alphabet_;
    std::vector<Shape> shapes_;
    std::vector<int> cellTest_;                   // per (shape, pattern cell): index into tests_, while instances are added
    std::vector<rules::RuleTables::Mask> tests_;  // distinct left-side masks
    std::vector<std::uint64_t> testCells_;        // [test * alphabet + state]: cells whose combination accepts the state
    struct Pending {
        int delta;
        std::uint64_t anchors;
    };
    std::vector<std::vector<Pending>> pending_;  // per (shape, pattern cell), while instances are added
    std::vector<int> firstCell_;                 // per shape: its first (shape, pattern cell), while instances are added
    std::vector<Step> steps_;
    int extraTests_ = 0;
    struct Filter {
        int shape, k, test;
    };
    std::vector<Filter> filters_;  // until finish()
};

}  // namespace holon::checker
