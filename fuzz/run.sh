#!/usr/bin/env bash
# Runs one fuzz target for SECONDS (default 600), seeded from ../shared/corpus when present.
#   fuzz/run.sh openscenario_load 600
# Targets: openscenario_load, opendrive_load, expression, distribution, convert.
# Needs the nightly toolchain and cargo-fuzz (`cargo install cargo-fuzz`). Seeds are copied into
# fuzz/corpus/TARGET (ignored by git); crashes land in fuzz/artifacts/TARGET.
set -euo pipefail
cd "$(dirname "$0")"
target=${1:?target}
seconds=${2:-600}
shared=${OSC2CR_SHARED:-../../shared}
mkdir -p "corpus/$target"
if [ -d "$shared/corpus" ] && [ -z "$(ls -A "corpus/$target")" ]; then
  case "$target" in
    opendrive_load) find "$shared/corpus" -name '*.xodr' -size -400k -exec cp {} "corpus/$target/" \; ;;
    expression) grep -rhoE '\$\{[^}]{1,200}\}' "$shared/corpus" --include=*.xosc | sort -u | sed 's/^\${//; s/}$//' \
                  | split -l 1 - "corpus/$target/expr-" ;;
    *) find "$shared/corpus" -name '*.xosc' -size -200k -exec cp {} "corpus/$target/" \; ;;
  esac
fi
# -rss_limit_mb: a huge allocation is a finding; -timeout: an input over 10 s is a hang.
exec cargo +nightly fuzz run "$target" "corpus/$target" -- \
  -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=262144 -print_final_stats=1
