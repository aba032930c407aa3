#pragma once
// Resource allocators (seed 000 §IV-B): the planner marks where creations and deletions are
// pending; an allocator decides which resource transfers (C D <=> D C and the like) fire. The
// planner and the allocator only meet through the cells, as in the paper's separation of concerns.

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace holon::planner {

class Execution;

/// The distance the gradient and demand allocators give a cell no demand reaches.
inline constexpr std::uint32_t kUnreached = 1u << 30;

class Allocator {
public:
    virtual ~Allocator() = default;
    virtual std::string name() const = 0;
    /// Called once per round before instances are chosen; returns whether the allocator's own
    /// state changed (a round that fires nothing and changes no allocator state ends the run).
    virtual bool update(const Execution&) { return false; }
    /// Whether this enabled transfer instance should fire now.
    virtual bool wants(const Execution&, std::int64_t anchor, int shape) const = 0;
    /// Whether this enabled planner instance (not a transfer) may fire now. An allocator decides
    /// where destroyers are spent, so it may hold back an instance that starts a deletion
    /// (planner/DeletionOrder.h); it must not hold back every enabled instance for ever.
    virtual bool releases(const Execution&, std::int64_t /*anchor*/, int /*shape*/) const { return true; }
    /// Told just before a transfer instance fires.
    virtual void firing(const Execution&, std::int64_t /*anchor*/, int /*shape*/) {}
};

/// The board cells a transfer instance takes mass from and gives it to, or {-1, -1}.
std::pair<std::int64_t, std::int64_t> transferEnds(const Execution& ex, std::int64_t anchor, int shape);

struct Problem;

/// The allocators `holon plan --allocator` offers.
enum class AllocatorKind { Random,
                           Gradient,
                           Demand,
                           Eager,
                           Optimal };

/// The allocator a name denotes ("random", "gradient", "demand", "eager" or "optimal"); throws
/// InputError, naming --allocator and the choices, for any other name. Callers parse the name
/// before any work, so a typo costs nothing.
AllocatorKind allocatorKind(const std::string& name);

/// The names allocatorKind accepts, for help texts: "random, gradient, demand, eager or optimal".
std::string allocatorChoices();

/// `seed` drives the allocator's own coin flips (the run's --seed).
std::unique_ptr<Allocator> makeAllocator(AllocatorKind kind, const Problem& problem, std::uint64_t seed);
std::unique_ptr<Allocator> makeAllocator(const std::string& name, const Problem& problem, std::uint64_t seed);

/// Whether the system moves a resource by transfers: the plans the transport bound is about.
bool movesResources(const Problem& problem);

/// The least number of transfers any plan for the problem needs (a transport bound, see
/// Transport.cpp), or -1 when the system has no transfers.
std::int64_t transferLowerBound(const Problem& problem);

}  // namespace holon::planner
