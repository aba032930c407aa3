#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as the 64 lowercase hex digits sha256sum prints: the
// content hash of a rule file and of the exported obligations a certificate names
// (checker/Certificate.h). Debian's allowed packages offer none, so it is written here.

#include <string>
#include <string_view>

namespace holon::rules {

std::string sha256Hex(std::string_view bytes);

}  // namespace holon::rules
