#pragma once
// Limits on what user input may ask for. Sizes computed from it (a shape's sides times --scale, a
// region's sides) are multiplied with an overflow check: a product that wraps modulo 2^64 would pass
// any size guard as a small one. A job's memory is estimated from them and checked against
// --memory before it allocates (exit 3, the limit named), not found out by the kernel.

#include "rules/Error.h"

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>

namespace holon::rules {

/// The product of the factors, or UINT64_MAX when it does not fit in 64 bits (so that it fails
/// every size limit).
inline std::uint64_t checkedProduct(std::initializer_list<std::uint64_t> factors) {
    std::uint64_t product = 1;
    for (std::uint64_t f : factors)
        if (__builtin_mul_overflow(product, f, &product)) return std::numeric_limits<std::uint64_t>::max();
    return product;
}

/// A count for messages: a saturated checkedProduct reads "more than 2^64".
inline std::string countText(std::uint64_t n) {
    return n == std::numeric_limits<std::uint64_t>::max() ? std::string("more than 2^64") : std::to_string(n);
}

}  // namespace holon::rules

namespace holon::rules {

/// Refuses a job whose estimated memory `bytes` is over `budgetBytes` (--memory), before it
/// allocates: LimitError (exit 3) saying what needs it, how much, and the option to raise.
inline void requireMemory(std::uint64_t bytes, std::uint64_t budgetBytes, const std::string& what) {
    if (bytes <= budgetBytes) return;
    char need[32];
    std::snprintf(need, sizeof need, "%.1f", static_cast<double>(bytes) / double(1 << 30));
    throw LimitError(what + " needs about " + need + " GiB, more than --memory " + std::to_string(budgetBytes >> 20) +
                     " MiB; raise --memory or give a smaller job");
}

}  // namespace holon::rules
