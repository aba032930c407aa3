#pragma once
// Tokens of the .holon language. A declaration ends at a newline, except inside parentheses or
// after a token that cannot end one (`and`, `,`, `=>`, `|` ...), so long rules may wrap.

#include "rules/Diagnostics.h"

#include <string>
#include <string_view>
#include <vector>

namespace holon::rules {

struct Token {
    enum class Kind { Ident,
                      Int,
                      Punct,
                      Newline,
                      End } kind = Kind::End;
    std::string text;
    SourceLoc loc;
    bool is(std::string_view t) const { return (kind == Kind::Punct || kind == Kind::Ident) && text == t; }
};

/// The words that start a declaration, in the order docs/language.md lists them.
const std::vector<std::string>& declarationKeywords();

std::vector<Token> tokenize(std::string_view source, Diagnostics& diagnostics);

}  // namespace holon::rules
