#!/bin/bash
# Issue 46: the four-task protocol-6 recording of Qwen2.5-Coder-1.5B in the paper's setup
# (--brief description), one method at a time, cheapest first. Resumable: re-run it after a kill;
# every reply already in the cache is a hit, so only the questions not yet answered reach the model.
# The model writes to a working copy of the committed cache (`WORK`, outside git's view), never to
# the committed file itself: after each method, and on demand (`record.sh snapshot`), a consistent
# copy taken with SQLite's backup API replaces the committed file when it holds more replies, which
# is then what to commit.
# Needs: python tools/install_local.py && python tools/local_model.py qwen2.5-coder-1.5b
set -u
cd "$(dirname "$0")/../.."
M=qwen2.5-coder-1.5b-instruct-q4_k_m
COMMITTED=reports/recording/qwen2.5-coder-1.5b-protocol6.sqlite
WORK=${WORK:-rec/qwen2.5-coder-1.5b-protocol6.sqlite}
OUT=${OUT:-rec/runs}
snapshot() {
  python - "$WORK" "$COMMITTED" <<'PY'
import sqlite3, sys
src, dst = sqlite3.connect(sys.argv[1], timeout=60), sqlite3.connect(sys.argv[2])
count = "select count(*) from replies"
if src.execute(count).fetchone() == dst.execute(count).fetchone():  # replies are only added
    print(f"{sys.argv[2]}: up to date")
    sys.exit(0)
src.backup(dst)
dst.execute("PRAGMA journal_mode=DELETE")
dst.commit()
print(f"{sys.argv[2]}: {dst.execute('select count(*) from replies').fetchone()[0]} replies")
PY
}
mkdir -p "$(dirname "$WORK")"
[ -e "$WORK" ] || cp "$COMMITTED" "$WORK"
if [ "${1:-}" = snapshot ]; then snapshot; exit; fi
for G in holodeck logicenvgen ifg cot; do
  nice -n 19 python -m logicenveval run --model "llamacpp:$HOME/.cache/logicenveval/models/$M.gguf" \
    --model-args threads=2,parallel=1,ctx=20480 --workers 1 --unit-timeout 21600 \
    --tasks clean_living_room,kitchen_dish_cleanup,bathroom_counter_sort,multi_room_lights_off \
    --generators "$G" --output "$OUT" --run-id "$G" --cache "$WORK" --quiet
  echo "$(date -u +%H:%M) done $G rc=$?"
  snapshot
done
