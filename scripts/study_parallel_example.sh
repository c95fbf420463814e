#!/usr/bin/env bash
# The README's sharded parameter study ("Parameter studies"), run by the test
# suite (tests/cli/test_cli_study.cpp): four shards of one study spread by
# GNU parallel, joined by `railstab merge`, then compared byte for byte with
# the same study run in one go.
#   usage: scripts/study_parallel_example.sh RAILSTAB SCENE WORK_DIR
# SCENE: cases/textbook_wheelset.toml (the keys below are its own).
set -euo pipefail
railstab=$1
scene=$2
work=$3
mkdir -p "$work"
cd "$work"
study=(--vary contacts.textbook_linear.conicity=0.1:0.4:0.1
       --vary 'elements.track_holder.stiffness_N_per_m[1]=2.5e5:7.5e5:2.5e5'
       --from 5 --to 120 --step 5)

# --- the README example ---------------------------------------------------
# -q: parallel quotes the command's words itself (the [1] is no shell glob).
parallel -q --halt now,fail=1 "$railstab" study "$scene" "${study[@]}" \
    --shard {}/4 --jobs 1 --out shard_{} ::: 1 2 3 4
"$railstab" merge merged shard_1 shard_2 shard_3 shard_4
# ---------------------------------------------------------------------------

"$railstab" study "$scene" "${study[@]}" --out whole
stem=textbook_wheelset_study
for f in "$stem.csv" "$stem.json" "${stem}_record.toml" "$stem.dat" "${stem}_plots.gp"; do
  cmp "whole/$f" "merged/$f"
done
for f in "${stem}_map.png" "${stem}_vs_key1.png" "${stem}_vs_key2.svg"; do
  test -s "merged/$f"
done
echo "merged == unsharded"
