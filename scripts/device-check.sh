#!/usr/bin/env bash
# Runs on the lent GPU machine, from the repository's root, with .devbundle carried
# (scripts/device-bundle.sh made it here). Unpacks the bundle, points GLVND's EGL at NVIDIA's
# driver, and runs the command given with OG (the oceanglobe executable) and OG_TESTS (the GL
# tests, when bundled) set; shaders are read from this checkout, so a shader change needs no
# new bundle. Without a command: the GPU check of docs/performance.md (bench of every view at
# 1920x1080 and 1280x720 with 1 and 4 samples; the per-pass breakdown, at 1080p with 4 samples
# too; three 720p renders to compare with llvmpipe's, forward at 4 samples and 1, and by
# compute at 1; the deferred and the compute sea's breakdowns; the surface pass's parts
# (ablated shaders, timing only); with FFmpeg bundled, the recording rate; with the GL tests
# bundled, their run in the time left to 550 s), its files written to $OUT. Every step has a
# time limit (run it with timeout_s near 590: the lent machine allows 600 s a command). A whole
# check took ~85 s on the H200 in the tenth session, 377 s with the compute sea's and the
# tests' runs in the thirty-third.
#   device run: bash scripts/device-check.sh            (carry .devbundle)
#   device run: bash scripts/device-check.sh '$OG_TESTS --gtest_filter=Transforms*'
set -uo pipefail
root=$PWD
bundle=/tmp/oceanglobe-bundle
rm -rf "$bundle" && mkdir -p "$bundle" && tar -C "$bundle" -xJf .devbundle/og-bundle.tar.xz || exit 2  # no stale stubs
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[[ -f $vendor ]] || vendor=$(find / -xdev -path '*egl_vendor.d*' -name '*nvidia*.json' 2>/dev/null | head -1)
[[ -n $vendor ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor  # else the machine's own (Mesa here)
export LD_LIBRARY_PATH=$bundle/stubs:$bundle/lib:/usr/local/nvidia/lib64:/usr/local/nvidia/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export OCEANGLOBE_SHADER_DIR=$root/shaders OCEANGLOBE_CACHE_DIR=/tmp/oceanglobe-cache
export OG=$bundle/bin/oceanglobe OG_TESTS=$bundle/bin/og_gl_tests
[[ -d $bundle/share/proj ]] && export PROJ_DATA=$bundle/share/proj PROJ_LIB=$bundle/share/proj
out=${OUT:-/tmp/oceanglobe-out}
mkdir -p "$out"
# The GL tests find their data by the paths compiled in (this machine's checkout of /work/main)
# and write into its build/tests/out.
if [[ -x $OG_TESTS && ! -e /work/main ]]; then mkdir -p /work && ln -s "$root" /work/main; fi
[[ -x $OG_TESTS ]] && mkdir -p "$root/build/tests/out"
quiet() { perl -0pe 's/stub called: curl_global_[a-z]*\n?//g' | grep -v "no version information available"; }

if [[ $# -gt 0 ]]; then
  (eval "$*") 2>&1 | quiet
  exit "${PIPESTATUS[0]}"
fi
# At most 8 files come back from $OUT: the texts in bench.txt, the breakdowns as JSON, the renders
# in one tar, the GL tests' log and the pictures their failures wrote (when bundled).
stamp=$(mktemp)  # (the tests' pictures newer than it come back)
{ nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader; uptime; } | tee "$out/bench.txt"
mkdir -p "$out/png"
render() {
  local name=$1; shift
  timeout 20 "$OG" render --width 1280 --height 720 --sun-elevation 20 --sun-azimuth 250 "$@" \
    -o "$out/png/$name.png" 2>&1 | quiet | tail -2
}
views=("sea-4m --lat 20 --lon -40 --alt 4 --heading 270 --pitch -10"
  "coast-2m-bank --lat 24.2 --lon -78.2 --alt 2 --heading 270 --pitch -10"
  "sea-2m-horizon --lat 36 --lon -5.5 --alt 2 --heading 270 --pitch 2")
for v in "${views[@]}"; do
  read -r name args <<<"$v"
  # shellcheck disable=SC2086 # the view's flags
  render "$name" --samples 4 $args
  # shellcheck disable=SC2086
  render "$name-1" --samples 1 $args
  # shellcheck disable=SC2086
  OCEANGLOBE_SEA=compute render "$name-compute" --samples 1 $args
  # shellcheck disable=SC2086 # (the visibility buffer where the sea has one class: sea-4m)
  OCEANGLOBE_SEA_SURFACE=visibility render "$name-visibility" --samples 4 $args
done
tar -C "$out" -cf "$out/renders.tar" png && rm -rf "$out/png"
timeout 160 "$OG" bench --size 1920x1080 --size 1280x720 --frames 30 --samples 1 4 2>&1 | quiet | tee -a "$out/bench.txt"
timeout 100 "$OG" bench --size 1920x1080 --size 1280x720 --frames 20 --samples 1 --breakdown --json 2>"$out/breakdown.err" >"$out/breakdown.json"
# The GPU's default, 4 samples, pass by pass (where its frames' extra time goes: "Thirty-fourth
# session" on llvmpipe's).
timeout 50 "$OG" bench --size 1920x1080 --frames 20 --samples 4 --breakdown 2>&1 | quiet | sed "s/^/4 samples: /" | tee -a "$out/bench.txt"
# The globe's parts by query and over blocks, llvmpipe's multisampling workaround (off on GPUs:
# gl::DriverProfile::multisampleShadesEveryBlock), against the above.
OCEANGLOBE_MSAA_PART_BLOCKS=1 timeout 30 "$OG" bench --size 1920x1080 --frames 20 --samples 4 --view sea-4m \
  --view limb-400km --view orbit-20000km 2>&1 | quiet | sed "s/^/4 samples, part blocks: /" | tee -a "$out/bench.txt"
# The visibility buffer (OCEANGLOBE_SEA_SURFACE=visibility, "Thirty-fifth session"): where the
# sea has one class the surface pass writes each pixel's grid triangle alone (no varyings, 4
# bytes) and the shading interpolates the triangle's vertices; at 4 samples (the GPU default,
# otherwise the sea forward) shaded once a pixel by compute shaders, then copied to the samples
# with sea. Against the default above: 4 samples, and one sample by fragments and by compute.
OCEANGLOBE_SEA_SURFACE=visibility timeout 40 "$OG" bench --size 1920x1080 --size 1280x720 --frames 20 --samples 4 \
  --view sea-4m --view sea-1km --view sea-8km --breakdown 2>&1 | quiet | sed "s/^/visibility, 4 samples: /" | tee -a "$out/bench.txt"
for sea in deferred compute; do
  OCEANGLOBE_SEA_SURFACE=visibility OCEANGLOBE_SEA=$sea timeout 30 "$OG" bench --size 1920x1080 --frames 20 --samples 1 \
    --view sea-4m --view sea-1km --view sea-8km --breakdown 2>&1 | quiet |
    sed "s/^/visibility, OCEANGLOBE_SEA=$sea: /" | tee -a "$out/bench.txt"
done
# The deferred sea (full-screen passes per class, the classes copied into the stencil where the
# driver cannot export them) and its classes shaded by compute shaders instead, against the
# default above (docs/performance.md, "Thirty-second session"), every view at one sample; and
# the forward sea in one program against its triangles in classes (OceanRenderer::drawForwardSplit,
# "Thirty-third session"; the default without stencil export but where, at one sample, a
# floor's frames go deferred by compute), at 1 and 4 samples.
for sea in deferred compute; do
  OCEANGLOBE_SEA=$sea timeout 60 "$OG" bench --size 1920x1080 --size 1280x720 --frames 20 --samples 1 --breakdown \
    2>&1 | quiet | sed "s/^/OCEANGLOBE_SEA=$sea: /" | tee -a "$out/bench.txt"
done
for sea in forward split; do
  OCEANGLOBE_SEA=$sea timeout 40 "$OG" bench --size 1920x1080 --frames 20 --samples 1 4 --view sea-2m-horizon \
    --view coast-2m-bank --view coast-2m-deep --view sea-4m 2>&1 | quiet | sed "s/^/OCEANGLOBE_SEA=$sea: /" | tee -a "$out/bench.txt"
done
# The deferred sea's surface pass by parts (its cost on the H200 was the deferred sea's:
# "Thirty-third session"): sea-4m by compute at 1080p with the pass's fragment shader writing
# constants (no varyings read: rasterising the grid and storing its layers) and discarding every
# fragment (the grid's vertices and rasterising alone), for the next step's choice between a
# thinner surface buffer and the grid rasterised by compute. Timing only: the pictures are wrong.
surfacePart() {
  local dir=/tmp/og-shaders-$1
  rm -rf "$dir" && cp -r "$root/shaders" "$dir"
  BODY=$2 perl -0pi -e 's/void main\(\) \{.*\z/void main() {\n$ENV{BODY}\n}\n/s' "$dir/ocean/sea_surface.frag"
  OCEANGLOBE_SHADER_DIR=$dir OCEANGLOBE_SEA=compute timeout 30 "$OG" bench --size 1920x1080 --frames 20 --samples 1 \
    --view sea-4m --breakdown 2>&1 | quiet | sed "s/^/surface pass $1: /" | tee -a "$out/bench.txt"
}
surfacePart writing-constants '  seaSurface0 = uvec4(0u, 1u, 0u, 0u);  // (class 1)
  seaSurface1 = seaSurface2 = seaSurface3 = uvec4(0u);
#ifndef SEA_SURFACE_COMPACT
  seaSurface4 = seaSurface5 = uvec4(0u);
#endif
#ifndef SEA_CLASS_IN_SURFACE
  gl_FragStencilRefARB = 1;
#endif'
surfacePart discarding '  discard;'
# The recording rate, where the bundle has FFmpeg (scripts/device-bundle.sh --record).
if [[ -e $bundle/lib/libavcodec.so.59 ]]; then
  # (a sample of 60 frames: the whole path, bench --record's default, four times over is long)
  timeout 120 "$OG" bench --record config/flythrough.toml --frames 60 --size 1280x720 --size 1920x1080 2>&1 | quiet | tee -a "$out/bench.txt"
fi
# The GL tests, where bundled (scripts/device-bundle.sh --tests); the tests that read Debian's
# data packages (ferret-datasets, GSHHG) or OSMesa fail there.
if [[ -x $OG_TESTS ]]; then
  left=$((550 - SECONDS))
  if ((left >= 30)); then
    timeout $left "$OG_TESTS" 2>&1 | quiet >"$out/gltests.txt"
    grep -E "^\[  (PASSED|FAILED) |^\[==========\]" "$out/gltests.txt" | tail -40
    # The pictures the tests wrote (a failure's *_change.png: which pixels moved), one tar;
    # only the change maps if all would pass the 16 MB a file that comes back.
    pictures() { (cd "$root/build/tests/out" && find . -name "$1" -newer "$stamp" -print0 | tar -cf "$out/testout.tar" --null -T -); }
    pictures "*.png"
    (($(stat -c %s "$out/testout.tar") < 15000000)) || pictures "*_change.png"
  else
    echo "device-check: no time left for the GL tests" | tee "$out/gltests.txt"
  fi
fi
