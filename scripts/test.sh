#!/usr/bin/env bash
# The README's test command: install dependencies, build, run every test tier with CTest; then
# the data readers' tests (malformed-file corpus, GDAL rasters, the land mask's PNG, the
# streamed imagery tiles, the shallow-bank correction and the start-up caches' reader
# core/CacheFile included) again under
# AddressSanitizer/UBSan in build-asan/ (only og_unit_tests is built there;
# docs/data.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 600
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DOCEANGLOBE_WERROR=ON \
  -DOCEANGLOBE_SANITIZE=ON >/dev/null
cmake --build build-asan -j "$(nproc)" --target og_unit_tests
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" --timeout 600 \
  --no-tests=error -R 'unit\.(Data|GeoRaster|LandMask|ImageryTiles|ShallowBanks|CacheFile|SrgbMips)'
