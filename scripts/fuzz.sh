#!/usr/bin/env bash
# Builds the libFuzzer targets (CMake preset `fuzz`, in build-fuzz/) and runs each for SECONDS
# (default 60): the scene parser, seeded with the example scenes and the malformed corpus, the
# message decoder, seeded with one message of each kind, the master's and a worker's state
# machines on hostile traffic (tests/fuzz/protocol_fuzz.cpp), the glTF reader, seeded with the .glb
# and .gltf files of tests/models and scenes/models, and the asset pack's decoder, seeded with
# the packs of scenes/chess.scene and scenes/street.scene, the line-by-line check of OBJ and
# PLY files, seeded with the repository's, the checkpoint reader, and the TCP
# door's framing and invitation check (tests/fuzz/tcp_frames_fuzz.cpp). Fails (non-zero exit) on any crash,
# sanitizer report, leak or input slower than 10 s; the input that failed is left in
# build-fuzz/fuzz/ as crash-*, leak-* or timeout-*, to replay with
# `build-fuzz/fuzz/prt_fuzz_scene_parser FILE`. The corpora grow in build-fuzz/corpus/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
if ! [[ $seconds =~ ^[0-9]+$ ]] || ((seconds < 1)); then
  echo "usage: scripts/fuzz.sh [SECONDS per target, default 60]" >&2
  exit 2
fi
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -- -j"$(nproc)" >/dev/null

corpus=build-fuzz/corpus
mkdir -p "$corpus/scene" "$corpus/message" "$corpus/protocol" "$corpus/model" "$corpus/pack" \
  "$corpus/checkpoint" "$corpus/tcp" "$corpus/mesh"
cp scenes/*.scene tests/malformed/*.scene "$corpus/scene/"
build-fuzz/fuzz/prt_fuzz_message_seeds "$corpus/message" scenes/fig08-basic-features.scene
cp tests/models/*.glb tests/models/*.gltf scenes/models/*.glb scenes/models/*.gltf \
   scenes/models/street/*.glb "$corpus/model/"
build-fuzz/fuzz/prt_fuzz_pack_seeds "$corpus/pack" scenes/chess.scene scenes/street.scene \
   scenes/models/maps.glb scenes/models/volume.glb
build-fuzz/fuzz/prt_fuzz_checkpoint_seeds "$corpus/checkpoint"
find tests/models scenes/models -maxdepth 1 \( -iname '*.obj' -o -iname '*.ply' \) \
  -exec cp {} "$corpus/mesh/" \;

# -rss_limit_mb and -malloc_limit_mb: an input must not make the code take gigabytes;
# -max_len: inputs of up to 64 kB (the parser's cost is linear; longer inputs only slow it),
# or as the third argument says (the model files and packs of the seeds are larger).
run() {
  local target=$1 dir=$2 max_len=${3:-65536}
  (cd build-fuzz/fuzz && ASAN_OPTIONS=detect_leaks=1 ./"$target" -max_total_time="$seconds" \
     -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len="$max_len" -print_final_stats=1 \
     "../../$dir" 2>"$target.log") || {
    echo "fuzz: $target FAILED; see build-fuzz/fuzz/$target.log:" >&2
    grep -E "ERROR|SUMMARY|Test unit written" "build-fuzz/fuzz/$target.log" >&2 || tail -20 "build-fuzz/fuzz/$target.log" >&2
    return 1
  }
  grep -E "stat::number_of_executed_units|stat::new_units_added" "build-fuzz/fuzz/$target.log" | sed "s/^/fuzz: $target /"
}
# The targets run side by side, one per core (a fuzzer is one process on one core): the same
# time for each, the wall time divided by the cores.
targets=(
  "prt_fuzz_scene_parser $corpus/scene"
  "prt_fuzz_message_decoder $corpus/message"
  "prt_fuzz_protocol $corpus/protocol"
  "prt_fuzz_model_reader $corpus/model 131072"
  "prt_fuzz_asset_pack $corpus/pack 1048576"
  "prt_fuzz_mesh_text $corpus/mesh 262144"
  "prt_fuzz_checkpoint $corpus/checkpoint"
  "prt_fuzz_tcp_frames $corpus/tcp"
)
jobs=$(nproc)
status=0
running=0
for t in "${targets[@]}"; do
  if ((running >= jobs)); then
    wait -n || status=1
    running=$((running - 1))
  fi
  # shellcheck disable=SC2086
  echo "fuzz: ${t%% *} for ${seconds} s"
  # shellcheck disable=SC2086
  run $t &
  running=$((running + 1))
done
while ((running > 0)); do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
