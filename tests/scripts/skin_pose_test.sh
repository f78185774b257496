#!/usr/bin/env bash
# scripts/crosscheck/skin_pose.py on scenes/skinned-tubes.gltf at two times (a key and
# half-way between keys): penumbra's silhouettes within a pixel of Blender's importer.
# Skipped (77) without blender or oiiotool.
set -euo pipefail
bin=$1
command -v blender >/dev/null && command -v oiiotool >/dev/null || exit 77
cd "$(dirname "$0")/../.."
exec python3 scripts/crosscheck/skin_pose.py scenes/skinned-tubes.gltf --times 0.75,1.5 \
    --size 96 --spp 8 --penumbra "$bin"
