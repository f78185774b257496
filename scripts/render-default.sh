#!/usr/bin/env bash
# Set up, build the renderer alone and render the default scene to out/cornell-box.exr
# (+ .png preview), denoised (the unbiased image stays in the EXR as the layer Noisy).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh --renderer
# --overwrite: render skips finished outputs (batch resume); this script always renders.
build/bin/penumbra render scenes/cornell-box.gltf -o out/cornell-box.exr --spp 64 --denoise \
    --overwrite "$@"
