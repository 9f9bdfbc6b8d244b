#!/bin/bash
# The house's rules a script can check (solver/README.md), run by the tests (ctest: house_rules):
#  1. layers: no include from a solver layer to one above it (scripts/check_layers.sh)
#  2. pairs: no code outside solver/neighbor and solver/interaction iterates over neighbour lists,
#     their transposes or listed pairs (the pair-sweep driver is the only code that knows how
#     pairs are stored)
#  3. sizes: no solver file over 400 lines, no solver function over 60 lines
# Exits 1 if any rule is broken, after printing every breach.
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root" || exit 2
status=0

scripts/check_layers.sh || status=1

pairs=$(grep -rnE '\.of\(|\.offset\(|\.entry\(|: [a-z_.]*candidates\)' solver --include='*.cpp' --include='*.hpp' |
        grep -v -e '^solver/neighbor/' -e '^solver/interaction/')
if [ -n "$pairs" ]; then
  echo "pairs: iterated outside the pair-sweep driver:"
  echo "$pairs"
  status=1
else
  echo "pairs: iterated only in solver/neighbor and solver/interaction"
fi

long_files=$(find solver -name '*.[ch]pp' -exec wc -l {} + | awk '$2 != "total" && $1 > 400 {print $2 ": " $1 " lines"}')
if [ -n "$long_files" ]; then
  echo "sizes: files over 400 lines:"
  echo "$long_files"
  status=1
fi
if /usr/bin/python3 scripts/function_lengths.py 60 solver; then
  echo "sizes: no solver file over 400 lines, no function over 60"
else
  status=1
fi
exit $status
