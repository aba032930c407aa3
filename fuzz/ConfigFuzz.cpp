// libFuzzer target for configuration files, the second input format after rule files: any byte
// string read as a configuration (canonical JSON, an ITF trace, ASCII art) or as an input mask, for
// systems on each lattice, must be accepted or rejected with InputError. A configuration that is
// accepted must write to JSON that reads back to the same configuration. Crashes, hangs, leaks,
// sanitizer reports and any other exception are failures.

#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Library.h"

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

struct World {
    holon::rules::System system;
    holon::rules::Region region;
    std::unique_ptr<holon::rules::Model> model;
    std::unique_ptr<holon::rules::Interpreter> in;
    World(const char* name, const char* spec) : system(holon::rules::librarySystem(name)), region(holon::rules::Region::parse(spec)) {
        model = std::make_unique<holon::rules::Model>(system, region.lattice());
        in = std::make_unique<holon::rules::Interpreter>(*model, region);
    }
};

const std::vector<std::unique_ptr<World>>& worlds() {
    static const auto all = [] {
        std::vector<std::unique_ptr<World>> w;
        w.push_back(std::make_unique<World>("planner_general1", "square:4x3"));
        w.push_back(std::make_unique<World>("general_lock2", "cubic:2x2x2"));
        w.push_back(std::make_unique<World>("hex_holes", "hex:r2"));
        return w;
    }();
    return all;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (const auto& w : worlds()) {
        try {
            const holon::rules::Configuration c = holon::rules::configFromText(*w->in, text);
            const std::string again = holon::rules::configToJson(*w->in, c).dump();
            if (!(holon::rules::configFromText(*w->in, again) == c)) std::abort();
        } catch (const holon::InputError&) {
        }
        try {
            (void)holon::rules::maskFromAscii(w->region, text);
        } catch (const holon::InputError&) {
        }
    }
    return 0;
}
