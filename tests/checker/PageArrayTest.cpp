// PageArray: growth keeps the elements, new elements read as zero even where earlier ones were
// cleared by shrinking, and large arrays survive remapping.

#include "checker/PageArray.h"

#include <cstdint>
#include <doctest/doctest.h>

using holon::checker::PageArray;

TEST_CASE("a page array grows without losing elements, and new elements are zero") {
    PageArray<std::uint32_t> a;
    CHECK(a.empty());
    a.resize(1000);
    for (std::size_t i = 0; i < a.size(); ++i) CHECK(a[i] == 0u);
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<std::uint32_t>(i + 1);
    a.resize(3'000'000);  // past 2 MiB: remapped, huge pages asked for
    CHECK(a[999] == 1000u);
    CHECK(a[1000] == 0u);
    CHECK(a[2'999'999] == 0u);
    a[2'999'999] = 7;
    a.resize(10);  // shrink, then grow over the old elements: they must read as zero
    a.resize(3'000'000);
    CHECK(a[9] == 10u);
    CHECK(a[10] == 0u);
    CHECK(a[999] == 0u);
    CHECK(a[2'999'999] == 0u);
    a[5] = 42;
    a.resize(6);
    a.shrinkToFit();
    CHECK(a[5] == 42u);
    a.resize(100);
    CHECK(a[6] == 0u);
    for (std::uint32_t i = 0; i < 1'000'000; ++i) a.push_back(i);
    CHECK(a.size() == 1'000'100);
    CHECK(a[100] == 0u);
    CHECK(a[1'000'099] == 999'999u);
    a.resize(100);
    PageArray<std::uint32_t> b = std::move(a);
    CHECK(a.empty());
    CHECK(b.size() == 100);
    CHECK(b[5] == 42u);
}
