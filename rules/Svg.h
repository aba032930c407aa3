#pragma once
// The one SVG writer behind every picture holon draws (check --svg, the planner's reports, the hex
// sculptor's frames, the Roombots runs, the bench figures): the document around a body, escaping
// of text, and the few shapes the pictures use, so no caller formats SVG markup by hand.

#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace holon::rules {

/// One attribute: a name and its value (numbers as an ostream writes them).
struct SvgAttr {
    SvgAttr(const char* name, std::string_view value) : name(name), value(value) {}
    SvgAttr(const char* name, const char* value) : name(name), value(value) {}
    SvgAttr(const char* name, const std::string& value) : name(name), value(value) {}
    template <class Number>
    requires std::is_arithmetic_v<Number>
    SvgAttr(const char* name, Number value) : name(name) {
        std::ostringstream s;
        s << value;
        this->value = s.str();
    }
    const char* name;
    std::string value;
};
using SvgAttrs = std::vector<SvgAttr>;

/// A finished document with the size its root declares, so a picture placed within another is
/// laid out by its size, never by reading the markup back.
struct SvgPicture {
    std::string document;
    double width = 0, height = 0;
};

class Svg {
public:
    /// `text` with &, <, > and " escaped, for element text and attribute values.
    static std::string escape(std::string_view text);

    /// <tag attrs/>
    Svg& element(std::string_view tag, const SvgAttrs& attrs, const SvgAttrs& more = {});
    /// <tag attrs>, closed by close(tag); groups, markers, patterns.
    Svg& open(std::string_view tag, const SvgAttrs& attrs = {}, const SvgAttrs& more = {});
    Svg& close(std::string_view tag);
    Svg& rect(double x, double y, double width, double height, const SvgAttrs& attrs = {});
    Svg& line(double x1, double y1, double x2, double y2, const SvgAttrs& attrs = {});
    Svg& circle(double cx, double cy, double r, const SvgAttrs& attrs = {});
    /// `d`: path data ("M0,0 L8,4 z").
    Svg& path(std::string_view d, const SvgAttrs& attrs = {});
    Svg& polygon(const std::vector<std::pair<double, double>>& points, const SvgAttrs& attrs = {});
    Svg& polyline(const std::vector<std::pair<double, double>>& points, const SvgAttrs& attrs = {});
    /// `content` escaped.
    Svg& text(double x, double y, std::string_view content, const SvgAttrs& attrs = {});
    /// A legend entry: a 14-unit swatch at (x, y) drawn with `swatch`, its label to the right.
    Svg& legend(double x, double y, std::string_view label, const SvgAttrs& swatch);
    /// Another picture placed at (x, y) within this one (its own document, as document() wrote it).
    Svg& nested(const std::string& document, double x, double y = 0);

    /// The document: width and height, the root's other attributes, `defs` (markers, patterns), a
    /// white background, then the body.
    std::string document(double width, double height, const SvgAttrs& attrs = {}, const Svg* defs = nullptr) const;
    /// document() with its size kept beside it.
    SvgPicture picture(double width, double height, const SvgAttrs& attrs = {}, const Svg* defs = nullptr) const {
        return {document(width, height, attrs, defs), width, height};
    }
    /// The body written so far.
    std::string body() const { return out_.str(); }

private:
    void attributes(const SvgAttrs& attrs);
    std::ostringstream out_;
};

}  // namespace holon::rules
