#!/usr/bin/env bash
# The README's main command: install dependencies, build, and record the descent from orbit
# to sea level (config/flythrough.toml, 20 s at 1280x720) on the embedded default data into
# out/flythrough.mp4, plus a few still renders.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/oceanglobe record config/flythrough.toml --width 1280 --height 720 -o out/flythrough.mp4
echo "wrote out/flythrough.mp4"
for scene in orbit_atlantic limb_400km gibraltar_300km sea_2m_low_sun; do
  build/oceanglobe render --config "config/scenes/${scene}.toml" -o "out/${scene}.png"
  echo "wrote out/${scene}.png"
done
build/oceanglobe render --config config/scenes/orbit_atlantic.toml -o out/orbit_atlantic.exr
echo "wrote out/orbit_atlantic.exr (linear HDR radiance)"
