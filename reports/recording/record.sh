#!/bin/bash
# Issue 46: the four-task protocol-6 recording of Qwen2.5-Coder-1.5B in the paper's setup
# (--brief description), one method at a time, cheapest first. Resumable: re-run it after a kill;
# every reply already in the cache is a hit, so only the questions not yet answered reach the model.
# Needs: python tools/install_local.py && python tools/local_model.py qwen2.5-coder-1.5b
set -u
cd "$(dirname "$0")/../.."
M=qwen2.5-coder-1.5b-instruct-q4_k_m
CACHE=reports/recording/qwen2.5-coder-1.5b-protocol6.sqlite
OUT=${OUT:-rec/runs}
for G in holodeck logicenvgen ifg cot; do
  nice -n 19 python -m logicenveval run --model "llamacpp:$HOME/.cache/logicenveval/models/$M.gguf" \
    --model-args threads=2,parallel=1,ctx=20480 --workers 1 --unit-timeout 21600 \
    --tasks clean_living_room,kitchen_dish_cleanup,bathroom_counter_sort,multi_room_lights_off \
    --generators "$G" --output "$OUT" --run-id "$G" --cache "$CACHE" --quiet
  echo "$(date -u +%H:%M) done $G rc=$?"
done
