// Diagnostics in the style of Souffle and the C compilers: every error of a phase is collected
// before the phase stops, then all are printed in source order with the offending line and a caret.

#include "rules/Diagnostics.h"

#include <algorithm>
#include <sstream>
#include <tuple>

namespace holon::rules {

Diagnostics::Diagnostics(std::string fileName, std::string source) : fileName_(std::move(fileName)) {
    std::istringstream in(source);
    for (std::string line; std::getline(in, line);) lines_.push_back(line);
}

void Diagnostics::error(SourceLoc loc, std::string message) {
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
    std::ostringstream out;
    for (const Diagnostic& d : sorted) {
        out << fileName_ << ':' << d.line << ':' << d.col << ": "
            << (d.severity == Diagnostic::Severity::Error ? "error" : "warning") << ": " << d.message;
        if (!d.name.empty()) out << " [-W" << d.name << ']';
        out << '\n';
        if (d.line >= 1 && d.line <= static_cast<int>(lines_.size())) {
            const std::string& text = lines_[d.line - 1];
            out << "  " << text << '\n' << "  ";
            for (int i = 1; i < d.col && i <= static_cast<int>(text.size()); ++i) out << (text[i - 1] == '\t' ? '\t' : ' ');
            out << "^\n";
        }
    }
    return out.str();
}

}  // namespace holon::rules
