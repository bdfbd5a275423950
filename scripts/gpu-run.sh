#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Run vtk-bloom's rendering tests, the frame-time benchmark and the vtk-bloom tool on a GPU
# machine, from the pack of scripts/gpu-pack.sh. Run it as root from a directory that holds
# .gl/ (the glvnd loader packages: libglvnd0 libopengl0 libegl1 libgl1 libglx0 libgles2, from
# `apt-get download`) and .gpupack/vtk-bloom-gpu.tar.xz; results go to $OUT (default: a new
# temporary directory):
#
#   OUT=DIR bash gpu-run.sh          (scripts/gpu-run.sh beside the pack; scripts/gpu-pack.sh)
#
#
#   gpu.txt          the GPU, its driver and the OpenGL renderer the pass ran on
#   ctest.log        ctest -R '^Rendering' (every rendering test), and ctest.xml (JUnit)
#   motion.md        the flicker sweep's figures (TestBloomPassMotion: the bloom's and the
#                    scene's coefficient of variation under sub-pixel camera steps)
#   frametime.md     BloomPassFrameTime: every scene and preset (or $PRESETS) at 1920x1080 and
#                    3840x2160, GPU timer, $FRAMES (default 50) frames of each kind: the bloom
#                    over the plain frame and over the cheapest float copy by the mean, and the
#                    bloom frame's median, mean, p99 and maximum
#   fusion.md        the default preset's frame time and four renderers with
#                    vtkBloomPassTesting::SetFuseSeparablePasses off (BloomPassFrameTime --pairs)
#   samples.md       the default preset in a window of 4 samples, each sample thresholded
#                    (vtkBloomPass::ThresholdSamples), then after the resolve (--resolved)
#   renderers.md     four bloomed renderers in one window (2 x 2 viewports) against the same
#                    four plain, at 1920x1080 and 3840x2160: the CPU's time in Render() and the
#                    GPU's (BloomPassFrameTime --renderers)
#   profile.md       the per-pass GPU profile of the default preset at 1920x1080 and 3840x2160,
#                    every scene, then what the user pays (the bloom frame over the plain frame)
#                    and its parts: the scene's float render, the depth's draw, the copy back,
#                    the chain, the composite
#   depthdraw.md     the frame-time table and lit-spheres' profile with the scene's depth drawn
#                    after the composite (BloomPassFrameTime --depth-draw), as every frame did
#                    before the scene rendered into the window's depth buffer: its cost
#   formats.md       the plain scene into a colour target of each format (RGBA8,
#                    R11F_G11F_B10F, RGBA16F, RGBA32F) blitted to the window, beside the plain
#                    frame, the compute copy and the bloom (BloomPassFrameTime --formats),
#                    lit-spheres and field-lines at 1920x1080 and 3840x2160, $FRAMES frames
#   quality.md       every preset, blurs tap by tap and PSF bloom (exact and split) at
#                    3840x2160: GPU time over the floor and error against vtkImageBloom
#                    REFERENCE (and quality.csv, for scripts/plot-gpu-quality.py)
#   sparse.md        sparse scenes (0 %, 0.1 %, 1 %, 10 % bright) at 3840x2160: the full chain
#                    against the content-aware one
#   sync.md          the cost of the pass's one wait for the GPU (BloomPassFrameTime --sync)
#   orbit.md         stutter: the bloom's own GPU time, frame by frame, over 1000
#                    frames of an orbiting camera at 3840x2160 (BloomPassFrameTime --orbit)
#   selective.md     selective bloom (scalar-field) against the whole scene's, the emission in
#                    the scene's render and in a second render, at 1920x1080 and 3840x2160
#                    (BloomPassFrameTime --selective), 4 x $FRAMES frames of each kind
#   psf.md           PSF bloom (the FFT convolution) on lit-spheres at 1920x1080 and 3840x2160,
#                    Airy PSFs of radius 16, 64 and 256 and a PSF as wide as the frame (grids
#                    up to 7680 x 6000, four-step transforms), each against the plain frame and
#                    the compute copy (BloomPassFrameTime --psf), $FRAMES frames of each kind
#   soak.md          long sessions (TestBloomPassSoak): the bloom, its emitters, presets and
#                    PSF mode, tiles and windows and the context switched for hundreds of
#                    frames, host memory and the card's (GL_NVX_gpu_memory_info) at the start
#                    and the end against the plain renderer, and nvidia-smi's memory in use
#                    before and after
#   stages.md        ShaderStageThroughput: one full-screen pass as a fragment and as a compute
#                    shader at 3840x2160
#   render.png       `vtk-bloom render` of lit-spheres at 3840x2160
#   run.log          everything printed
#
# STEPS (default "tests frametime renderers fusion samples profile quality sparse sync orbit
# selective psf soak stages render")
# picks the steps (depthdraw and formats only when named). At most 8 files come back from the device tool: pick fewer steps there.
# The script exits with ctest's status. It unpacks the loaders into / (they are absent from a
# CUDA image) and the pack at the absolute paths it was built with.
set -uo pipefail
cd "${VTKBLOOM_GPU_ROOT:-$PWD}" || exit 1
OUT=${OUT:-$(mktemp -d)}
mkdir -p "$OUT"
FRAMES=${FRAMES:-50}
STEPS=${STEPS:-tests frametime renderers fusion samples profile quality sparse sync orbit selective psf soak stages render}
PRESETS=${PRESETS:-all}
step() { [[ " $STEPS " == *" $1 "* ]]; }
exec > >(tee "$OUT/run.log") 2>&1

for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
tar -C / --no-overwrite-dir -xJf .gpupack/vtk-bloom-gpu.tar.xz || exit 1
# shellcheck disable=SC1091
. /opt/vtk-bloom-gpu/env
export LD_LIBRARY_PATH=/opt/vtk-bloom-gpu/lib
bin=$VTKBLOOM_GPU_BUILD/bin
mkdir -p "$VTKBLOOM_GPU_BUILD/Testing/Temporary"
# glvnd finds the NVIDIA EGL vendor in its default folders; where the driver is mounted
# elsewhere, name its file.
if ! ls /usr/share/glvnd/egl_vendor.d/*nvidia* >/dev/null 2>&1; then
  for j in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json \
    /usr/local/share/glvnd/egl_vendor.d/10_nvidia.json; do
    [ -f "$j" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$j && break
  done
fi
missing=$(ldd "$bin"/* | grep 'not found' | sort -u)
[ -z "$missing" ] || echo "gpu-run: missing libraries: $missing"

{
  echo "pack: commit $VTKBLOOM_GPU_COMMIT, VTK $VTKBLOOM_GPU_VTK"
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.sm,clocks.max.sm \
    --format=csv
  "$bin/BloomPassFrameTime" --info
} | tee "$OUT/gpu.txt"

status=0
# The rendering test executables (scripts/gpu-pack.sh packs each of them).
rendering_executables=(TestBloomPass TestBloomPassHardCases TestBloomPassRegion
  TestBloomPassMotion TestBloomPassSoak TestBloomPassGallery TestBloomPassLight
  TestBloomPassTiles)
if step tests; then
echo "== rendering tests"
export CI=true # a test whose data is missing fails instead of skipping
export VTKBLOOM_EXPECT_COMPUTE=1 # the card runs the compute passes, or the tests fail
if command -v ctest >/dev/null 2>&1; then
  ctest --test-dir "$VTKBLOOM_GPU_BUILD" -R '^Rendering' --output-on-failure --timeout 600 \
    --no-tests=error --output-junit "$OUT/ctest.xml" 2>&1 | tee "$OUT/ctest.log"
  status=${PIPESTATUS[0]}
else
  # No CMake there: every rendering test executable the pack holds (gpu-pack.sh's list), in
  # its CTest working directory; a missing one, or a test that skips, fails the step.
  status=0
  for t in "${rendering_executables[@]}"; do
    if [ ! -x "$bin/$t" ]; then
      echo "gpu-run: the pack has no $t" | tee -a "$OUT/ctest.log"
      status=1
      continue
    fi
    (cd "$VTKBLOOM_GPU_BUILD/Testing" && timeout 600 "$bin/$t") 2>&1 | tee "$OUT/$t.log" |
      tee -a "$OUT/ctest.log" >/dev/null
    [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
    if grep -q '^\[  SKIPPED \]' "$OUT/$t.log"; then
      echo "gpu-run: $t skipped tests on the card" | tee -a "$OUT/ctest.log"
      status=1
    fi
  done
fi
# The flicker sweep's figures (issue 30, part 2), which the test prints.
(cd "$VTKBLOOM_GPU_BUILD/Testing" && timeout 300 "$bin/TestBloomPassMotion") 2>&1 |
  grep '^\[ flicker \]' | tee "$OUT/motion.md"
fi

if step frametime; then
echo "== frame time"
{
  echo "GPU timer (GL_TIME_ELAPSED), $FRAMES frames of each kind"
  echo
  for size in "1920 1080" "3840 2160"; do
    # shellcheck disable=SC2086
    timeout 300 "$bin/BloomPassFrameTime" all $size "$FRAMES" "$PRESETS"
    echo
  done
} | tee "$OUT/frametime.md"
fi

if step renderers; then
echo "== four bloomed renderers in one window"
{
  for size in "1920 1080" "3840 2160"; do
    timeout 300 "$bin/BloomPassFrameTime" --renderers lit-spheres $size "$FRAMES"
    echo
  done
} | tee "$OUT/renderers.md"
fi

if step fusion; then
echo "== the chain's separable pairs as two passes each (FuseSeparablePasses off), to compare"
{
  for size in "1920 1080" "3840 2160"; do
    timeout 300 "$bin/BloomPassFrameTime" --pairs all $size "$FRAMES" default
    echo
    timeout 300 "$bin/BloomPassFrameTime" --pairs --renderers lit-spheres $size "$FRAMES"
    echo
  done
} | tee "$OUT/fusion.md"
fi

if step samples; then
echo "== a multisampled window (4 samples): the samples thresholded apart, then after the resolve"
{
  for size in "1920 1080" "3840 2160"; do
    timeout 300 "$bin/BloomPassFrameTime" --samples 4 all $size "$FRAMES" default
    echo
    timeout 300 "$bin/BloomPassFrameTime" --samples 4 --resolved all $size "$FRAMES" default
    echo
  done
} | tee "$OUT/samples.md"
fi

if step profile; then
echo "== per-pass profile"
{
  for size in "1920 1080" "3840 2160"; do
    # shellcheck disable=SC2086
    timeout 300 "$bin/BloomPassFrameTime" --profile all $size "$FRAMES" default
    echo
  done
} | tee "$OUT/profile.md"
fi

if step depthdraw; then
echo "== the frame with the depth drawn after the composite"
{
  echo "GPU timer (GL_TIME_ELAPSED), $FRAMES frames of each kind; BloomPassFrameTime --depth-draw"
  echo
  for size in "1920 1080" "3840 2160"; do
    # shellcheck disable=SC2086
    timeout 300 "$bin/BloomPassFrameTime" --depth-draw all $size "$FRAMES" "$PRESETS"
    echo
    # shellcheck disable=SC2086
    timeout 300 "$bin/BloomPassFrameTime" --depth-draw --profile lit-spheres $size 50 default
    echo
  done
} | tee "$OUT/depthdraw.md"
fi

if step formats; then
echo "== the scene's colour target, format by format"
{
  for size in "1920 1080" "3840 2160"; do
    for scene in lit-spheres field-lines; do
      # shellcheck disable=SC2086
      timeout 300 "$bin/BloomPassFrameTime" --formats $scene $size "$FRAMES"
      echo
    done
  done
} | tee "$OUT/formats.md"
fi

if step quality; then
echo "== error against time"
timeout 400 "$bin/BloomPassFrameTime" --quality lit-spheres 3840 2160 "$FRAMES" \
  "$OUT/quality.csv" | tee "$OUT/quality.md"
fi

if step sparse; then
echo "== sparse scenes"
timeout 200 "$bin/BloomPassFrameTime" --sparse 3840 2160 "$FRAMES" | tee "$OUT/sparse.md"
fi

if step sync; then
echo "== the wait for the GPU"
timeout 120 "$bin/BloomPassFrameTime" --sync lit-spheres 3840 2160 "$FRAMES" | tee "$OUT/sync.md"
fi

if step orbit; then
echo "== stutter over an orbiting camera"
{
  for scene in lit-spheres field-lines; do
    timeout 300 "$bin/BloomPassFrameTime" --orbit "$scene" 3840 2160 1000
    echo
  done
} | tee "$OUT/orbit.md"
fi

# BloomPassFrameTime MODE SCENE at 1920x1080 and at 3840x2160: both_sizes SECONDS MODE SCENE
# FRAMES, each run bounded by SECONDS.
both_sizes() {
  for size in "1920 1080" "3840 2160"; do
    # shellcheck disable=SC2086
    timeout "$1" "$bin/BloomPassFrameTime" "$2" "$3" $size "$4"
    echo
  done
}

if step selective; then
echo "== selective bloom in one render"
both_sizes 200 --selective scalar-field "$((4 * FRAMES))" | tee "$OUT/selective.md"
fi

if step psf; then
echo "== PSF bloom"
both_sizes 400 --psf lit-spheres "$FRAMES" | tee "$OUT/psf.md"
fi

if step soak; then
echo "== long sessions"
used() { nvidia-smi --query-gpu=memory.used --format=csv,noheader 2>/dev/null | head -n 1; }
before=$(used)
soak_log=$OUT/soak.log
(cd "$VTKBLOOM_GPU_BUILD/Testing" && timeout 600 "$bin/TestBloomPassSoak") >"$soak_log" 2>&1
soak_status=$?
{
  echo "nvidia-smi memory in use before: $before"
  grep -E '^\[ soak \]|OK \]|FAILED|Failure|grew' "$soak_log"
  echo "nvidia-smi memory in use after: $(used)"
} | tee "$OUT/soak.md"
[ "$soak_status" -eq 0 ] || status=1
fi

if step stages; then
echo "== fragment and compute shaders"
timeout 120 "$bin/ShaderStageThroughput" 3840 2160 "$FRAMES" | tee "$OUT/stages.md"
fi

if step render; then
echo "== vtk-bloom render"
timeout 120 "$bin/vtk-bloom" render --size 3840x2160 lit-spheres "$OUT/render.png" &&
  ls -la "$OUT/render.png"
fi
echo "gpu-run: ctest status $status"
exit "$status"
