#pragma once
// Writes that fail once a command's work has started (a full disk, a folder removed under it) do
// not stop the work: the command collects them, prints its results, then reports them all at once
// as one InputError (exit 2 through main). Paths are checked before the work (rules/OutputFile.h),
// so what is collected here is what no check could foresee.

#include "rules/Error.h"
#include "rules/OutputFile.h"

#include <functional>
#include <new>
#include <string>
#include <vector>

namespace holon::cli {

class WriteErrors {
public:
    /// Runs `write`; an InputError it throws is kept, with its reason, instead of propagating, and
    /// so is running out of memory while it makes what it writes (the SVG of a huge region).
    /// `what` names the output in that message ("--svg out.svg"). Whether it was written.
    bool attempt(const std::function<void()>& write, const std::string& what = "an output") {
        try {
            write();
            return true;
        } catch (const InputError& e) {
            add(e.what());
        } catch (const std::bad_alloc&) {
            add(what + ": not written: the machine has no memory left to make it");
        }
        return false;
    }
    /// Writes `text()` to `path` for `option`, adding the path and `note` to `written` when it is
    /// written.
    void write(const std::string& option, const std::string& path, const std::function<std::string()>& text, std::vector<std::string>& written,
               const std::string& note = "") {
        attempt(
            [&] {
                const rules::OutputFile file(option, path);
                file.write(text());
                written.push_back(file.path() + note);
            },
            option + " " + path);
    }
    void add(std::string message) { messages_.push_back(std::move(message)); }
    bool empty() const { return messages_.empty(); }
    /// Throws one InputError naming every failed write; returns when none failed.
    void raise() const {
        if (messages_.empty()) return;
        std::string all = messages_.front();
        for (std::size_t k = 1; k < messages_.size(); ++k) all += "\n  " + messages_[k];
        throw InputError(all);
    }

private:
    std::vector<std::string> messages_;
};

}  // namespace holon::cli
