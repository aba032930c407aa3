#pragma once
// Running checks from tests: a system, a region, and the kept exploration.

#include "TestSupport.h"
#include "checker/Check.h"
#include "checker/Trace.h"
#include "rules/Error.h"
#include "rules/TextFile.h"

namespace holon::test {

/// A deliberately broken variant of a library system, from tests/checker/broken/STEM.holon.
inline rules::System brokenSystem(const std::string& stem) {
    return parse(rules::readTextFile(std::string(HOLON_TEST_DIR) + "/checker/broken/" + stem + ".holon"));
}

struct Checked {
    World world;
    checker::CheckReport report;
    checker::Exploration kept;
    const checker::PropertyResult& property(const std::string& name) const {
        for (const auto& p : report.properties)
            if (p.name == name) return p;
        FAIL("no property " << name);
        return report.properties.front();
    }
    /// Every trace in the report replays through the reference interpreter.
    void replayAll() const {
        for (const auto& p : report.properties) {
            if (!p.trace) continue;
            std::string why;
            INFO(p.name << ": " << why);
            CHECK(checker::replay(*p.trace, *kept.engine, *world.in, &why));
        }
    }
};

inline Checked checkAll(rules::System system, const std::string& spec, checker::Limits limits = {}) {
    Checked c{World(std::move(system), spec), {}, {}};
    checker::CheckOptions o;
    o.all = true;
    o.limits = limits;
    c.report = checker::check(*c.world.model, c.world.region, o, &c.kept);
    return c;
}

inline Checked checkFrom(rules::System system, const std::string& spec, const std::string& start, const std::string& target,
                         checker::Limits limits = {}, std::vector<std::string> properties = {}) {
    Checked c{World(std::move(system), spec), {}, {}};
    checker::CheckOptions o;
    o.limits = limits;
    o.properties = std::move(properties);
    auto config = c.world.ascii(start);
    if (!target.empty()) c.world.mark(config, "target", target);
    o.initial.push_back(config);
    c.report = checker::check(*c.world.model, c.world.region, o, &c.kept);
    return c;
}

/// general-lock_2 with a ranking (tests/checker/broken/general_lock2_ranked.holon) from two
/// creators and a D on square:3x2: transfers between locked pairs can cycle there.
inline Checked checkLockedTransfers(rules::System system) {
    Checked c{World(std::move(system), "square:3x2"), {}, {}};
    checker::CheckOptions o;
    auto start = c.world.in->empty();
    c.world.set(start, 0, 0, "C"), c.world.set(start, 1, 0, "C"), c.world.set(start, 0, 1, "D");
    o.initial.push_back(start);
    c.report = checker::check(*c.world.model, c.world.region, o, &c.kept);
    return c;
}

}  // namespace holon::test
