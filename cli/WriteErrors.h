#pragma once
// Writes that fail once a command's work has started (a full disk, a folder removed under it) do
// not stop the work: the command collects them, prints its results, then reports them all at once
// as one InputError (exit 2 through main). Paths are checked before the work (rules/OutputFile.h),
// so what is collected here is what no check could foresee.

#include "rules/Error.h"

#include <functional>
#include <string>
#include <vector>

namespace holon::cli {

class WriteErrors {
public:
    /// Runs `write`; an InputError it throws is kept, with its reason, instead of propagating.
    void attempt(const std::function<void()>& write) {
        try {
            write();
        } catch (const InputError& e) {
            add(e.what());
        }
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
