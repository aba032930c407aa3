// `holon export`: files other tools read. A planning shape (`--shape`, the syntax of plan --from,
// with an optional `--target`, plan's --to) or a configuration (`--config`, what check --from
// reads: JSON, ASCII art, an ITF trace's state, plan's end.json) written as a VisibleSim world
// (rules/VisibleSim.h) and/or as a .binvox voxel file (rules/Binvox.h), which plan --from reads
// back. Modules are coloured as in holon's SVG pictures: a configuration's cells by their state
// (checker::stateColour), a shape's modules in one colour and its target in another.

#include "checker/Draw.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "planner/Shape.h"
#include "rules/Binvox.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/OutputFile.h"
#include "rules/Region.h"
#include "rules/VisibleSim.h"

#include <iostream>
#include <map>
#include <optional>

namespace holon::cli {

namespace {

struct ExportArgs {
    std::string shape, target, config, rules, region, visibleSim, binvox, robot;
    std::vector<std::string> noWarnings;
    int scale = 1, margin = 0;
    std::uint64_t memoryMiB = kDefaultMemoryMiB;
};

// What the export holds per module at its peak, beside the shape's own cells: the module and its
// colour (48 bytes), its line of a VisibleSim world (about 55) and the copy the writer makes of the
// text. Measured: box:200x200x200 (8 million modules) peaked at 1.25 GB, 156 bytes a module. A
// .binvox alone holds the modules and their cells (60 bytes) and a bit per voxel of the cube: the
// same box peaked at 494 MB, 62 bytes a module.
constexpr std::uint64_t kBytesPerModule = 160, kBytesPerVoxelModule = 64;
// A configuration's text while it is parsed, per byte: the text and its JSON tree (measured 14).
constexpr std::uint64_t kBytesPerConfigByte = 16;

/// Refuses an export whose modules would not fit --memory, before the world is built.
void requireExportMemory(std::uint64_t modules, const ExportArgs& a) {
    const std::uint64_t perModule = a.visibleSim.empty() ? kBytesPerVoxelModule : kBytesPerModule;
    rules::requireMemory(rules::checkedProduct({modules, perModule}), a.memoryMiB << 20, "writing " + rules::countText(modules) + " modules");
}

// A shape's modules and its target cells: the first two colours of the checker's palette.
constexpr const char* kShapeColour = "#4e79a7";
constexpr const char* kTargetColour = "#59a14f";

/// What is exported: the lattice, the modules (and target cells) with their colours, and the lines
/// that say what they are.
struct Exported {
    const rules::Lattice* lattice = nullptr;
    std::vector<rules::VisibleSimCell> blocks, targets;
    std::vector<std::string> comments;
};

Exported fromShapes(const ExportArgs& a) {
    const std::uint64_t memory = a.memoryMiB << 20;
    const planner::Shape shape = planner::parseShape(a.shape, a.scale, memory);
    requireExportMemory(shape.cells.size(), a);
    Exported e;
    e.lattice = &rules::Lattice::get(shape.dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D);
    for (rules::Vec v : shape.cells) e.blocks.push_back({v, kShapeColour});
    e.comments.push_back("holon export: shape " + shape.name + (a.scale > 1 ? " at --scale " + std::to_string(a.scale) : "") + ", " +
                         std::to_string(shape.cells.size()) + " modules in " + kShapeColour);
    if (!a.target.empty()) {
        const planner::Shape target = planner::parseShape(a.target, a.scale, memory - std::min(memory, shape.cells.size() * sizeof(rules::Vec)));
        if (target.dimension != shape.dimension)
            throw InputError("--target '" + a.target + "' is a " + std::to_string(target.dimension) + "D shape, --shape '" + a.shape + "' a " +
                             std::to_string(shape.dimension) + "D one; give two shapes of the same dimension, as plan --from and --to");
        requireExportMemory(shape.cells.size() + target.cells.size(), a);
        for (rules::Vec v : target.cells) e.targets.push_back({v, kTargetColour});
        e.comments.push_back("target (targetList): shape " + target.name + ", " + std::to_string(target.cells.size()) + " cells in " + kTargetColour);
    }
    return e;
}

[[noreturn]] void refuseBinvox2D(const rules::Lattice& lattice) {
    throw InputError("--binvox: binvox holds 3D voxel shapes and this " + lattice.name() + " one is 2D; give a 3D shape or configuration, or write --visiblesim");
}

Exported fromConfiguration(const ExportArgs& a) {
    // A JSON configuration (plan's end.json included) names its system and region, a trace its
    // rule file and region: those are the defaults; ASCII art names neither.
    const rules::ConfigText file = rules::readConfigText(a.config);  // once: a pipe gives its text once
    const std::string source = namedInText(file.text, "source");
    const std::string rulesName = !a.rules.empty() ? a.rules : !source.empty() ? source
                                                                               : namedInText(file.text, "system");
    const std::string regionSpec = !a.region.empty() ? a.region : namedInText(file.text, "region");
    if (rulesName.empty() || regionSpec.empty())
        throw InputError("--config " + a.config + " does not name its " + (rulesName.empty() ? "system" : "region") +
                         "; give --rules (the system it is a configuration of) and --region (the region it lies on), as holon check --from takes them");
    const auto system = loadRules(rulesName, a.noWarnings, !a.rules.empty() ? "--rules" : "the system --config " + a.config + " names,");
    if (!system) throw InputError("--rules " + rulesName + ": the rule file has errors (above)");
    // Before the region is built and the text parsed: a JSON configuration's parsed form took
    // 14 bytes per byte of its text (a 45 MB file peaked at 651 MB under --memory 16).
    const rules::Region region = rules::Region::parse(regionSpec, 1u << 22, [&](std::uint64_t cells) {
        rules::requireMemory(rules::checkedProduct({file.text.size(), kBytesPerConfigByte}) + rules::checkedProduct({cells, rules::Region::kBytesPerCell}), a.memoryMiB << 20,
                             "reading --config " + a.config + " (" + std::to_string(file.text.size()) + " bytes, on region " + regionSpec + " of " +
                                 std::to_string(cells) + " cells)");
    });
    // Before the text is parsed (seconds for a large file): a 2D region has no voxels to write.
    if (!a.binvox.empty() && region.lattice().dimension() != 3) refuseBinvox2D(region.lattice());
    const rules::Model model(*system, region.lattice());
    const rules::Interpreter in(model, region);
    const rules::Configuration c = rules::configFromText(in, file);
    if (!file.index) notePictureShortfall("--config", a.config, region, file.text);  // FILE#N is an ITF trace
    std::uint64_t modules = 0;
    for (const rules::CellValue v : c.cells) modules += v != 0;
    requireExportMemory(modules, a);
    Exported e;
    e.lattice = &region.lattice();
    std::map<std::string, std::string> legend;  // colour -> the states drawn in it
    for (int i = 0; i < region.size(); ++i) {
        if (!c.cells[i]) continue;
        const std::string colour = checker::stateColour(model, c.cells[i]);
        e.blocks.push_back({region.cell(i), colour});
        std::string& names = legend[colour];
        const std::string name = model.alphabet().name(c.cells[i]);
        if (names.find(" " + name + ",") == std::string::npos && names.size() < 200) names += " " + name + ",";
    }
    e.comments.push_back("holon export: configuration " + a.config + " of system " + system->name + " on region " + region.spec() + ", " +
                         std::to_string(e.blocks.size()) + " modules");
    for (const auto& [colour, names] : legend) e.comments.push_back("colour " + colour + ":" + names.substr(0, names.size() - 1));
    return e;
}

rules::VisibleSimRobot robotFor(const std::string& name, const rules::Lattice& lattice) {
    if (name.empty()) return lattice.kind() == rules::LatticeKind::Hex2D ? rules::VisibleSimRobot::Hexanodes : rules::VisibleSimRobot::SlidingCubes;
    for (auto robot : {rules::VisibleSimRobot::SlidingCubes, rules::VisibleSimRobot::BlinkyBlocks, rules::VisibleSimRobot::Hexanodes})
        if (name == rules::visibleSimRobotName(robot)) return robot;
    throw InputError("--robot '" + name + "': choose slidingCubes, blinkyBlocks or hexanodes");
}

int run(const ExportArgs& a) {
    if (a.shape.empty() == a.config.empty())
        throw InputError("give --shape SHAPE (a planning shape, as plan --from takes) or --config FILE (a configuration, as check --from takes), one of the two");
    // An option that does not apply is refused, not ignored.
    if (!a.target.empty() && a.shape.empty()) throw InputError("--target is a planning shape's target and goes with --shape; a configuration has none");
    if (a.scale != 1 && a.shape.empty()) throw InputError("--scale goes with --shape; a configuration is written as it is");
    if (!a.shape.empty() && (!a.rules.empty() || !a.region.empty())) throw InputError("--rules and --region go with --config; --shape is read as holon plan --from reads it");
    if (!a.shape.empty() && !a.noWarnings.empty()) throw InputError("-W silences a rule file's warnings and goes with --config; --shape reads no rule file");
    if (a.visibleSim.empty() && (!a.robot.empty() || a.margin != 0)) throw InputError("--robot and --margin go with --visiblesim");
    if (a.visibleSim.empty() && a.binvox.empty()) throw InputError("say what to write: --visiblesim FILE.xml, --binvox FILE.binvox, or both");
    // Output paths are checked before the work.
    std::optional<rules::OutputFile> visibleSimFile, binvoxFile;
    if (!a.visibleSim.empty()) visibleSimFile.emplace("--visiblesim", a.visibleSim);
    if (!a.binvox.empty()) binvoxFile.emplace("--binvox", a.binvox);

    const Exported e = a.shape.empty() ? fromConfiguration(a) : fromShapes(a);
    std::string world, voxels;
    if (visibleSimFile) {
        const rules::VisibleSimRobot robot = robotFor(a.robot, *e.lattice);
        std::vector<std::string> comments = e.comments;
        comments.push_back(std::string("VisibleSim ") + rules::visibleSimRobotName(robot) + " world (format of VisibleSim commit 86bca12, 2021-06-02)");
        world = rules::visibleSimWorld(*e.lattice, robot, e.blocks, e.targets, comments, a.margin);
    }
    if (binvoxFile) {
        if (e.lattice->dimension() != 3) refuseBinvox2D(*e.lattice);
        if (!e.targets.empty()) throw InputError("--binvox holds one shape; write the target with its own holon export --shape " + a.target + " --binvox FILE");
        std::vector<rules::Vec> cells;
        for (const rules::VisibleSimCell& b : e.blocks) cells.push_back(b.at);
        voxels = rules::writeBinvox(cells);
    }
    if (visibleSimFile) {
        visibleSimFile->write(world);
        std::cout << "wrote " << visibleSimFile->path() << ": a VisibleSim world of " << e.blocks.size() << " modules"
                  << (e.targets.empty() ? "" : " and a target of " + std::to_string(e.targets.size()) + " cells") << '\n';
    }
    if (binvoxFile) {
        binvoxFile->write(voxels);
        std::cout << "wrote " << binvoxFile->path() << ": " << e.blocks.size() << " voxels\n";
    }
    return kExitOk;
}

}  // namespace

Run addExportCommand(CLI::App& app) {
    auto a = std::make_shared<ExportArgs>();
    CLI::App* sub = app.add_subcommand("export", "write a shape or a configuration for other tools: a VisibleSim world (XML), a .binvox voxel file");
    sub->add_option("--shape", a->shape, "a planning shape, as holon plan --from takes (generator or file, .binvox included)");
    sub->add_option("--target", a->target, "with --shape: the target shape, as holon plan --to takes, written as the VisibleSim world's target (targetList)");
    sub->add_option("--scale", a->scale, "with --shape: every cell becomes a KxK (3D: KxKxK) block, as in holon plan")->check(CLI::Range(1, rules::kMaxCoordinate));
    sub->add_option("--config", a->config, "a configuration, as holon check --from takes: JSON, ASCII art, an ITF trace (FILE#N: state N), plan's end.json");
    sub->add_option("--rules", a->rules, "with --config: the rule file or bundled system it is a configuration of (default: the one a JSON file or trace names)");
    sub->add_option("--region", a->region, "with --config: the region it lies on, square:WxH, cubic:WxHxD or hex:rR (default: the one a JSON file or trace names)");
    sub->add_option("--visiblesim", a->visibleSim, "write a VisibleSim world (XML) for the VisibleSim modular-robot simulator: square2d and cubic3d as slidingCubes, hex2d as hexanodes");
    sub->add_option("--robot", a->robot, "the VisibleSim module type: slidingCubes (default on square2d and cubic3d), blinkyBlocks, or hexanodes (hex2d)");
    sub->add_option("--margin", a->margin, "with --visiblesim: empty cells around the modules in the world's grid, room to move (default 0: the grid just holds them)")->check(CLI::Range(0, 1000));
    sub->add_option("--binvox", a->binvox, "write the 3D cells as a .binvox voxel file (holon plan --from reads it back)");
    sub->add_option("--memory", a->memoryMiB, "memory bound in MiB for the shapes or the configuration (default 16384)")->check(memoryValidator());
    sub->add_option("-W", a->noWarnings, "silence a warning of the rule file: -W no-NAME");
    return [a] { return withinMemory(a->memoryMiB, [&] { return run(*a); }); };
}

}  // namespace holon::cli
