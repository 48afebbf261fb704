#!/usr/bin/env bash
# Runs a fuzz harness once over every file of a folder (a regression folder or a seed corpus), as
# ctest does in the sanitizer build: any crash, sanitizer report or unexpected exception fails.
#   fuzz/run_inputs.sh build-sanitize/fuzz/fuzz_scene fuzz/regressions/scene
set -euo pipefail
harness="$1" folder="$2"
source "$(dirname "$0")/../tests/sanitizer/env.sh"
mapfile -d '' inputs < <(find "$folder" -type f ! -name 'README*' -print0 | sort -z)
if [ ${#inputs[@]} -eq 0 ]; then
  echo "$folder: no inputs yet (nothing to run)"
  exit 0
fi
echo "$folder: ${#inputs[@]} inputs"
# Given files rather than a folder, libFuzzer runs each once and never writes to the folder.
exec "$harness" -rss_limit_mb=2048 -timeout=60 "${inputs[@]}"
