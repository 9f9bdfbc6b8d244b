#!/bin/bash
# The solver's layers, lowest first (solver/README.md). A file may include its own layer and those
# below it, never one above: prints each include that breaks this and exits 1 if there is any.
# Layers on one line are peers and do not include each other.
cd "$(dirname "$0")/../solver" || exit 2
layers=(
  "core"
  "io"
  "kernel"
  "neighbor"
  "interaction"
  "particles"
  "geometry"
  "fluid solid"
  "fsi"
  "boundary"
  "simulation"
  "time"
  "observers"
  "scene"
  "run"
  "app"
)
declare -A rank
for r in "${!layers[@]}"; do for l in ${layers[$r]}; do rank[$l]=$r; done; done
bad=0
for dir in */; do
  from=${dir%/}
  [ -n "${rank[$from]}" ] || { echo "solver/$from: not in the layer list of scripts/check_layers.sh"; bad=1; continue; }
  while IFS=: read -r file line text; do
    to=$(sed -E 's@.*#include "([a-z_]+)/.*@\1@' <<<"$text")
    [ -n "${rank[$to]}" ] || continue
    if [ "${rank[$to]}" -gt "${rank[$from]}" ] || { [ "${rank[$to]}" -eq "${rank[$from]}" ] && [ "$to" != "$from" ]; }; then
      echo "solver/$file:$line: $from includes $to (a layer above or a peer)"
      bad=1
    fi
  done < <(grep -rnE '#include "[a-z_]+/' "$from" | sed "s@^@@")
done
[ $bad -eq 0 ] && echo "layers: no include from a layer to one above it"
exit $bad
