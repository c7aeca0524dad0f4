#!/usr/bin/env bash
# Sanitizer job: an AddressSanitizer + UndefinedBehaviorSanitizer build of the headless targets (core,
# GPU library, CLI) and their tests in build-asan/ (headless: EGL needs no X server). Any report in
# ParticleLab's code fails it; third-party findings are suppressed, with the reason, in .ci/lsan.supp.
set -euo pipefail
cd "$(dirname "$0")/.."
# float-cast-overflow is not part of GCC's "undefined": a double from a file cast to an integer it does not
# fit (a snapshot's step of 1e19) is undefined behaviour it finds only when named.
flags="-O1 -g -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer"
flags="$flags -fno-sanitize-recover=undefined,float-cast-overflow"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARTICLELAB_BUILD_UI=OFF \
    -DPARTICLELAB_BUILD_TESTS=ON "-DCMAKE_CXX_FLAGS=$flags" \
    "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined,float-cast-overflow" \
    "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=address,undefined,float-cast-overflow"
cmake --build build-asan -j2
# verify_asan_link_order=0: the preloaded Mesa driver (see .ci/lsan.supp) comes before the runtime.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:verify_asan_link_order=0"
export LSAN_OPTIONS="suppressions=$PWD/.ci/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The fuzzer's processes start 5× slower under the sanitizers: its corrupted snapshots and mutated preset
# files, where values read from a file meet integers, bounds and allocations, in 500 cases (about a
# minute); the other classes run in full in the main job.
export PARTICLELAB_FUZZ_CASES=500 PARTICLELAB_FUZZ_CLASSES=snapshot,preset
driver=$(ls /usr/lib/*/dri/swrast_dri.so 2>/dev/null | head -n 1 || true)
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
chmod 700 "$XDG_RUNTIME_DIR"
cd build-asan
env ${driver:+LD_PRELOAD="$driver"} ctest --output-on-failure --timeout 900
