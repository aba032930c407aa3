// `holon view INPUT -o FILE.html`: one self-contained HTML page that plays a run back in a
// browser: an ITF trace, a plan, a hex sculpting run or a Roombots run (viewer/Readers.h), told
// apart by their content. The page needs no network and no server (docs/viewer.md).

#include "cli/Commands.h"

#include "rules/OutputFile.h"
#include "viewer/Page.h"
#include "viewer/Readers.h"

#include <iostream>
#include <memory>

namespace holon::cli {

namespace {

struct ViewArgs {
    std::string input, out, rules;
    std::uint64_t memoryMiB = kDefaultMemoryMiB;
};

int run(const ViewArgs& a) {
    rules::OutputClaims::reading("the input", a.input);  // -o must not replace it
    const rules::OutputFile file("-o", a.out);           // checked before the input is read
    viewer::Run r = viewer::readRun(a.input, a.rules, a.memoryMiB << 20);
    viewer::sample(r);  // to say so below; page() would
    file.write(viewer::page(r));
    std::cout << "view " << a.out << ": " << r.title << ", " << r.steps.size() - 1 << " steps shown"
              << (r.sampled > 1 ? " (sampled: each is " + std::to_string(r.sampled) + " steps of the run's " + std::to_string(r.runSteps) + ")" : "") << ", "
              << r.cells.size() << " cells\n";
    return kExitOk;
}

}  // namespace

Run addViewCommand(CLI::App& app) {
    auto a = std::make_shared<ViewArgs>();
    CLI::App* sub = app.add_subcommand("view", "write a self-contained HTML viewer of a trace, plan, hex run or Roombots run (docs/viewer.md)");
    sub->add_option("input", a->input, "an ITF trace (check/path --trace-out), a plan (plan --plan-out), a hex run (hex --steps-out) or a Roombots run (roombots --out: steps_*.jsonl)")->required();
    sub->add_option("-o,--out", a->out, "the HTML file to write")->required();
    sub->add_option("--rules", a->rules, "the rule file the input's states belong to (default: the one it names)");
    sub->add_option("--memory", a->memoryMiB, "memory bound in MiB for reading the input (default 16384): a larger input is refused before it is read (exit 3)")
        ->check(memoryValidator());
    return [a] { return withinMemory(a->memoryMiB, [&] { return run(*a); }); };
}

}  // namespace holon::cli
