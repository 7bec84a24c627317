#!/usr/bin/env bash
# Packs the built oceanglobe (with --tests, the GL test binary; with --record, FFmpeg and x264 for
# `record`) with the shared libraries it loads into .devbundle/og-bundle.tar.xz, for a machine
# without the Debian packages: the GPU machine some sessions are lent (Ubuntu with NVIDIA's
# driver, no network; docs/performance.md, "Tenth session"). scripts/device-check.sh unpacks and
# runs it there. The bundle is ~30 MB (more with --tests, PROJ's database included, and with
# --record): with the working tree (~21 MB) about the 64 MiB the lent machine takes, so bundle
# the tests or the recorder, not both.
#
# FFmpeg comes only with --record (its module, oceanglobe-ffmpeg.so, is what loads it:
# core/Plugin.hpp). To stay small, the libraries of what a GPU check does not use are replaced
# by stubs of the same name: OSMesa, GLFW, ecCodes, ICU, and GDAL's drivers for formats the
# embedded data does not use. Debian links its libraries with BIND_NOW, so a stub defines every symbol the
# bundle imports from it: functions that return 0 (and say so once on stderr), data as zeros.
# glibc and libstdc++ are the machine's own (newer than Debian 12's).
set -euo pipefail
cd "$(dirname "$0")/.."
tests=0 record=0
for arg in "$@"; do
  case $arg in
    --tests) tests=1 ;;   # the GL tests too (build/tests/og_gl_tests)
    --record) record=1 ;; # FFmpeg with H.264 (x264) for `record` and `bench --record`
    *) echo "device-bundle: unknown option '$arg' (--tests, --record)" >&2; exit 2 ;;
  esac
done
[[ -x build/oceanglobe ]] || { echo "device-bundle: build/oceanglobe is missing (cmake --build build)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/lib" "$work/stubs" "$work/bin" .devbundle
# The modules beside the executable, where core/Plugin.hpp looks (GDAL's: the embedded imagery's
# first decode; FFmpeg's only for recording).
cp build/oceanglobe build/oceanglobe-gdal.so "$work/bin/"
if [[ $record == 1 ]]; then cp build/oceanglobe-ffmpeg.so "$work/bin/"; fi
if [[ $tests == 1 ]]; then
  cp build/tests/og_gl_tests "$work/bin/"
  # PROJ's database for the GeoTIFF imagery tests' warps (~1 MB compressed): device-check.sh
  # points PROJ_DATA at it.
  mkdir -p "$work/share/proj"
  cp /usr/share/proj/proj.db "$work/share/proj/"
fi
strip -s "$work"/bin/*

stubbed=(libOSMesa.so.8 libglfw.so.3
  libeccodes.so.0 libicuuc.so.72 libcurl-gnutls.so.4 libodbc.so.2 libodbcinst.so.2 libblosc.so.1
  libarmadillo.so.11 libqhull_r.so.8.0 libheif.so.1 libgif.so.7 libcfitsio.so.10 libwebp.so.7 libpq.so.5
  libopenjp2.so.7 libkmlbase.so.1 libkmldom.so.1 libkmlengine.so.1 libfyba.so.0 libspatialite.so.7
  libmariadb.so.3 libfreexl.so.1 libogdi.so.4.1 libgeos_c.so.1 libdfalt.so.0 libmfhdfalt.so.0)
if [[ $record == 1 ]]; then
  # FFmpeg itself, with x264; its other codecs, formats and hardware back-ends go (not libdrm
  # and libX11, which the drivers' EGL may load).
  stubbed+=(libvpx.so.7 libwebpmux.so.3 librsvg-2.so.2 libcairo.so.2 libzvbi.so.0 libsnappy.so.1
    libaom.so.3 libcodec2.so.1.0 libgsm.so.1 libjxl.so.0.7 libjxl_threads.so.0.7 libmp3lame.so.0 libopus.so.0
    librav1e.so.0 libshine.so.3 libspeex.so.1 libSvtAv1Enc.so.1 libtheoraenc.so.1 libtheoradec.so.1
    libtwolame.so.0 libvorbis.so.0 libvorbisenc.so.2 libx265.so.199 libxvidcore.so.4 libva.so.2 libmfx.so.1
    libdav1d.so.6 libgme.so.0 libopenmpt.so.0 libchromaprint.so.1 libbluray.so.2 librabbitmq.so.4 librist.so.4
    libsrt-gnutls.so.1.5 libssh-gcrypt.so.4 libzmq.so.5 libva-drm.so.2 libva-x11.so.2 libvdpau.so.1
    libOpenCL.so.1 libsoxr.so.0)
fi
realpath_of() {
  local path
  path=$(ldconfig -p | awk -v n="$1" '$1 == n {print $NF; exit}')
  [[ -n $path ]] || { echo "device-bundle: $1 is not installed (scripts/install-deps.sh)" >&2; exit 2; }
  readlink -f "$path"
}

# Empty stubs first, so that ldd lists only the libraries the rest still needs.
for s in "${stubbed[@]}"; do gcc -shared -Wl,-soname,"$s" -o "$work/stubs/$s" -x c /dev/null; done
LD_LIBRARY_PATH="$work/stubs" ldd "$work"/bin/* | awk '$3 ~ /^\// {print $3}' | sort -u |
  grep -vE "/(libc|libm|libdl|libpthread|librt|libgcc_s|libstdc\+\+)\.so|ld-linux|$work" |
  while read -r l; do cp -L "$l" "$work/lib/"; done
cp -L "$(realpath_of libGLdispatch.so.0)" "$work/lib/"

# Then each stub with what the bundle imports from the real library.
for f in "$work"/lib/* "$work"/bin/*; do nm -D --undefined-only "$f" | awk '{sub(/@.*/, "", $2); print $2}'; done |
  sort -u >"$work/imports"
for s in "${stubbed[@]}"; do
  real=$(realpath_of "$s")
  {
    echo '#include <stdio.h>'
    nm -D -S --defined-only "$real" | awk 'NF == 4 {sub(/@.*/, "", $4); print $3, $4, $2} NF == 3 {sub(/@.*/, "", $3); print $2, $3, 0}' |
      sort -u -k2,2 | awk -v so="$s" 'NR == FNR {want[$1] = 1; next} ($2 in want) {
        n++
        if ($1 ~ /[TtWiI]/) printf "long f%d(void) __asm__(\"%s\");\nlong f%d(void) { static int told; if (!told++) fputs(\"stub called: %s\\n\", stderr); return 0; }\n", n, $2, n, $2
        else printf "char d%d[0x%s + 8] __asm__(\"%s\") __attribute__((aligned(16)));\n", n, $3, $2
      }' "$work/imports" -
  } >"$work/stub.c"
  gcc -shared -fPIC -w -Wl,-soname,"$s" -o "$work/stubs/$s" "$work/stub.c"
done

tar -C "$work" -cf - bin lib stubs $([[ -d $work/share ]] && echo share) | xz -T0 -6 >"$work/og-bundle.tar.xz"
mv "$work/og-bundle.tar.xz" .devbundle/og-bundle.tar.xz
echo "device-bundle: .devbundle/og-bundle.tar.xz, $(du -h .devbundle/og-bundle.tar.xz | cut -f1)"
