#!/usr/bin/env bash
# Quick start 2: install what is missing, build, and run the whole test suite. The GUI (and later GL)
# tests need an X server: the suite runs inside one Xvfb. Tests run one at a time: each model already
# uses both cores through OpenMP, and two of them spinning on 2 cores slow each other down tenfold.
set -euo pipefail
cd "$(dirname "$0")/.."
./.ci/install-deps.sh
./.ci/build.sh
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
chmod 700 "$XDG_RUNTIME_DIR"
cd build
xvfb-run -a -s "-screen 0 1280x800x24" ctest --output-on-failure --timeout 600
