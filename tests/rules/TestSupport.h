#pragma once
// Helpers shared by the rules tests: parse a system from text, build configurations from ASCII art.

#include "rules/ConfigIo.h"
#include "rules/Diagnostics.h"
#include "rules/Interpreter.h"
#include "rules/Library.h"
#include "rules/Parser.h"

#include <doctest/doctest.h>
#include <filesystem>
#include <memory>
#include <string>

namespace holon::test {

inline rules::System parse(const std::string& text) {
    rules::Diagnostics d("test.holon", text);
    auto s = rules::parseSystem(text, d);
    INFO(d.render());
    REQUIRE(s.has_value());
    return *s;
}

/// A system placed on a region, with an interpreter; owns everything it points to.
struct World {
    rules::System system;
    rules::Region region;
    std::unique_ptr<rules::Model> model;
    std::unique_ptr<rules::Interpreter> in;
    World(rules::System s, const std::string& spec) : system(std::move(s)), region(rules::Region::parse(spec)) {
        model = std::make_unique<rules::Model>(system, region.lattice());
        in = std::make_unique<rules::Interpreter>(*model, region);
    }
    static World library(const std::string& stem, const std::string& spec) { return World(rules::librarySystem(stem), spec); }
    rules::Configuration ascii(const std::string& art) const { return rules::configFromAscii(*in, art); }
    /// Sets input `name` on the cells marked in the ASCII mask.
    void mark(rules::Configuration& c, const std::string& name, const std::string& mask) const {
        const int k = system.inputIndex(name);
        REQUIRE(k >= 0);
        auto bits = rules::maskFromAscii(region, mask);
        for (int i = 0; i < region.size(); ++i)
            if (bits[i]) c.inputs[i] |= 1u << k;
    }
    int value(const std::string& name) const {
        for (int v = 0; v < model->alphabet().size(); ++v)
            if (model->alphabet().name(static_cast<rules::CellValue>(v)) == name) return v;
        FAIL("no state " << name);
        return -1;
    }
    void set(rules::Configuration& c, int x, int y, const std::string& state) const {
        c.cells[region.indexOf({x, y, 0})] = static_cast<rules::CellValue>(value(state));
    }
    std::string at(const rules::Configuration& c, int x, int y) const {
        return model->alphabet().name(c.cells[region.indexOf({x, y, 0})]);
    }
    /// Names of the rules of the enabled instances, sorted, with repeats.
    std::vector<std::string> enabledRules(const rules::Configuration& c) const {
        std::vector<std::string> names;
        for (const auto& i : in->enabled(c)) names.push_back(model->rules()[model->shapes()[i.shape].rule].name);
        std::sort(names.begin(), names.end());
        return names;
    }
};

}  // namespace holon::test
