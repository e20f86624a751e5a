#!/usr/bin/env bash
# Rewrites the ```text blocks of README.md and docs/ that quote the output of
# the ```sh block before them, from what those commands print now
# (tests/doc_commands.cpp checks that they match). Needs the Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target brdflut_doc_commands brdflut_cli -j"${BRDFLUT_JOBS:-2}" > /dev/null
BRDFLUT_UPDATE_DOC_OUTPUT=1 ./build/tests/brdflut_doc_commands --gtest_filter="${1:-*}" | grep -E "^rewrote|FAILED|PASSED"
