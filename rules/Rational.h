#pragma once
// Exact rationals for masses (general_n needs i/n and 1 + 1/n) and for arithmetic in expressions.

#include <compare>
#include <cstdint>
#include <numeric>
#include <string>

namespace holon::rules {

class Rational {
public:
    constexpr Rational(std::int64_t num = 0, std::int64_t den = 1) : num_(num), den_(den) { normalise(); }
    std::int64_t num() const { return num_; }
    std::int64_t den() const { return den_; }
    bool isInteger() const { return den_ == 1; }
    friend Rational operator+(Rational a, Rational b) {
        if (a.den_ == 1 && b.den_ == 1) return Rational(a.num_ + b.num_);
        return {a.num_ * b.den_ + b.num_ * a.den_, a.den_ * b.den_};
    }
    friend Rational operator-(Rational a, Rational b) {
        if (a.den_ == 1 && b.den_ == 1) return Rational(a.num_ - b.num_);
        return {a.num_ * b.den_ - b.num_ * a.den_, a.den_ * b.den_};
    }
    friend Rational operator*(Rational a, Rational b) { return {a.num_ * b.num_, a.den_ * b.den_}; }
    Rational operator-() const { return {-num_, den_}; }
    Rational& operator+=(Rational b) { return *this = *this + b; }
    friend bool operator==(Rational a, Rational b) { return a.num_ == b.num_ && a.den_ == b.den_; }
    friend std::strong_ordering operator<=>(Rational a, Rational b) { return a.num_ * b.den_ <=> b.num_ * a.den_; }
    std::string str() const { return den_ == 1 ? std::to_string(num_) : std::to_string(num_) + "/" + std::to_string(den_); }
    double toDouble() const { return static_cast<double>(num_) / static_cast<double>(den_); }

private:
    constexpr void normalise() {
        if (den_ == 1) return;  // integers, the common case in counts, need no gcd
        if (den_ < 0) num_ = -num_, den_ = -den_;
        const std::int64_t g = std::gcd(num_, den_);
        if (g > 1) num_ /= g, den_ /= g;
    }
    std::int64_t num_, den_;
};

}  // namespace holon::rules
