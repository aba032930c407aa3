// The .holon tokenizer: identifiers, integers, punctuation, significant newlines and `//` comments.
// Unknown characters are reported (escaped) and skipped so that the parser still sees the rest of
// the line; past the error limit the lexer stops.

#include "rules/Lexer.h"

#include "rules/Escape.h"

#include <array>
#include <cctype>

namespace holon::rules {

namespace {

constexpr std::array<std::string_view, 25> kPunct{"<=>", "=>", "<=", ">=", "==", "!=", "..", "<", ">", "=", ":",
                                                  "|", "&", "!", "@", ",", "(", ")", "*", "#", "_", "/",
                                                  "+", "-", ";"};

bool continuesLine(const Token& t) {
    static constexpr std::array<std::string_view, 14> joiners{"and", "or", "not", "implies", "if", "assuming", ",",
                                                              "=>", "<=>", "|", "&", ":", "=", "("};
    if (t.kind != Token::Kind::Ident && t.kind != Token::Kind::Punct) return false;
    for (auto j : joiners)
        if (t.text == j) return true;
    return false;
}

bool startsDeclaration(std::string_view rest) {
    for (const std::string& k : declarationKeywords())
        if (rest.substr(0, k.size()) == k && (rest.size() == k.size() || rest[k.size()] == ' ')) return true;
    return false;
}

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

}  // namespace

const std::vector<std::string>& declarationKeywords() {
    static const std::vector<std::string> words{"system", "lattice", "symmetry", "field", "states", "input", "mass",
                                                "rule", "constraint", "goal", "invariant", "ranking", "progress", "holonomic",
                                                "conserves"};
    return words;
}

std::vector<Token> tokenize(std::string_view src, Diagnostics& diagnostics) {
    std::vector<Token> tokens;
    int line = 1, col = 1, depth = 0;
    std::size_t i = 0;
    auto push = [&](Token::Kind kind, std::string text, SourceLoc loc) { tokens.push_back({kind, std::move(text), loc}); };
    while (i < src.size() && !diagnostics.stopped()) {
        const char c = src[i];
        const SourceLoc loc{line, col};
        if (c == '\n') {
            // An unclosed parenthesis must not swallow the rest of the file: a declaration keyword at
            // the start of the next line ends it.
            if (depth > 0 && startsDeclaration(src.substr(i + 1))) depth = 0;
            if (depth == 0 && !tokens.empty() && tokens.back().kind != Token::Kind::Newline && !continuesLine(tokens.back()))
                push(Token::Kind::Newline, "", loc);
            ++i, ++line, col = 1;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i, ++col;
            continue;
        }
        if (c == '/' && i + 1 < src.size() && src[i + 1] == '/') {
            while (i < src.size() && src[i] != '\n') ++i, ++col;
            continue;
        }
        if (identStart(c)) {
            std::size_t j = i;
            while (j < src.size() && identChar(src[j])) ++j;
            if (j - i > kMaxIdentifier)
                diagnostics.error(loc, "a name of " + std::to_string(j - i) + " characters; names have at most " +
                                           std::to_string(kMaxIdentifier));
            push(Token::Kind::Ident, std::string(src.substr(i, std::min<std::size_t>(j - i, kMaxIdentifier))), loc);
            col += static_cast<int>(j - i), i = j;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t j = i;
            while (j < src.size() && std::isdigit(static_cast<unsigned char>(src[j]))) ++j;
            if (j - i > 9) {
                diagnostics.error(loc, "number too large: at most 999999999 (9 digits); write a smaller one, or a fraction");
                push(Token::Kind::Int, "1", loc);  // not 0: a denominator of 0 added a second error
            } else {
                push(Token::Kind::Int, std::string(src.substr(i, j - i)), loc);
            }
            col += static_cast<int>(j - i), i = j;
            continue;
        }
        bool matched = false;
        for (auto p : kPunct) {
            if (src.substr(i, p.size()) == p) {
                if (p == "(") ++depth;
                if (p == ")" && depth > 0) --depth;
                push(Token::Kind::Punct, std::string(p), loc);
                i += p.size(), col += static_cast<int>(p.size());
                matched = true;
                break;
            }
        }
        if (matched) continue;
        const unsigned char u = static_cast<unsigned char>(c);
        // NAME.rev is how holon shows an unnamed reverse rule; a file names it with `/ REVERSE`.
        const bool reverse = c == '.' && src.substr(i + 1, 3) == "rev" && !tokens.empty() && tokens.back().kind == Token::Kind::Ident;
        diagnostics.error(loc, u >= 0x80 ? std::string("non-ASCII character; .holon files are plain ASCII")
                               : reverse ? "unexpected character '.': '" + tokens.back().text + ".rev' is how a reverse rule is shown; to name it here, declare it 'rule " + tokens.back().text + " / NAME: ...' and write NAME"
                                         : "unexpected character '" + escapeText(std::string_view(&c, 1)) + "'");
        // Skip a whole UTF-8 sequence so one character gives one diagnostic.
        std::size_t j = i + 1;
        while (u >= 0x80 && j < src.size() && (static_cast<unsigned char>(src[j]) & 0xC0) == 0x80) ++j;
        i = j, ++col;
    }
    // The end of the file is placed just after the last token, as compilers do: on a line that
    // exists, not on the empty line after the final line break.
    SourceLoc end{1, 1};
    if (!tokens.empty()) {
        const Token& last = tokens.back();
        end = last.kind == Token::Kind::Newline ? last.loc : SourceLoc{last.loc.line, last.loc.col + static_cast<int>(last.text.size())};
    }
    if (!tokens.empty() && tokens.back().kind != Token::Kind::Newline) push(Token::Kind::Newline, "", end);
    push(Token::Kind::End, "", end);
    return tokens;
}

}  // namespace holon::rules
