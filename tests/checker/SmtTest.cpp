// The Z3 adapter (checker/Smt.h): answers as the Result enum, a model's values, every Z3 error as
// smt::Failure, the inspection the invariant printer needs, and the reference counting the
// exported SMT-LIB2 files depend on.

#include "checker/Smt.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

using namespace holon::checker;

TEST_CASE("the adapter answers sat with a model, unsat, and under assumptions") {
    smt::Context ctx;
    const smt::Term x = ctx.boolConst("x"), n = ctx.intConst("n");
    smt::Solver s(ctx);
    s.add(smt::implies(x, n == 3) && n > 1 && n < 4);
    REQUIRE(s.check({x}) == smt::Result::Sat);
    CHECK(s.model().isTrue(x));
    CHECK(s.model().intValue(n) == 3);
    s.push();
    s.add(x && n != ctx.intVal(3));
    CHECK(s.check() == smt::Result::Unsat);
    s.pop();
    CHECK(s.check({!x, n == 3}) == smt::Result::Sat);
    CHECK(s.check({smt::anyOf(ctx, {})}) == smt::Result::Unsat);
    CHECK(s.check({smt::anyOf(ctx, {x, !x})}) == smt::Result::Sat);
}

TEST_CASE("a Z3 error leaves the adapter as smt::Failure") {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "holon_smt_test_bad.smt2";
    std::ofstream(file) << "(assert (and p\n";
    smt::Context ctx;
    smt::Solver s(ctx);
    CHECK_THROWS_AS(s.addFile(file.string()), smt::Failure);
    std::filesystem::remove(file);
}

TEST_CASE("terms are inspected as the invariant printer needs") {
    smt::Context ctx;
    const smt::Term a = ctx.boolConst("a"), b = ctx.boolConst("b");
    CHECK((a && b).op() == smt::Term::Op::And);
    CHECK((a || b).arity() == 2);
    CHECK(smt::same((a || b).arg(1), b));
    CHECK((!a).op() == smt::Term::Op::Not);
    CHECK((a == b).op() == smt::Term::Op::Eq);
    CHECK(ctx.boolVal(true).op() == smt::Term::Op::True);
    CHECK(a.op() == smt::Term::Op::Other);
    // Horn clauses: closed over their constants, whose bound variables a relation's definition uses.
    const smt::Term closed = smt::universalClosure(smt::implies(a, b));
    CHECK(closed.str().rfind("(forall", 0) == 0);
    CHECK(smt::same(smt::universalClosure(ctx.boolVal(true)), ctx.boolVal(true)));
}

TEST_CASE("a context whose move assignments kept a long chain is freed in linear time") {
    // Left to Z3, the kept links are freed one per sweep of the whole term table: 20,000 links
    // took minutes. Not a speed target, a complexity guard: linear takes milliseconds.
    const auto start = std::chrono::steady_clock::now();
    {
        smt::Context ctx;
        smt::Term q = ctx.boolVal(true);
        for (int i = 0; i < 20000; ++i) q = q && ctx.boolConst("x" + std::to_string(i));
    }
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(20));
}

TEST_CASE("a move assignment keeps the overwritten term referenced, as the exported files need") {
    // Z3's SMT-LIB2 printer let-binds a subterm with more than one reference. proofs/smt was
    // written with Z3 4.8.12's C++ move assignment, which never releases the term it overwrites:
    // `q` built as a chain prints with a let per link, and must go on doing so for the files to
    // regenerate.
    smt::Context ctx;
    smt::Term q = ctx.boolVal(false);
    for (const char* name : {"a", "b", "c"}) q = q || ctx.boolConst(name);
    smt::Solver s(ctx);
    s.add(q);
    CHECK(s.toSmt2().find("(let") != std::string::npos);
}
