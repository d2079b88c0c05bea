# shellcheck shell=bash disable=SC2034  # sourced: render_args is for the scripts that source it
# Shared by the job scripts (sourced, not run): the render's parameters
# from the environment, and kerf's flags for them (docs/farm.md).
#   KERF     the kerf binary (default: kerf on PATH)
#   SCENE    the scene file (required)
#   OUT      the output pattern, OUT.png (default: SCENE's name, .png, here)
#   WIDTH, HEIGHT   the image size (default 1920 x 1080)
#   QUALITY  preview | draft | final | best (default final):
#            preview: --preview; draft: --aa off; final: kerf's default
#            adaptive anti-aliasing; best: --aa-samples 64 --aa-threshold 0.02
#   FRAMES   the animation's length (frames.sbatch)
#   TILES    the number of bands (tiles.sbatch, assemble.sbatch)
#   KERF_ARGS  further kerf render flags (-D name=value, --seed N, ...)
KERF=${KERF:-kerf}
: "${SCENE:?set SCENE to the scene file}"
OUT=${OUT:-$(basename "${SCENE%.*}").png}
WIDTH=${WIDTH:-1920}
HEIGHT=${HEIGHT:-1080}
QUALITY=${QUALITY:-final}
case $QUALITY in
  preview) quality=(--preview) ;;
  draft) quality=(--aa off) ;;
  final) quality=() ;;
  best) quality=(--aa-samples 64 --aa-threshold 0.02) ;;
  *) echo "farm: QUALITY must be preview, draft, final or best, not '$QUALITY'" >&2; exit 2 ;;
esac
# shellcheck disable=SC2206  # KERF_ARGS is a list of words by design
render_args=("$SCENE" -o "$OUT" -W "$WIDTH" -H "$HEIGHT" "${quality[@]}" --threads "${SLURM_CPUS_PER_TASK:-1}"
             --resume ${KERF_ARGS:-})

# The band files kerf render --tile K/N writes for OUT: OUT_tileKofN.png,
# K with as many digits as N - 1.
tile_files() {
  local n=$1 last=$(( $1 - 1 )) k
  for ((k = 0; k < n; k++)); do printf '%s_tile%0*dof%d.png\n' "${OUT%.*}" "${#last}" "$k" "$n"; done
}
