// Diagnostics in the style of Souffle and the C compilers: every error of a phase is collected
// before the phase stops, then all are printed in source order with the offending line and a caret.
// The echoed line is an excerpt of at most kWindow columns around the caret, with raw bytes
// escaped, so a 30 KB line of garbage prints as a few lines.

#include "rules/Diagnostics.h"

#include "rules/Escape.h"

#include <algorithm>
#include <sstream>
#include <string_view>
#include <tuple>

namespace holon::rules {

namespace {

constexpr int kWindow = 100;

/// The columns of a line as the lexer counts them: an ASCII byte, or a non-ASCII byte with the
/// continuation bytes after it.
std::vector<std::string_view> columns(std::string_view line) {
    std::vector<std::string_view> out;
    for (std::size_t i = 0; i < line.size();) {
        std::size_t j = i + 1;
        if (static_cast<unsigned char>(line[i]) >= 0x80)
            while (j < line.size() && (static_cast<unsigned char>(line[j]) & 0xC0) == 0x80) ++j;
        out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

/// The excerpt of `line` around column `col` and the caret line under it, both indented by two.
std::string excerptWithCaret(std::string_view line, int col) {
    const auto cols = columns(line);
    const int n = static_cast<int>(cols.size());
    const int at = std::clamp(col - 1, 0, n);
    const int begin = std::clamp(at - kWindow / 2, 0, std::max(0, n - kWindow));
    const int end = std::min(n, begin + kWindow);
    std::string text = begin > 0 ? "..." : "", caret(text.size(), ' ');
    for (int i = begin; i < end; ++i) {
        const std::string shown = cols[i] == "\t" ? "\t" : escapeText(cols[i]);
        text += shown;
        // A well-formed character takes one column; an escape takes as many as it prints.
        if (i < at) caret += shown == "\t" ? std::string("\t") : std::string(shown == cols[i] ? 1 : shown.size(), ' ');
    }
    if (end < n) text += "...";
    return "  " + text + "\n  " + caret + "^\n";
}

}  // namespace

Diagnostics::Diagnostics(std::string fileName, std::string source) : fileName_(std::move(fileName)), source_(std::move(source)) {}

void Diagnostics::error(SourceLoc loc, std::string message) {
    if (errors_ == kMaxErrors) {
        stopped_ = true;
        return;
    }
    diagnostics_.push_back({Diagnostic::Severity::Error, loc, loc.line, loc.col, std::move(message), {}});
    ++errors_;
}

void Diagnostics::warning(SourceLoc loc, std::string name, std::string message) {
    if (silenced_.count(name)) return;
    diagnostics_.push_back({Diagnostic::Severity::Warning, loc, loc.line, loc.col, std::move(message), std::move(name)});
}

const std::vector<std::string>& Diagnostics::warningNames() {
    static const std::vector<std::string> names{"unused-value", "unused-input", "unmassed-value", "duplicate-rule",
                                                "no-rules"};
    return names;
}

std::string Diagnostics::render() const {
    std::vector<Diagnostic> sorted = diagnostics_;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return std::tie(a.line, a.col) < std::tie(b.line, b.col);
    });
    const std::string file = escapeText(fileName_);
    std::ostringstream out;
    // One pass over the source finds every diagnostic's line, as they come sorted.
    const std::string_view source = source_;
    int line = 1;
    std::size_t start = 0;
    for (const Diagnostic& d : sorted) {
        out << file << ':' << d.line << ':' << d.col << ": "
            << (d.severity == Diagnostic::Severity::Error ? "error" : "warning") << ": " << escapeText(d.message, true);
        if (!d.name.empty()) out << " [-W" << d.name << ']';
        out << '\n';
        while (line < d.line && start < source.size()) {
            const std::size_t newline = source.find('\n', start);
            start = newline == std::string_view::npos ? source.size() : newline + 1;
            ++line;
        }
        if (d.line < 1 || line != d.line || start >= source.size()) continue;
        std::string_view text = source.substr(start, source.find('\n', start) - start);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        out << excerptWithCaret(text, d.col);
    }
    if (stopped_)
        out << file << ": error: too many errors; stopping after the first " << kMaxErrors << " (fix these and run again)\n";
    return out.str();
}

}  // namespace holon::rules
