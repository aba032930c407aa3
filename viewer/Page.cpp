// The viewer's page: the template's one placeholder replaced by the run's data. Steps are deltas
// (cell, new state) in one array with an offset per step; the page rebuilds keyframes and the
// states before each change when it loads, so stepping back costs what stepping forward does.

#include "viewer/Page.h"

#include "checker/Draw.h"
#include "rules/Error.h"
#include "rules/StopSignals.h"
#include "viewer/ViewerPage.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace holon::viewer {

namespace {

std::string base64(const std::string& bytes) {
    static const char* const kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = (std::uint32_t(static_cast<unsigned char>(bytes[i])) << 16) | (i + 1 < bytes.size() ? std::uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8 : 0u) |
                                (i + 2 < bytes.size() ? std::uint32_t(static_cast<unsigned char>(bytes[i + 2])) : 0u);
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
    }
    return out;
}

/// Little-endian bytes of integers of `width` bytes (the page reads them as Int32Array / Uint16Array).
class Packed {
public:
    explicit Packed(int width) : width_(width) {}
    void add(std::int64_t v) {
        for (int b = 0; b < width_; ++b) bytes_ += static_cast<char>((static_cast<std::uint64_t>(v) >> (8 * b)) & 0xff);
    }
    std::string text() const { return base64(bytes_); }

private:
    int width_;
    std::string bytes_;
};

}  // namespace

std::string pageData(const Run& run) {
    if (run.states.size() > 65535) throw LimitError("the run has " + std::to_string(run.states.size()) + " distinct cell states, more than the viewer's 65535");
    const checker::TraceColours colours = checker::traceColours();
    nlohmann::json j{{"kind", run.kind}, {"title", run.title}, {"notes", run.notes}, {"lattice", rules::Lattice::get(run.lattice).name()}, {"violation", run.violation}, {"sampled", run.sampled}, {"runSteps", run.runSteps}, {"maxChanges", kMaxChanges}};
    j["palette"] = {{"changed", colours.changed}, {"context", colours.context}, {"cell", colours.cell}, {"noFill", colours.noFill}};
    // A box region in x-fastest order (every region of a plan) is sent as its corner and size.
    Vec lo{}, size{};
    if (!run.cells.empty()) {
        lo = run.cells[0];
        Vec hi = lo;
        for (Vec v : run.cells) lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)}, hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
        size = {hi.x - lo.x + 1, hi.y - lo.y + 1, hi.z - lo.z + 1};
    }
    bool box = std::int64_t(size.x) * size.y * size.z == static_cast<std::int64_t>(run.cells.size());
    for (std::size_t i = 0; box && i < run.cells.size(); ++i) {
        const int k = static_cast<int>(i);
        box = run.cells[i] == lo + Vec{k % size.x, k / size.x % size.y, k / size.x / size.y};
    }
    if (box) {
        j["box"] = {lo.x, lo.y, lo.z, size.x, size.y, size.z};
    } else {
        Packed points(4);
        for (Vec v : run.cells) points.add(v.x), points.add(v.y), points.add(v.z);
        j["points"] = points.text();
    }
    nlohmann::json states = nlohmann::json::array();
    for (const Run::State& s : run.states) states.push_back({s.key, s.colour, s.text});
    j["states"] = states;
    j["legend"] = run.legend;
    nlohmann::json inputs = nlohmann::json::array();
    for (const Run::Input& in : run.inputs) {
        Packed cells(4);
        for (int c : in.cells) cells.add(c);
        inputs.push_back({{"name", in.name}, {"colour", in.colour}, {"cells", cells.text()}});
    }
    j["inputs"] = inputs;
    Packed start(2);
    for (int s : run.start) start.add(s);
    j["start"] = start.text();
    Packed changeStart(4), changeCell(4), changeState(2), contextStart(4), contextCell(4);
    nlohmann::json labels = nlohmann::json::array(), marked = nlohmann::json::object();
    std::int64_t changes = 0, context = 0;
    for (std::size_t k = 0; k < run.steps.size(); ++k) {
        const Run::Step& s = run.steps[k];
        labels.push_back(s.label);
        changeStart.add(changes), contextStart.add(context);
        for (const auto& [cell, state] : s.changes) changeCell.add(cell), changeState.add(state);
        for (int c : s.context) contextCell.add(c);
        changes += static_cast<std::int64_t>(s.changes.size()), context += static_cast<std::int64_t>(s.context.size());
        if (!s.marked.empty()) marked[std::to_string(k)] = s.marked;
    }
    changeStart.add(changes), contextStart.add(context);
    j["labels"] = labels;
    j["marked"] = marked;
    j["changeStart"] = changeStart.text(), j["changeCell"] = changeCell.text(), j["changeState"] = changeState.text();
    j["contextStart"] = contextStart.text(), j["contextCell"] = contextCell.text();
    const std::string dumped = j.dump();
    // Inside <script>, "</" ends the element, and "<!--" with "<script" makes the parser miss the end
    // tag (a rule named "<!--<script>" gave a dead page). In JSON "<" only occurs in strings, where
    // "\u003c" means the same: every one is written so.
    std::string text;
    text.reserve(dumped.size());
    for (const char c : dumped) c == '<' ? text += "\\u003c" : text += c;
    return text;
}

std::string page(Run run) {
    sample(run);
    rules::StopSignals::checkJob("building the page");
    std::string html = kViewerPage;
    const std::string marker = "HOLON_VIEWER_DATA";
    const std::size_t at = html.find(marker);
    if (at == std::string::npos) throw std::logic_error("viewer/viewer.html has no HOLON_VIEWER_DATA placeholder");
    return html.replace(at, marker.size(), pageData(run));
}

}  // namespace holon::viewer
