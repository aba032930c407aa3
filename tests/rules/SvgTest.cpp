// The one SVG writer: every text and attribute value escaped, the document around the body.

#include "rules/Svg.h"

#include <doctest/doctest.h>

using holon::rules::Svg;

TEST_CASE("the SVG writer escapes text and attribute values and wraps the body in one document") {
    Svg svg;
    svg.text(1, 2, "a<b & \"c\"", {{"fill", "x\"y"}}).rect(0, 0, 14, 14, {{"fill", "#fff"}}).legend(5, 6, "in<put", {{"fill", "red"}});
    const std::string body = svg.body();
    CHECK(body.find("<text x=\"1\" y=\"2\" fill=\"x&quot;y\">a&lt;b &amp; &quot;c&quot;</text>") != std::string::npos);
    CHECK(body.find("<rect x=\"5\" y=\"6\" width=\"14\" height=\"14\" fill=\"red\"/>") != std::string::npos);
    CHECK(body.find(">in&lt;put</text>") != std::string::npos);
    CHECK(body.find('<', body.find("a&lt;b")) == body.find("</text>"));  // no raw '<' inside the text

    Svg defs;
    defs.open("marker", {{"id", "m"}}).close("marker");
    const std::string doc = svg.document(100, 50.5, {{"font-size", 11}}, &defs);
    CHECK(doc.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"50.5\" font-size=\"11\">\n<defs>\n<marker id=\"m\">", 0) == 0);
    CHECK(doc.find("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>") > doc.find("</defs>"));
    CHECK(doc.find(body) != std::string::npos);
    CHECK(doc.substr(doc.size() - 7) == "</svg>\n");

    // A picture placed in another keeps its size and content but not its namespace.
    Svg outer;
    outer.nested(Svg().circle(1, 1, 1).document(20, 10), 30);
    CHECK(outer.body().rfind("<svg x=\"30\" width=\"20\" height=\"10\">", 0) == 0);
    CHECK(outer.body().find("<circle cx=\"1\" cy=\"1\" r=\"1\"/>") != std::string::npos);
}
