// Allocator selection by name.

#include "planner/Allocator.h"

#include "rules/Error.h"

namespace holon::planner {

std::unique_ptr<Allocator> randomAllocator();
std::unique_ptr<Allocator> gradientAllocator(const Problem& problem);

std::unique_ptr<Allocator> makeAllocator(const std::string& name, const Problem& problem) {
    if (name == "random") return randomAllocator();
    if (name == "gradient") return gradientAllocator(problem);
    if (name == "optimal")
        throw InputError("--allocator optimal does not run plans yet; use gradient (every run still reports transfer_lower_bound, the transport optimum)");
    throw InputError("--allocator '" + name + "': choose random, gradient or optimal");
}

}  // namespace holon::planner
