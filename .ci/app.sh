#!/usr/bin/env bash
# Quick start 1: install what is missing, build, and open ParticleLab with a preset (default gas-write-up).
set -euo pipefail
cd "$(dirname "$0")/.."
./.ci/install-deps.sh
./.ci/build.sh
exec ./build/app/particlelab "${1:-gas-write-up}"
