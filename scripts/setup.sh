#!/usr/bin/env bash
# Installs the Debian 12 packages penumbra needs to build and run; with --test, also
# those only the tests and benchmarks need. Idempotent: packages already present are skipped, and apt
# is not touched when nothing is missing. Runs apt-get directly as root, through sudo
# otherwise.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config git python3
    libembree-dev libtbb-dev
    libopenimageio-dev openimageio-tools libopencolorio-dev
    libtinygltf-dev nlohmann-json3-dev libstb-dev
    libdraco-dev libmeshoptimizer-dev
    libzstd-dev
    libcli11-dev
    # The Python module (python/, build/python): pybind11's headers, Python's, and numpy,
    # whose arrays it returns.
    pybind11-dev python3-dev python3-numpy
)
if [ "${1:-}" = "--test" ]; then
    packages+=(
        # The unit tests and the microbenchmarks (build/bin/penumbra_tests, penumbra_bench).
        libgtest-dev libbenchmark-dev
        # The asan preset (scripts/sanitize.sh, scripts/fuzz.sh): clang with its sanitizer
        # and libFuzzer runtimes, and llvm-symbolizer for readable reports.
        clang libclang-rt-14-dev llvm-14
        # A real studio OCIO config (blender-data's config.ocio) and Blender itself, whose
        # compositor must read our AOV EXRs (tests/io/color/color_test.cpp,
        # tests/apps/blender_roundtrip_test.cpp); its glTF importer needs numpy
        # (scripts/crosscheck/).
        blender blender-data python3-numpy
        # The Python module's test reads the CLI's EXRs (python/tests/).
        python3-openimageio
        # Embree's pathtracer tutorial and its Cornell box (scripts/crosscheck/efficiency.py
        # --embree).
        embree-tools
        # A single-node Slurm cluster for the farm test (tests/farm/run_slurm_test.sh).
        slurm-wlm munge
        # Instruction counts of a render (scripts/render_instructions.sh), and Embree's
        # share of its time (scripts/embree_share.py).
        valgrind linux-perf
    )
fi

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#packages[@]} packages are installed"
    exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
    SUDO=()
else
    SUDO=(sudo)
fi
echo "setup: installing ${missing[*]}"
"${SUDO[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
