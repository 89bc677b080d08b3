#!/usr/bin/env bash
# CLI: mutated scenes (see cli_scene_fuzz.py): no NaN or Inf in a report, exit 0 only
# without a failed check, exits and stderr as the README promises.
cd "$(dirname "$0")/../.." || exit 1
exec python3 test/cli/cli_scene_fuzz.py 400
