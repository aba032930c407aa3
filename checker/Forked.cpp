// Forked solver jobs (see Forked.h), used by the reachability proofs (Reach.cpp) to race two Spacer
// runs on the two cores and to skip freeing Z3's memory afterwards.

#include "checker/Forked.h"

#include "rules/Error.h"
#include "rules/StopSignals.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <iostream>
#include <optional>
#include <poll.h>
#include <string>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace holon::checker {

namespace {

struct Child {
    pid_t pid = -1;
    int fd = -1;
    std::string text;
};

/// The job's answer, with an exception turned into {"input_error"} or {"error"}.
nlohmann::json answerOf(const ForkedJob& job, bool forked) {
    try {
        return job(forked);
    } catch (const InputError& e) {
        return {{"input_error", e.what()}};
    } catch (const std::bad_alloc&) {  // what() is "std::bad_alloc": say it
        return {{"error", "the solver job ran out of memory; choose a smaller region"}, {"resources", true}};
    } catch (const std::exception& e) {
        return {{"error", e.what()}};
    }
}

std::optional<Child> spawn(const ForkedJob& job) {
    int fds[2];
    if (pipe(fds) != 0) return std::nullopt;
    std::cout.flush(), std::cerr.flush();
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]), close(fds[1]);
        return std::nullopt;
    }
    if (pid == 0) {
        // The child dies with its parent, however the parent ends (SIGKILL included); a parent
        // gone before this line is seen as a new parent id.
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(1);
        rules::leaveTemporariesToParent();
        close(fds[0]);
        const std::string text = answerOf(job, true).dump();
        for (std::size_t done = 0; done < text.size();) {
            const ssize_t n = write(fds[1], text.data() + done, text.size() - done);
            if (n <= 0) break;
            done += static_cast<std::size_t>(n);
        }
        _exit(0);
    }
    close(fds[1]);
    return Child{pid, fds[0], {}};
}

/// Reads what the child wrote so far into `text`: false once the child closed the pipe.
bool readMore(int fd, std::string& text) {
    char buffer[65536];
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0) return errno == EINTR || errno == EAGAIN;
    text.append(buffer, static_cast<std::size_t>(n));
    return n > 0;
}

int reap(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    return status;
}

/// The answer a child wrote, or why there is none.
nlohmann::json received(const std::string& text, int status) {
    nlohmann::json answer = nlohmann::json::parse(text, nullptr, false);
    if (answer.is_discarded() || !answer.is_object()) {
        if (WIFSIGNALED(status)) return {{"error", "the solver process died (signal " + std::to_string(WTERMSIG(status)) + ")"}, {"resources", true}};
        return {{"error", "the solver process gave no answer"}};
    }
    return answer;
}

}  // namespace

ForkedAnswer firstDecisive(const std::vector<ForkedJob>& jobs, const std::function<bool(const nlohmann::json&)>& decisive, const Budget& budget) {
    // SIGINT and SIGTERM, while children run, are recorded for the race to stop them (the default
    // would end this process and leave them running).
    const rules::StopSignals stopSignals(false);
    const volatile std::sig_atomic_t& stopSignal = *rules::StopSignals::caught();
    std::vector<Child> children;
    for (const ForkedJob& job : jobs) {
        auto child = spawn(job);
        if (!child) break;
        children.push_back(*child);
    }
    auto stopAll = [&] {
        for (Child& c : children) {
            if (c.fd >= 0) close(c.fd), c.fd = -1;
            if (c.pid > 0) kill(c.pid, SIGKILL), waitpid(c.pid, nullptr, 0), c.pid = -1;
        }
    };
    ForkedAnswer result;
    if (children.size() < jobs.size()) {  // no fork: job 0 here
        stopAll();
        result = {0, answerOf(jobs[0], false)};
    }
    bool decided = result.job >= 0;
    // The jobs' own timeouts answer first; a child past them by this much is stuck.
    constexpr double kGraceSeconds = 0.5;
    for (std::size_t open = decided ? 0 : children.size(); open > 0 && !decided;) {
        if (stopSignal) break;
        if (budget.limited() && budget.elapsed() > budget.seconds() + kGraceSeconds) {
            if (result.job < 0) result.answer = {{"error", "timeout: the solver process did not answer in time"}};
            break;
        }
        std::vector<pollfd> polled;
        for (const Child& c : children)
            if (c.fd >= 0) polled.push_back({c.fd, POLLIN, 0});
        // Short waits, so that a signal or the deadline is seen at once.
        if (poll(polled.data(), polled.size(), 100) < 0) {
            if (errno == EINTR) continue;
            break;
        }
        for (std::size_t k = 0; k < children.size() && !decided; ++k) {
            Child& c = children[k];
            if (c.fd < 0) continue;
            auto it = std::find_if(polled.begin(), polled.end(), [&](const pollfd& p) { return p.fd == c.fd; });
            if (it == polled.end() || !it->revents) continue;
            if (readMore(c.fd, c.text)) continue;
            close(c.fd), c.fd = -1, --open;
            const int status = reap(c.pid);
            c.pid = -1;
            nlohmann::json answer = received(c.text, status);
            decided = answer.contains("input_error") || decisive(answer);
            if (decided || result.job < 0) result = {static_cast<int>(k), std::move(answer)};
        }
    }
    stopAll();
    if (stopSignal) throw Interrupted(stopSignal);  // also one that came while job 0 ran here
    if (result.answer.is_object() && result.answer.contains("input_error")) throw InputError(result.answer["input_error"].get<std::string>());
    return result;
}

ForkedTask::ForkedTask(ForkedJob job) : job_(std::move(job)) {
    if (auto child = spawn(job_)) pid_ = child->pid, fd_ = child->fd;
}

ForkedTask::~ForkedTask() { stop(); }

void ForkedTask::stop() {
    if (fd_ >= 0) close(fd_), fd_ = -1;
    if (pid_ > 0) kill(pid_, SIGKILL), reap(pid_), pid_ = -1;
}

std::optional<nlohmann::json> ForkedTask::answer(const Budget& budget) {
    std::string text;
    for (;;) {
        // A spent budget ends the wait, and also stops the job from starting here without a child.
        if (budget.expired() || budget.interrupted()) {
            stop();
            return std::nullopt;
        }
        if (pid_ < 0) return answerOf(job_, false);
        pollfd polled{fd_, POLLIN, 0};
        // Short waits, so that a signal or the deadline is seen at once.
        if (poll(&polled, 1, 100) < 0 && errno != EINTR) break;
        if (polled.revents && !readMore(fd_, text)) break;
    }
    close(fd_), fd_ = -1;
    const int status = reap(pid_);
    pid_ = -1;
    return received(text, status);
}

}  // namespace holon::checker
