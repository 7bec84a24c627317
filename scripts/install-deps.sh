#!/usr/bin/env bash
# Installs oceanglobe's build and test dependencies from Debian 12's packages.
# Skips apt entirely when everything is already installed (fast, works offline).
set -euo pipefail

packages=(
  build-essential cmake pkg-config python3-glad
  libglfw3-dev libglm-dev libgeographiclib-dev libopenexr-dev
  libegl-dev libgl-dev libosmesa6-dev libegl-mesa0 libgl1-mesa-dri
  libnetcdf-dev libeccodes-dev libpng-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev
  # FFTW: the wave patterns' FFTs where GL renders on the CPU (llvmpipe), and the tests'
  # reference of the GPU's
  libfftw3-dev
  # jemalloc: the process's allocator, its large blocks on 2 MiB pages (src/core/MallocConf.cpp)
  libjemalloc-dev
  # Google Earth KML tours (record/view/path convert)
  libpugixml-dev
  # video output for `record`; ffmpeg/ffprobe for the tests and the Slurm encode step
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev ffmpeg
  # the viewer's test: a private X server and synthetic key presses
  xvfb xdotool
  # GDAL/PROJ: georeferenced imagery (GeoTIFF/COG, JPEG/PNG + world file) and GeoTIFF DEMs;
  # gdal-bin for the tests' synthetic GeoTIFFs and scripts/derive_default_data.sh
  libgdal-dev gdal-bin
  # the default day/night imagery (NASA Visible Earth, public domain), derived into data/
  xplanet-images
  # GSHHG shorelines (the land/water mask derived into data/; -high for finer local masks)
  gmt-gshhg-low gmt-gshhg-high
  # real data: ETOPO relief/bathymetry and monthly winds (used by tests when present)
  ferret-datasets
  # ncgen: builds the small wind file of the docs' time-lapse pictures from its CDL text
  netcdf-bin
  # NCO (ncks/ncap2/ncatted): scripts/derive_default_data.sh derives data/etopo5_relief.nc
  # and the default wind from the Ferret data sets (not needed to build)
  nco
  # the Slurm test: a private single-node Slurm (slurmctld + slurmd) and its MUNGE daemon
  slurm-wlm munge
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "oceanglobe: installing ${missing[*]}" >&2
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
