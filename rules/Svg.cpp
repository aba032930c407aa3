// The SVG writer: markup is written in one place, attribute values always quoted with " and text
// always escaped, so a rule, state or input name holding '<' or '&' cannot break a picture.

#include "rules/Svg.h"

namespace holon::rules {

std::string Svg::escape(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

void Svg::attributes(const SvgAttrs& attrs) {
    for (const SvgAttr& a : attrs) out_ << ' ' << a.name << "=\"" << escape(a.value) << '"';
}

Svg& Svg::element(std::string_view tag, const SvgAttrs& attrs, const SvgAttrs& more) {
    out_ << '<' << tag;
    attributes(attrs), attributes(more);
    out_ << "/>\n";
    return *this;
}

Svg& Svg::open(std::string_view tag, const SvgAttrs& attrs, const SvgAttrs& more) {
    out_ << '<' << tag;
    attributes(attrs), attributes(more);
    out_ << ">\n";
    return *this;
}

Svg& Svg::close(std::string_view tag) {
    out_ << "</" << tag << ">\n";
    return *this;
}

Svg& Svg::rect(double x, double y, double width, double height, const SvgAttrs& attrs) {
    return element("rect", {{"x", x}, {"y", y}, {"width", width}, {"height", height}}, attrs);
}

Svg& Svg::line(double x1, double y1, double x2, double y2, const SvgAttrs& attrs) {
    return element("line", {{"x1", x1}, {"y1", y1}, {"x2", x2}, {"y2", y2}}, attrs);
}

Svg& Svg::circle(double cx, double cy, double r, const SvgAttrs& attrs) { return element("circle", {{"cx", cx}, {"cy", cy}, {"r", r}}, attrs); }

Svg& Svg::path(std::string_view d, const SvgAttrs& attrs) { return element("path", {{"d", d}}, attrs); }

namespace {

std::string pointList(const std::vector<std::pair<double, double>>& points) {
    std::ostringstream s;
    for (std::size_t k = 0; k < points.size(); ++k) s << (k ? " " : "") << points[k].first << ',' << points[k].second;
    return s.str();
}

}  // namespace

Svg& Svg::polygon(const std::vector<std::pair<double, double>>& points, const SvgAttrs& attrs) {
    return element("polygon", {{"points", pointList(points)}}, attrs);
}

Svg& Svg::polyline(const std::vector<std::pair<double, double>>& points, const SvgAttrs& attrs) {
    return element("polyline", {{"points", pointList(points)}}, attrs);
}

Svg& Svg::text(double x, double y, std::string_view content, const SvgAttrs& attrs) {
    out_ << "<text";
    attributes({{"x", x}, {"y", y}}), attributes(attrs);
    out_ << '>' << escape(content) << "</text>\n";
    return *this;
}

Svg& Svg::legend(double x, double y, std::string_view label, const SvgAttrs& swatch) {
    rect(x, y, 14, 14, swatch);
    return text(x + 18, y + 11, label);
}

Svg& Svg::nested(const std::string& document, double x, double y) {
    // The nested root keeps its size and drops its namespace (the outer one declares it).
    const std::string root = "<svg xmlns=\"http://www.w3.org/2000/svg\"";
    out_ << "<svg x=\"" << x << '"';
    if (y != 0) out_ << " y=\"" << y << '"';
    out_ << (document.compare(0, root.size(), root) == 0 ? document.substr(root.size()) : document.substr(4));
    return *this;
}

std::string Svg::document(double width, double height, const SvgAttrs& attrs, const Svg* defs) const {
    Svg root;
    root.out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\"";
    root.attributes({{"width", width}, {"height", height}}), root.attributes(attrs);
    root.out_ << ">\n";
    if (defs) root.open("defs").out_ << defs->body(), root.close("defs");
    root.element("rect", {{"width", "100%"}, {"height", "100%"}, {"fill", "white"}});
    return root.body() + body() + "</svg>\n";
}

}  // namespace holon::rules
