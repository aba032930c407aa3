// Holonomy checking. A pair (c, c') of legal configurations that are adjacent in state space but
// not one rule instance apart, while c' is reachable from c, is a discrete nonholonomic constraint
// (seed 000 §II-A, Fig. 2); its true distance is a BGL shortest path. For the resource systems the
// check runs on occupancy classes: union-find over the occupancy-preserving edges (transfers) gives
// the configurations reachable "for free", and every occupancy toggle that a state of equal mass in
// the same component realises must be one occupancy-changing edge away from that class.

#include "checker/Holonomy.h"
#include "rules/Parameter.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <map>
#include <numeric>
#include <set>

namespace holon::checker {

namespace {

/// Candidate witnesses: violating pairs among the configurations with the three smallest module
/// counts (a few hundred per count).
struct Witnesses {
    std::map<int, std::vector<std::pair<StateId, StateId>>> byModules;
    void add(StateId from, StateId to, int m) {
        auto& list = byModules[m];
        if (list.size() < 256) list.push_back({from, to});
        if (byModules.size() > 3) byModules.erase(std::prev(byModules.end()));
    }
};

bool isSuccessor(const Explorer& ex, StateId from, StateId to) {
    const auto& row = ex.rowStart();
    const auto& succ = ex.successors();
    return std::find(succ.begin() + row[from], succ.begin() + row[from + 1], to) != succ.begin() + row[from + 1];
}

PropertyResult finish(const Explorer& ex, const GraphView& graph, PropertyResult r, std::uint64_t violations, const Witnesses& w,
                      const std::string& adjacency, const std::string& holdsText) {
    if (violations == 0) {
        r.verdict = ex.stats().stopped == StopReason::Finished ? Verdict::Holds : Verdict::Unknown;
        r.limited = r.verdict == Verdict::Unknown;
        r.summary = r.verdict == Verdict::Holds ? holdsText
                                                : "no violation among the states explored before the limit";
        return r;
    }
    // Among the smallest configurations, show the pair that is furthest apart: it makes the
    // nonholonomic constraint most visible (seed 000 Fig. 2 needs four pivots). Ties go to fewer
    // modules.
    std::pair<StateId, StateId> chosen = w.byModules.begin()->second.front();
    int longest = -1, modules = w.byModules.begin()->first;
    for (const auto& [m, pairs] : w.byModules) {
        std::vector<StateId> froms;
        for (const auto& p : pairs)
            if (std::find(froms.begin(), froms.end(), p.first) == froms.end()) froms.push_back(p.first);
        for (std::size_t k = 0; k < froms.size() && k < 24; ++k) {
            const auto dist = graph.distancesFrom(froms[k]);
            for (const auto& p : pairs)
                if (p.first == froms[k] && dist[p.second] > longest) longest = dist[p.second], chosen = p, modules = m;
        }
    }
    const auto path = graph.shortestPath(chosen.first, chosen.second);
    r.verdict = Verdict::Violated;
    r.trace = traceAlong(ex, path);
    r.trace->property = r.name;
    r.trace->description = "two configurations one " + adjacency + " apart need " + std::to_string(path.size() - 1) + " rule steps";
    r.witness = {{"pairs", violations}, {"distance", path.size() - 1}, {"modules", modules}};
    r.summary = std::to_string(violations) + " adjacent pairs need more than one step; e.g. distance " + std::to_string(path.size() - 1);
    return r;
}

/// A violation found before the timeout or a signal stands, but its count covers only the states checked.
void markPartial(PropertyResult& r, const Budget& budget) {
    r.summary = "at least " + r.summary + (budget.interrupted() ? " (a signal stopped the count)" : " (the timeout stopped the count)");
    r.witness["partial"] = true;
}

PropertyResult stoppedEarly(PropertyResult r, double seconds, const Budget& budget) {
    r.verdict = Verdict::Unknown;
    r.limited = true;
    r.summary = budget.interrupted() ? "stopped by a signal during the holonomy check, no violation found yet"
                                     : "stopped by the timeout during the holonomy check, no violation found yet; raise " + rules::parameterName(rules::Parameter::Timeout);
    r.seconds = seconds;
    return r;
}

}  // namespace

PropertyResult checkHolonomy(const Explorer& ex, const Components& comps, const rules::Property& property, const Budget& budget) {
    const auto start = std::chrono::steady_clock::now();
    PropertyResult r;
    r.name = property.name;
    r.kind = "holonomic";
    const rules::Engine& e = ex.engine();
    const rules::Region& region = e.region();
    const rules::Alphabet& alphabet = e.model().alphabet();
    const bool byMove = property.adjacency == rules::Property::Adjacency::Move;
    const bool projected = !byMove && (alphabet.size() > 2 || !property.exprs.empty());
    const bool symmetricGraph = symmetric(ex);
    std::uint64_t violations = 0;
    Witnesses best;
    const GraphView graph(ex);
    std::vector<CellValue> cells(region.size());
    auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

    bool timedOut = false;
    auto outOfTime = [&] { return timedOut || (timedOut = budget.expired() || budget.interrupted()); };
    auto consider = [&](StateId c, StateId other, int modules) {
        if (other == kNoState || other == c || isSuccessor(ex, c, other)) return;
        if (comps.of[c] != comps.of[other]) return;  // unreachable both ways
        if (!symmetricGraph && graph.shortestPath(c, other).empty()) return;
        ++violations;
        best.add(c, other, modules);
    };

    if (!projected) {
        for (StateId c : ex.ids()) {
            if (outOfTime()) break;
            ex.unpack(c, cells.data());
            int modules = 0;
            for (CellValue v : cells) modules += v != 0;
            for (int i = 0; i < region.size(); ++i) {
                if (byMove) {
                    if (!cells[i]) continue;
                    for (int d = 0; d < region.lattice().degree(); ++d) {
                        const int j = region.neighbour(i, d);
                        if (j < 0 || cells[j]) continue;
                        std::swap(cells[i], cells[j]);
                        const StateId other = ex.find(cells.data());
                        std::swap(cells[i], cells[j]);
                        consider(c, other, modules);
                    }
                } else {
                    const CellValue old = cells[i];
                    cells[i] = old ? 0 : 1;  // the one occupied state
                    const StateId other = ex.find(cells.data());
                    cells[i] = old;
                    consider(c, other, modules);
                }
            }
        }
        const std::string adjacency = byMove ? "module move" : "occupancy toggle";
        if (timedOut && violations == 0) return stoppedEarly(r, seconds(), budget);
        PropertyResult out = finish(ex, graph, r, violations, best, adjacency,
                                    "configurations one " + adjacency + " apart are one rule step apart, or unreachable");
        out.seconds = seconds();
        if (timedOut) markPartial(out, budget);
        return out;
    }

    // Projected check for resource systems (general_n, general-lock_n).
    if (region.size() > 64) {
        r.summary = "the projected check supports regions of at most 64 cells";
        r.seconds = seconds();
        return r;
    }
    // Occupancy: the cells holding a complete metamodule (`of P`, default every occupied cell). A
    // configuration is clean when it has no partial metamodule; pixel steps go between clean ones.
    const rules::CellPredicate* complete = property.exprs.empty() ? nullptr : &property.exprs[0].pred;
    const auto ids = ex.ids();
    const std::size_t n = ex.store().capacityUsed();
    std::vector<std::uint64_t> occupancy(n, 0);
    std::vector<std::int64_t> mass(n, 0);
    std::vector<char> clean(n, 0);
    for (StateId c : ids) {
        ex.unpack(c, cells.data());
        std::uint64_t occupied = 0;
        for (int i = 0; i < region.size(); ++i) {
            if (!cells[i]) continue;
            occupied |= std::uint64_t{1} << i;
            if (!complete || e.cellMatches(*complete, i, cells[i])) occupancy[c] |= std::uint64_t{1} << i;
        }
        clean[c] = occupied == occupancy[c];
        mass[c] = e.massUnits(cells.data());
    }
    // Transfer classes: union-find over the edges that keep the occupancy.
    std::vector<StateId> root(n);
    std::iota(root.begin(), root.end(), 0u);
    auto find = [&](StateId x) {
        while (root[x] != x) x = root[x] = root[root[x]];
        return x;
    };
    const auto& row = ex.rowStart();
    const auto& succ = ex.successors();
    for (StateId c : ids)
        for (std::uint64_t k = row[c]; k < row[c + 1]; ++k)
            if (occupancy[succ[k]] == occupancy[c]) root[find(c)] = find(succ[k]);
    std::vector<char> classHasClean(n, 0);
    for (StateId c : ids)
        if (clean[c]) classHasClean[find(c)] = 1;
    // For each class, the occupancies one occupancy-changing edge away whose class reaches a clean
    // configuration: a pixel step realised by transfers, one change, and transfers again.
    std::map<StateId, std::set<std::uint64_t>> reach;
    for (StateId c : ids)
        for (std::uint64_t k = row[c]; k < row[c + 1]; ++k)
            if (occupancy[succ[k]] != occupancy[c] && classHasClean[find(succ[k])]) reach[find(c)].insert(occupancy[succ[k]]);
    // Clean configurations per (occupancy, mass), with a representative per component.
    std::map<std::pair<std::uint64_t, std::int64_t>, std::map<int, StateId>> present;
    for (StateId c : ids)
        if (clean[c]) present[{occupancy[c], mass[c]}].emplace(comps.of[c], c);
    std::set<StateId> classesDone;
    for (StateId c : ids) {
        if (outOfTime()) break;
        if (!clean[c]) continue;
        const StateId cls = find(c);
        if (!classesDone.insert(cls).second) continue;
        const auto& reachable = reach[cls];
        for (int i = 0; i < region.size(); ++i) {
            const std::uint64_t target = occupancy[c] ^ (std::uint64_t{1} << i);
            auto it = present.find({target, mass[c]});
            if (it == present.end()) continue;
            auto same = it->second.find(comps.of[c]);
            if (same == it->second.end() || reachable.count(target)) continue;
            if (!symmetricGraph && graph.shortestPath(c, same->second).empty()) continue;
            ++violations;
            best.add(c, same->second, std::popcount(occupancy[c]));
        }
    }
    if (timedOut && violations == 0) return stoppedEarly(r, seconds(), budget);
    PropertyResult out = finish(ex, graph, r, violations, best, "occupancy toggle (modulo transfers)",
                                "every pixel step is one occupancy change plus transfers, or unreachable");
    out.seconds = seconds();
    if (timedOut) markPartial(out, budget);
    return out;
}

}  // namespace holon::checker
