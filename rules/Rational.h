#pragma once
// Exact rationals for masses (general_n needs i/n and 1 + 1/n) and for arithmetic in expressions.
// Numerators and denominators are 64-bit; every operation is computed in 128 bits and reduced, and
// a result that still does not fit is an ArithmeticOverflow (bad input: the rule file's numbers),
// never a wrapped value: three denominators near 10^9 once summed to a negative number, and
// `check` reported a true invariant violated while `verify` proved it.

#include "rules/Error.h"

#include <compare>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

namespace holon::rules {

/// An exact value too large for Rational: the CLI's exit code 2, with the operation.
class ArithmeticOverflow : public InputError {
public:
    explicit ArithmeticOverflow(const std::string& what)
        : InputError("the exact value of " + what + " does not fit 64-bit numerators and denominators; use numbers with smaller denominators") {}
};

/// The least common multiple of two positive denominators, or ArithmeticOverflow.
inline std::int64_t checkedLcm(std::int64_t a, std::int64_t b) {
    const __int128 l = static_cast<__int128>(a / std::gcd(a, b)) * b;
    if (l > std::numeric_limits<std::int64_t>::max()) throw ArithmeticOverflow("the common denominator of 1/" + std::to_string(a) + " and 1/" + std::to_string(b));
    return static_cast<std::int64_t>(l);
}

class Rational {
public:
    constexpr Rational(std::int64_t num = 0, std::int64_t den = 1) : num_(num), den_(den) { normalise(); }
    std::int64_t num() const { return num_; }
    std::int64_t den() const { return den_; }
    bool isInteger() const { return den_ == 1; }
    friend Rational operator+(Rational a, Rational b) { return wide(Wide{a.num_} * b.den_ + Wide{b.num_} * a.den_, Wide{a.den_} * b.den_, a, " + ", b); }
    friend Rational operator-(Rational a, Rational b) { return wide(Wide{a.num_} * b.den_ - Wide{b.num_} * a.den_, Wide{a.den_} * b.den_, a, " - ", b); }
    friend Rational operator*(Rational a, Rational b) { return wide(Wide{a.num_} * b.num_, Wide{a.den_} * b.den_, a, " * ", b); }
    Rational operator-() const { return wide(-Wide{num_}, den_, 0, " - ", *this); }
    Rational& operator+=(Rational b) { return *this = *this + b; }
    friend bool operator==(Rational a, Rational b) { return a.num_ == b.num_ && a.den_ == b.den_; }
    friend std::strong_ordering operator<=>(Rational a, Rational b) { return Wide{a.num_} * b.den_ <=> Wide{b.num_} * a.den_; }
    std::string str() const { return den_ == 1 ? std::to_string(num_) : std::to_string(num_) + "/" + std::to_string(den_); }
    double toDouble() const { return static_cast<double>(num_) / static_cast<double>(den_); }

private:
    using Wide = __int128;
    static Wide gcd(Wide a, Wide b) {
        if (a < 0) a = -a;
        while (b != 0) a %= b, std::swap(a, b);
        return a;
    }
    /// num / den (den > 0) reduced, or ArithmeticOverflow naming `a op b`.
    static Rational wide(Wide num, Wide den, Rational a, const char* op, Rational b) {
        if (den != 1)
            if (const Wide g = gcd(num, den); g > 1) num /= g, den /= g;
        constexpr Wide lo = std::numeric_limits<std::int64_t>::min() + 1, hi = std::numeric_limits<std::int64_t>::max();
        if (num < lo || num > hi || den > hi) throw ArithmeticOverflow(a.str() + op + b.str());
        Rational r;
        r.num_ = static_cast<std::int64_t>(num), r.den_ = static_cast<std::int64_t>(den);
        return r;
    }
    constexpr void normalise() {
        if (den_ == 1) return;  // integers, the common case in counts, need no gcd
        if (den_ < 0) num_ = -num_, den_ = -den_;
        const std::int64_t g = std::gcd(num_, den_);
        if (g > 1) num_ /= g, den_ /= g;
    }
    std::int64_t num_, den_;
};

}  // namespace holon::rules
