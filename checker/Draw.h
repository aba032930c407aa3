#pragma once
// Pictures of configurations and traces for a person: ASCII for the terminal, SVG for a file.

#include "checker/Trace.h"
#include "rules/Svg.h"

#include <functional>
#include <map>
#include <string>

namespace holon::checker {

/// One character for each state a set of configurations shows: a state's one-character name where it
/// has one; otherwise a square-lattice arrow for its pointer or a free letter, distinct from every
/// other state's (not a value's initial, which would read as that value). `legend` maps the characters that
/// are not a state's own name to the full names ("a = C&F"), empty when every state shown has one.
struct AsciiKey {
    std::map<CellValue, char> chars;
    std::string legend;
    char operator()(CellValue v) const { return v ? chars.at(v) : '.'; }
};
AsciiKey asciiKey(const rules::Engine& engine,
                  const std::vector<const std::vector<CellValue>*>& configurations);
/// One configuration, one character per cell, with the legend when it needs one.
std::string drawAscii(const rules::Engine& engine, const std::vector<CellValue>& cells);
/// The region's layout with one character per cell from `charOf(cell)` (3D: z slices side by side,
/// each headed by its z).
std::string drawCells(const rules::Region& region, const std::function<char(int cell)>& charOf);
/// The engine's inputs, one mask per input ("-- input target:" and '#' where it holds), so a reader
/// sees which input values a trace needs; empty for a system without inputs.
std::string drawInputsAscii(const rules::Engine& engine);
/// Every state of the trace with the rule that led to it and the cells that changed (full state
/// names), the legend of the characters used, and one mask per input.
std::string drawTraceAscii(const Trace& trace, const rules::Engine& engine);
/// The fill colour of a state value, "#rrggbb": fixed by the value's name and its field's declared
/// values, so a value has the same colour in every picture of a system.
std::string valueColour(const rules::Field& field, int value);
/// The fill colour of a non-empty cell state in every picture (the SVG traces, VisibleSim worlds):
/// valueColour of its first enum field, grey when it has none.
std::string stateColour(const rules::Model& model, CellValue v);
/// The text inside a cell: the values of every enum and integer field, in declaration order.
std::string cellText(const rules::System& system, const std::vector<int>& fields);
/// The colours drawTraceSvg draws with besides the values' (valueColour), for other pictures of
/// the same traces (the browser viewer): the outlines of changed, context (blocking) and other
/// cells, the fill of a state that has no fill field, and one colour per input.
struct TraceColours {
    std::string changed, context, cell, noFill;
    std::vector<std::string> inputs;
};
TraceColours traceColours();
/// Frames left to right; each cell filled by the colour of its first enum field, its text naming the
/// values of every enum and integer field, one arrow with a head per pointer field (each field its
/// own colour and dash; in 3D, +z and -z as a dot and a cross in a circle); changed cells outlined in
/// red, the rule's other cells (context, blocking) dashed, marked cells crossed; each input as an
/// outline of its cells (shaded where empty); titles wrapped to the picture; a legend naming every
/// value shown and every input. 3D regions drawn as z slices.
rules::SvgPicture drawTrace(const Trace& trace, const rules::Engine& engine, const std::string& title);
inline std::string drawTraceSvg(const Trace& trace, const rules::Engine& engine, const std::string& title) {
    return drawTrace(trace, engine, title).document;
}

}  // namespace holon::checker
