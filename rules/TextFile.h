#pragma once
// Reading a whole input file: the one reader of every text input holon takes (rule files, shapes,
// configurations, certificates, structures), bounded in size and stoppable while it waits.

#include "rules/Limits.h"

#include <istream>
#include <memory>
#include <string>

namespace holon::rules {

/// Reads a whole file; throws InputError naming the file when it cannot be read, is a folder, or
/// holds more than `maxBytes` (so /dev/zero or a wrong file stops with a message, not the machine).
/// A pipe or FIFO that nothing writes yet is waited for until a signal (Interrupted) or the job's
/// deadline (LimitError about the timeout, rules/Budget.h setJobDeadline).
std::string readTextFile(const std::string& path, std::size_t maxBytes = kMaxFileBytes);

/// The same file as a stream, for inputs read a line at a time (a plan of millions of lines): the
/// same errors when it cannot be opened, and the same waits, in slices, for a pipe or FIFO.
std::unique_ptr<std::istream> openInputStream(const std::string& path);

}  // namespace holon::rules
