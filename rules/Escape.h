#pragma once
// Quoting user text in messages: a raw NUL, ESC or broken UTF-8 byte copied into a message can
// garble the terminal it is printed on or break the tool reading it.

#include <cstddef>
#include <string>
#include <string_view>

namespace holon::rules {

/// `text` with control bytes, DEL and bytes that are not well-formed UTF-8 written as \xNN. With
/// `keepLayout`, newlines and tabs stay as they are (a multi-line message).
std::string escapeText(std::string_view text, bool keepLayout = false);
/// A short quotation for a message: escaped, and cut after `maxChars` bytes of text with "...".
std::string excerpt(std::string_view text, std::size_t maxChars = 60);

}  // namespace holon::rules
