#!/bin/sh
# Fails when a string literal in rules/, checker/ or planner/ spells a command-line flag ("--memory"):
# the library names a parameter with rules::parameterName (rules/Parameter.h), and only cli/ knows
# the options (cli/ParameterNames.cpp). A line is read from its start as code, `//` comments' text
# excluded, string literals and character literals (a digit separator too) skipped whole, up to a
# string literal that holds "--" and a letter; so `--depth` in code and flags in comments pass.
# Usage: no_flag_names.sh SOURCE_DIR
cd "$1" || exit 2
found=$(grep -rnP --include='*.cpp' --include='*.h' \
    "^(?:[^\"/']|/(?!/)|\"(?:[^\"\\\\]|\\\\.)*\"|'(?:[^'\\\\]|\\\\.)+')*\"(?:[^\"\\\\]|\\\\.)*--[A-Za-z]" rules checker planner)
if [ -n "$found" ]; then
    printf '%s\n' "$found"
    echo "a library message spells a command-line flag; name the parameter with rules::parameterName(rules::Parameter::...) and give it an option in cli/ParameterNames.cpp"
    exit 1
fi
