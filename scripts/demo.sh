#!/usr/bin/env bash
# The README's main command: install dependencies, build, and render the descent from orbit
# to sea level on the embedded default data into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
for scene in orbit_atlantic limb_400km gibraltar_300km sea_2m_low_sun; do
  build/oceanglobe render --config "config/scenes/${scene}.toml" -o "out/${scene}.png"
  echo "wrote out/${scene}.png"
done
build/oceanglobe render --config config/scenes/orbit_atlantic.toml -o out/orbit_atlantic.exr
echo "wrote out/orbit_atlantic.exr (linear HDR radiance)"
