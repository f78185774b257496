#!/usr/bin/env bash
# Configures and builds penumbra (Release) into build/. The CLI ends up at
# build/bin/penumbra. `--renderer` builds the CLI alone (no test binary, no benchmarks,
# neither of their packages needed); otherwise every target, tests and benchmarks
# included. Other arguments are passed to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
if [ "${1:-}" = "--renderer" ]; then
    shift
    targets=(--target penumbra)
    # Tests stay configured in a build that has them: only the build is narrowed.
    if [ ! -f build/CMakeCache.txt ]; then
        set -- -DPENUMBRA_BUILD_TESTS=OFF -DPENUMBRA_BUILD_BENCH=OFF "$@"
    fi
else
    set -- -DPENUMBRA_BUILD_TESTS=ON -DPENUMBRA_BUILD_BENCH=ON "$@"
fi
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
# ccache, when a developer has it, shares compiled objects between checkouts.
if command -v ccache >/dev/null 2>&1; then
    generator+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(cd .. && pwd)}"
fi
if [ ! -f build/CMakeCache.txt ]; then
    cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@"
else
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
fi
cmake --build build --parallel "$(nproc)" "${targets[@]}"
