#!/usr/bin/env bash
# Renders a camera path as a PNG sequence split across a Slurm job array, one chunk of frames
# per array task; then encode once with scripts/slurm_record.sh --encode (or as a dependent job).
#
#   n=$(build/oceanglobe record config/flythrough.toml --count-frames)   # e.g. 601
#   sbatch --array=0-$(( (n + 99) / 100 - 1 )) scripts/slurm_record.sh config/flythrough.toml out/frames
#   sbatch --dependency=afterok:JOBID scripts/slurm_record.sh --encode out/frames out/flythrough.mp4
#
# Each task renders frames [task*CHUNK, (task+1)*CHUNK) with --resume, so a pre-empted or failed
# task can simply be resubmitted: frames already renamed into place are skipped. The output
# directory must be on a file system all nodes share.
#SBATCH --job-name=oceanglobe-record
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
#SBATCH --output=slurm-%x-%A_%a.out
set -euo pipefail

OCEANGLOBE=${OCEANGLOBE:-build/oceanglobe}
CHUNK=${CHUNK:-100}     # frames per array task
FPS=${FPS:-30}          # must match between the render and the encode step

if [[ ${1:-} == --encode ]]; then
  frames=${2:?frames directory}
  out=${3:?output .mp4}
  # One encode over the whole sequence; yuv420p + faststart so every player takes it.
  ffmpeg -v error -y -framerate "$FPS" -i "$frames/frame_%05d.png" \
    -c:v libx264 -preset medium -crf 20 -pix_fmt yuv420p -movflags +faststart "$out.tmp.mp4"
  mv "$out.tmp.mp4" "$out"
  echo "wrote $out"
  exit 0
fi

path=${1:?camera path file}
frames=${2:?output directory for frames}
task=${SLURM_ARRAY_TASK_ID:?run with sbatch --array}
mkdir -p "$frames"
first=$((task * CHUNK))
"$OCEANGLOBE" record "$path" --fps "$FPS" --frames "$first:$((first + CHUNK))" --resume \
  -o "$frames/frame_%05d.png"
