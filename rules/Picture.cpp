// The one ASCII-picture reader (rules/Picture.h). A ragged row is refused because every reader
// used to guess differently: one padded short rows with empty cells, one ignored what stood past
// the width it expected, one accepted any shape; a picture means the same thing everywhere now.

#include "rules/Picture.h"

#include "rules/Error.h"

#include <sstream>

namespace holon::rules {

std::vector<std::string> pictureRows(const std::string& text, bool rectangular) {
    std::vector<std::string> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        rows.push_back(line);
    }
    while (!rows.empty() && rows.back().find_first_not_of(" \t") == std::string::npos) rows.pop_back();
    if (rectangular)
        for (std::size_t r = 1; r < rows.size(); ++r)
            if (rows[r].size() != rows[0].size())
                throw InputError("line " + std::to_string(r + 1) + " has " + std::to_string(rows[r].size()) + " characters but line 1 has " +
                                 std::to_string(rows[0].size()) + "; draw every row equally wide (pad with '.')");
    return rows;
}

}  // namespace holon::rules
