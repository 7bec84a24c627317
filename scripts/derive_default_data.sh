#!/bin/sh
# Derives the default data embedded in oceanglobe: data/etopo5_relief.nc (relief) from the ETOPO5
# grid, and data/navy_winds_199201.nc (wind) from the monthly navy winds, both in Debian's
# ferret-datasets package; the imagery and the land mask below. Needs the nco and netcdf-bin
# packages (gdal-bin, gmt, python3-numpy and python3-gdal for the land mask).
#
# ETOPO5 stores relief as float metres on a 5' (about 9 km) grid. Two changes make the embedded
# copy small (about 4.6 MB instead of 37 MB), both documented in data/README.md:
#  - heights rounded to whole metres (the source's values are whole metres already, up to float
#    noise) and stored as int16 with shuffle + deflate;
#  - sea floor deeper than 200 m rounded to 100 m steps. Water that deep is optically deep
#    everywhere (the ocean's colour no longer sees the floor) and no coast, bank or land
#    height depends on it, while its metre-level noise is most of the file's entropy (lossless
#    the file is 8.4 MB). Land and the shelf (-200 m and above, the -10 m bank placeholder
#    that data/ShallowBanks looks for included) keep every metre.
# The axes are rewritten as exact multiples of 5' (the source's longitudes carry float noise:
# 0.0833341 degrees spacing, 359.92 last).
#
# Usage: scripts/derive_default_data.sh [SOURCE.cdf] [OUTPUT.nc]
set -eu

src=${1:-/usr/share/ferret-vis/data/etopo5.cdf}
out=${2:-$(dirname "$0")/../data/etopo5_relief.nc}

for tool in ncap2 ncatted ncks nccopy; do
  command -v "$tool" >/dev/null 2>&1 || {
    echo "derive_default_data.sh: '$tool' not found (apt-get install nco netcdf-bin)" >&2
    exit 1
  }
done
[ -r "$src" ] || {
  echo "$src: not readable (apt-get install ferret-datasets)" >&2
  exit 1
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

# 1. Drop the float fill attributes first: ncap2 would otherwise convert -1e34 to a short
#    _FillValue of 0 and turn every sea-level cell into "missing". The source has no missing
#    cells (checked below). Then round to whole metres (floor(x+0.5): this ncap2's round()
#    hangs), the deep floor to 100 m, and store as short.
ncks -O -h -v ROSE "$src" "$tmp/float.nc"
ncatted -O -h -a missing_value,ROSE,d,, -a _FillValue,ROSE,d,, "$tmp/float.nc"
ncap2 -O -h -s 'lo=ROSE.min(); hi=ROSE.max();' "$tmp/float.nc" "$tmp/range.nc"
lo=$(ncks -H -C -v lo "$tmp/range.nc" | sed -n 's/.*lo = *\([-0-9.e+]*\).*/\1/p')
hi=$(ncks -H -C -v hi "$tmp/range.nc" | sed -n 's/.*hi = *\([-0-9.e+]*\).*/\1/p')
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo != "" && hi != "" && lo >= -12000 && hi <= 9000) }' || {
  echo "derive_default_data.sh: $src: ROSE range [$lo, $hi] is not plausible relief in metres" >&2
  exit 1
}
# 1b. ETOPO5's coastal checkerboard (data/README.md, "Changes from the source", 2): along some
#    coasts (off Tetouan, Miami, Costa Rica, the Gulf of California, ...) the grid alternates
#    cell by cell between a shallow placeholder and the shelf's depth (-8, -198, -8, -197 m),
#    diagonally, so lone shallow cells stand in deeper water and render as turquoise crosses.
#    A cell is cleaned when it is shallower than 50 m and both its row neighbours (west and
#    east, across the seam), or both its column neighbours (south and north), are at least
#    100 m deeper and within 10 m of each other (the checkerboard's signature: its deep
#    partners repeat one value; real reefs and steep coasts have unequal sides); it takes the
#    mean of that pair (of all four when both pairs qualify). One pass on the unmodified
#    neighbours (order-free, deterministic); the count is printed (344 cells in etopo5.cdf).
#    The -10 m bank plateaus (data/ShallowBanks) and cells beside land keep their depth.
ncap2 -O -h -s 'ROSE=floor(ROSE+0.5f);
  *e=ROSE; e(:,0:4318)=ROSE(:,1:4319); e(:,4319)=ROSE(:,0);
  *w=ROSE; w(:,1:4319)=ROSE(:,0:4318); w(:,0)=ROSE(:,4319);
  *n=ROSE; n(0:2159,:)=ROSE(1:2160,:);
  *s=ROSE; s(1:2160,:)=ROSE(0:2159,:);
  *shallow=(ROSE < 0.0f && ROSE > -50.0f);
  *ew=(shallow && e <= ROSE-100.0f && w <= ROSE-100.0f && abs(e-w) <= 10.0f);
  *ns=(shallow && n <= ROSE-100.0f && s <= ROSE-100.0f && abs(n-s) <= 10.0f);
  nclean=(ew || ns).total();
  where(ew && ns) ROSE=floor((e+w+n+s)/4.0f+0.5f);
  where(ew && ns == 0) ROSE=floor((e+w)/2.0f+0.5f);
  where(ns && ew == 0) ROSE=floor((n+s)/2.0f+0.5f);' "$tmp/float.nc" "$tmp/clean.nc"
nclean=$(ncks -H -C -v nclean "$tmp/clean.nc" | sed -n 's/.*nclean = *\([0-9.]*\).*/\1/p')
echo "derive_default_data.sh: $nclean checkerboard cells cleaned"
ncks -O -h -x -v nclean "$tmp/clean.nc" "$tmp/clean2.nc"
ncap2 -O -h -s 'ROSE=short(ROSE); where(ROSE < -200) ROSE=short(floor(ROSE/100.0f+0.5f)*100);
  ETOPO05_X=array(0.0,1.0/12.0,$ETOPO05_X); ETOPO05_Y=array(-90.0,1.0/12.0,$ETOPO05_Y);' \
  "$tmp/clean2.nc" "$tmp/short.nc"

# 2. Attributes: keep the axes' units (they are how readers find the axes), describe the field.
history="scripts/derive_default_data.sh: ROSE from $(basename "$src") rounded to int16 metres, coastal checkerboard cleaned ($nclean cells), below -200 m to 100 m; axes exact 5'; NetCDF-4, shuffle, deflate 9"
ncatted -O -h \
  -a history,ROSE,d,, \
  -a units,ROSE,o,c,"m" \
  -a long_name,ROSE,o,c,"relief of the surface of the Earth (topography and bathymetry)" \
  -a standard_name,ROSE,o,c,"height_above_mean_sea_level" \
  -a positive,ROSE,o,c,"up" \
  -a comment,ROSE,o,c,"whole metres; coastal checkerboard placeholders cleaned; sea floor below -200 m rounded to 100 m" \
  -a standard_name,ETOPO05_X,o,c,"longitude" \
  -a standard_name,ETOPO05_Y,o,c,"latitude" \
  -a title,global,o,c,"ETOPO5 global relief, 5 arc-minute, whole metres" \
  -a source,global,o,c,"ETOPO5 5-minute gridded elevation data (NOAA National Geophysical Data Center, 1988) as distributed with the Ferret data sets (Debian package ferret-datasets, file etopo5.cdf, from IRI/LDEO worldbath.nc)" \
  -a license,global,o,c,"Public domain: ETOPO5 is a work of the U.S. Government (NOAA NGDC) and not subject to copyright" \
  -a references,global,o,c,"Data Announcement 88-MGG-02, Digital relief of the Surface of the Earth. NOAA, National Geophysical Data Center, Boulder, Colorado, 1988" \
  -a history,global,o,c,"$history" \
  -a Conventions,global,o,c,"CF-1.8" \
  "$tmp/short.nc"
ncatted -O -h -a _FillValue,ROSE,c,s,-32768 "$tmp/short.nc"

# 3. NetCDF-4 classic model, deflate level 9 with byte shuffle.
nccopy -k nc7 -d 9 -s "$tmp/short.nc" "$tmp/out.nc"
mv "$tmp/out.nc" "$out"
echo "wrote $out ($(wc -c <"$out") bytes)"

# ---------------------------------------------------------------------------------------------
# data/navy_winds_199201.nc: the default wind field, January 1992 from the FNOC monthly winds.
# Same treatment: fill attributes dropped (this month has no missing cells, checked), components
# rounded to 0.01 m/s and packed as int16 with scale_factor 0.01, NetCDF-4 + deflate.
wsrc=${WIND_SOURCE:-/usr/share/ferret-vis/data/monthly_navy_winds.cdf}
wout=${WIND_OUTPUT:-$(dirname "$0")/../data/navy_winds_199201.nc}
[ -r "$wsrc" ] || {
  echo "$wsrc: not readable (apt-get install ferret-datasets)" >&2
  exit 1
}
# Time step 120 is 1992-01-17 (hours since 1980-01-14 14:00), the last January in the file.
ncks -O -h -d TIME,120 -v UWND,VWND "$wsrc" "$tmp/wind.nc"
ncap2 -O -h -s 'nu=(UWND==-99.9f).total(); nv=(VWND==-99.9f).total();' "$tmp/wind.nc" "$tmp/wmiss.nc"
missing=$(ncks -H -C -v nu,nv "$tmp/wmiss.nc" | sed -n 's/.*n[uv] = *\([-0-9.e+_]*\).*/\1/p' | tr '\n' ' ')
for m in $missing; do
  case $m in 0|_) ;; *) echo "derive_default_data.sh: $wsrc: $m missing wind cells in step 120" >&2; exit 1 ;; esac
done
ncatted -O -h -a missing_value,UWND,d,, -a _FillValue,UWND,d,, \
  -a missing_value,VWND,d,, -a _FillValue,VWND,d,, "$tmp/wind.nc"
ncap2 -O -h -s 'UWND=short(floor(UWND*100.0f+0.5f)); VWND=short(floor(VWND*100.0f+0.5f));' \
  "$tmp/wind.nc" "$tmp/wshort.nc"
whistory="scripts/derive_default_data.sh: UWND, VWND time step 120 from $(basename "$wsrc"), packed int16 0.01 m/s; NetCDF-4, shuffle, deflate 9"
ncatted -O -h \
  -a history,UWND,d,, -a history,VWND,d,, \
  -a scale_factor,UWND,o,f,0.01 -a scale_factor,VWND,o,f,0.01 \
  -a units,UWND,o,c,"m s-1" -a units,VWND,o,c,"m s-1" \
  -a standard_name,UWND,o,c,"eastward_wind" -a standard_name,VWND,o,c,"northward_wind" \
  -a long_name,UWND,o,c,"monthly mean zonal wind (FNOC)" \
  -a long_name,VWND,o,c,"monthly mean meridional wind (FNOC)" \
  -a standard_name,FNOCX,o,c,"longitude" -a standard_name,FNOCY,o,c,"latitude" \
  -a standard_name,TIME,o,c,"time" -a calendar,TIME,o,c,"standard" \
  -a title,global,o,c,"FNOC monthly mean surface winds, January 1992, 2.5 degrees" \
  -a source,global,o,c,"Fleet Numerical Oceanography Center (US Navy) monthly winds as distributed with the Ferret data sets (Debian package ferret-datasets, file monthly_navy_winds.cdf)" \
  -a license,global,o,c,"Public domain: a work of the U.S. Government (US Navy FNOC; distributed by NOAA PMEL under the Ferret License Agreement, which places it in the public domain)" \
  -a history,global,o,c,"$whistory" \
  -a Conventions,global,o,c,"CF-1.8" \
  "$tmp/wshort.nc"
ncatted -O -h -a _FillValue,UWND,c,s,-32768 -a _FillValue,VWND,c,s,-32768 "$tmp/wshort.nc"
nccopy -k nc7 -d 9 -s "$tmp/wshort.nc" "$tmp/wout.nc"
mv "$tmp/wout.nc" "$wout"
echo "wrote $wout ($(wc -c <"$wout") bytes)"

# --- Default imagery: NASA Visible Earth day ("Blue Marble") and night ("Earth at night")
# images as Debian's xplanet-images ships them (2048 x 1024 JPEG, plate carree, -180..180 E,
# -90..90 N, public domain), copied byte for byte, each with a world file (pixel-centre
# registration, 360/2048 degrees per pixel) so GDAL reads them like any user imagery.
ximages=${XPLANET_IMAGES:-/usr/share/xplanet/images}
for pair in "earth.jpg:blue_marble_2048x1024" "night.jpg:night_lights_2048x1024"; do
  src="$ximages/${pair%%:*}"
  dst="$(dirname "$0")/../data/${pair##*:}"
  [ -r "$src" ] || { echo "derive_default_data.sh: $src missing (apt-get install xplanet-images)" >&2; exit 1; }
  cp "$src" "$dst.jpg"
  printf '0.17578125\n0\n0\n-0.17578125\n-179.912109375\n89.912109375\n' >"$dst.jgw"
  echo "wrote $dst.jpg ($(wc -c <"$dst.jpg") bytes) and $dst.jgw"
done

# --- Land/water mask from the GSHHG shorelines (Debian gmt-gshhg-high, LGPL-3+ / public domain
# data, see data/README.md): the high-resolution shorelines rasterised at 15" in 10 degree
# tiles (lakes as water, islands in lakes as land), packed into the 2' mask (each cell the
# majority of its 8 x 8 fine cells) and the fine cells' blocks where a 2' cell holds both
# (scripts/derive_landmask_15s.py, about 33 CPU minutes). Needs gmt, python3-numpy and
# python3-gdal (only here, not to build).
if command -v gmt >/dev/null 2>&1; then
  /usr/bin/python3 "$(dirname "$0")/derive_landmask_15s.py" "$(dirname "$0")/../data"
else
  echo "derive_default_data.sh: gmt not found; data/gshhg_landmask_* not rebuilt (apt-get install gmt gmt-gshhg-high python3-numpy python3-gdal)" >&2
fi
