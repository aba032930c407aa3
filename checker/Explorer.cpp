// Breadth-first exploration of the reconfiguration graph (seed 000 §II-B: vertices are legal
// configurations, edges single rule instances). Successors come from the compiled engine, which the
// tests hold to the reference interpreter. The frontier is expanded in chunks; within a chunk both
// cores expand disjoint slices and insert into the lock-free store; between chunks the store grows
// and the limits are checked, so a limit stops the search between two chunks with everything found
// so far intact. Parent links give shortest paths for counterexample traces. Only legal states are
// stored, so successors are looked up before any constraint is evaluated; after --all the ids are
// ranks in a bitmap over the candidate configurations, a perfect hash in the manner of Edelkamp and
// Sulewski's ranking-based state space search, and no hash table is needed.

#include "checker/Explorer.h"

#include "checker/ConnectedSets.h"
#include "rules/Error.h"
#include "rules/Parameter.h"
#include "rules/WorkerPool.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace holon::checker {

Explorer::Explorer(const rules::Engine& engine, Options options)
    : engine_(&engine), constraints_(engine), options_(std::move(options)),
      budget_(options_.budget || options_.limits.budget()),
      store_(StateLayout(engine.region().size(), engine.model().alphabet().size(), options_.onWords && WordSuccessors::fits(engine))) {
    if (store_.layout().planeMajor()) words_ = std::make_unique<WordSuccessors>(constraints_, store_.layout());
}

std::vector<CellValue> Explorer::cells(StateId id) const {
    std::vector<CellValue> c(engine_->region().size());
    unpack(id, c.data());
    return c;
}

StateId Explorer::addInitial(const CellValue* cells) {
    if (complete_) throw InternalError("addInitial after addAllLegal, which already holds every legal configuration");
    std::vector<std::uint64_t> packed(store_.layout().words());
    store_.layout().pack(cells, packed.data());
    store_.reserve(1);
    growLinks(store_.capacityUsed() + 1);
    auto [id, inserted] = store_.insert(packed.data());
    if (inserted) {
        frontier_.push_back(id);
        if (options_.onState) options_.onState(id, cells);
    }
    return id;
}

std::uint64_t Explorer::indexOf(const CellValue* cells) const {
    std::uint64_t index = 0;
    for (std::size_t i = 0; i < placeValue_.size(); ++i) index += cells[i] * placeValue_[i];
    return index;
}

StateId Explorer::find(const CellValue* cells) const {
    if (ranked()) return rankOf(indexOf(cells));
    thread_local std::vector<std::uint64_t> packed;
    packed.resize(store_.layout().words());
    store_.layout().pack(cells, packed.data());
    return store_.find(packed.data());
}

void Explorer::addAllLegal() {
    if (store_.capacityUsed() != 0) throw InternalError("addAllLegal on an explorer that already holds states");
    const int n = engine_->region().size();
    const int a = engine_->model().alphabet().size();
    const double candidates = std::pow(static_cast<double>(a), n);
    const double budget = std::min(4.0e9, static_cast<double>(options_.limits.maxStates) * 64.0);
    // Beyond what the states cap lets the run hold, the cap stops it (a limit, exit 3); beyond
    // what any cap allows, the region is too large for --all (bad input, exit 2).
    if (candidates > budget && candidates <= 4.0e9)
        throw LimitError(rules::parameterName(rules::Parameter::All) + " on region " + engine_->region().spec() + " means " + std::to_string(a) + "^" + std::to_string(n) +
                             " candidate configurations, more than " + rules::parameterName(rules::Parameter::MaxStates) + " " + std::to_string(options_.limits.maxStates) +
                             " lets the run hold (64 candidates per state); raise it",
                         rules::Parameter::MaxStates);
    if (candidates > budget)
        throw InputError(rules::parameterName(rules::Parameter::All) + " on region " + engine_->region().spec() + " means " + std::to_string(a) + "^" + std::to_string(n) +
                             " candidate configurations, too many to enumerate; choose a smaller region, or explore from a configuration with " +
                             rules::parameterName(rules::Parameter::Initial),
                         rules::Parameter::All);
    const std::uint64_t total = static_cast<std::uint64_t>(std::llround(candidates));
    // The ranking costs 12 bytes per 64 candidates; it replaces the hash table when that fits
    // comfortably in the memory bound.
    const bool rank = options_.rankAllLegal && static_cast<double>(total) / 64.0 * 12.0 <= static_cast<double>(options_.limits.memoryBytes) / 4.0;
    placeValue_.assign(n, 1);
    for (int i = 1; i < n; ++i) placeValue_[i] = placeValue_[i - 1] * static_cast<std::uint64_t>(a);
    if (rank) legalBits_.assign((total + 63) / 64, 0);
    // Phase 1, on all threads: the legal candidates. Ranked, each thread sets bits in a bitmap of
    // its own (the jobs' indices interleave, and one shared bitmap made two cores slower than
    // one); otherwise each job (an index range, or the connected sets from one lowest cell) lists
    // its indices, and the lists are stored in job order, so ids do not depend on the threads.
    // Where a bitmap per thread would not fit in a quarter of the memory bound, ranked runs list
    // indices too (the lists hold only legal candidates).
    const int threads = std::max(1, options_.limits.threads);
    const bool privateBits = rank && static_cast<double>(threads) * static_cast<double>(total) / 8.0 <= static_cast<double>(options_.limits.memoryBytes) / 4.0;
    std::vector<PageArray<std::uint64_t>> bitmaps(privateBits ? threads : 0);
    for (auto& b : bitmaps) b.resize(legalBits_.size());
    std::vector<std::vector<std::uint64_t>> lists;
    struct alignas(64) Count {
        std::atomic<std::uint64_t> n{0};
    };
    std::vector<Count> listed(threads);  // per thread: indices it listed
    auto found = [&](int thread, std::size_t job, std::uint64_t index) {
        if (privateBits) bitmaps[thread][index >> 6] |= std::uint64_t{1} << (index & 63);
        else lists[job].push_back(index), listed[thread].n.store(listed[thread].n.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    };
    // Asked by the enumerations every so often: the deadline, and the lists against the memory
    // bound (16 bytes an index: a vector's doubling) and --max-states.
    const std::size_t fixedBytes = (bitmaps.size() + 1) * legalBits_.size() * 8;
    auto stop = [&] {
        std::uint64_t n = 0;
        for (const Count& c : listed) n += c.n.load(std::memory_order_relaxed);
        if (const auto why = budget_.reached()) halt(*why);
        else if (!options_.limits.storable(n)) halt(StopReason::MaxStates);
        else if (fixedBytes + 16 * n >= options_.limits.memoryBytes) halt(StopReason::Memory);
        return halted() != StopReason::Finished;
    };
    const rules::CellPredicate* connected = n <= 64 ? constraints_.connectedConjunct() : nullptr;
    if (connected) {
        lists.resize(n + 1);
        legalByConnectedSets(*connected, found, stop);
    } else {
        const std::uint64_t batch = 1u << 20;
        lists.resize((total + batch - 1) / batch);
        legalByIndex(total, batch, found, stop);
    }
    auto giveUp = [&](std::uint64_t count) {  // a limit: nothing is stored, explore() reports it
        enumerated_ = count;
        legalBits_ = {}, placeValue_ = {};
    };
    if (halted() != StopReason::Finished) {
        std::uint64_t count = 0;
        for (const auto& list : lists) count += list.size();
        for (const auto& b : bitmaps)
            for (const std::uint64_t w : b) count += std::popcount(w);
        return giveUp(count);
    }
    // Phase 2: store them, ranked in candidate order (an id is its rank), else in job order (ids
    // do not depend on the threads).
    for (const auto& b : bitmaps)
        for (std::size_t w = 0; w < legalBits_.size(); ++w) legalBits_[w] |= b[w];
    bitmaps.clear();
    if (rank) {
        for (const auto& list : lists)
            for (const std::uint64_t index : list) legalBits_[index >> 6] |= std::uint64_t{1} << (index & 63);
        lists.clear();
    }
    std::size_t count = 0;
    for (const auto& list : lists) count += list.size();
    for (const std::uint64_t w : legalBits_) count += std::popcount(w);
    if (!options_.limits.storable(count)) halt(StopReason::MaxStates);
    else if (rankingBytes() + count * bytesPerNewState() >= options_.limits.memoryBytes) halt(StopReason::Memory);
    if (halted() != StopReason::Finished) return giveUp(count);
    if (!rank) store_.reserve(count);
    growLinks(count);
    frontier_.reserve(count);
    std::vector<CellValue> cells(n);
    std::vector<std::uint64_t> packed(store_.layout().words());
    auto stored = [&](StateId id) {
        frontier_.push_back(id);
        if (options_.onState) unpack(id, cells.data()), options_.onState(id, cells.data());
    };
    if (rank) {
        for (std::size_t w = 0; w < legalBits_.size(); ++w)
            for (std::uint64_t bits = legalBits_[w]; bits; bits &= bits - 1) {
                digits(w * 64 + static_cast<std::uint64_t>(std::countr_zero(bits)), cells.data());
                store_.layout().pack(cells.data(), packed.data());
                stored(store_.append(packed.data()));
            }
        rankBefore_.resize(legalBits_.size());
        StateId before = 0;
        for (std::size_t w = 0; w < legalBits_.size(); ++w) rankBefore_[w] = before, before += static_cast<StateId>(std::popcount(legalBits_[w]));
    } else {
        placeValue_.clear();
        for (const auto& list : lists)
            for (const std::uint64_t index : list) {
                digits(index, cells.data());
                store_.layout().pack(cells.data(), packed.data());
                if (const auto [id, inserted] = store_.insert(packed.data()); inserted) stored(id);
            }
    }
    complete_ = true;
}

void Explorer::digits(std::uint64_t index, CellValue* cells) const {
    // The index's digits in base a, the alphabet size. Indices stay below 2^32 (the candidate
    // budget), where a reciprocal in double, corrected by one step, divides exactly; a 64-bit
    // division per digit cost most of the enumeration.
    const int n = engine_->region().size(), a = engine_->model().alphabet().size();
    if (!(a & (a - 1))) {
        const int bits = std::countr_zero(static_cast<unsigned>(a));
        for (int i = 0; i < n; ++i, index >>= bits) cells[i] = static_cast<CellValue>(index & static_cast<std::uint64_t>(a - 1));
        return;
    }
    const double reciprocal = 1.0 / a;
    for (int i = 0; i < n; ++i) {
        auto quotient = static_cast<std::uint64_t>(static_cast<double>(index) * reciprocal);
        std::int64_t rest = static_cast<std::int64_t>(index) - static_cast<std::int64_t>(quotient * a);
        if (rest < 0) --quotient, rest += a;
        if (rest >= a) ++quotient, rest -= a;
        cells[i] = static_cast<CellValue>(rest);
        index = quotient;
    }
}

template <class Sink, class Stop>
void Explorer::legalByIndex(std::uint64_t total, std::uint64_t batch, Sink& found, Stop& stop) {
    // Every candidate, in batches of indices (the index is the number whose digits in base a
    // are the cells' states): the evaluator follows the few cells that change from one to the
    // next.
    const int n = engine_->region().size();
    std::atomic<std::uint64_t> next{0};
    auto work = [&](int thread) {
        Evaluator ev(constraints_);
        std::vector<CellValue> cells(n);
        for (std::uint64_t job; !stop() && (job = next.fetch_add(1)) * batch < total;) {
            const std::uint64_t lo = job * batch, hi = std::min(total, lo + batch);
            digits(lo, cells.data());
            ev.load(cells.data());
            for (std::uint64_t index = lo; index < hi; ++index, ev.advance())
                if (ev.legal()) found(thread, job, index);
        }
    };
    rules::WorkerPool(std::max(1, options_.limits.threads)).run(work);
}

template <class Sink, class Stop>
void Explorer::legalByConnectedSets(const rules::CellPredicate& connected, Sink& found, Stop& stop) {
    // Every legal configuration's T cells are connected (T: the predicate of a `connected(T)`
    // conjunct), so only configurations whose T cells are a connected set (or none) are
    // candidates: each cell of the set takes a state T accepts, each other cell one it does not.
    const int n = engine_->region().size(), a = engine_->model().alphabet().size();
    std::vector<std::vector<CellValue>> in(n), out(n);  // per cell, the states T accepts / rejects
    for (int c = 0; c < n; ++c)
        for (int v = 0; v < a; ++v) (engine_->cellMatches(connected, c, static_cast<CellValue>(v)) ? in : out)[c].push_back(static_cast<CellValue>(v));
    const ConnectedSets sets(constraints_.adjacency().neighbours());
    std::atomic<int> next{0};
    // The common case: every cell has one state T accepts and one it rejects (pixel: M and _),
    // so a set is one candidate, whose cells in each state and index follow from the set alone.
    const bool determined = constraints_.onWords() &&
                            std::all_of(in.begin(), in.end(), [](const auto& o) { return o.size() == 1; }) &&
                            std::all_of(out.begin(), out.end(), [](const auto& o) { return o.size() == 1; });
    std::vector<std::uint64_t> inCells(a), outCells(a), gain(n);  // gain: index added by a cell joining
    std::uint64_t base = 0;
    if (determined)
        for (int c = 0; c < n; ++c) {
            inCells[in[c][0]] |= std::uint64_t{1} << c, outCells[out[c][0]] |= std::uint64_t{1} << c;
            base += out[c][0] * placeValue_[c], gain[c] = (in[c][0] - out[c][0]) * placeValue_[c];  // wraps: unsigned
        }
    const int connectedWord = constraints_.connectedConjunctWord();  // holds by construction
    auto work = [&](int thread) {
        std::vector<CellValue> cells(n);
        std::vector<int> choice(n), varying;
        std::uint64_t occupied[64];
        auto one = [&](std::size_t job, std::uint64_t set) {
            std::uint64_t index = base;
            for (std::uint64_t b = set; b; b &= b - 1) index += gain[std::countr_zero(b)];
            for (int v = 0; v < a; ++v) occupied[v] = (set & inCells[v]) | (~set & outCells[v]);
            WordConstraints::Words words;
            constraints_.wordsOf(occupied, words);
            if (constraints_.legalOn(words, nullptr, connectedWord)) found(thread, job, index);
        };
        auto each = [&](std::size_t job, std::uint64_t set) {
            if (determined) return one(job, set);
            varying.clear();
            std::uint64_t index = 0;
            for (int c = 0; c < n; ++c) {
                const auto& options = (set >> c) & 1u ? in[c] : out[c];
                if (options.empty()) return;
                choice[c] = 0, cells[c] = options[0], index += cells[c] * placeValue_[c];
                if (options.size() > 1) varying.push_back(c);
            }
            while (true) {  // every combination of the cells' options: an odometer
                if (legalCells(cells.data(), occupied)) found(thread, job, index);
                std::size_t k = 0;
                for (; k < varying.size(); ++k) {
                    const int c = varying[k];
                    const auto& options = (set >> c) & 1u ? in[c] : out[c];
                    index -= cells[c] * placeValue_[c];
                    choice[c] = (choice[c] + 1) % static_cast<int>(options.size());
                    cells[c] = options[choice[c]];
                    index += cells[c] * placeValue_[c];
                    if (choice[c] != 0) break;
                }
                if (k == varying.size()) return;
            }
        };
        std::uint32_t done = 0;
        for (int v; !stop() && (v = next.fetch_add(1)) <= n;) {
            if (v == n) each(n, 0);  // no T cell at all
            else sets.forEachFrom(v, [&](std::uint64_t set) {
                each(v, set);
                return ++done % 4096 != 0 || !stop();
            });
        }
    };
    rules::WorkerPool(std::max(1, options_.limits.threads)).run(work);
}

bool Explorer::legalCells(const CellValue* cells, std::uint64_t* occupied) const {
    if (!constraints_.onWords()) return engine_->legal(cells);
    const int n = engine_->region().size(), a = engine_->model().alphabet().size();
    for (int v = 0; v < a; ++v) occupied[v] = 0;
    for (int c = 0; c < n; ++c) occupied[cells[c]] |= std::uint64_t{1} << c;
    WordConstraints::Words words;
    constraints_.wordsOf(occupied, words);
    return constraints_.legalOn(words);
}

bool Explorer::gather(StateId id, Successors& out, Worker& worker) {
    // Under a ranking a successor is only its rank; otherwise it is packed by patching the
    // parent's words and its table slot is prefetched. On words, a successor's legality is
    // decided here, before any look-up: only legal states are stored, so an illegal successor
    // (40% of them for general1) would be looked up for nothing.
    const StateLayout& layout = store_.layout();
    const int words = layout.words();
    const std::uint64_t* base = store_.state(id);
    out.from = id;
    out.count = 0;
    if (words_) {
        // A two-state alphabet's candidate index is the word of the cells in state 1.
        const bool binary = engine_->model().alphabet().size() == 2;
        WordSuccessors::Loaded& loaded = out.loaded;
        words_->load(base, loaded, ranked() && !binary, !complete_);
        const std::uint64_t index = !ranked() ? 0 : binary ? loaded.occupied[1]
                                                           : indexOf(loaded.cells);
        words_->forEach(loaded, [&](int p, const std::uint64_t* delta, std::uint64_t indexDelta) {
            const std::size_t k = out.count;
            if (ranked()) {
                out.via[k] = p, out.keys[k] = index + indexDelta, ++out.count;
                return;
            }
            std::uint64_t* successor = &out.packed[k * words];
            for (int w = 0; w < words; ++w) successor[w] = base[w] ^ delta[w];
            if (!complete_ && !words_->legal(successor, loaded, p)) return;
            out.via[k] = p, ++out.count;
        });
    } else {
        bool stopped = false;
        std::vector<CellValue>& cells = out.cells;
        cells.resize(engine_->region().size());
        unpack(id, cells.data());
        const std::uint64_t index = ranked() ? indexOf(cells.data()) : 0;
        engine_->forEachMatch(cells.data(), [&](int p) {
            const rules::Engine::Placed& placed = engine_->instances()[p];
            CellValue old[rules::Engine::kMaxCells];
            for (int k = 0; k < placed.size; ++k) old[k] = cells[placed.cells[k]];
            const std::size_t at = out.count++;
            out.via[at] = p;
            if (ranked()) {                            // the rank is all a look-up needs: no packed successor
                std::uint64_t successorIndex = index;  // wraps below zero and back: unsigned arithmetic
                for (int k = 0; k < placed.size; ++k) {
                    const int c = placed.cells[k];
                    successorIndex += (static_cast<std::uint64_t>(engine_->rewritten(placed, k, old)) - cells[c]) * placeValue_[c];
                }
                out.keys[at] = successorIndex;
                return;
            }
            // Only the hash is kept: resolve rebuilds the words where it needs them, so that one
            // state's successors never hold the region's words once per instance. A limit
            // skips the rest (a state of a huge region has hundreds of thousands).
            if ((at & 255) == 255) stopped = stopped || stopping(worker, 256);
            if (stopped) return;
            packSuccessor(out, p, out.packed.data());
            out.keys[at] = store_.prefetch(out.packed.data());
        });
        return !stopped;
    }
    if (!ranked())
        for (std::size_t k = 0; k < out.count; ++k) out.keys[k] = store_.prefetch(&out.packed[k * words]);
    return true;
}

void Explorer::packSuccessor(const Successors& s, int placed, std::uint64_t* out) const {
    const rules::Engine::Placed& p = engine_->instances()[placed];
    const StateLayout& layout = store_.layout();
    const std::uint64_t* base = store_.state(s.from);
    std::copy(base, base + layout.words(), out);
    CellValue old[rules::Engine::kMaxCells];
    for (int k = 0; k < p.size; ++k) old[k] = s.cells[p.cells[k]];
    for (int k = 0; k < p.size; ++k) layout.set(out, p.cells[k], engine_->rewritten(p, k, old));
}

Explorer::Worker::Worker(const WordConstraints& constraints, int words, bool onWords) : ev(constraints), scratch(words) {
    const std::size_t room = constraints.engine().instances().size();  // successors of one state at most
    // On words a state has at most 6 words and the region 64 cells: every successor is kept
    // packed. Cell by cell, one successor's words at a time.
    for (Successors& s : ring) s.packed.resize((onWords ? room : 1) * words), s.keys.resize(room), s.probe.resize(room), s.via.resize(room);
}

std::uint64_t Explorer::Worker::bufferBytes(std::uint64_t instances, int words, bool onWords) {
    const std::uint64_t packed = (onWords ? instances : 1) * static_cast<std::uint64_t>(words) * 8;
    return 3 * (packed + instances * (8 + 8 + 4));  // the ring: packed words, keys, probes, via
}

bool Explorer::claimRoom(Worker& worker, std::uint64_t n, bool mayRefuse) {
    // From the worker's own share first; the round's room is taken a block at a time, so the
    // threads seldom meet on its cache line.
    if (worker.room >= n) return worker.room -= n, true;
    for (const std::uint64_t take : {std::max<std::uint64_t>(n, 4096), n}) {
        const auto want = static_cast<std::int64_t>(take);
        if (room_.fetch_sub(want, std::memory_order_relaxed) >= want) return worker.room += take - n, true;
        room_.fetch_add(want, std::memory_order_relaxed);
    }
    if (!mayRefuse) return false;
    for (std::uint64_t seen = refusedClaim_.load(); seen < n && !refusedClaim_.compare_exchange_weak(seen, n);) {}
    abandon_.store(true, std::memory_order_relaxed);
    return false;
}

bool Explorer::resolve(const Successors& s, Worker& worker) {
    // A state is either done or untouched. Its new successors are stored in room taken for them
    // beforehand: for a state with few successors, one for each (most are known already, and the
    // rest is given back); otherwise a first pass looks every successor up and decides the
    // legality of those not found, changing nothing, so that a limit or a full store puts the
    // state back for a later round, and takes room for exactly the new ones. Only legal states
    // are ever stored, so a successor found needs no constraint check; one not found is new if
    // gather already decided it is legal (on words), is checked with the incremental evaluator
    // (cell by cell), or, when the store already holds every legal configuration (--all), known
    // to be illegal.
    constexpr StateId kFresh = kNoState - 1;  // a new legal successor, not stored yet
    constexpr std::size_t kOnePass = 1024;
    const int words = store_.layout().words();
    std::uint64_t* scratch = worker.scratch.data();
    auto successor = [&](std::size_t k) -> const std::uint64_t* {
        if (words_) return &s.packed[k * words];
        packSuccessor(s, s.via[k], scratch);
        return scratch;
    };
    Evaluator& ev = worker.ev;
    bool loaded = false;
    auto lookUp = [&](std::size_t k) {
        const StateId sid = ranked() ? rankOf(s.keys[k]) : store_.find(successor(k), s.keys[k], s.probe[k]);
        if (sid != kNoState || complete_) return sid;
        if (!words_) {  // on words: decided in gather
            if (!loaded) ev.load(s.cells.data()), loaded = true;
            CellValue saved[rules::Engine::kMaxCells];
            ev.apply(s.via[k], saved);
            const bool legal = ev.legal();
            ev.undo(s.via[k], saved);
            if (!legal) return kNoState;
        }
        return kFresh;
    };
    std::uint64_t room = s.count;
    const bool onePass = s.count <= kOnePass && (complete_ || claimRoom(worker, room, false));
    std::vector<StateId>& found = worker.found;
    if (!onePass) {
        found.resize(s.count);
        room = 0;
        for (std::size_t k = 0; k < s.count; ++k) {
            if ((k & 255) == 255 && stopping(worker, 256)) return false;  // a state of a huge region can take seconds
            if ((found[k] = lookUp(k)) == kFresh) ++room;
        }
        if (room && !claimRoom(worker, room, true)) return false;
    }
    thread_local std::vector<StateId> seen;
    thread_local std::vector<std::pair<StateId, int>> rulesSeen;  // (successor, rule) of every recorded step
    seen.clear(), rulesSeen.clear();
    // The rules an instance's step is a step of: its shape may be kept once for several
    // (rules::RuleShape::rules). An instance that adds one to a step already recorded is listed too.
    auto addsRules = [&](StateId sid, std::int32_t via) {
        bool added = false;
        for (int rule : engine_->model().shapes()[static_cast<std::size_t>(engine_->instances()[via].shape)].rules)
            if (std::find(rulesSeen.begin(), rulesSeen.end(), std::pair<StateId, int>{sid, rule}) == rulesSeen.end()) rulesSeen.push_back({sid, rule}), added = true;
        return added;
    };
    std::uint64_t edges = 0, added = 0;
    for (std::size_t k = 0; k < s.count; ++k) {
        StateId sid = onePass ? lookUp(k) : found[k];
        if (sid == kNoState) continue;
        if (sid == kFresh) {
            const auto [id, inserted] = store_.insert(successor(k), s.keys[k], worker.ids);
            sid = id;
            if (inserted) {
                ++added;
                parent_[sid] = s.from + 1;
                via_[sid] = s.via[k] + 1;
                worker.next.push_back(sid);
                if (options_.onState) {
                    thread_local std::vector<CellValue> unpacked;
                    unpacked.resize(engine_->region().size());
                    unpack(sid, unpacked.data());
                    options_.onState(sid, unpacked.data());
                }
            }
        }
        // Two instances with the same effect are one edge of the graph.
        if (!words_ || !words_->unique(s.via[k])) {
            if (std::find(seen.begin(), seen.end(), sid) != seen.end()) {
                if (options_.recordEdges && addsRules(sid, s.via[k])) worker.otherRules.push_back({s.from, sid, s.via[k]});
                continue;
            }
            seen.push_back(sid);
            if (options_.recordEdges) addsRules(sid, s.via[k]);
        }
        ++edges;
        if (options_.recordEdges) worker.edges.push_back({s.from, sid, s.via[k]});
    }
    if (!complete_) worker.room += room - added;  // what was not used, or another thread stored first
    if (edges == 0) worker.terminal.push_back(s.from);
    worker.edgeCount += edges;
    return true;
}

void Explorer::expandRange(const StateId* states, std::size_t lo, std::size_t hi, Worker& worker) {
    // A software pipeline over the frontier, so that a look-up finds its data in cache: the
    // successors of state k are generated (their table slots prefetched) while those of state k - 1
    // have their stored states (or their words of the ranking) prefetched and those of state k - 2
    // are looked up. A stop puts back every state not resolved yet.
    Successors* ring = worker.ring;
    auto putBack = [&](std::size_t first) { worker.deferred.insert(worker.deferred.end(), states + first, states + hi); };
    for (std::size_t k = lo; k < hi + 2; ++k) {
        if (k < hi) {
            if (stopping(worker, 1) || !gather(states[k], ring[k % 3], worker)) return putBack(k - std::min<std::size_t>(k - lo, 2));
        }
        if (k >= lo + 1 && k - 1 < hi) {
            Successors& s = ring[(k - 1) % 3];
            if (ranked())
                for (std::size_t j = 0; j < s.count; ++j) prefetchRank(s.keys[j]);
            else
                for (std::size_t j = 0; j < s.count; ++j) s.probe[j] = store_.prefetchStored(s.keys[j]);
        }
        if (k >= lo + 2 && !resolve(ring[(k - 2) % 3], worker)) return putBack(k - 2);
    }
}

std::size_t Explorer::bytesPerNewState() const {
    // Its words, its table slots at 7/8 full and while the table is rebuilt, its hole flag, its
    // BFS links, its row start, its place in a frontier list.
    return static_cast<std::size_t>(store_.layout().words()) * 8 + 10 + 1 + 8 + 8 + 4;
}

std::size_t Explorer::bytesHeld(const std::vector<Worker>& workers, std::size_t listed) const {
    // The stored states with their table and BFS links, and the row starts built when the search
    // ends. Room reserved beyond the states stored is not counted: its pages are untouched until
    // a state is stored there, and a round stores at most the room it was given.
    const std::size_t used = store_.capacityUsed();
    std::size_t bytes = store_.bytesUsed() + rankingBytes() + used * (sizeof(StateId) + sizeof(std::int32_t)) +
                        (options_.recordEdges ? used * sizeof(std::uint64_t) : 0) + (listed + terminal_.size()) * sizeof(StateId);
    for (const Worker& w : workers) {
        // Each edge is held by its worker now and in the rows (successor and instance) later.
        bytes += w.edges.size() * (sizeof(Worker::Edge) + sizeof(StateId) + sizeof(std::int32_t));
        for (const Successors& s : w.ring)
            bytes += s.packed.capacity() * 8 + (s.keys.capacity() + s.probe.capacity()) * 8 + s.via.capacity() * 4 + s.cells.capacity();
        bytes += (w.found.capacity() + w.next.capacity() + w.terminal.capacity() + w.deferred.capacity()) * sizeof(StateId);
    }
    return bytes;
}

const ExploreStats& Explorer::explore() {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto last = start;
    stats_ = {};
    const int threads = std::max(1, options_.limits.threads);
    const std::uint64_t branching = std::max<std::size_t>(1, engine_->instances().size());
    // A chunk of frontier states per round; the room reserved for a round's new states is at
    // most kRoundBytes of store (a million states of a few words), whatever the branching: a
    // round that needs more puts its remaining states back and runs again after growing.
    const std::uint64_t chunk = std::max<std::uint64_t>(64, std::min<std::uint64_t>(1u << 14, (1u << 20) / branching));
    constexpr std::uint64_t kRoundBytes = 32ull << 20;
    // The workers' buffers hold one state's successors, a slot per instance of the region: on a
    // huge region they alone can be over the memory bound, and then nothing is explored.
    const std::uint64_t workerBytes = rules::checkedProduct({std::uint64_t(threads), Worker::bufferBytes(branching, store_.layout().words(), words_ != nullptr)});
    const bool workersFit = workerBytes < options_.limits.memoryBytes;
    std::vector<Worker> workers;
    // Each takes a pass over its buffers (0.3 s on 4 million cells): the budget is read between them.
    for (int t = 0; t < threads && workersFit && !budget_.reached(); ++t) workers.emplace_back(constraints_, store_.layout().words(), words_ != nullptr);
    rules::WorkerPool pool(threads);
    // A level's states are kept by the worker that found them, and each worker expands a slice of
    // its own list first (their words were written from its core, so they are in its cache),
    // then helps with the others'. Threads take slices a piece at a time: the cores of a shared
    // host seldom run at the same speed, and an even split leaves the faster one waiting.
    constexpr std::size_t kPiece = 256;
    struct alignas(64) Cursor {
        std::atomic<std::size_t> next{0};
        const StateId* states = nullptr;
        std::size_t end = 0;
    };
    std::vector<Cursor> cursors(threads);
    std::vector<std::vector<StateId>> level(threads), next(threads), retry(threads), putBack(threads);
    level[0] = std::move(frontier_);
    frontier_.clear();
    const std::uint64_t blockRoom = static_cast<std::uint64_t>(threads) * StateStore::IdBlock::kSize;
    const std::uint64_t perState = bytesPerNewState();
    // The store's size when a round last ran with a state put back over the state cap.
    std::uint64_t overCapAt = std::numeric_limits<std::uint64_t>::max();
    auto sizeOf = [](const std::vector<std::vector<StateId>>& lists) {
        std::size_t n = 0;
        for (const auto& l : lists) n += l.size();
        return n;
    };
    if (halted() != StopReason::Finished)  // --all stopped while listing the legal configurations
        stats_.stopped = halted(), stats_.enumerating = true, stats_.frontier = enumerated_;
    else if (const auto why = budget_.reached(); why || !workersFit)  // a signal during the set-up is a signal, not a memory stop
        halt(why.value_or(StopReason::Memory)), stats_.stopped = halted(), stats_.frontier = sizeOf(level);
    while (sizeOf(level) > 0 && stats_.stopped == StopReason::Finished) {
        const std::size_t chunks = (sizeOf(level) + chunk - 1) / chunk;
        for (std::size_t c = 0; c < chunks; ++c) {
            auto from = [&](int t, std::size_t k) { return level[t].size() * k / chunks; };  // slice k of list t
            std::size_t left = 0;                                                            // states of this level not yet expanded, the chunk's included
            for (int t = 0; t < threads; ++t) left += level[t].size() - from(t, c);
            // Rounds on the chunk's slices, then on the states a round put back.
            std::size_t size = 0, pending = 0;
            for (int t = 0; t < threads; ++t) {
                cursors[t].next = 0, cursors[t].states = level[t].data() + from(t, c), cursors[t].end = from(t, c + 1) - from(t, c);
                size += cursors[t].end;
            }
            for (pending = size; pending > 0;) {
                // The room for this round's new states: what the states put back asked for at
                // least, within the state cap (Limits::stateRoom) and the memory bound. A state
                // put back asking for more than the cap leaves is retried once with what is left
                // (other threads may have stored its successors meanwhile); asking again at the
                // same size, it needs a state beyond the cap.
                const std::uint64_t refused = refusedClaim_.exchange(0);
                const std::uint64_t capRoom = options_.limits.stateRoom(store_.size());
                const bool overCap = refused > capRoom;
                std::uint64_t want = 0;
                if (!complete_) want = std::min(std::max(std::min<std::uint64_t>(pending * branching, std::max<std::uint64_t>(1, kRoundBytes / perState)), refused), capRoom);
                // As many states as the memory bound has left room for, and at least the largest
                // state put back (within the cap).
                const std::size_t held = bytesHeld(workers, sizeOf(level) + sizeOf(next) + sizeOf(retry));
                want = std::min<std::uint64_t>(want, held < options_.limits.memoryBytes ? (options_.limits.memoryBytes - held) / perState : 0);
                const std::uint64_t need = complete_ ? 0 : std::min(std::max<std::uint64_t>(refused, 1), capRoom);
                StopReason limit = StopReason::Finished;
                if (overCap && store_.size() == overCapAt) limit = StopReason::MaxStates;
                else if (const auto why = budget_.reached()) limit = *why;
                else if (held >= options_.limits.memoryBytes || want < need) limit = StopReason::Memory;
                if (overCap) overCapAt = store_.size();
                room_ = static_cast<std::int64_t>(want);
                for (Worker& w : workers) w.room = 0;
                abandon_ = false;
                if (limit != StopReason::Finished) {
                    halt(limit);
                } else {
                    try {
                        if (!complete_) {
                            store_.reserve(want + blockRoom);
                            growLinks(store_.capacityUsed() + want + blockRoom);
                        }
                        pool.run([&](int t) {
                            try {
                                for (int i = 0; i < threads; ++i) {
                                    const int u = (t + i) % threads;
                                    for (std::size_t lo; !abandon_.load(std::memory_order_relaxed) && (lo = cursors[u].next.fetch_add(kPiece)) < cursors[u].end;)
                                        expandRange(cursors[u].states, lo, std::min(cursors[u].end, lo + kPiece), workers[t]);
                                }
                            } catch (...) {
                                abandon_ = true;  // the others stop too; the pool rethrows on this thread
                                throw;
                            }
                        });
                    } catch (const std::bad_alloc&) {  // every thread is back: a memory stop
                        halt(StopReason::Memory);
                    }
                }
                for (int t = 0; t < threads; ++t) {
                    Worker& w = workers[t];
                    store_.release(w.ids);
                    next[t].insert(next[t].end(), w.next.begin(), w.next.end());
                    terminal_.insert(terminal_.end(), w.terminal.begin(), w.terminal.end());
                    stats_.edges += w.edgeCount;
                    w.next.clear(), w.terminal.clear(), w.edgeCount = 0;
                    // What the round left: the states the workers put back, the pieces no one took.
                    putBack[t].swap(w.deferred);
                    w.deferred.clear();
                }
                for (int u = 0; u < threads; ++u)
                    for (std::size_t k = std::min(cursors[u].next.load(), cursors[u].end); k < cursors[u].end; ++k) putBack[u].push_back(cursors[u].states[k]);
                std::swap(retry, putBack);
                for (auto& l : putBack) l.clear();
                pending = sizeOf(retry);
                for (int t = 0; t < threads; ++t) cursors[t].next = 0, cursors[t].states = retry[t].data(), cursors[t].end = retry[t].size();
                stats_.states = store_.size();
                stats_.frontier = left - size + pending + sizeOf(next);
                if (halted() != StopReason::Finished) {
                    stats_.stopped = halted();
                    break;
                }
                if (options_.onProgress && std::chrono::duration<double>(Clock::now() - last).count() > 0.5) {
                    last = Clock::now();
                    stats_.seconds = std::chrono::duration<double>(last - start).count();
                    options_.onProgress(stats_);
                }
            }
            for (auto& l : retry) l.clear();
            if (stats_.stopped != StopReason::Finished) break;
        }
        if (stats_.stopped != StopReason::Finished) break;
        std::swap(level, next);
        for (auto& l : next) l.clear();
        if (sizeOf(level) > 0) ++stats_.depth;
        if (sizeOf(level) > 0 && options_.decided && options_.decided()) {
            stats_.stopped = StopReason::Decided;
            stats_.frontier = sizeOf(level);
        }
    }
    std::sort(terminal_.begin(), terminal_.end());
    stats_.states = store_.size();
    store_.shrinkToFit();
    parent_.resize(store_.capacityUsed());
    via_.resize(store_.capacityUsed());
    parent_.shrinkToFit();
    via_.shrinkToFit();
    if (options_.recordEdges) buildRows(workers);
    stats_.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats_.bytes = store_.bytes() + rankingBytes() + parent_.size() * 8 + succ_.size() * 8 + rowStart_.size() * 8;
    return stats_;
}

void Explorer::buildRows(std::vector<Worker>& perThread) {
    const std::size_t n = store_.capacityUsed();
    rowStart_.assign(n + 1, 0);
    for (const Worker& f : perThread)
        for (const Worker::Edge& e : f.edges) ++rowStart_[e.from + 1];
    for (std::size_t i = 0; i < n; ++i) rowStart_[i + 1] += rowStart_[i];
    succ_.resize(rowStart_[n]);
    succVia_.resize(rowStart_[n]);
    std::vector<std::uint64_t> fill(rowStart_.begin(), rowStart_.end() - 1);
    for (Worker& f : perThread) {
        for (const Worker::Edge& e : f.edges) {
            succ_[fill[e.from]] = e.to;
            succVia_[fill[e.from]++] = e.via;
        }
        f.edges.resize(0);
        f.edges.shrinkToFit();
    }
    otherVia_.clear();
    for (Worker& f : perThread) {
        for (const Worker::Edge& e : f.otherRules)
            for (std::uint64_t k = rowStart_[e.from]; k < rowStart_[e.from + 1]; ++k)
                if (succ_[k] == e.to) otherVia_.push_back({k, e.via});
        f.otherRules = {};
    }
    std::sort(otherVia_.begin(), otherVia_.end());
}

std::vector<std::int32_t> Explorer::viasOf(std::uint64_t edge) const {
    std::vector<std::int32_t> out{succVia_[edge]};
    for (auto it = std::lower_bound(otherVia_.begin(), otherVia_.end(), std::pair<std::uint64_t, std::int32_t>{edge, INT32_MIN}); it != otherVia_.end() && it->first == edge; ++it)
        out.push_back(it->second);
    return out;
}

std::vector<StateId> Explorer::ids() const {
    std::vector<StateId> out;
    for (StateId id = 0; id < store_.capacityUsed(); ++id)
        if (!store_.isHole(id)) out.push_back(id);
    return out;
}

std::vector<std::pair<StateId, std::int32_t>> Explorer::pathTo(StateId id) const {
    std::vector<std::pair<StateId, std::int32_t>> path;
    for (StateId s = id; s != kNoState; s = parent(s)) path.push_back({s, via(s)});
    std::reverse(path.begin(), path.end());
    return path;
}

std::size_t Explorer::bytesPerState() const {
    const double ranking = static_cast<double>(rankingBytes()) / static_cast<double>(std::max<std::uint64_t>(1, store_.size()));
    return static_cast<std::size_t>(std::ceil(store_.bytesPerState() + ranking)) + sizeof(StateId) + sizeof(std::int32_t);
}

}  // namespace holon::checker
