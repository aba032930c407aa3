# Every external dependency of holon is found here, and only here.
find_package(PkgConfig REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(doctest REQUIRED)
find_package(Threads REQUIRED)
pkg_check_modules(Z3 REQUIRED IMPORTED_TARGET z3)
# LEMON's network simplex: the independent solver the transport bound's min-cost flow
# (planner/MinCostFlow.cpp) is tested against.
pkg_check_modules(LEMON REQUIRED IMPORTED_TARGET lemon)
find_package(Boost 1.74 REQUIRED)
