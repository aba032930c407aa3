#pragma once
// The one checked writer for everything holon writes to a file: a path is checked before the work
// starts (so a finished job is never thrown away for a bad path), a file is written to a temporary
// beside it and renamed into place (never half-written), and every write error is reported with
// the system's reason. Special files (/dev/stdout, a pipe) are written in place, errors checked.

#include <fstream>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace holon::rules {

/// A file being written in pieces (a plan's moves as they happen): the text goes to a temporary
/// file; commit() checks every write and renames it into place. Destroyed without commit() (an
/// error, a signal that unwinds), the temporary is removed and the old file, if any, stays.
class OutputStream {
public:
    OutputStream(std::string option, std::string path);
    OutputStream(OutputStream&&) noexcept;
    ~OutputStream();
    std::ostream& stream() { return *out_; }
    /// Flushes, checks, closes and renames; throws InputError with the reason of the first write
    /// that failed (a stream's error state keeps none: /dev/full was reported as "Invalid argument").
    void commit();

private:
    struct Buffer;  // a file descriptor's buffer that keeps the first write error (OutputFile.cpp)
    std::string option_, path_, temp_;
    std::unique_ptr<Buffer> buffer_;
    std::unique_ptr<std::ostream> out_;
    bool committed_ = false;
    int tracked_ = -1;  // its entry among the temporaries removeTemporaries removes
};

/// Removes every temporary being written now (async-signal-safe): a signal that ends holon before
/// its files are renamed into place leaves none behind (export interrupted mid-write left 200 MB
/// of FILE.tmp-XXXXXX).
void removeTemporaries() noexcept;

class OutputFile {
public:
    /// Checks now that `path` can be written: its folder exists and takes files, and it is not a
    /// folder itself. `option` (e.g. "--svg") names it in messages. Throws InputError otherwise.
    OutputFile(std::string option, std::string path);
    const std::string& path() const { return path_; }
    const std::string& option() const { return option_; }
    /// Writes the whole file at once; throws InputError with the reason when it cannot.
    void write(const std::string& text) const;
    /// Writes through a stream (for large outputs); the same guarantees.
    void write(const std::function<void(std::ostream&)>& fill) const;
    /// Starts writing in pieces.
    OutputStream open() const { return OutputStream(option_, path_); }

private:
    std::string option_, path_;
};

/// The outputs one job names, so that two options never write the same file: while an
/// OutputClaims lives (the CLI makes one per command), every OutputFile and output folder claims
/// its path for its option, and a second option naming the same file, or a file inside a folder
/// another option writes, is refused (InputError) before any work. A plan's --html once replaced
/// its --plan-out, and exit 0 said the job was done. Without one, nothing is checked. A folder
/// the job created and left empty (refused, failed, interrupted) is removed when it goes.
class OutputClaims {
public:
    OutputClaims();
    ~OutputClaims();
    OutputClaims(const OutputClaims&) = delete;
    OutputClaims& operator=(const OutputClaims&) = delete;
    /// An input the job reads that no output may replace, named by `option`: every file a command
    /// reads its rules, configurations, masks and shapes from (path --svg once replaced the rule
    /// file it was given, and exit 0 said the job was done).
    static void reading(const std::string& option, const std::string& path);
};

/// Makes sure `dir` is a folder holon can write into, creating it if missing (its parent must exist:
/// a mistyped parent is refused, not created);
/// throws InputError naming `option` and the reason. `names`, when given, are the only files the
/// option writes there (a '*' matches any text: "snapshot-*.svg"); another option may then name
/// any other file in the folder (plan --out run --plan-out run/plan.jsonl). Without them the
/// whole folder is the option's.
void prepareOutputDir(const std::string& option, const std::string& dir, const std::vector<std::string>& names = {});

/// A family of output files, `prefix` + an id + `suffix` ("frame_" 200 ".svg"): the one spelling
/// of its names, for writing them and for the pattern that finds an earlier run's.
struct OutputNames {
    std::string prefix, suffix;
    std::string of(const std::string& id) const { return prefix + id + suffix; }
    std::string pattern() const { return prefix + "*" + suffix; }
};

/// Removes the files in `dir` (not below it) whose names match `names` (patterns as above): the
/// outputs an earlier run left in a reused folder. Called when a run starts writing, so the folder
/// holds one run's files; a stale violation.itf.json or frame_2000.svg beside a new run's summary
/// read as this run's.
void removeEarlierOutputs(const std::string& dir, const std::vector<std::string>& names);

}  // namespace holon::rules
